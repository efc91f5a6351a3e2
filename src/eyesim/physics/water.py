"""Water: the pool a submarine scene is filled with, and the buoyancy and drag it exerts on a body.

A scene is under water when one of its robots swims (a `buoyancy` line or a drive that swims).
The water then fills the whole floor up to its surface: the height of the highest wall (the pool's
rim), or DEFAULT_SURFACE without walls. It is fresh water of DENSITY kg/m^3 (docs/robots.md)."""

from __future__ import annotations

from dataclasses import dataclass

from eyesim.physics.units import mm
from eyesim.scene.description import Scene
from eyesim.scene.drives import drive_of

DENSITY = 1000.0  # kg/m^3, fresh water
DEFAULT_SURFACE = 1.0  # m, a pool without walls
GRAVITY = 9.81  # m/s^2, MuJoCo's default
OBJECT_DRAG = 2.0  # N per m/s on a floating object


@dataclass(frozen=True)
class Water:
    surface: float  # m above the floor
    density: float = DENSITY


def water_of(scene: Scene) -> Water | None:
    # (mypy cannot see RobotType's fields: scene/parts assembles it with make_dataclass)
    swimming = any(
        drive_of(scene.robot_types[p.type_name]).swims or scene.robot_types[p.type_name].buoyancy is not None  # type: ignore[attr-defined]
        for p in scene.robots
    )
    if not swimming:
        return None
    walls = scene.world.walls
    return Water(max(mm(w.height) for w in walls) if walls else DEFAULT_SURFACE)


class WaterForces:
    """Buoyancy and linear drag on one free body, through `data.xfrc_applied` (world frame, at the
    body's centre of mass, with the torques of forces that act elsewhere).

    The body is taken as upright for how much of it is under water: its hull spans `height` metres
    around `hull_centre` (body frame); buoyancy scales with the submerged part of that span and acts
    at `buoyancy_centre`, so a centre of buoyancy above the centre of mass rights the body. Drag
    opposes the velocity along the body's own axes (`drag`, N per m/s) and its rotation
    (`rotational_drag`, N*m per rad/s), scaled the same way. It acts where the water presses on
    the hull: the centre of its submerged part (`pressure_centre` across, the middle of the
    submerged span up and down), not at the centre of mass. Thrusters level with the hull's middle
    then push a submarine straight, however low its centre of mass sits; drag at the centre of
    mass would leave their thrust a lever that pitches it nose down (13 degrees for a Mako-like
    hull) and drives it into the pool floor."""

    def __init__(
        self,
        body: int,
        volume: float,
        buoyancy_centre,
        hull_centre,
        height: float,
        drag=(0.0, 0.0, 0.0),
        rotational_drag: float = 0.0,
        pressure_centre=None,
    ):
        self.body = body
        self.volume = volume  # m^3
        self.buoyancy_centre = buoyancy_centre
        self.hull_centre = hull_centre
        self.height = height
        self.drag = drag
        self.rotational_drag = rotational_drag
        across = pressure_centre if pressure_centre is not None else hull_centre
        self.pressure_x, self.pressure_y = across[0], across[1]
        self.bottom = hull_centre[2] - height / 2  # of the hull, body frame

    def bind(self, world) -> None:
        self.water = world.water
        self.model, self.data = world.model, world.data
        joint = self.model.body_jntadr[self.body]
        self.dof = int(self.model.jnt_dofadr[joint])

    def submerged_fraction(self) -> float:
        centre_z = self._world_point(self.hull_centre)[2]
        bottom = centre_z - self.height / 2
        return min(1.0, max(0.0, (self.water.surface - bottom) / self.height))

    def _world_point(self, local) -> tuple[float, float, float]:
        pos, rot = self.data.xpos[self.body], self.data.xmat[self.body]
        x, y, z = local
        return (
            pos[0] + rot[0] * x + rot[1] * y + rot[2] * z,
            pos[1] + rot[3] * x + rot[4] * y + rot[5] * z,
            pos[2] + rot[6] * x + rot[7] * y + rot[8] * z,
        )

    def apply(self) -> None:
        forces = self.data.xfrc_applied[self.body]
        fraction = self.submerged_fraction()
        if fraction == 0.0:
            forces[:] = 0.0
            return
        lift = self.water.density * self.volume * GRAVITY * fraction
        com = self.data.xipos[self.body]
        cx, cy, cz = self._world_point(self.buoyancy_centre)
        arm = (cx - com[0], cy - com[1], cz - com[2])
        # Drag in the body frame: the free joint's linear velocity is in world axes, its angular
        # velocity in body axes.
        rot = self.data.xmat[self.body]
        qvel = self.data.qvel
        vx, vy, vz = qvel[self.dof], qvel[self.dof + 1], qvel[self.dof + 2]
        local = (
            rot[0] * vx + rot[3] * vy + rot[6] * vz,
            rot[1] * vx + rot[4] * vy + rot[7] * vz,
            rot[2] * vx + rot[5] * vy + rot[8] * vz,
        )
        drag_local = [-fraction * d * v for d, v in zip(self.drag, local)]
        drag = [
            rot[3 * i] * drag_local[0] + rot[3 * i + 1] * drag_local[1] + rot[3 * i + 2] * drag_local[2]
            for i in range(3)
        ]
        spin = [qvel[self.dof + 3 + i] for i in range(3)]
        spin_world = [rot[3 * i] * spin[0] + rot[3 * i + 1] * spin[1] + rot[3 * i + 2] * spin[2] for i in range(3)]
        # where the drag acts: the middle of the submerged part of the hull
        px, py, pz = self._world_point((self.pressure_x, self.pressure_y, self.bottom + fraction * self.height / 2))
        lever = (px - com[0], py - com[1], pz - com[2])
        forces[0] = drag[0]
        forces[1] = drag[1]
        forces[2] = drag[2] + lift
        # torques of the lift at the centre of buoyancy (arm x (0, 0, lift)) and of the drag at the
        # centre of pressure (lever x drag), plus rotational drag
        forces[3] = (
            arm[1] * lift + lever[1] * drag[2] - lever[2] * drag[1] - fraction * self.rotational_drag * spin_world[0]
        )
        forces[4] = (
            -arm[0] * lift + lever[2] * drag[0] - lever[0] * drag[2] - fraction * self.rotational_drag * spin_world[1]
        )
        forces[5] = lever[0] * drag[1] - lever[1] * drag[0] - fraction * self.rotational_drag * spin_world[2]


def object_water_forces(body: int, volume_litres: float, height: float, centre) -> WaterForces:
    """Buoyancy of a floating object (its .esObj `buoyancy`), with some drag so it settles."""
    drag = (OBJECT_DRAG, OBJECT_DRAG, OBJECT_DRAG)
    return WaterForces(body, volume_litres / 1000.0, centre, centre, height, drag, OBJECT_DRAG / 100)
