"""`settings CALLTIME=<ms>` in .sim files (and `call_time` in JSON), and `eyesim run --call-time`:
read, written, checked with clear errors."""

import subprocess

import pytest
from support.programs import eyesim_command

from eyesim.scene.description import Settings
from eyesim.scene.diagnostics import Diagnostics
from eyesim.scene.json_format import dumps, parse_json, to_json
from eyesim.scene.sim import parse_sim, write_sim


def test_the_call_time_is_read_written_and_kept_in_json():
    diagnostics = Diagnostics()
    document = parse_sim("settings SEED=3 calltime=4.6\n", "a.sim", diagnostics)
    assert not diagnostics.items
    assert document.settings == Settings(seed=3, call_time=4.6)
    assert "CALLTIME=4.6" in write_sim(document)
    assert parse_sim(write_sim(document), "b.sim", Diagnostics()).settings == document.settings
    kind, from_json = parse_json(dumps(to_json("scene", document)), "a.json", Diagnostics())
    assert kind == "scene" and from_json.settings == document.settings
    zero = parse_sim("settings CALLTIME=0\n", "z.sim", Diagnostics())
    assert zero.settings.call_time == 0 and "CALLTIME=0" in write_sim(zero)  # 0 is a choice, not the default
    assert parse_sim("settings VIS\n", "d.sim", Diagnostics()).settings.call_time is None  # the default


def test_bad_call_times_are_errors_with_their_place():
    diagnostics = Diagnostics()
    parse_sim("# lab scene\nsettings CALLTIME=-1 CALLTIME=fast CALLTIME=5000 CALLTIME\n", "c.sim", diagnostics)
    assert [str(d) for d in diagnostics.items] == [
        "c.sim:2:10: error: settings: CALLTIME expects a time in ms from 0 to 1000, found '-1'",
        "c.sim:2:22: error: settings: CALLTIME expects a time in ms from 0 to 1000, found 'fast'",
        "c.sim:2:36: error: settings: CALLTIME expects a time in ms from 0 to 1000, found '5000'",
        "c.sim:2:50: error: settings: CALLTIME needs a value: CALLTIME=<a time in ms from 0 to 1000>",
    ]
    text = dumps(to_json("scene", parse_sim("settings CALLTIME=2\n", "d.sim", Diagnostics())))
    diagnostics = Diagnostics()
    parse_json(text.replace('"call_time": 2.0', '"call_time": -2'), "e.json", diagnostics)
    assert [str(d) for d in diagnostics.items] == [
        "e.json:5:18: error: /settings/call_time: expected a number >= 0, found -2"
    ]


@pytest.mark.parametrize(
    "value,message",
    [
        ("-1", "eyesim run: --call-time -1: must be from 0 to 1000 (ms)"),
        ("2000", "eyesim run: --call-time 2000: must be from 0 to 1000 (ms)"),
        ("soon", "argument --call-time: invalid float value: 'soon'"),
    ],
)
def test_bad_call_times_on_the_command_line(tmp_path, value, message):
    result = subprocess.run(
        eyesim_command("run", "--headless", "--port", "0", "--until", "0.1", "--call-time", value),
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=60,
    )
    assert result.returncode == 2
    assert message in result.stderr
