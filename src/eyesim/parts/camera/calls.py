"""RoBIOS camera group: CAMInit and colour and gray frames from the robot's camera (CAMRelease only
stops it: protocol.json's "calls").

A frame is drawn, turned gray and encoded on the render thread (physics/render_worker.py), not on
the simulation thread, which serves every program: CAMGet's reply is Deferred."""

from eyesim.calls.errors import CallError, component_of
from eyesim.net.session import Deferred
from eyesim.parts.camera.component import Camera
from eyesim.physics.render import to_gray
from eyesim.protocol import constants, encode_image_reply
from eyesim.protocol.constants import CUSTOM

GROUP = "cam"  # protocol.json's group of the operations below

# The camera's RoBIOS resolutions (QQVGA..CAM5MP; CUSTOM is the LCD's) -> (width, height)
CAMERA_RESOLUTIONS = {name: value for name, value in constants.GROUPS["resolutions"].items() if value != CUSTOM}
RESOLUTIONS = {
    value: (getattr(constants, f"{name}_X"), getattr(constants, f"{name}_Y"))
    for name, value in CAMERA_RESOLUTIONS.items()
}
NAMES = ", ".join(f"{name} {value}" for name, value in CAMERA_RESOLUTIONS.items())


def _camera(robot) -> Camera:
    return component_of(robot, Camera)


def _started(robot) -> tuple[Camera, tuple[int, int]]:
    """The camera and its (width, height), once CAMInit chose them."""
    camera = _camera(robot)
    if camera.size is None:
        raise CallError("the camera is not initialised; call CAMInit first")
    return camera, camera.size


def cam_init(sim, robot, request):
    (resolution,) = request.args
    camera = _camera(robot)
    if resolution == CUSTOM:
        raise CallError("CUSTOM is for LCD images only; the camera takes " + NAMES)
    if resolution not in RESOLUTIONS:
        raise CallError(f"unknown resolution {resolution}; expected one of {NAMES}")
    width, height = RESOLUTIONS[resolution]
    camera.start(width, height)
    return (0, width, height)


def cam_get(sim, robot, request):
    return _image(robot, request, gray=False)


def cam_get_gray(sim, robot, request):
    return _image(robot, request, gray=True)


def _image(robot, request, gray: bool) -> Deferred:
    camera, (width, height) = _started(robot)

    def reply(image):  # on the render thread
        pixels = to_gray(image) if gray else image
        values = (0, width, height, pixels)  # for request observers (the recorder): the array, not bytes
        return values, encode_image_reply(request.op.code, request.request_id, values[:3], pixels)

    frame = camera.take(reply)
    return Deferred(frame, lambda: camera.taken(frame))


HANDLERS = {
    "CAM_INIT": cam_init,
    "CAM_GET": cam_get,
    "CAM_GET_GRAY": cam_get_gray,
}
