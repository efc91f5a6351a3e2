"""The RoBIOS constants generated from the "constants" groups of interface/protocol.json.

Every constant a program can name (key codes, colours, resolutions, LCD modes, PSD positions, IR
remote codes, ...) is listed there once, in its group, with its value. From that list
interface/generate.py writes:

- the constant definitions of robios/include/eyebot.h (between its "generated constants" markers);
- eye/constants.py: the same names for Python programs;
- eyesim/protocol/constants.py: the same names for the simulator, plus GROUPS (each group's names
  and values), from which the simulator takes the sets it checks against (PSD positions, IR codes,
  camera resolutions).

A constant has one of:
- "value": an integer, or a string of a hex literal kept as written ("0x00000001"). C writes a
  code above INT_MAX as int (`((int)0x80000000u)`), Python as the unsigned number;
- "char": one character, a character code (C '0', Python ord("0"));
- "text": a string;
- "expression": a product or sum of integers and constants defined before it ("QVGA_X * QVGA_Y").
Optional: "doc" (the comment beside it), "guard" (C defines it only where nothing else did:
`#ifndef`), "c_only" (Python has its own: True and False).
"""

from __future__ import annotations

import re
from pathlib import Path

from layers import REGENERATE, WIDTH, declaration_lines, heading_lines, wrap

ROOT = Path(__file__).resolve().parent.parent
EYE_CONSTANTS = ROOT / "src" / "eye" / "constants.py"
SIM_CONSTANTS = ROOT / "src" / "eyesim" / "protocol" / "constants.py"

HEADER_BEGIN = "/* ==== Generated constants ==== */"
HEADER_END = "/* ==== End of the generated constants ==== */"
HEADER_NOTE = (
    'From the "constants" groups of interface/protocol.json down to "End of the generated constants": '
    "change them there and run `make protocol`."
)
KINDS = ("value", "char", "text", "expression")
NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
EXPRESSION = re.compile(r"[A-Za-z0-9_ *+]+")
INT_MAX = 0x7FFFFFFF


def load(spec: dict) -> list[dict]:
    """The constants groups, checked: one kind of value each, unique names, 32-bit integers, and
    expressions of earlier constants only."""
    values_of(spec)
    return spec.get("constants", [])


def values_of(spec: dict) -> dict[str, int | str]:
    """Every constant's value by its name, checked as `load` says."""
    values: dict[str, int | str] = {}
    groups = spec.get("constants", [])
    for group in groups:
        for entry in group["constants"]:
            where = f"protocol.json: constants {group['group']}: {entry.get('name')}"
            name = entry.get("name", "")
            if not NAME.fullmatch(name) or name in values:
                raise SystemExit(f"{where}: a constant needs a C name used only once")
            kinds = [kind for kind in KINDS if kind in entry]
            if len(kinds) != 1:
                raise SystemExit(f"{where}: give exactly one of {', '.join(KINDS)}")
            values[name] = evaluate(entry, values, where)
    return values


def evaluate(entry: dict, earlier: dict, where: str) -> int | str:
    if "text" in entry:
        return entry["text"]
    if "char" in entry:
        if len(entry["char"]) != 1 or not 32 <= ord(entry["char"]) < 127 or entry["char"] in "'\\":
            raise SystemExit(f"{where}: a char is one printable ASCII character other than ' and \\")
        return ord(entry["char"])
    if "expression" in entry:
        expression = entry["expression"]
        names = NAME.findall(expression)
        unknown = [n for n in names if not n[0].isdigit() and n not in earlier]
        if not EXPRESSION.fullmatch(expression) or unknown:
            raise SystemExit(
                f"{where}: an expression multiplies or adds numbers and constants defined "
                f"before it (unknown: {', '.join(unknown) or 'none'})"
            )
        value = eval(expression, {"__builtins__": {}}, dict(earlier))  # checked above: names, digits, * and +
    else:
        value = entry["value"]
        if isinstance(value, str):
            if not re.fullmatch(r"0x[0-9A-F]+", value):
                raise SystemExit(f"{where}: a value string is a hex literal in upper case (0x00FF00)")
            value = int(value, 16)
    if not isinstance(value, int) or not -(2**31) <= value < 2**32:
        raise SystemExit(f"{where}: {value!r} is not a 32-bit integer")
    return value


# ---- eyebot.h ---------------------------------------------------------------------------------------


