"""Positions of JSON values and keys."""

from eyesim.scene.jsonpos import json_positions


def test_values_and_keys():
    text = '{\n  "a": [1, {"b": "x"}],\n  "c": -2.5e3, "d": true, "e": null, "f": {}, "g": []\n}'
    values, keys = json_positions(text)
    assert values[()] == (1, 1)
    assert values[("a",)] == (2, 8)
    assert values[("a", 0)] == (2, 9)
    assert values[("a", 1, "b")] == (2, 18)
    assert keys[("a", 1, "b")] == (2, 13)
    assert values[("c",)] == (3, 8)
    assert values[("g",)] == (3, 52)


def test_strings_with_escapes():
    values, _ = json_positions('{"k\\"ey": "a\\u00e9\\"", "z": 1}')
    assert values[("z",)] == (1, 29)
