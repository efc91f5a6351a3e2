"""Recording runs: MCAP recordings (Recorder, Recording), trajectory CSV, final LCD images.

    from eyesim.record import Recorder
    with Recorder(sim, "run.mcap"):
        sim.run(until=10)

See docs/recording.md. The names below are imported when first used, so that reading a recording
(`eyesim export`, `plot`, `render`, `replay`) does not load the simulator (MuJoCo) that making
one needs."""

from __future__ import annotations

import importlib

_MODULES = {
    "Recorder": "eyesim.record.mcap_recorder",
    "Recording": "eyesim.record.recording",
    "RecordingError": "eyesim.record.recording",
    "TrajectoryRecorder": "eyesim.record.trajectory_csv",
    "save_lcd_images": "eyesim.record.lcd_images",
}

__all__ = sorted(_MODULES)


def __getattr__(name: str):
    if name not in _MODULES:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(_MODULES[name]), name)
