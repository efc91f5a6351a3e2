"""`eyesim export`: the trajectory CSV of `eyesim run --record x.csv`, written from a recording."""

from __future__ import annotations

from pathlib import Path

from eyesim.record import schemas
from eyesim.record.recording import Recording
from eyesim.record.trajectory_csv import HEADER, RECORD_PERIOD_US, row


def export_csv(recording: Recording, path: str | Path) -> int:
    """Writes the CSV rows (every 10 ms, as a live run does) from the pose samples; returns the rows
    written. A recording with a pose rate below 100 Hz gives rows only at its own samples."""
    count = 0
    with open(path, "w", encoding="ascii") as file:
        file.write(HEADER)
        for index, time_us in enumerate(recording.pose_times):
            if time_us % RECORD_PERIOD_US:
                continue
            for robot_id in recording.robot_ids:
                pose = recording.pose(schemas.robot_frame(robot_id), index)
                if pose is not None:
                    file.write(row(time_us, robot_id, pose[0] + pose[1]))
                    count += 1
    return count
