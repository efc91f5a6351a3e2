"""RoBIOS-7 for Python: `from eye import *` gives every RoBIOS function and constant, over libeyesim.

The functions call the same C library C programs link (through ctypes), so a Python program talks
to the simulator exactly as a C program does. Calling conventions follow EyeSim's eye.py: images
come back as new buffers, out-parameters as lists, RADIOReceive as [id, message]; see
docs/api/python.md. There is one module per RoBIOS group (eye.lcd, eye.key, ...), generated from
protocol/protocol.json; what a group does beyond passing values to C is in eye/handwritten/."""

from eye import _sleep  # noqa: F401  (time.sleep in simulation time)
from eye import constants
from eye._library import EyeSimError, lib
from eye.constants import *  # noqa: F401,F403
from eye.lcd import *  # noqa: F401,F403
from eye.key import *  # noqa: F401,F403
from eye.os import *  # noqa: F401,F403
from eye.timer import *  # noqa: F401,F403
from eye.ser import *  # noqa: F401,F403
from eye.audio import *  # noqa: F401,F403
from eye.io import *  # noqa: F401,F403
from eye.irtv import *  # noqa: F401,F403
from eye.psd import *  # noqa: F401,F403
from eye.lidar import *  # noqa: F401,F403
from eye.cam import *  # noqa: F401,F403
from eye.radio import *  # noqa: F401,F403
from eye.servo import *  # noqa: F401,F403
from eye.motor import *  # noqa: F401,F403
from eye.vw import *  # noqa: F401,F403
from eye.ip import *  # noqa: F401,F403
from eye.sim import *  # noqa: F401,F403
from eye import lcd, key, os, timer, ser, audio, io, irtv, psd, lidar, cam, radio, servo, motor, vw, ip, sim

GROUPS = (lcd, key, os, timer, ser, audio, io, irtv, psd, lidar, cam, radio, servo, motor, vw, ip, sim)

__all__ = ["lib", "EyeSimError", *constants.__all__, *(name for group in GROUPS for name in group.__all__)]
