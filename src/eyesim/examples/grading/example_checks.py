"""Custom checks of examples.toml (kind = "python"): each gets the finished simulation
(eyesim.Simulation) and the check's params, and returns True/False, a score 0..1, or
(score, message)."""

import re


def printed_values(sim, robot, tag):
    """The numbers the robot's program printed on lines `<tag> <number>`."""
    return [int(m) for m in re.findall(rf"^{tag} (-?\d+)$", sim.robot(robot).stdout, flags=re.MULTILINE)]


def depth_held(sim, robot, target, tolerance):
    """The submarine reported a dived and a cruising depth within tolerance of the target."""
    depths = printed_values(sim, robot, "dived") + printed_values(sim, robot, "cruised")
    if len(depths) != 2:
        return 0.0, f"expected 'dived' and 'cruised' lines, found depths {depths}"
    off = [abs(d - target) for d in depths]
    held = sum(o <= tolerance for o in off) / 2
    return held, f"depths {depths} mm, target {target} ± {tolerance}"


def surfaced(sim, robot):
    [depth] = printed_values(sim, robot, "surfaced") or [None]
    return (depth is not None and depth <= 0), f"depth at the end: {depth} mm"
