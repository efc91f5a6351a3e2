"""Error replies say what is wrong, never which function was called: the C library puts the name
the program used in front ("eyesim: VWDrive: ..."), so a name in the message would show twice."""

import re

from support.client import RemoteError
from support.connected import connected_program
from support.worlds import arena_scene

# One failing request of every group whose handlers raise errors.
FAILING = [
    ("LCD_SET_POS", (21, 0)),
    ("KEY_WAIT", (0x10,)),
    ("CAM_GET", ()),
    ("CAM_INIT", (10,)),
    ("OS_WAIT", (-1,)),
    ("TIMER_DETACH", (7,)),
    ("PSD_GET", (7,)),
    ("LIDAR_SET", (0, 0, 360)),
    ("SERVO_SET", (9, 0)),
    ("SERVO_RANGE", (1, 200, 100)),
    ("MOTOR_DRIVE", (3, 50)),
    ("MOTOR_PID", (1, 256, 0, 0)),
    ("ENCODER_READ", (9,)),
    ("VW_DRIVE", (10, 100, 100)),
    ("ANALOG_READ", (9,)),
    ("ANALOG_TRANSFER", ()),
    ("RADIO_SEND", (2, b"hi")),
    ("SIM_GET_ROBOT", (9,)),
    ("SIM_GET_OBJECT", (9,)),
    ("SIM_SET_OBJECT", (1, 0, 0, 0, 0)),
    ("AU_PLAY", ("notes.txt", b"not a sound")),
]
FUNCTION_NAME_FIRST = re.compile(r"[A-Z]{2,}[A-Za-z0-9]*:")  # "VWDrive:", "LIDARSet:", "SIMSetObject:"


def test_error_messages_do_not_start_with_a_function_name():
    scene = arena_scene([("S4", (500, 500, 0))], objects=[("Crate1", (1500, 1500, 0))])
    with connected_program(scene) as (sim, client):
        messages = {}
        for op, args in FAILING:
            try:
                client.call(op, *args)
            except RemoteError as error:
                messages[op] = error.message
        assert set(messages) == {op for op, _ in FAILING}, "some requests did not fail"
        named = {op: message for op, message in messages.items() if FUNCTION_NAME_FIRST.match(message)}
        assert named == {}
