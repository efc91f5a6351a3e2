"""The report's trajectory plot, an SVG image: each robot's true path over the scene's walls and
markers, with its start, its end and where it touched walls, objects or other robots.

Written as text, not drawn with matplotlib: a plot costs about a millisecond instead of a tenth of
a second of the grader's CPU, which grades the cases on the same cores."""

from __future__ import annotations

import math
from html import escape
from pathlib import Path

COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf")
WIDTH = 480  # px of the image; its height follows the plotted area's shape
MAX_HEIGHT = 480
MARGIN = 150  # mm around what is drawn
TOP, LEFT = 34, 8  # px for the title and legend, and at the left
GRID_STEPS = (100, 200, 250, 500, 1000, 2000, 2500, 5000, 10000)  # mm between grid lines


def trajectory_plot(scene, result: dict, path: Path) -> Path:
    robots = [(robot_id, robot) for robot_id, robot in sorted(result.get("robots", {}).items()) if robot["path"]]
    xs = [v for w in scene.world.walls for v in (w.x1, w.x2)] + [m.x for m in scene.markers]
    ys = [v for w in scene.world.walls for v in (w.y1, w.y2)] + [m.y for m in scene.markers]
    for _, robot in robots:
        xs += [p[1] for p in robot["path"]]
        ys += [p[2] for p in robot["path"]]
    if not xs:
        xs, ys = [0.0], [0.0]
    left, right = min(xs) - MARGIN, max(xs) + MARGIN
    bottom, top = min(ys) - MARGIN, max(ys) + MARGIN
    scale = min((WIDTH - 2 * LEFT) / (right - left), (MAX_HEIGHT - TOP - LEFT) / (top - bottom))
    height = round(TOP + LEFT + (top - bottom) * scale)

    def at(x: float, y: float) -> str:  # world mm -> image px, y up
        return f"{LEFT + (x - left) * scale:.1f},{TOP + (top - y) * scale:.1f}"

    parts = [
        f"<svg xmlns='http://www.w3.org/2000/svg' width='{WIDTH}' height='{height}' "
        f"viewBox='0 0 {WIDTH} {height}' font-family='sans-serif' font-size='10'>",
        f"<rect width='{WIDTH}' height='{height}' fill='#ffffff'/>",
        _grid(left, right, bottom, top, at),
    ]
    for wall in scene.world.walls:
        parts.append(
            f"<polyline points='{at(wall.x1, wall.y1)} {at(wall.x2, wall.y2)}' stroke='#555555' "
            f"stroke-width='{max(1.5, wall.thickness * scale):.1f}' stroke-linecap='square'/>"
        )
    for number, marker in enumerate(scene.markers, start=1):
        x, y = at(marker.x, marker.y).split(",")
        colour = "#{:02x}{:02x}{:02x}".format(*marker.color[:3])
        parts.append(f"<circle cx='{x}' cy='{y}' r='5' fill='{colour}'/>")
        parts.append(f"<text x='{float(x) + 7:.1f}' y='{float(y) - 5:.1f}' font-size='9'>marker {number}</text>")
    for index, (robot_id, robot) in enumerate(robots):
        colour = COLOURS[index % len(COLOURS)]
        points = robot["path"]
        parts.append(
            f"<polyline points='{' '.join(at(p[1], p[2]) for p in points)}' fill='none' stroke='{colour}' "
            f"stroke-width='1.5' stroke-linejoin='round'/>"
        )
        x, y = at(points[0][1], points[0][2]).split(",")
        parts.append(f"<circle cx='{x}' cy='{y}' r='3.5' fill='{colour}'/>")
        end_x, end_y = map(float, at(robot["final"]["x"], robot["final"]["y"]).split(","))
        parts.append(
            f"<path d='M{end_x - 4:.1f},{end_y - 4:.1f}L{end_x + 4:.1f},{end_y + 4:.1f}"
            f"M{end_x - 4:.1f},{end_y + 4:.1f}L{end_x + 4:.1f},{end_y - 4:.1f}' "
            f"stroke='{colour}' stroke-width='2'/>"
        )
        for contact in result.get("contacts", []):
            if f"robot {robot_id}" in (contact["first"], contact["second"]):
                where = min(points, key=lambda p: abs(p[0] - contact["start"]))
                parts.append(_star(*map(float, at(where[1], where[2]).split(","))))
        parts.append(
            f"<text x='{WIDTH - 70}' y='{TOP + 12 + 13 * index}' fill='{colour}'>— robot {escape(robot_id)}</text>"
        )
    title = f"{result['student']} / {result['case']}  (mm; o start, x end, * contact)"
    parts.append(f"<text x='{WIDTH / 2}' y='14' text-anchor='middle'>{escape(title)}</text>")
    parts.append("</svg>")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(parts), encoding="utf-8")
    return path


def _grid(left: float, right: float, bottom: float, top: float, at) -> str:
    """Light grid lines labelled in mm, about five across."""
    step = next((s for s in GRID_STEPS if (right - left) / s <= 6), GRID_STEPS[-1])
    lines = []
    for x in range(math.ceil(left / step) * step, math.floor(right / step) * step + 1, step):
        (x1, y1), (x2, y2) = (at(x, bottom).split(","), at(x, top).split(","))
        lines.append(f"<line x1='{x1}' y1='{y1}' x2='{x2}' y2='{y2}'/>")
        lines.append(f"<text x='{float(x1) + 2:.1f}' y='{float(y1) - 3:.1f}' stroke='none'>{x}</text>")
    for y in range(math.ceil(bottom / step) * step, math.floor(top / step) * step + 1, step):
        (x1, y1), (x2, y2) = (at(left, y).split(","), at(right, y).split(","))
        lines.append(f"<line x1='{x1}' y1='{y1}' x2='{x2}' y2='{y2}'/>")
        lines.append(f"<text x='{float(x1) + 2:.1f}' y='{float(y1) - 3:.1f}' stroke='none'>{y}</text>")
    return f"<g stroke='#e4e4e4' fill='#999999' font-size='8'>{''.join(lines)}</g>"


def _star(x: float, y: float) -> str:
    corners = [
        (x + r * math.sin(math.pi * k / 5), y - r * math.cos(math.pi * k / 5))
        for k, r in zip(range(10), [6.0, 2.5] * 5)
    ]
    return f"<polygon points='{' '.join(f'{a:.1f},{b:.1f}' for a, b in corners)}' fill='#000000'/>"
