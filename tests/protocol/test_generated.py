"""The generated protocol tables and pass-through layers are up to date, and every operation has exactly
one handler."""

import ast
import copy
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from eyesim import calls
from eyesim.protocol import generated as g

ROOT = Path(__file__).resolve().parents[2]


def test_generated_files_match_protocol_json():
    """Also the viewer channel's: viewer-app/src/generated/viewer_protocol.ts (the messages' and the HTTP
    routes' types and parsers) and the server's copy of interface/viewer.schema.json."""
    result = subprocess.run(
        [sys.executable, str(ROOT / "interface" / "generate.py"), "--check"], capture_output=True, text=True
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_the_route_table_is_generated_from_the_schema_and_goes_stale_with_it():
    """Routes (each route's request and answer types) and ROUTE_ANSWERS come from the schema's
    `routes`: the committed file has every route, and a route added to the schema changes it."""
    import generate_viewer  # protocol/, on the path for layers below
    import robios_constants

    constants = robios_constants.values_of(json.loads((ROOT / "interface/protocol.json").read_text()))
    schema = generate_viewer.with_constants(json.loads(generate_viewer.SCHEMA.read_text()), constants, {})
    committed = generate_viewer.TS_OUT.read_text()
    for route, entry in schema["routes"].items():
        answer = entry["response"]["$ref"].removeprefix("#/$defs/")
        assert f'  "{route}": {{ request: ' in committed and f'  "{route}": parse{answer},' in committed
    schema["routes"]["POST /scenes/rename"] = {
        "request": {"$ref": "#/$defs/Place"},
        "response": {"$ref": "#/$defs/EditorState"},
    }
    regenerated = generate_viewer.Generator(schema).typescript()
    assert regenerated != committed
    assert '  "POST /scenes/rename": { request: Place; response: EditorState };' in regenerated
    schema["routes"]["POST /scenes/rename"]["response"] = {"type": "object"}
    with pytest.raises(SystemExit, match="must be a \\$ref to a definition"):
        generate_viewer.Generator(schema)


def test_every_operation_but_the_sessions_own_has_a_handler():
    # the handshake and the library's THREADS notice are the engine's own
    missing = [op.name for op in g.OPS.values() if op.group != "session" and op.code not in calls.HANDLERS]
    assert missing == []


def test_a_handler_module_may_only_handle_its_own_groups_operations(monkeypatch):
    from eyesim.parts.psd import calls as psd_calls

    monkeypatch.setitem(psd_calls.HANDLERS, "LIDAR_GET", psd_calls.HANDLERS["PSD_GET"])
    with pytest.raises(RuntimeError, match="eyesim.parts.psd.calls handles LIDAR_GET, an operation of group lidar"):
        calls._build_registry()


def test_a_part_folder_finds_its_handlers_and_two_modules_may_not_share_a_group(monkeypatch):
    from eyesim.parts.psd import calls as psd_calls

    modules = calls.handler_modules()
    assert modules["psd"] is psd_calls and modules["lcd"].__name__ == "eyesim.calls.lcd"
    monkeypatch.setattr(psd_calls, "GROUP", "lcd")
    with pytest.raises(RuntimeError, match="eyesim.calls.lcd and eyesim.parts.psd.calls both handle group lcd"):
        calls.handler_modules()
    monkeypatch.setattr(psd_calls, "GROUP", "lidar")
    with pytest.raises(
        RuntimeError, match="eyesim.parts.psd.calls and eyesim.parts.lidar.calls both handle group lidar"
    ):
        calls.handler_modules()


def test_operation_codes_are_unique_and_fit_the_header():
    codes = [op.code for op in g.OPS.values()]
    assert len(codes) == len(set(codes))
    assert all(0 < code < 65536 for code in codes)


# ---- The pass-through layers (interface/layers.py) ------------------------------------------------

sys.path.insert(0, str(ROOT / "interface"))
import layers  # noqa: E402  (interface/layers.py, beside generate.py)

SPEC = json.loads((ROOT / "interface" / "protocol.json").read_text())


def api_functions() -> list[dict]:
    return [f for group in SPEC["api"] for f in group["functions"]]


def test_every_generated_file_says_so_and_how_to_regenerate():
    for path in layers.outputs(SPEC):
        text = path.read_text()
        assert "interface/protocol.json" in text and "make protocol" in text, path


def test_a_changed_description_makes_the_header_and_the_python_module_stale():
    spec = copy.deepcopy(SPEC)
    psd = next(g for g in spec["api"] if g["group"] == "psd")
    psd["functions"][0]["doc"] = "a new description"
    changed = {path for path, text in layers.outputs(spec).items() if path.read_text() != text}
    assert changed == {layers.HEADER, layers.EYE / "psd.py"}


def test_a_new_pass_through_function_is_generated_in_every_layer():
    """docs/developing.md's walk-through: an op and an api entry in protocol.json give the C wrapper,
    the eyebot.h declaration, the ctypes prototype and the Python wrapper."""
    spec = copy.deepcopy(SPEC)
    spec["ops"].append(
        {
            "name": "PSD_GET_BOTH",
            "code": 2099,
            "group": "psd",
            "cost": "device",
            "cost_us": 100,
            "request": [["psd", "i32"]],
            "reply": [["result", "i32"], ["mm", "i32"], ["raw", "i32"]],
        }
    )
    psd = next(g for g in spec["api"] if g["group"] == "psd")
    psd["functions"].append(
        {
            "name": "PSDGetBoth",
            "c": "int PSDGetBoth(int psd, int *mm, int *raw)",
            "op": "PSD_GET_BOTH",
            "error": "1",
            "python": "hand",
            "doc": "both readings",
        }
    )
    psd["functions"].append(
        {
            "name": "PSDGetTwice",
            "c": "int PSDGetTwice(int psd)",
            "op": "PSD_GET",
            "error": "-1",
            "doc": "the distance again",
        }
    )
    new = layers.outputs(spec)
    changed = {path for path, text in new.items() if path.read_text() != text}
    assert changed == {layers.HEADER, layers.C_WRAPPERS, layers.PY_PROTOTYPES, layers.EYE / "psd.py"}
    assert "int PSDGetBoth(int psd, int *mm, int *raw); /* both readings */" in new[layers.HEADER]
    assert (
        "int PSDGetBoth(int psd, int *mm, int *raw)\n{\n    es_value args[1] = {es_int(psd)};\n"
        '    es_value result[3] = {{0}};\n    int rc = es_call("PSDGetBoth", ES_OP_PSD_GET_BOTH, args, result);\n'
        "    es_out(mm, result[1].i); /* zeros after an error */\n    es_out(raw, result[2].i);\n"
        "    return rc ? 1 : (int)result[0].i;\n}"
    ) in new[layers.C_WRAPPERS]
    assert '"PSDGetBoth": (INT, [INT, INTS, INTS]),' in new[layers.PY_PROTOTYPES]
    module = new[layers.EYE / "psd.py"]
    assert "from eye.handwritten.psd import PSDGetBoth" in module
    assert 'def PSDGetTwice(psd: int) -> int:\n    """The distance again."""\n    return C.PSDGetTwice(psd)' in module


def code_names(path: Path) -> set[str]:
    """The identifiers (and, in Python, strings) a source uses in its code, not in its comments."""
    if path.suffix == ".c":
        return set(re.findall(r"\w+", re.sub(r"/\*.*?\*/|//[^\n]*", " ", path.read_text(), flags=re.S)))
    tree = ast.parse(path.read_text())
    docstrings = {
        id(node.body[0].value)
        for node in ast.walk(tree)
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef)) and ast.get_docstring(node)
    }
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            names.add(node.id)
        elif isinstance(node, ast.Attribute):
            names.add(node.attr)
        elif isinstance(node, (ast.FunctionDef, ast.alias)):
            names.add(node.name)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docstrings:
            names.add(node.value)
    return names


