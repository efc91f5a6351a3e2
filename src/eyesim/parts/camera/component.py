"""The robot's camera: its pose on the robot (with pan and tilt), its resolution, its images.

An image is rendered only when a program asks for one (CAMGet), on the process's render thread
(physics/render_worker.py) from a copy of the world taken when it was asked for; the last image
the program got is kept for the viewer."""

from __future__ import annotations

import math

import numpy as np

from eyesim.parts.camera.declaration import CameraSpec
from eyesim.physics import render, render_worker
from eyesim.physics.units import mm
from eyesim.protocol import generated as g
from eyesim.robot.actuators import Servo
from eyesim.robot.component import Component

MAX_FOV = 170.0  # degrees: wider views cannot be drawn by a pinhole (nor resampled into a fisheye)
SERVO_RATE = 300.0  # degrees per second a pan or tilt servo turns (a fast hobby servo)
EDITOR_IMAGE = (160, 120)  # the robot editor's test drive takes images this size


class Camera(Component):
    """Pan turns the camera left (positive) or right about the robot's z axis, tilt then raises
    (positive) or lowers it; both in degrees from looking straight ahead."""

    noun = "camera"

    def __init__(self, spec: CameraSpec, context):
        self.spec = spec
        self.robot = context.robot
        self.position = np.array([mm(spec.x), mm(spec.y), mm(spec.z)])
        self.fov = min(max(spec.fov, 1.0), MAX_FOV)
        self.size: tuple[int, int] | None = None  # (width, height) once CAMInit chose a resolution
        self.image_count = 0  # images taken so far (never reset: the viewer goes by it)
        self._published = 0  # the image count the viewer was last sent
        self.reset()

    def reset(self) -> None:
        self.pan, self.tilt = self.spec.pan, self.spec.tilt
        self.image: np.ndarray | None = None  # the last image taken, for the viewer

    def publish(self, robot_id: int, events, again: bool) -> None:
        """The last image the program took, for the viewer."""
        if self.image is not None and (again or self._published != self.image_count):
            self._published = self.image_count
            events.camera(robot_id, self.image)

    # -- set-up ----------------------------------------------------------------------------
    def start(self, width: int, height: int) -> None:
        self.size = (width, height)
        render_worker.prepare(self.world, width, height)

    def stop(self) -> None:
        self.size = None

    # -- images ----------------------------------------------------------------------------
    def view(self, width: int, height: int) -> render.View:
        """Where the camera is and looks now, in the world."""
        data = self.world.data
        rotation = data.xmat[self.robot.body].reshape(3, 3)
        pan, tilt = math.radians(self.pan), math.radians(self.tilt)
        forward = (math.cos(tilt) * math.cos(pan), math.cos(tilt) * math.sin(pan), math.sin(tilt))
        up = (-math.sin(tilt) * math.cos(pan), -math.sin(tilt) * math.sin(pan), math.cos(tilt))
        return render.View(
            position=tuple(data.xpos[self.robot.body] + rotation @ self.position),
            forward=tuple(rotation @ forward),
            up=tuple(rotation @ up),
            width=width,
            height=height,
            fov=self.fov,
            fisheye=self.spec.fisheye,
            own_body=self.robot.body,
        )

    def take(self, finish) -> render_worker.Frame:
        """Start an image at the chosen resolution, of the world as it is now, drawn on the render
        thread; `finish(image)` makes the reply there. `taken(frame)` once the program has it."""
        if self.size is None:
            raise RuntimeError("the camera has no resolution yet: start it first (CAMInit)")
        width, height = self.size
        return render_worker.draw(self.world, self.view(width, height), finish)

    def taken(self, frame: render_worker.Frame) -> None:
        """The program got this image: it is the one the viewer shows."""
        if frame.image is not None:
            self.image = frame.image
            self.image_count += 1

    def capture(self) -> np.ndarray:
        """A colour image at the chosen resolution, (height, width, 3) uint8, top row first, waited
        for (not for programs' calls: the robot editor's preview, tests)."""
        frame = self.take(lambda image: None)
        frame.wait()
        if frame.error is not None or frame.image is None:
            raise RuntimeError(f"the camera image could not be drawn:\n{frame.error}")
        self.taken(frame)
        return frame.image

    # -- how it shows itself (robot/component.py) --------------------------------------------------
    recorded_ops = frozenset((g.OP_CAM_GET, g.OP_CAM_GET_GRAY))

    def recorded(self, op: int, args: tuple, reply: tuple) -> tuple[str, object] | None:
        """The image the program took (CAMGet, CAMGetGray: the viewer's colour one)."""
        return None if self.image is None else ("camera", self.image.copy())

    def editor_view(self) -> dict:
        """Where it is and looks, and its field of view."""
        view = self.view(*EDITOR_IMAGE)
        return {
            "camera": {
                "position": np.asarray(view.position),
                "forward": np.asarray(view.forward),
                "up": np.asarray(view.up),
                "fov": view.fov,
                "aspect": EDITOR_IMAGE[0] / EDITOR_IMAGE[1],
                "fisheye": view.fisheye,
            }
        }

    def readings(self) -> dict:
        self.start(*EDITOR_IMAGE)
        return {"camera": self.capture()}


class CameraServo(Servo):
    """A pan or tilt servo: SERVOSet 0..255 maps linearly onto the camera line's range (degrees);
    it starts at 0 degrees, looking straight ahead."""

    def neutral_raw(self) -> float:
        return self.raw_of(0.0)

    def raw_of(self, degrees: float) -> float:
        return (degrees - self.low_value) / (self.high_value - self.low_value) * 255


class ServoCamera(Camera):
    """A camera whose pan and/or tilt servos (`SERVO<n>(<min>,<max>)` in the camera line) turn it."""

    def __init__(self, spec: CameraSpec, context):
        self.servos = {}
        if spec.pan_servo is not None:
            self.servos[spec.pan_servo] = self.pan_servo = CameraServo(spec.pan_servo, *spec.pan_range, SERVO_RATE)
        if spec.tilt_servo is not None:
            self.servos[spec.tilt_servo] = self.tilt_servo = CameraServo(spec.tilt_servo, *spec.tilt_range, SERVO_RATE)
        super().__init__(spec, context)

    def reset(self) -> None:
        super().reset()
        for servo in self.servos.values():
            servo.reset_servo()
        self._follow_servos()

    def before_step(self, dt: float) -> None:
        for servo in self.servos.values():
            servo.advance(dt)
        self._follow_servos()

    def _follow_servos(self) -> None:
        if self.spec.pan_servo is not None:
            self.pan = self.pan_servo.position
        if self.spec.tilt_servo is not None:
            self.tilt = self.tilt_servo.position


def create(context) -> list[Component]:
    spec = context.robot_type.camera
    if spec is None:
        return []
    if spec.pan_servo is not None or spec.tilt_servo is not None:
        return [ServoCamera(spec, context)]
    return [Camera(spec, context)]
