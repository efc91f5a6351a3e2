"""`eyesim render`: a video of a recording, drawn from above with a fixed view (top_view.py) and
encoded by the ffmpeg that imageio-ffmpeg bundles (H.264 in MP4, or VP9 in WebM). A run whose scene
was edited in the viewer is drawn with the scene that ran at each frame's time."""

from __future__ import annotations

import bisect
import math
from pathlib import Path

import imageio_ffmpeg
import numpy as np
from PIL import ImageOps

from eyesim.record.recording import Recording
from eyesim.record.top_view import BACKGROUND, TopView

CODECS = {
    ".mp4": ("libx264", ["-crf", "23", "-preset", "veryfast"]),
    ".webm": ("libvpx-vp9", ["-b:v", "0", "-crf", "34"]),
}


def frame_times(start_us: int, end_us: int, fps: float, speed: float) -> list[int]:
    """Simulation times of the frames: one every speed / fps seconds, from the start to the end."""
    count = math.floor((end_us - start_us) / 1e6 * fps / speed + 1e-9) + 1
    return [start_us + round(k * speed / fps * 1e6) for k in range(count)]


def robot_paths(recording: Recording, until_us: int) -> dict[int, list[tuple[float, float]]]:
    """Each robot's (x, y) positions from the first sample to `until_us`, one every 10 pose samples at most."""
    last = recording.pose_index(until_us)
    if last is None:
        return {}
    step = max(1, (last + 1) // 2000)
    paths = {}
    for robot_id in recording.robot_ids:
        times, poses = recording.robot_track(robot_id)  # only while the robot was in the scene
        shown = poses[: bisect.bisect_right(times, until_us), :2]
        if len(shown):
            paths[robot_id] = [tuple(p) for p in shown[::step].tolist()] + [tuple(shown[-1].tolist())]
    return paths


def render(
    recording: Recording,
    output: str | Path,
    fps: float = 30,
    speed: float = 1.0,
    size: int = 720,
    start: float | None = None,
    end: float | None = None,
) -> int:
    """Writes the video; returns its number of frames. ValueError for bad options or file type."""
    output = Path(output)
    if output.suffix.lower() not in CODECS:
        raise ValueError(f"{output.name}: the video file must end in .mp4 or .webm")
    if not (math.isfinite(fps) and 1 <= fps <= 120):
        raise ValueError(f"--fps {fps:g}: expected 1 to 120 frames per second")
    if not (math.isfinite(speed) and speed > 0):
        raise ValueError(f"--speed {speed:g}: expected a positive factor")
    if not 64 <= size <= 4096:
        raise ValueError(f"--size {size}: expected 64 to 4096 pixels")
    start_us = recording.start_us if start is None else round(start * 1e6)
    end_us = recording.end_us if end is None else round(end * 1e6)
    if not recording.start_us <= start_us <= end_us <= recording.end_us:
        raise ValueError(
            f"--start/--end: the recording goes from {recording.start_us / 1e6:g} to "
            f"{recording.end_us / 1e6:g} s, and the start must come before the end"
        )
    floor = recording.attachment("floor-texture")
    views: dict[int, TopView] = {}  # per scene of the run (edited in the viewer: several)

    def view_at(time_us: int) -> TopView:
        segment = recording.segment_at(time_us)
        if segment.start_us not in views:
            views[segment.start_us] = TopView(segment.scene, size, floor)
        return views[segment.start_us]

    frame_size = view_at(start_us).size  # an edit that resized the floor is fitted into it
    codec, options = CODECS[output.suffix.lower()]
    writer = imageio_ffmpeg.write_frames(
        str(output),
        frame_size,
        fps=fps,
        codec=codec,
        pix_fmt_out="yuv420p",
        output_params=options,
        macro_block_size=2,
        ffmpeg_log_level="error",
    )
    writer.send(None)
    times = frame_times(start_us, end_us, fps, speed)
    try:
        for time_us in times:
            view = view_at(time_us)
            snapshot = recording.snapshot_at(time_us)
            paths = robot_paths(recording, time_us) if view.scene["settings"].get("trace", False) else None
            frame = view.draw(snapshot, paths, f"t = {time_us / 1e6:.2f} s")
            if frame.size != frame_size:
                frame = ImageOps.pad(frame, frame_size, color=BACKGROUND)
            writer.send(np.ascontiguousarray(np.asarray(frame)))
    finally:
        writer.close()
    return len(times)
