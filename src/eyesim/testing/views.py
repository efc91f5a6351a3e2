"""Read-only views of one robot or object of a `eyesim.Simulation`, in the RoBIOS units: mm and
degrees (as SIMGetRobot and VWGetPosition report them), seconds of simulation time."""

from __future__ import annotations

import math
from pathlib import Path
from typing import NamedTuple

import numpy as np

from eyesim.parts.camera.component import Camera
from eyesim.robot.components.lcd import Lcd
from eyesim.robot.components.vw import VwController
from eyesim.testing.contacts import Contact, Thing


class Pose(NamedTuple):
    x: float  # mm
    y: float  # mm
    phi: float  # degrees, counter-clockwise from the x axis
    z: float = 0.0  # mm

    def distance_to(self, x: float, y: float) -> float:
        return math.hypot(self.x - x, self.y - y)


class RobotView:
    def __init__(self, api, robot):
        self._api = api
        self._robot = robot
        self.id = robot.id
        self.name = robot.name

    def __repr__(self) -> str:
        return f"<robot {self.id} {self.name} at {self.pose}>"

    # -- where it is -------------------------------------------------------------------------
    @property
    def pose(self) -> Pose:
        """The true pose now."""
        x, y, z, phi = self._robot.pose_mm()
        return Pose(x, y, phi, z)

    @property
    def path(self) -> list:
        """True poses (observe.PathPoint: t, x, y, phi) every 10 ms of simulation time."""
        return self._api._paths.paths[self.id]

    @property
    def odometry(self) -> Pose | None:
        """What the robot believes (VWGetPosition): mm and degrees since its start or
        VWSetPosition; None for a robot without VW control."""
        vw = self._robot.component(VwController)
        if vw is None:
            return None
        x, y, phi = vw.odometry
        return Pose(x * 1000, y * 1000, math.degrees(phi))

    def closest_approach(self, x: float, y: float, before: float | None = None) -> tuple[float, float]:
        """(distance in mm, time in s) of the path's point nearest (x, y), at or before `before`."""
        points = [p for p in self.path if before is None or p.t <= before + 1e-9]
        best = min(points, key=lambda p: math.hypot(p.x - x, p.y - y))
        return math.hypot(best.x - x, best.y - y), best.t

    # -- what it shows -------------------------------------------------------------------------
    def lcd_image(self) -> np.ndarray:
        """What the LCD shows: (320, 480, 3) uint8, a copy."""
        return self._robot.component(Lcd).screen().copy()

    def lcd_text(self) -> list[str]:
        """The LCD's text by row (see Lcd.text_rows)."""
        return self._robot.component(Lcd).text_rows()

    def lcd_text_at(self, row: int, column: int = 0, length: int | None = None) -> str:
        rows = self.lcd_text()
        text = rows[row] if row < len(rows) else ""
        return text[column:] if length is None else text[column : column + length].ljust(length)

    def lcd_shows(self, text: str) -> bool:
        return any(text in row for row in self.lcd_text())

    @property
    def menu(self) -> list[str]:
        return list(self._robot.component(Lcd).menu or ["", "", "", ""])

    def camera_image(self) -> np.ndarray | None:
        """The last image the program took with CAMGet (height, width, 3), or None."""
        camera = self._robot.component(Camera)
        return None if camera is None or camera.image is None else camera.image.copy()

    # -- its program ---------------------------------------------------------------------------
    @property
    def program(self):
        """The launcher.ProgramRun (or CallableRun) of the robot's program, or None."""
        return self._api._runs.get(self.id)

    @property
    def stdout(self) -> str:
        return self.program.text("stdout") if self.program else ""

    @property
    def stderr(self) -> str:
        return self.program.text("stderr") if self.program else ""

    @property
    def exit_code(self) -> int | None:
        """The program's exit status (negative: the signal that ended it); None while it runs,
        when it was stopped at the end of the run, or without a program."""
        run = self.program
        return None if run is None or run.stopped_by_us else run.exit_code

    @property
    def workdir(self) -> Path | None:
        return self._api._workdirs.get(self.id)

    def read_file(self, name: str) -> bytes:
        """A file the program wrote, relative to its working directory."""
        if self.workdir is None:
            raise ValueError(f"robot {self.id} runs no program: it has no working directory to read {name} from")
        return (self.workdir / name).read_bytes()

    def serial_output(self, interface: int = 0) -> bytes:
        return bytes(self._api._events.serial.get((self.id, interface), b""))

    # -- what it touched -------------------------------------------------------------------------
    def contacts(self, with_kind: str = "any") -> list[Contact]:
        """Episodes of touching walls, robots or objects ('wall', 'robot', 'object', 'any')."""
        return self._api._contacts.of(Thing("robot", self.id), with_kind)


class ObjectView:
    def __init__(self, api, thing):
        self._api = api
        self._thing = thing
        self.id = thing.id
        self.name = thing.type.name

    @property
    def pose(self) -> Pose:
        x, y, z, phi = self._thing.pose_mm()
        return Pose(x, y, phi, z)

    def contacts(self, with_kind: str = "any") -> list[Contact]:
        return self._api._contacts.of(Thing("object", self.id), with_kind)
