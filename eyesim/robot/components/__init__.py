"""Registry of component kinds: each factory looks at a robot type and returns the components it needs.

Adding a component kind = one new module with a `create(context)` function + one line here."""

from eyesim.robot.components import differential_drive, keys, lcd, psd, vw

FACTORIES = (
    differential_drive.create,
    vw.create,
    psd.create,
    lcd.create,
    keys.create,
)
