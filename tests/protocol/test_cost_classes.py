"""Every operation's cost class (protocol.json's "cost", docs/protocol.md#what-a-call-costs): what the
EyeBot does itself is local, what reaches its hardware or the world a device call, blocking calls
wait; the generator refuses anything else."""

import copy
import json
import sys
from pathlib import Path

import pytest

from eyesim.protocol import generated as g
from eyesim.protocol.ops import DEVICE, LOCAL, WAIT

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "interface"))
import generate  # noqa: E402  (interface/generate.py)

SPEC = json.loads((ROOT / "interface" / "protocol.json").read_text())


def test_every_op_has_a_class_and_blocking_ops_are_the_waits():
    assert {op.cost for op in g.OPS.values()} == {LOCAL, DEVICE, WAIT}
    assert all((op.cost == WAIT) == op.blocking for op in g.OPS.values())


def test_drawing_and_the_clock_are_local_sensors_and_motors_reach_the_robot():
    by_class = {name: op.cost for name, op in g.OPS_BY_NAME.items()}
    assert all(by_class[op.name] == LOCAL for op in g.OPS.values() if op.group == "lcd")
    for name in ("OS_GET_COUNT", "OS_MACHINE_NAME", "TIMER_ATTACH", "HELLO"):
        assert by_class[name] == LOCAL, name
    for name in (
        "PSD_GET",
        "VW_GET_POSITION",
        "VW_SET_SPEED",
        "MOTOR_DRIVE",
        "KEY_READ",
        "CAM_GET",
        "RADIO_SEND",
        "SIM_GET_ROBOT",
        "LIDAR_GET",
        "SER_SEND",
    ):
        assert by_class[name] == DEVICE, name
    # a local call costs microseconds (an image some more), far below the 4 ms call time
    assert max(op.cost_us for op in g.OPS.values() if op.cost == LOCAL) <= 500
    assert g.OPS_BY_NAME["LCD_PIXEL"].cost_us == g.OPS_BY_NAME["OS_GET_COUNT"].cost_us == 10


def test_the_docs_list_each_class():
    docs = (ROOT / "docs" / "protocol.md").read_text()
    section = docs[docs.index("## What a call costs") :]
    for cost in (LOCAL, DEVICE, WAIT):
        assert f"| `{cost}` |" in section


@pytest.mark.parametrize(
    "change,message",
    [
        ({"cost": "cheap"}, "cost must be one of local, device, wait, not 'cheap'"),
        ({"cost": "wait"}, "a blocking op costs its wait"),
        ({"cost": None}, "cost must be one of"),
    ],
)
def test_the_generator_refuses_a_missing_or_wrong_class(change, message, capsys):
    spec = copy.deepcopy(SPEC)
    op = next(op for op in spec["ops"] if op["name"] == "PSD_GET")
    op.update(change)
    if op["cost"] is None:
        del op["cost"]
    with pytest.raises(SystemExit, match=f"op PSD_GET: {message}"):
        generate.check(spec)
    blocking = next(op for op in copy.deepcopy(SPEC)["ops"] if op["name"] == "KEY_GET")
    blocking["cost"] = "device"
    with pytest.raises(SystemExit, match="op KEY_GET: a blocking op costs its wait"):
        generate.check({**SPEC, "ops": [blocking]})