def c_value(entry: dict) -> str:
    if "text" in entry:
        return '"' + entry["text"].replace("\\", "\\\\").replace('"', '\\"') + '"'
    if "char" in entry:
        return f"'{entry['char']}'"
    if "expression" in entry:
        return f"({entry['expression']})"
    value = entry["value"]
    if isinstance(value, str) and int(value, 16) > INT_MAX:
        return f"((int){value}u)"
    return str(value)


def c_lines(entry: dict) -> list[tuple[str, str]]:
    definition = f"#define {entry['name']} {c_value(entry)}"
    if entry.get("guard"):
        return [(f"#ifndef {entry['name']}", entry.get("doc", "")), (definition, ""), ("#endif", "")]
    return [(definition, entry.get("doc", ""))]


def header_section(groups: list[dict]) -> str:
    out = [HEADER_BEGIN, *comment_block(HEADER_NOTE)]
    for group in groups:
        out += ["", *heading_lines(group), ""]
        out += declaration_lines([line for entry in group["constants"] for line in c_lines(entry)])
    out += ["", HEADER_END]
    return "\n".join(out)


def comment_block(text: str) -> list[str]:
    lines = wrap(text, WIDTH - 6)
    block = ["/* " + lines[0], *(" * " + line for line in lines[1:])]
    block[-1] += " */"
    return block


def header_source(groups: list[dict], current: str, path: Path) -> str:
    begin, end = current.find(HEADER_BEGIN), current.find(HEADER_END)
    if begin < 0 or end < begin:
        raise SystemExit(f"{path}: the generated-constants markers are missing")
    return current[:begin] + header_section(groups) + current[end + len(HEADER_END) :]


# ---- Python -----------------------------------------------------------------------------------------


def python_value(entry: dict) -> str:
    if "text" in entry:
        return repr(entry["text"]).replace("'", '"')
    if "char" in entry:
        return f'ord("{entry["char"]}")'
    if "expression" in entry:
        return entry["expression"]
    return str(entry["value"])


def python_definitions(groups: list[dict]) -> list[str]:
    out = []
    for group in groups:
        entries = [entry for entry in group["constants"] if not entry.get("c_only")]
        if not entries:
            continue
        out += ["", f"# {group['title']}"]
        if group.get("note"):
            out += ["# " + line for line in wrap(group["note"], WIDTH - 2)]
        for entry in entries:
            line = f"{entry['name']} = {python_value(entry)}"
            out.append(line + (f"  # {entry['doc']}" if entry.get("doc") else ""))
    return out


def docstring(text: str) -> list[str]:
    lines = wrap(text, WIDTH - 3)
    lines[0] = '"""' + lines[0]
    lines[-1] += '"""'
    return lines


def eye_source(groups: list[dict]) -> str:
    doc = docstring(
        "RoBIOS constants as plain Python ints (strings for the few text constants), with eyebot.h's "
        f"values. {REGENERATE}"
    )
    out = [
        *doc,
        *python_definitions(groups),
        "",
        '__all__ = [name for name in dir() if name.isupper() and not name.startswith("_")]',
    ]
    return "\n".join(out) + "\n"


def simulator_source(groups: list[dict]) -> str:
    doc = docstring(
        "The RoBIOS constants, as programs see them in eyebot.h and eye.constants: the simulator "
        "takes every RoBIOS value from here. GROUPS holds each group's names and values in "
        f"protocol.json's order. {REGENERATE}"
    )
    out = [*doc, *python_definitions(groups), "", "GROUPS: dict[str, dict[str, int | str]] = {"]
    for group in groups:
        entries = [entry["name"] for entry in group["constants"] if not entry.get("c_only")]
        if entries:
            start = f'    "{group["group"]}": {{'
            pairs = ", ".join(f'"{name}":\0{name}' for name in entries)  # \0: never broken there
            items = [line.replace("\0", " ") for line in wrap(pairs, WIDTH - len(start) - 2)]
            out += [start + items[0], *(" " * len(start) + line for line in items[1:])]
            out[-1] += "},"
    out.append("}")
    return "\n".join(out) + "\n"


def outputs(spec: dict, header_path: Path, header: str) -> dict[Path, str]:
    """eyebot.h (given as the text the other layers made of it) with its constants, and the two Python modules."""
    groups = load(spec)
    return {
        header_path: header_source(groups, header, header_path),
        EYE_CONSTANTS: eye_source(groups),
        SIM_CONSTANTS: simulator_source(groups),
    }
