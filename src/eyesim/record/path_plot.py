"""`eyesim plot`: every robot's path over the world map (floor, walls, markers, objects), as an image."""

from __future__ import annotations

import io
import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # no display needed: only files are written
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, Polygon, Rectangle  # noqa: E402

from eyesim.record.recording import Recording  # noqa: E402
from eyesim.record.top_view import yaw  # noqa: E402

IMAGE_TYPES = (".png", ".svg", ".pdf")


def _footprint(x: float, y: float, heading: float, length: float, width: float) -> list[tuple[float, float]]:
    c, s = math.cos(heading), math.sin(heading)
    return [
        (x + c * u - s * v, y + s * u + c * v)
        for u, v in (
            (length / 2, width / 2),
            (-length / 2, width / 2),
            (-length / 2, -width / 2),
            (length / 2, -width / 2),
        )
    ]


def plot_paths(recording: Recording, output: str | Path, dpi: int = 150) -> None:
    """Draws the map, each robot's path from start (circle) to end (its footprint), and a legend."""
    output = Path(output)
    if output.suffix.lower() not in IMAGE_TYPES:
        raise ValueError(f"{output.name}: the image file must end in .png, .svg or .pdf")
    last = recording.segments[-1]  # the scene the run ended with (edits in the viewer: the last)
    scene = last.scene
    width, height = scene["floor"]["width"], scene["floor"]["height"]
    figure, axes = plt.subplots(figsize=(7, 7 * height / width + 0.6))
    texture = recording.attachment("floor-texture")
    if texture:
        axes.imshow(plt.imread(io.BytesIO(texture)), extent=(0, width, 0, height), zorder=0)
    else:
        axes.add_patch(Rectangle((0, 0), width, height, color="#f6f2e8", zorder=0))
    for wall in scene["walls"]:
        axes.plot(
            [wall["x1"], wall["x2"]],
            [wall["y1"], wall["y2"]],
            color=[c / 255 for c in wall["color"]],
            linewidth=max(1.0, wall["thickness"] * 200),
            solid_capstyle="butt",
            zorder=1,
        )
    for marker in scene["markers"]:
        axes.add_patch(
            Circle((marker["x"], marker["y"]), 0.0125, color=[c / 255 for c in marker["color"][:3]], zorder=1)
        )
    first = recording.snapshot_at(last.start_us)
    objects = {o["id"]: o for o in scene["objects"]}
    for pose in first["objects"] if first else []:
        thing = objects.get(pose["id"])
        if thing is not None:
            size = thing["size"]
            x, y = pose["pos"][:2]
            if thing["shape"] == "box":
                axes.add_patch(
                    Polygon(
                        _footprint(x, y, yaw(pose["quat"]), size[0], size[1]),
                        color=[c / 255 for c in thing["color"]],
                        alpha=0.8,
                        zorder=2,
                    )
                )
            else:
                axes.add_patch(Circle((x, y), size[0], color=[c / 255 for c in thing["color"]], alpha=0.8, zorder=2))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    robots = {r["id"]: r for segment in recording.segments for r in segment.scene["robots"]}  # latest wins
    for index, robot in enumerate(robots[i] for i in recording.robot_ids):
        _, poses = recording.robot_track(robot["id"])
        if len(poses) == 0:
            continue
        color = colors[index % len(colors)]
        axes.plot(
            poses[:, 0], poses[:, 1], color=color, linewidth=1.6, zorder=3, label=f"robot {robot['id']} {robot['name']}"
        )
        axes.add_patch(Circle(tuple(poses[0, :2]), 0.02, fill=False, edgecolor=color, linewidth=1.5, zorder=4))
        end = poses[-1]
        axes.add_patch(
            Polygon(
                _footprint(end[0], end[1], yaw(end[3:7]), *robot["size"][:2]),
                facecolor=color,
                edgecolor="black",
                linewidth=0.8,
                zorder=4,
            )
        )
    axes.set_xlim(0, width)
    axes.set_ylim(0, height)
    axes.set_aspect("equal")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    edited = f"; the scene as edited at {last.start_us / 1e6:.1f} s" if len(recording.segments) > 1 else ""
    axes.set_title(f"{recording.path.name}: paths over {recording.duration_s:.1f} s (circle: start){edited}")
    if robots:
        axes.legend(loc="upper right", fontsize="small")
    figure.tight_layout()
    figure.savefig(output, dpi=dpi)
    plt.close(figure)
