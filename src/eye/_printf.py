"""C printf formatting for LCDPrintf/LCDSetPrintf, done in Python: every conversion C accepts,
surplus arguments ignored (student code writes `LCDPrintf("Hello\\n", "")`)."""

from __future__ import annotations

import math
import re
from typing import Any, Iterator

# %[flags][width][.precision][length]conversion
_SPEC = re.compile(
    r"%(?P<flags>[-+ #0]*)(?P<width>\*|\d+)?(?:\.(?P<precision>\*|\d*))?"
    r"(?P<length>hh|h|ll|l|L|q|j|z|Z|t)?(?P<conversion>[diouxXeEfFgGaAcspn%])"
)
_BITS = {"hh": 8, "h": 16, "l": 64, "ll": 64, "q": 64, "j": 64, "z": 64, "Z": 64, "t": 64}  # else int: 32
_MISSING = object()


def printf(function: str, format: object, args: tuple) -> str:
    """`format` filled in as C's printf would. A conversion with no argument left is printed as it
    is (C would print garbage), so "100%" and "50% done" without arguments come out unchanged."""
    if isinstance(format, bytes):
        format = format.decode("utf-8", errors="replace")
    if not isinstance(format, str):
        return str(format)
    supply = iter(args)
    out, pos = [], 0
    while (start := format.find("%", pos)) >= 0:
        out.append(format[pos:start])
        spec = _SPEC.match(format, start)
        if spec is None:  # not a conversion: glibc prints it as it is
            out.append("%")
            pos = start + 1
            continue
        out.append(_convert(function, spec, supply))
        pos = spec.end()
    out.append(format[pos:])
    return "".join(out)


def _convert(function: str, spec: re.Match, supply: Iterator[Any]) -> str:
    conversion, flags = spec["conversion"], spec["flags"]
    if conversion == "%":
        return "%"
    if conversion == "n":
        raise ValueError(f"{function}: %n is not supported (it would store into a C variable)")
    width: Any = spec["width"]
    precision: Any = spec["precision"]
    if width == "*":
        width = next(supply, _MISSING)
        if width is _MISSING:
            return spec.group(0)
        if int(width) < 0:  # as in C: a negative * width means left-justified
            flags += "-"
        width = abs(int(width))
    width = int(width) if width else 0
    if precision == "*":
        precision = next(supply, _MISSING)
        if precision is _MISSING:
            return spec.group(0)
        precision = int(precision) if int(precision) >= 0 else None  # negative: as if none
    elif precision is not None:
        precision = int(precision or 0)  # "%.f" is precision 0
    value: Any = next(supply, _MISSING)
    if value is _MISSING:
        return spec.group(0)
    if conversion in "diouxXeEfFgGaA" and isinstance(value, (str, bytes)):  # C would print garbage
        raise TypeError(f"{function}: {spec.group(0)} needs a number, not the text {value!r}")
    try:
        if conversion in "diouxX":
            return _integer(value, conversion, flags, width, precision, spec["length"])
        if conversion in "eEfFgG":
            return (
                "%"
                + flags
                + (str(width) if width else "")
                + ("" if precision is None else f".{precision}")
                + conversion
            ) % float(value)
        if conversion in "aA":
            return _pad(_hex_float(float(value), precision, conversion == "A"), width, flags)
        if conversion == "c":
            return _pad(chr(value & 0xFF) if isinstance(value, int) else _one_character(value), width, flags)
        if conversion == "p":
            return _pad("(nil)" if not value else f"0x{int(value):x}", width, flags)
        text = (
            "(null)"
            if value is None
            else (value.decode("utf-8", errors="replace") if isinstance(value, bytes) else str(value))
        )
        return _pad(text if precision is None else text[:precision], width, flags)
    except (TypeError, ValueError) as error:
        raise TypeError(f"{function}: {spec.group(0)} cannot print {value!r} ({error})") from None


def _integer(value, conversion: str, flags: str, width: int, precision: int | None, length: str | None) -> str:
    number = int(value)
    bits = _BITS.get(length or "", 32)
    if conversion in "di":
        if length in ("hh", "h"):  # C converts to signed char / short
            number = (number + (1 << (bits - 1))) % (1 << bits) - (1 << (bits - 1))
        sign = "-" if number < 0 else "+" if "+" in flags else " " if " " in flags else ""
        number = abs(number)
    else:  # unsigned: a negative number wraps around as in C
        sign = ""
        if number < 0 or length in ("hh", "h"):
            number %= 1 << bits
    digits = format(number, {"d": "d", "i": "d", "u": "d", "o": "o", "x": "x", "X": "X"}[conversion])
    if precision is not None:
        digits = "" if precision == 0 and number == 0 else digits.rjust(precision, "0")
    prefix = ""
    if "#" in flags and conversion == "o" and not digits.startswith("0"):
        digits = "0" + digits
    elif "#" in flags and conversion in "xX" and number:
        prefix = "0" + conversion
    return _pad(digits, width, flags, sign + prefix, zeros=precision is None)


def _pad(text: str, width: int, flags: str, lead: str = "", zeros: bool = False) -> str:
    """lead + text, padded to width: left-justified with '-', with zeros after the sign with '0'
    (numbers only), else with spaces in front."""
    gap = width - len(lead) - len(text)
    if gap <= 0:
        return lead + text
    if "-" in flags:
        return lead + text + " " * gap
    if zeros and "0" in flags:
        return lead + "0" * gap + text
    return " " * gap + lead + text


def _hex_float(value: float, precision: int | None, upper: bool) -> str:
    """%a: glibc's form, shortest exact digits (0x1.8p+0); a precision is not supported."""
    if precision is not None:
        raise ValueError("a precision with %a is not supported")
    if math.isinf(value) or math.isnan(value):
        text = ("-" if value < 0 else "") + ("inf" if math.isinf(value) else "nan")
    else:
        mantissa, exponent = value.hex().split("p")
        text = mantissa.rstrip("0").rstrip(".") + "p" + exponent
    return text.upper() if upper else text


def _one_character(value) -> str:
    text = value.decode("utf-8", errors="replace") if isinstance(value, bytes) else value
    if not isinstance(text, str) or len(text) != 1:
        raise TypeError("%c takes an int or a single character")
    return text
