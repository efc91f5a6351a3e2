"""The report's trajectory plot: each robot's true path over the scene's walls and markers, with
its start, its end and where it touched walls, objects or other robots."""

from __future__ import annotations

from pathlib import Path

COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf")


def trajectory_plot(scene, result: dict, path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")  # files only, never a window
    from matplotlib.figure import Figure

    figure = Figure(figsize=(4.8, 4.0), dpi=80)
    axes = figure.add_subplot()
    for wall in scene.world.walls:
        axes.plot(
            [wall.x1, wall.x2],
            [wall.y1, wall.y2],
            color="#555555",
            linewidth=max(1.0, wall.thickness / 12),
            solid_capstyle="projecting",
        )
    for number, marker in enumerate(scene.markers, start=1):
        axes.plot(marker.x, marker.y, "o", color=[c / 255 for c in marker.color[:3]], markersize=9)
        axes.annotate(f"marker {number}", (marker.x, marker.y), textcoords="offset points", xytext=(6, 6), fontsize=7)
    for index, (robot_id, robot) in enumerate(sorted(result.get("robots", {}).items())):
        colour = COLOURS[index % len(COLOURS)]
        points = robot["path"]
        if not points:
            continue
        xs, ys = [p[1] for p in points], [p[2] for p in points]
        axes.plot(xs, ys, color=colour, linewidth=1.5, label=f"robot {robot_id}")
        axes.plot(xs[0], ys[0], "o", color=colour, markersize=6)
        axes.plot(robot["final"]["x"], robot["final"]["y"], "x", color=colour, markersize=8, markeredgewidth=2)
        for contact in result.get("contacts", []):
            if f"robot {robot_id}" in (contact["first"], contact["second"]):
                at = min(points, key=lambda p: abs(p[0] - contact["start"]))
                axes.plot(at[1], at[2], "*", color="#000000", markersize=9)
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("x (mm)", fontsize=8)
    axes.set_ylabel("y (mm)", fontsize=8)
    axes.tick_params(labelsize=7)
    if result.get("robots"):
        axes.legend(fontsize=7, loc="best")
    axes.set_title(f"{result['student']} / {result['case']}  (o start, x end, * contact)", fontsize=8)
    figure.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path)
    return path
