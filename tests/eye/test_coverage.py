"""Every function eyebot.h declares has a Python wrapper in `eye`, with the C prototype it declares;
every wrapper has type hints and a docstring; every constant has eyebot.h's value."""

from __future__ import annotations

import ctypes
import inspect
import re
import subprocess
from pathlib import Path

import pytest

HEADER = Path(__file__).resolve().parents[2] / "robios" / "include" / "eyebot.h"


# Functions of eyebot.h that Python programs never had: EyeSim's eye.py did not wrap them.
C_ONLY = {"SIMLaserScan"}


def declarations() -> dict[str, tuple[str, list[str]]]:
    """name -> (return type, parameter types) of every function eyebot.h declares, except the
    inline compatibility helpers (docs/api/compatibility.md)."""
    source = re.sub(r"/\*.*?\*/|//[^\n]*", " ", HEADER.read_text(), flags=re.S)
    source = re.sub(r'"(?:\\.|[^"\\])*"', '""', source)  # string literals (messages) hold no declarations
    source = re.sub(r"^\s*#.*?(?<!\\)$", " ", source, flags=re.M | re.S)  # preprocessor lines
    source = re.sub(r"static\s+inline[^{;]*\{[^}]*\}", " ", source)
    found = {}
    for match in re.finditer(r"([A-Za-z_][\w\s\*]*?)\b([A-Z][A-Za-z0-9_]*)\s*\(([^()]*)\)\s*([^;{]*);", source):
        result, name, params, attributes = match.groups()
        if result.strip().startswith(("typedef", "extern")):
            continue
        types = [] if params.strip() in ("", "void") else [parameter_type(p) for p in params.split(",")]
        found[name] = (" ".join(result.split()), types)
    return found


def parameter_type(parameter: str) -> str:
    """'const BYTE *img' -> 'const BYTE *', 'int distance[]' -> 'int *', '...' -> '...'."""
    parameter = " ".join(parameter.replace("*", " * ").split())
    if parameter == "...":
        return parameter
    if "(" in parameter:
        return "function"
    array = parameter.endswith("]")
    parameter = re.sub(r"\[\s*\w*\s*\]$", "", parameter).strip()
    words = parameter.split()
    if len(words) > 1 and re.fullmatch(r"[A-Za-z_]\w*", words[-1]) and words[-1] not in ("int", "char", "BYTE"):
        words = words[:-1]  # the parameter's name
    return " ".join(words) + (" *" if array else "")


def kind_of_c(c_type: str) -> str:
    """The ctypes-level kind of a C type, as eye's prototypes must declare it."""
    bare = c_type.replace("const ", "").replace("unsigned char", "BYTE").replace("uint8_t", "BYTE").strip()
    kinds = {
        "int": "int",
        "COLOR": "int",
        "TIMER": "int",
        "BYTE": "byte",
        "char": "char",
        "bool": "bool",
        "void": "void",
        "char *": "text",
        "BYTE *": "bytes",
        "int *": "ints",
        "function": "function",
    }
    return kinds.get(bare, f"unknown C type {c_type!r}")


def kind_of_ctypes(t) -> str:
    kinds = {
        None: "void",
        ctypes.c_int: "int",
        ctypes.c_ubyte: "byte",
        ctypes.c_char: "char",
        ctypes.c_bool: "bool",
        ctypes.c_char_p: "text",
        ctypes.POINTER(ctypes.c_char): "text",
        ctypes.c_void_p: "text",
        ctypes.POINTER(ctypes.c_ubyte): "bytes",
        ctypes.POINTER(ctypes.c_int): "ints",
    }
    if isinstance(t, type) and issubclass(t, ctypes._CFuncPtr):
        return "function"
    return kinds.get(t, f"unknown ctypes type {t!r}")


