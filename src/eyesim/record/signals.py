"""Signals for plots: named time series of a robot's pose, odometry, speeds, encoders, battery, PSD
readings and the signals its parts give (a bumper's bumper.<id>), from a recording or the live
history (docs/recording.md, "Plots").

A source gives `robot_ids`, `robot_track(id) -> (times_us, poses (N, 7))`, `states[id]` and
`psd[id]` (lists of (time_us, message)); a signal id is "robot/<id>/<name>"."""

from __future__ import annotations

import math

import numpy as np

MAX_POINTS = 20_000  # per series sent to a browser: more would not show on a screen anyway


def catalogue(source) -> list[dict]:
    """Every signal the source has: {id, robot, name, label, unit}."""
    signals = []
    for robot_id in source.robot_ids:
        names = [("x", "m"), ("y", "m"), ("phi", "deg")]
        states = source.states.get(robot_id) or []
        state = states[-1][1] if states else None
        if state is not None:
            if state.get("odometry") is not None:
                names += [
                    ("odometry.x", "m"),
                    ("odometry.y", "m"),
                    ("odometry.phi", "deg"),
                    ("v", "m/s"),
                    ("w", "deg/s"),
                ]
            names += [(f"encoder.{n}", "ticks") for n in state.get("encoders", {})]
            if state.get("battery") is not None:
                names.append(("battery", "V"))
            names += [(name, unit) for name, (_, unit) in state.get("signals", {}).items()]
        psd_ids = sorted({reading["psd"] for _, reading in source.psd.get(robot_id, ()) if "distance_mm" in reading})
        names += [(f"psd.{n}", "mm") for n in psd_ids]
        signals += [
            {
                "id": f"robot/{robot_id}/{name}",
                "robot": robot_id,
                "name": name,
                "label": f"robot {robot_id} {name}",
                "unit": unit,
            }
            for name, unit in names
        ]
    return signals


def series(source, signal_id: str) -> tuple[list[float], list[float]] | None:
    """(times in s, values) of one signal, thinned to MAX_POINTS; None for an unknown id."""
    parts = signal_id.split("/")
    if len(parts) != 3 or parts[0] != "robot" or not parts[1].isdigit() or int(parts[1]) not in source.robot_ids:
        return None
    robot_id, name = int(parts[1]), parts[2]
    if name in ("x", "y", "phi"):
        times, poses = source.robot_track(robot_id)
        if name == "phi":
            w, x, y, z = poses[:, 3], poses[:, 4], poses[:, 5], poses[:, 6]
            values = np.degrees(np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))
        else:
            values = poses[:, 0 if name == "x" else 1]
        return _thin(np.asarray(times) / 1e6, values)
    if name.startswith("psd."):
        readings = [
            (t, r["distance_mm"])
            for t, r in source.psd.get(robot_id, ())
            if str(r["psd"]) == name[4:] and "distance_mm" in r
        ]
        return _thin(np.array([t for t, _ in readings]) / 1e6, np.array([v for _, v in readings], dtype=float))
    pick = _state_value(name) or _part_signal(source, robot_id, name)
    if pick is None:
        return None
    rows = [(t, pick(s)) for t, s in source.states.get(robot_id, ())]
    rows = [(t, v) for t, v in rows if v is not None]
    return _thin(np.array([t for t, _ in rows]) / 1e6, np.array([v for _, v in rows], dtype=float))


def _state_value(name: str):
    """How to read a signal from an eyesim.RobotState message (None when absent)."""
    if name.startswith("odometry."):
        key = name.split(".", 1)[1]
        scale = math.degrees(1) if key == "phi" else 1.0
        return lambda s: s["odometry"][key] * scale if s.get("odometry") else None
    if name == "v":
        return lambda s: s["speed"]["v"] if s.get("speed") else None
    if name == "w":
        return lambda s: math.degrees(s["speed"]["w"]) if s.get("speed") else None
    if name.startswith("encoder."):
        key = name.split(".", 1)[1]
        return lambda s: s.get("encoders", {}).get(key)
    if name == "battery":
        return lambda s: s.get("battery")
    return None


def _part_signal(source, robot_id: int, name: str):
    """How to read a signal one of the robot's parts gives (robot/component.py); None when none
    of them gives one of that name."""
    states = source.states.get(robot_id) or []
    if not states or name not in states[-1][1].get("signals", {}):
        return None
    return lambda s: s.get("signals", {}).get(name, (None,))[0]


def _thin(times: np.ndarray, values: np.ndarray) -> tuple[list[float], list[float]]:
    step = max(1, math.ceil(len(times) / MAX_POINTS))
    return np.asarray(times, dtype=float)[::step].tolist(), np.asarray(values, dtype=float)[::step].tolist()
