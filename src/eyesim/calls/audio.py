"""RoBIOS audio group: beeps and sound files play in simulation time; the viewer plays them aloud."""

import base64

from eyesim.calls.errors import CallError, require
from eyesim.robot.components.analog_io import MICROPHONE, AnalogInputs
from eyesim.robot.components.speaker import BEEP_HERTZ, BEEP_SECONDS, Speaker
from eyesim.robot.sound_files import SoundError, sound_length

from eyesim.protocol import generated as g

MAX_SOUND_BYTES = dict(g.OPS[g.OP_AU_PLAY].lengths)[1]  # protocol.json; the C library's AUPlay reads at most as much


def _speaker(robot) -> Speaker:
    return require(robot.component(Speaker), robot, "speaker")


def au_beep(sim, robot, request):
    _speaker(robot).play(BEEP_SECONDS, request.time_us)
    sim.events.sound(robot.id, {"sound": "beep", "duration": BEEP_SECONDS, "frequency": BEEP_HERTZ})
    return (0,)


def au_play(sim, robot, request):
    name, data = request.args
    speaker = _speaker(robot)
    try:
        kind, seconds = sound_length(data)
    except SoundError as error:
        raise CallError(f"{name}: {error}") from None
    speaker.play(seconds, request.time_us)
    sound = {"sound": "file", "name": name, "format": kind, "duration": round(seconds, 3)}
    if sim.events.wants_lcd:  # a viewer is watching: only it can play the bytes
        sound["data"] = base64.b64encode(data).decode("ascii")
    sim.events.sound(robot.id, sound)
    return (0,)


def au_done(sim, robot, request):
    return (1 if _speaker(robot).done(request.time_us) else 0,)


def au_microphone(sim, robot, request):
    """One sample of the microphone, which is analog channel 8."""
    return (require(robot.component(AnalogInputs), robot, "microphone").read(MICROPHONE),)


HANDLERS = {"AU_BEEP": au_beep, "AU_PLAY": au_play, "AU_DONE": au_done, "AU_MICROPHONE": au_microphone}