def test_the_header_parser_finds_what_it_should():
    found = declarations()
    assert found["LCDPrintf"] == ("int", ["const char *", "..."])
    assert found["IPOverlayGray"] == ("void", ["const BYTE *", "const BYTE *", "COLOR", "BYTE *"])
    assert found["IPPRGB2Hue"] == ("BYTE", ["BYTE", "BYTE", "BYTE"])
    assert found["SIMLaserScan"] == ("int", ["int *"])
    assert "LCDInit" not in found and "XInitThreads" not in found


def test_every_declared_function_has_a_wrapper(eye):
    missing = [
        name
        for name in declarations()
        if name not in C_ONLY and (not callable(getattr(eye, name, None)) or name not in eye.__all__)
    ]
    assert not missing, f"eyebot.h functions without a Python wrapper in eye: {missing}"


def test_wrappers_use_the_declared_prototypes(eye):
    from eye._library import PROTOTYPES

    wrong = []
    for name, (result, params) in declarations().items():
        if name in C_ONLY:
            assert name not in eye.__all__, f"{name} is listed as C-only but eye has it"
            continue
        if name not in PROTOTYPES:
            wrong.append(f"{name}: no prototype in eye/_prototypes.py")
            continue
        restype, argtypes = PROTOTYPES[name]
        declared = [kind_of_c(result)] + [kind_of_c(p) for p in params if p != "..."]
        bound = [kind_of_ctypes(restype)] + [kind_of_ctypes(t) for t in argtypes]
        if declared != bound:
            wrong.append(f"{name}: eyebot.h has {declared}, eye/_prototypes.py {bound}")
    assert not wrong, "\n".join(wrong)


def test_every_wrapper_has_type_hints_and_a_docstring(eye):
    lacking = []
    for name in eye.__all__:
        function = getattr(eye, name)
        if not inspect.isfunction(function):
            continue
        signature = inspect.signature(function)
        hinted = signature.return_annotation is not inspect.Signature.empty and all(
            p.annotation is not inspect.Parameter.empty for p in signature.parameters.values()
        )
        if not hinted or not (function.__doc__ or "").strip():
            lacking.append(name)
    assert not lacking, f"without type hints or docstring: {lacking}"


def constants() -> list[str]:
    """The object-like macros of eyebot.h that programs use as constants (not the header's own
    EYEBOT_ guards nor the library's EYESIM_ build switches, such as the Windows DLL's exports)."""
    names = re.findall(r"^\s*#\s*define\s+([A-Z][A-Z0-9_]*)\s+\S", HEADER.read_text(), flags=re.M)
    return [n for n in names if not n.startswith(("EYEBOT_", "EYESIM_"))]


def test_every_constant_has_the_header_value(eye, compiler, tmp_path):
    names = constants()
    assert {"ANYKEY", "QVGA_SIZE", "LCD_FB_NOROTATION", "IRTV_POWER", "MACHINE_NAME"} <= set(names)
    lines = []
    for name in names:
        if isinstance(getattr(eye, name, None), str):
            lines.append(f'printf("{name} %s\\n", {name});')
        else:
            lines.append(f'printf("{name} %lld\\n", (long long)({name}));')
    exe = compiler.build(
        '#include "eyebot.h"\n#include <stdio.h>\nint main(void)\n{\n' + "\n".join(lines) + "\nreturn 0;\n}\n",
        name="constants",
    )
    printed = subprocess.run([str(exe)], capture_output=True, text=True, check=True).stdout.splitlines()
    wrong = []
    for line in printed:
        name, value = line.split(" ", 1)
        python = getattr(eye, name, None)
        if isinstance(python, str):
            ok = python == value
        else:
            # Key codes are unsigned in Python (ANYKEY = 0xFFFFFFFF), C ints in C.
            ok = isinstance(python, int) and python & 0xFFFFFFFF == int(value) & 0xFFFFFFFF
        if not ok or name not in eye.__all__:
            wrong.append(f"{name}: C {value}, eye {python!r}")
    assert not wrong, wrong


@pytest.mark.parametrize("name", ["lib", "CAMWIDTH", "CAMSIZE", "EyeSimError"])
def test_the_module_also_exports(eye, name):
    assert name in eye.__all__
