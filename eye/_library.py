"""Loads libeyesim, the same C library C programs link, and declares the C prototype of every function."""

from __future__ import annotations

import ctypes
import sys
from ctypes import CFUNCTYPE, POINTER, c_bool, c_char, c_char_p, c_int, c_ubyte, c_void_p
from pathlib import Path

from eyesim import paths


class EyeSimError(RuntimeError):
    """The eye module cannot do what was asked (for example: the C library lacks a function)."""


def library_path() -> Path:
    """libeyesim inside the installed eyesim package, or in $EYESIM_ROBIOS (a development build)."""
    name = {"darwin": "libeyesim.dylib", "win32": "eyesim.dll", "cygwin": "cygeyesim.dll"}.get(sys.platform,
                                                                                              "libeyesim.so")
    return paths.robios_lib_dir() / name


def _load() -> ctypes.CDLL:
    path = library_path()
    if not path.is_file():
        raise ImportError(
            f"eye: the RoBIOS C library is not at {path}. Reinstall EyeSim (pip install eyesim), or for a "
            f"development build set EYESIM_ROBIOS to its install prefix (docs/api/python.md)")
    try:
        return ctypes.CDLL(str(path))
    except OSError as error:
        raise ImportError(f"eye: cannot load the RoBIOS C library {path}: {error}") from None


lib = _load()

# Parameter kinds, named for what they carry.
INT, BYTE, CHAR, BOOL = c_int, c_ubyte, c_char, c_bool
TEXT = c_char_p               # a NUL-terminated string the function reads
TEXT_OUT = POINTER(c_char)    # a buffer the function writes a string into
BYTES = POINTER(c_ubyte)      # an image or data buffer
INTS = POINTER(c_int)         # an int out-parameter, or an array of ints
TIMER_FUNCTION = CFUNCTYPE(None)

