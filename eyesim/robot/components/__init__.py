"""Registry of component kinds: each factory looks at a robot type and returns the components it needs.

Adding a component kind = one new module with a `create(context)` function + one line here."""

from eyesim.robot.components import differential_drive  # one import and one FACTORIES line per kind
from eyesim.robot.components import keys
from eyesim.robot.components import lcd
from eyesim.robot.components import psd
from eyesim.robot.components import vw

FACTORIES = (
    differential_drive.create,
    vw.create,
    psd.create,
    lcd.create,
    keys.create,
)
