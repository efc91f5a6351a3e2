"""RoBIOS PSD group: PSDGet and PSDGetRaw read a robot's sensor by its RoBIOS id."""

from eyesim.calls.errors import CallError
from eyesim.parts.psd.component import PsdSensor

GROUP = "psd"  # protocol.json's group of the operations below


def _sensor(robot, psd_id: int) -> PsdSensor:
    for sensor in robot.components_of(PsdSensor):
        if sensor.id == psd_id:
            return sensor
    ids = sorted(s.id for s in robot.components_of(PsdSensor))
    raise CallError(f"robot {robot.id} has no PSD {psd_id} (it has {ids or 'none'})")


def psd_get(sim, robot, request):
    (psd_id,) = request.args
    return (_sensor(robot, psd_id).distance_mm(),)


def psd_get_raw(sim, robot, request):
    (psd_id,) = request.args
    return (_sensor(robot, psd_id).raw(),)


HANDLERS = {"PSD_GET": psd_get, "PSD_GET_RAW": psd_get_raw}
