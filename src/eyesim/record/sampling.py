"""What a recording samples from the simulation at a simulation time: poses, robot state, rays.

Values are plain Python numbers taken on the simulation thread, so they can be encoded later on
another thread; floats keep full precision (the CSV export must equal a live `--record x.csv`)."""

from __future__ import annotations

from eyesim.record import schemas
from eyesim.robot.components.battery import Battery
from eyesim.robot.components.vw import VwController


def _transform(time_us: int, child: str, pos, quat) -> dict:
    return {
        "timestamp": schemas.stamp(time_us),
        "parent_frame_id": schemas.WORLD_FRAME,
        "child_frame_id": child,
        "translation": {"x": float(pos[0]), "y": float(pos[1]), "z": float(pos[2])},
        "rotation": {"x": float(quat[1]), "y": float(quat[2]), "z": float(quat[3]), "w": float(quat[0])},
    }


def transforms(sim) -> dict:
    """foxglove.FrameTransforms: every robot, object and moving robot part in the world frame."""
    data, now = sim.world.data, sim.time_us
    frames = [_transform(now, schemas.robot_frame(r.id), data.xpos[r.body], data.xquat[r.body]) for r in sim.robots]
    frames += [_transform(now, schemas.object_frame(o.id), data.xpos[o.body], data.xquat[o.body]) for o in sim.objects]
    frames += [
        _transform(now, schemas.body_frame(b), data.xpos[b], data.xquat[b]) for r in sim.robots for b in r.shown_parts
    ]
    return {"transforms": frames}


def robot_state(robot) -> dict:
    """eyesim.RobotState: odometry and speed (drives with V-omega control), encoders, battery, and
    the signals of its parts (a bumper's)."""
    vw = robot.component(VwController)
    battery = robot.component(Battery)
    state = {
        "robot": robot.id,
        "odometry": None,
        "speed": None,
        "encoders": {str(n): e.encoder() for n, e in sorted(robot.encoders.items())},
        "battery": battery.volts if battery is not None else None,
    }
    if vw is not None:
        x, y, phi = vw.odometry
        v, w = vw.measured_speed()
        state["odometry"] = {"x": float(x), "y": float(y), "phi": float(phi)}
        state["speed"] = {"v": float(v), "w": float(w)}
    signals = {name: [value, unit] for c in robot.components for name, (value, unit) in c.signals().items()}
    if signals:  # what the robot's parts give to plot (robot/component.py): [value, unit] by name
        state["signals"] = signals
    return state
