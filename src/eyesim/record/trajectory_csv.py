"""Robot trajectories as CSV: every robot's true pose every 10 ms of simulation time.

Teachers grade from these, and the determinism tests compare them byte for byte, so values are
written with full float precision and sampled on simulation time, never wall time. The same rows
come from a live run (TrajectoryRecorder) and from an MCAP recording (eyesim export)."""

from __future__ import annotations

from pathlib import Path

RECORD_PERIOD_US = 10_000  # one row per robot every 10 ms of simulation time
HEADER = "time_s,robot,x,y,z,qw,qx,qy,qz\n"


def row(time_us: int, robot_id: int, values) -> str:
    """One CSV line: time, robot id, x, y, z (m), qw, qx, qy, qz, floats as repr (round-trips exactly)."""
    return f"{time_us / 1e6!r},{robot_id}," + ",".join(repr(float(v)) for v in values) + "\n"


class TrajectoryRecorder:
    """Called after every physics step; writes `time_s,robot,x,y,z,qw,qx,qy,qz` rows (metres)."""

    def __init__(self, path: str | Path):
        self.file = open(path, "w", encoding="ascii")
        self.file.write(HEADER)

    def __call__(self, sim) -> None:
        if sim.time_us % RECORD_PERIOD_US:
            return
        data = sim.world.data
        for robot in sim.robots:
            self.file.write(row(sim.time_us, robot.id, [*data.xpos[robot.body], *data.xquat[robot.body]]))

    def close(self) -> None:
        self.file.close()
