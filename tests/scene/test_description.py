"""The scene description is immutable data with readable locations and diagnostics."""

import dataclasses

import pytest

from eyesim.scene import description
from eyesim.scene.description import Diagnostic, Location


def test_every_dataclass_is_frozen():
    for value in vars(description).values():
        if dataclasses.is_dataclass(value) and isinstance(value, type):
            assert value.__dataclass_params__.frozen, value.__name__


def test_location_text():
    assert str(Location("a.sim", 3, 7)) == "a.sim:3:7"
    assert str(Location("a.sim", 3)) == "a.sim:3"
    assert str(Location("a.sim")) == "a.sim"


def test_diagnostic_text():
    assert str(Diagnostic("error", Location("a.sim", 1, 2), "expected x")) == "a.sim:1:2: error: expected x"


def test_placements_and_types_cannot_be_changed():
    with pytest.raises(dataclasses.FrozenInstanceError):
        description.Pose(1, 2).x = 3
