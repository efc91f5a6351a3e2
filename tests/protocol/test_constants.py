"""The RoBIOS constants are written once, in protocol.json's "constants" groups: eyebot.h's defines,
eye/constants.py and the simulator's eyesim/protocol/constants.py are generated from them, and no
other file of the simulator, the library or the eye package defines one of them by hand."""

import ast
import copy
import json
import re
import sys
from pathlib import Path

import pytest

from eyesim.protocol import constants as sim_constants

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "interface"))
import generate  # noqa: E402  (interface/generate.py)
import generate_viewer  # noqa: E402
import layers  # noqa: E402
import robios_constants  # noqa: E402

SPEC = json.loads((ROOT / "interface" / "protocol.json").read_text())
ENTRIES = [entry for group in SPEC["constants"] for entry in group["constants"]]
NAMES = {entry["name"] for entry in ENTRIES}
PYTHON_NAMES = {entry["name"] for entry in ENTRIES if not entry.get("c_only")}

# eyebot.h's macros that are no RoBIOS constants: its include guard, the feature-test macro, the
# printf attribute, the DLL-export marker and the sleep functions rerouted on Windows and macOS.
NOT_CONSTANTS = {
    "EYEBOT_H",
    "_DEFAULT_SOURCE",
    "EYEBOT_PRINTF",
    "EYESIM_EXPORTS_MARKED",
    "sleep",
    "usleep",
    "nanosleep",
    "clock_nanosleep",
    "Sleep",
}
DEFINE = re.compile(r"^\s*#\s*define\s+(\w+)", re.MULTILINE)
SIM_GENERATED = {
    ROOT / "src/eyesim/protocol/constants.py",
    ROOT / "src/eyesim/protocol/generated.py",
    ROOT / "src/eye/constants.py",
}


def header_parts() -> tuple[str, str]:
    """eyebot.h's generated constants section, and the rest of the file."""
    text = (ROOT / "robios/include/eyebot.h").read_text()
    begin = text.index(robios_constants.HEADER_BEGIN)
    end = text.index(robios_constants.HEADER_END)
    return text[begin:end], text[:begin] + text[end:]


def test_every_define_in_eyebot_h_is_a_generated_constant_or_no_constant():
    section, rest = header_parts()
    assert set(DEFINE.findall(section)) == NAMES
    assert set(DEFINE.findall(rest)) <= NOT_CONSTANTS, set(DEFINE.findall(rest)) - NOT_CONSTANTS


def test_eye_constants_and_the_simulators_are_the_same_names_and_values():
    eye_module = ast.parse((ROOT / "src/eye/constants.py").read_text())
    assigned = {
        target.id
        for node in eye_module.body
        if isinstance(node, ast.Assign)
        for target in node.targets
        if isinstance(target, ast.Name) and target.id != "__all__"
    }
    assert assigned == PYTHON_NAMES
    values = {name: getattr(sim_constants, name) for name in PYTHON_NAMES}
    assert values["KEY_ESCAPE"] == 0x80000000 and values["IRTV_OK"] == ord("O") and values["VGA_SIZE"] == 921600
    assert values["MACHINE_NAME"] == "EyeBot"
    groups = {name: value for group in sim_constants.GROUPS.values() for name, value in group.items()}
    assert groups == values
    assert list(sim_constants.GROUPS["psd"]) == ["PSD_FRONT", "PSD_LEFT", "PSD_RIGHT", "PSD_BACK"]


def literal(node: ast.AST):
    try:
        return ast.literal_eval(node)
    except ValueError:
        return None


def hand_copies(path: Path, root: Path = ROOT) -> list[str]:
    """Module-level assignments in `path` of a constant's value to its name or its name without its
    prefix (AUTOREFRESH = 0x01 for LCD_AUTOREFRESH), and dict literals mapping either name to the
    value or its character ({"PSD_FRONT": 1}, {"RED": "R"} for IRTV_RED)."""
    values = {entry["name"]: getattr(sim_constants, entry["name"]) for entry in ENTRIES if not entry.get("c_only")}
    known: dict[str, list] = {}  # a name (with or without its prefix) -> the values it stands for
    for name, value in values.items():
        for alias in {name, name.split("_", 1)[-1]}:
            known.setdefault(alias, []).append(value)
            if isinstance(value, int) and 32 <= value < 127:
                known[alias].append(chr(value))  # IRTV codes as their characters
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Assign):
            for target in node.targets:
                names = target.elts if isinstance(target, ast.Tuple) else [target]
                value = literal(node.value)
                assigned = value if isinstance(target, ast.Tuple) and isinstance(value, tuple) else [value]
                for name, value in zip(names, assigned):
                    if isinstance(name, ast.Name) and value is not None and value in known.get(name.id, ()):
                        found.append(f"{path.relative_to(root)}:{node.lineno} {name.id} = {value!r}")
        if isinstance(node, ast.Dict):
            for key, value in zip(node.keys, node.values):
                key, value = literal(key) if key else None, literal(value)
                if isinstance(key, str) and value is not None and value in known.get(key, ()):
                    found.append(f"{path.relative_to(root)}:{node.lineno} {{{key!r}: {value!r}}}")
    return found


