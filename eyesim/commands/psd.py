"""RoBIOS PSD group: infrared distance sensors."""

from eyesim.commands.errors import CommandError
from eyesim.robot.components.psd import PsdSensor


def psd_get(sim, robot, request):
    (psd_id,) = request.args
    for sensor in robot.components_of(PsdSensor):
        if sensor.id == psd_id:
            return (sensor.distance_mm(),)
    ids = sorted(s.id for s in robot.components_of(PsdSensor))
    raise CommandError(f"PSDGet: robot {robot.id} has no PSD {psd_id} (it has {ids or 'none'})")


HANDLERS = {"PSD_GET": psd_get}