# name -> (return type, parameter types), as in eyebot.h; tests/eye/test_coverage.py checks them.
PROTOTYPES: dict[str, tuple[object, list]] = {
    # LCD
    "LCDPrintf": (INT, [TEXT]),
    "LCDSetPrintf": (INT, [INT, INT, TEXT]),
    "LCDClear": (INT, []),
    "LCDSetPos": (INT, [INT, INT]),
    "LCDGetPos": (INT, [INTS, INTS]),
    "LCDSetColor": (INT, [INT, INT]),
    "LCDSetFont": (INT, [INT, INT]),
    "LCDSetFontSize": (INT, [INT]),
    "LCDSetMode": (INT, [INT]),
    "LCDMenu": (INT, [TEXT, TEXT, TEXT, TEXT]),
    "LCDMenuI": (INT, [INT, TEXT, INT, INT]),
    "LCDGetSize": (INT, [INTS, INTS]),
    "LCDPixel": (INT, [INT, INT, INT]),
    "LCDGetPixel": (INT, [INT, INT]),
    "LCDLine": (INT, [INT, INT, INT, INT, INT]),
    "LCDArea": (INT, [INT, INT, INT, INT, INT, INT]),
    "LCDCircle": (INT, [INT, INT, INT, INT, INT]),
    "LCDImageSize": (INT, [INT]),
    "LCDImageStart": (INT, [INT, INT, INT, INT]),
    "LCDImage": (INT, [BYTES]),
    "LCDImageGray": (INT, [BYTES]),
    "LCDImageBinary": (INT, [BYTES]),
    "LCDRefresh": (INT, []),
    # Keys
    "KEYGet": (INT, []),
    "KEYRead": (INT, []),
    "KEYWait": (INT, [INT]),
    "KEYGetXY": (INT, [INTS, INTS]),
    "KEYReadXY": (INT, [INTS, INTS]),
    # Camera
    "CAMInit": (INT, [INT]),
    "CAMRelease": (INT, []),
    "CAMGet": (INT, [BYTES]),
    "CAMGetGray": (INT, [BYTES]),
    # Image processing
    "IPSetSize": (INT, [INT]),
    "IPReadFile": (INT, [TEXT, BYTES]),
    "IPWriteFile": (INT, [TEXT, BYTES]),
    "IPWriteFileGray": (INT, [TEXT, BYTES]),
    "IPLaplace": (None, [BYTES, BYTES]),
    "IPSobel": (None, [BYTES, BYTES]),
    "IPCol2Gray": (None, [BYTES, BYTES]),
    "IPGray2Col": (None, [BYTES, BYTES]),
    "IPRGB2Col": (None, [BYTES, BYTES, BYTES, BYTES]),
    "IPCol2HSI": (None, [BYTES, BYTES, BYTES, BYTES]),
    "IPOverlay": (None, [BYTES, BYTES, BYTES]),
    "IPOverlayGray": (None, [BYTES, BYTES, INT, BYTES]),
    "IPPRGB2Col": (INT, [BYTE, BYTE, BYTE]),
    "IPPCol2RGB": (None, [INT, BYTES, BYTES, BYTES]),
    "IPPCol2HSI": (None, [INT, BYTES, BYTES, BYTES]),
    "IPPRGB2Hue": (BYTE, [BYTE, BYTE, BYTE]),
    "IPPRGB2HSI": (None, [BYTE, BYTE, BYTE, BYTES, BYTES, BYTES]),
    # System
    "OSExecute": (c_void_p, [TEXT]),
    "OSVersion": (INT, [TEXT_OUT]),
    "OSVersionIO": (INT, [TEXT_OUT]),
    "OSMachineSpeed": (INT, []),
    "OSMachineType": (INT, []),
    "OSMachineName": (INT, [TEXT_OUT]),
    "OSMachineID": (INT, []),
    # Time and timers
    "OSWait": (INT, [INT]),
    "OSAttachTimer": (INT, [INT, TIMER_FUNCTION]),
    "OSDetachTimer": (INT, [INT]),
    "OSGetTime": (INT, [INTS, INTS, INTS, INTS]),
    "OSGetCount": (INT, []),
    # Serial
    "SERInit": (INT, [INT, INT, INT]),
    "SERSendChar": (INT, [INT, CHAR]),
    "SERSend": (INT, [INT, TEXT]),
    "SERReceiveChar": (CHAR, [INT]),
    "SERReceive": (INT, [INT, TEXT_OUT, INT]),
    "SERCheck": (BOOL, [INT]),
    "SERFlush": (INT, [INT]),
    "SERClose": (INT, [INT]),
    # Audio
    "AUBeep": (INT, []),
    "AUPlay": (INT, [TEXT]),
    "AUDone": (INT, []),
    "AUMicrophone": (INT, []),
    # Distance sensors
    "PSDGet": (INT, [INT]),
    "PSDGetRaw": (INT, [INT]),
    "LIDARGet": (INT, [INTS]),
    "LIDARSet": (INT, [INT, INT, INT]),
    # Servos, motors, encoders
    "SERVOSet": (INT, [INT, INT]),
    "SERVOSetRaw": (INT, [INT, INT]),
    "SERVORange": (INT, [INT, INT, INT]),
    "MOTORDrive": (INT, [INT, INT]),
    "MOTORDriveRaw": (INT, [INT, INT]),
    "MOTORPID": (INT, [INT, INT, INT, INT]),
    "MOTORPIDOff": (INT, [INT]),
    "MOTORSpeed": (INT, [INT, INT]),
    "ENCODERRead": (INT, [INT]),
    "ENCODERReset": (INT, [INT]),
    # V-omega driving
    "VWSetSpeed": (INT, [INT, INT]),
    "VWGetSpeed": (INT, [INTS, INTS]),
    "VWSetPosition": (INT, [INT, INT, INT]),
    "VWGetPosition": (INT, [INTS, INTS, INTS]),
    "VWStraight": (INT, [INT, INT]),
    "VWTurn": (INT, [INT, INT]),
    "VWCurve": (INT, [INT, INT, INT]),
    "VWDrive": (INT, [INT, INT, INT]),
    "VWRemain": (INT, []),
    "VWDone": (INT, []),
    "VWWait": (INT, []),
    "VWStalled": (INT, []),
    "VWDriveRemain": (INT, []),
    "VWDriveDone": (INT, []),
    "VWDriveWait": (INT, []),
    # Digital and analog I/O
    "DIGITALSetup": (INT, [INT, CHAR]),
    "DIGITALRead": (INT, [INT]),
    "DIGITALReadAll": (INT, []),
    "DIGITALWrite": (INT, [INT, INT]),
    "ANALOGRead": (INT, [INT]),
    "ANALOGVoltage": (INT, []),
    "ANALOGRecord": (INT, [INT, INT]),
    "ANALOGTransfer": (INT, [BYTES]),
    # IR remote
    "IRTVGet": (INT, []),
    "IRTVRead": (INT, []),
    "IRTVFlush": (INT, []),
    "IRTVGetStatus": (INT, []),
    # Radio
    "RADIOInit": (INT, []),
    "RADIOGetID": (INT, []),
    "RADIOSend": (INT, [INT, TEXT]),
    "RADIOReceive": (INT, [INTS, TEXT_OUT, INT]),
    "RADIOCheck": (INT, []),
    "RADIOStatus": (INT, [INTS]),
    "RADIORelease": (INT, []),
    # Simulation only
    "SIMGetRobot": (INT, [INT, INTS, INTS, INTS, INTS]),
    "SIMSetRobot": (INT, [INT, INT, INT, INT, INT]),
    "SIMGetObject": (INT, [INT, INTS, INTS, INTS, INTS]),
    "SIMSetObject": (INT, [INT, INT, INT, INT, INT]),
    "SIMGetRobotCount": (INT, []),
    "SIMGetObjectCount": (INT, []),
}


class _Functions:
    """libeyesim's functions with their prototypes, bound on first use: a library older than this
    module still loads, and only a call to a function it lacks fails, saying so."""

    def __getattr__(self, name: str):
        if name not in PROTOTYPES:
            raise AttributeError(name)
        try:
            function = getattr(lib, name)
        except AttributeError:
            raise EyeSimError(f"{name} is not in the C library {library_path()}, which is older than this eye "
                              f"module; rebuild or reinstall EyeSim") from None
        function.restype, function.argtypes = PROTOTYPES[name]
        setattr(self, name, function)
        return function


C = _Functions()


def library_int(name: str) -> int | None:
    """The value of an int variable the library exports (IP_SIZE, CAMSIZE, ...), None if it has none."""
    try:
        return c_int.in_dll(lib, name).value
    except ValueError:
        return None