def test_no_python_module_defines_a_robios_constant_by_hand():
    sources = sorted(set((ROOT / "src").rglob("*.py")) - SIM_GENERATED)
    assert len(sources) > 100
    found = [copy for path in sources for copy in hand_copies(path)]
    assert found == []


def test_the_copy_finder_finds_the_copies_this_repository_had(tmp_path):
    """The kinds of copy there were before the constants were generated."""
    module = tmp_path / "copies.py"
    module.write_text(
        'KEY1, KEY2 = 0x1, 0x2\nAUTOREFRESH = 0x01\nPSD_IDS = {"PSD_FRONT": 1}\nTAB = 4\n'
        'BUTTONS = {"RED": "R", "OK": "K"}\n'
    )
    found = [line.split(" ", 1)[1] for line in hand_copies(module, tmp_path)]
    assert found == ["KEY1 = 1", "KEY2 = 2", "AUTOREFRESH = 1", "{'PSD_FRONT': 1}", "{'RED': 'R'}"]


def test_no_c_source_defines_a_robios_constant():
    sources = sorted((ROOT / "robios/src").glob("*.[ch]")) + [ROOT / "robios/include/eyebot++.h"]
    found = [f"{path.name}: {name}" for path in sources for name in DEFINE.findall(path.read_text()) if name in NAMES]
    assert found == []


def test_make_protocol_writes_the_constants_and_a_changed_one_goes_stale():
    files = generate.outputs()
    for path in (robios_constants.EYE_CONSTANTS, robios_constants.SIM_CONSTANTS, layers.HEADER):
        assert files[path] == path.read_text(), f"{path} is stale: run make protocol"
    changed = copy.deepcopy(SPEC)
    next(e for g in changed["constants"] for e in g["constants"] if e["name"] == "PSD_BACK")["value"] = 5
    header = files[layers.HEADER]
    regenerated = robios_constants.outputs(changed, layers.HEADER, header)
    assert "#define PSD_BACK 5" in regenerated[layers.HEADER] and "#define PSD_BACK 4" in header
    assert "PSD_BACK = 5" in regenerated[robios_constants.EYE_CONSTANTS]
    assert "PSD_BACK = 5" in regenerated[robios_constants.SIM_CONSTANTS]


@pytest.mark.parametrize(
    "entry, message",
    [
        ({"name": "KEY1", "value": 1}, "a C name used only once"),
        ({"name": "TWO", "value": 1, "text": "1"}, "exactly one of"),
        ({"name": "AREA", "expression": "QVGA_X * WIDTH"}, "unknown: WIDTH"),
        ({"name": "BIG", "value": "0x1FFFFFFFF"}, "not a 32-bit integer"),
        ({"name": "LOWER", "value": "0xff"}, "hex literal in upper case"),
        ({"name": "QUOTE", "char": "'"}, "one printable ASCII character"),
    ],
)
def test_the_generator_refuses_a_constant_it_cannot_write(entry, message):
    changed = copy.deepcopy(SPEC)
    changed["constants"][-1]["constants"].append(entry)
    with pytest.raises(SystemExit, match=message):
        robios_constants.load(changed)


def test_the_viewer_schema_names_the_soft_keys_and_gets_their_values_from_protocol_json():
    """The viewer schema (JSON, for the browser too) names the soft keys a key command may press;
    the server's copy and the TypeScript get KEY1..KEY4's values from protocol.json."""
    source = json.loads((ROOT / "interface" / "viewer.schema.json").read_text())
    assert source["$defs"]["KeyCommand"]["properties"]["key"] == {
        "description": "KEY1..KEY4",
        "x-robios-constants": ["KEY1", "KEY2", "KEY3", "KEY4"],
    }
    from eyesim.protocol.channel_schema import SCHEMA

    keys = [sim_constants.KEY1, sim_constants.KEY2, sim_constants.KEY3, sim_constants.KEY4]
    assert SCHEMA["$defs"]["KeyCommand"]["properties"]["key"]["enum"] == keys
    changed = {
        name: value * 16
        for name, value in robios_constants.values_of(json.loads(generate.SPEC.read_text())).items()
        if isinstance(value, int)
    }
    outputs = generate_viewer.outputs(changed)
    assert "KEY3: 64," in outputs[generate_viewer.TS_OUT]
    assert json.loads(outputs[generate_viewer.PACKAGE_COPY])["$defs"]["KeyCommand"]["properties"]["key"]["enum"] == [
        16,
        32,
        64,
        128,
    ]


def test_a_schema_naming_an_unknown_constant_is_refused():
    with pytest.raises(SystemExit, match="x-robios-constants names KEY9, which protocol.json does not define"):
        generate_viewer.with_constants({"enum-ish": {"x-robios-constants": ["KEY1", "KEY9"]}}, {"KEY1": 1}, {})