def test_pass_through_functions_are_written_nowhere_by_hand():
    """Adding a pass-through function takes protocol.json, its handler and its docs: the hand-written
    C and Python sources never use one by name (they would be a second copy to keep in step)."""
    hand_written = [p for p in (ROOT / "robios" / "src").glob("*.c") if p != layers.C_WRAPPERS]
    hand_written += list(layers.HANDWRITTEN.glob("*.py")) + [ROOT / "src" / "eye" / "_library.py"]
    generated = {f["name"] for f in api_functions() if f.get("op") and f.get("python", "pass") == "pass"}
    assert len(generated) > 50
    named = {(name, p.name) for p in hand_written for name in generated & code_names(p)}
    assert named == set()


def test_every_api_function_is_generated_or_written_by_hand_once():
    groups = {g["group"] for g in SPEC["api"]}
    handwritten = {p.stem for p in layers.HANDWRITTEN.glob("*.py")} - {"__init__"}
    assert handwritten <= groups
    for group in SPEC["api"]:
        hand = [f["name"] for f in group["functions"] if f.get("python") == "hand"]
        module = layers.HANDWRITTEN / f"{group['group']}.py"
        assert bool(hand) == module.exists(), group["group"]


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda f: f.update(c="int PSDGet(int psd, int extra)"), "do not match PSD_GET's request"),
        (lambda f: f.update(op="PSD_GONE"), "unknown op 'PSD_GONE'"),
        (lambda f: f.pop("error"), 'needs its "error" return value'),
        (lambda f: f.update(c="int PSDGet(float psd)"), "unknown C type 'float'"),
        (lambda f: f.update(doc=""), 'needs its "doc"'),
    ],
)
def test_a_wrong_api_entry_is_refused_with_its_name(change, message):
    spec = copy.deepcopy(SPEC)
    psd = next(g for g in spec["api"] if g["group"] == "psd")
    change(psd["functions"][0])
    with pytest.raises(SystemExit) as refused:
        layers.load(spec)
    assert "api psd: PSDGet" in str(refused.value) and message in str(refused.value)


def test_the_viewer_schema_is_package_data_the_server_loads():
    """The installed package carries interface/viewer.schema.json (as eyesim/protocol/viewer.schema.json,
    found with importlib.resources) and checks messages against it."""
    from importlib import resources

    from eyesim.protocol import channel_schema

    packaged = resources.files("eyesim.protocol").joinpath("viewer.schema.json")
    assert packaged.is_file()
    assert json.loads(packaged.read_text(encoding="utf-8")) == channel_schema.SCHEMA
    source = json.loads((ROOT / "interface/viewer.schema.json").read_text())
    assert channel_schema.SCHEMA["$defs"].keys() == source["$defs"].keys()
