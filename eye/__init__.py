"""RoBIOS-7 for Python: `from eye import *` gives every RoBIOS function and constant, over libeyesim.

The functions call the same C library C programs link (through ctypes), so a Python program talks
to the simulator exactly as a C program does. Calling conventions follow EyeSim's eye.py: images
come back as new buffers, out-parameters as lists, RADIOReceive as [id, message]; see
docs/api/python.md."""

from eye import _sleep  # noqa: F401  (time.sleep in simulation time)
from eye import constants
from eye._library import EyeSimError, lib
from eye.audio import *  # noqa: F401,F403
from eye.camera import *  # noqa: F401,F403
from eye.constants import *  # noqa: F401,F403
from eye.image import *  # noqa: F401,F403
from eye.keys import *  # noqa: F401,F403
from eye.lcd import *  # noqa: F401,F403
from eye.motors import *  # noqa: F401,F403
from eye.ports import *  # noqa: F401,F403
from eye.radio import *  # noqa: F401,F403
from eye.sensors import *  # noqa: F401,F403
from eye.serial import *  # noqa: F401,F403
from eye.sim import *  # noqa: F401,F403
from eye.system import *  # noqa: F401,F403
from eye.irtv import *  # noqa: F401,F403
from eye.vw import *  # noqa: F401,F403
from eye import audio, camera, image, irtv, keys, lcd, motors, ports, radio, sensors, serial, sim, system, vw

GROUPS = (lcd, keys, camera, image, system, serial, audio, sensors, motors, vw, ports, irtv, radio, sim)

__all__ = ["lib", "EyeSimError", *constants.__all__, *(name for group in GROUPS for name in group.__all__)]
