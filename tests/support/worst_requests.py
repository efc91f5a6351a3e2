"""The worst legal request of every operation: the largest sizes and values the protocol lets a
program send (docs/protocol.md), in an order where each one does its most work (the camera is
started at its largest resolution before CAM_GET, the serial interface opened before SER_SEND, ...).

Shared by tests/net/test_worst_requests.py (each is answered, memory stays bounded) and
bench/bench_worst_requests.py (what each costs the simulation thread)."""

from __future__ import annotations

from eyesim.calls.audio import MAX_SOUND_BYTES
from eyesim.protocol import generated as g

INT_MAX, INT_MIN = 2**31 - 1, -(2**31)
U32_MAX = 2**32 - 1
# The largest payload a frame carries: the frame limit less the header and one length field.
LARGEST = g.MAX_FRAME - g.HEADER_SIZE - 4
RANGE_MM, RANGE_DEG, RANGE_SPEED, RANGE_TURN = 10_000_000, 3_600_000, 100_000, 360_000


def most(op: str, field: str) -> int:
    """The longest a str or bytes field of `op` may be (protocol.json's lengths, else the frame's)."""
    spec = g.OPS_BY_NAME[op]
    index = [name for name, _ in spec.request].index(field)
    return dict(spec.lengths).get(index, LARGEST)


def big_text(size: int = LARGEST) -> str:
    """Text that makes the LCD work hardest per byte: line feeds and tabs scroll and pad."""
    return ("\t\n" * (size // 2 + 1))[:size]


def big_bytes(size: int = LARGEST) -> bytes:
    """Bytes that look like no sound file, so a sound-length reader scans all of them."""
    return (b"\xff\xfe" * (size // 2 + 1))[:size]


def smallest_mp3_frames(size: int) -> bytes:
    """An MP3 file of the shortest frames there are (MPEG-1 layer I, 32 kbit/s, 48 kHz: 32 bytes)."""
    frame = bytes([0xFF, 0xFF, 0x14, 0x00]) + bytes(28)
    return frame * (size // len(frame))


def worst_requests(robot_id: int = 1):
    """(op name, arguments) for every operation but HELLO and THREADS (sent by the client's
    handshake), each at its worst; `robot_id` is the robot the program drives. The 16 MiB
    arguments are made one at a time, as they are taken (memory is measured meanwhile)."""
    steps = [
        ("LCD_PRINTF", lambda: (big_text(most("LCD_PRINTF", "text")),)),
        ("LCD_SET_PRINTF", lambda: (0, 0, big_text(most("LCD_SET_PRINTF", "text")))),
        ("LCD_CLEAR", ()),
        ("LCD_MENU", lambda: tuple(big_text(most("LCD_MENU", f"key{k}")) for k in range(1, 5))),
        ("LCD_SET_POS", (INT_MAX, INT_MIN)),
        ("LCD_GET_POS", ()),
        ("LCD_SET_COLOR", (INT_MAX, INT_MIN)),
        ("LCD_SET_FONT", (INT_MAX, INT_MIN)),
        ("LCD_SET_FONT_SIZE", (INT_MAX,)),
        ("LCD_SET_MODE", (INT_MAX,)),
        ("LCD_MENU_I", lambda: (INT_MAX, big_text(most("LCD_MENU_I", "label")), INT_MAX, INT_MIN)),
        ("LCD_GET_SIZE", ()),
        ("LCD_PIXEL", (INT_MAX, INT_MIN, INT_MAX)),
        ("LCD_GET_PIXEL", (INT_MAX, INT_MIN)),
        ("LCD_LINE", (INT_MIN, INT_MIN, INT_MAX, INT_MAX, 0xFFFFFF)),
        ("LCD_LINE", (INT_MIN, 160, INT_MAX, 161, 0xFFFFFF)),
        ("LCD_AREA", (INT_MIN, INT_MIN, INT_MAX, INT_MAX, 0xFFFFFF, 1)),
        ("LCD_CIRCLE", (240, 160, INT_MAX, 0xFFFFFF, 1)),
        ("LCD_CIRCLE", (240, 160, INT_MAX, 0xFFFFFF, 0)),
        ("LCD_CIRCLE", (240, 160, 300, 0xFFFFFF, 0)),
        # the largest colour image (a 5-megapixel camera's), shown over the whole LCD
        ("LCD_IMAGE", lambda: (0, 0, 2592, 1944, INT_MAX, INT_MAX, 0, bytes(most("LCD_IMAGE", "pixels")))),
        ("LCD_IMAGE", (0, 0, 480, 320, 480, 320, 0, bytes(480 * 320 * 3))),
        ("LCD_REFRESH", ()),
        ("KEY_GET", ()),
        ("KEY_READ", ()),
        ("KEY_WAIT", (INT_MAX,)),
        ("KEY_GET_XY", ()),
        ("KEY_READ_XY", ()),
        ("CAM_INIT", (5,)),  # CAM5MP, 2592 x 1944
        ("CAM_GET", ()),
        ("CAM_GET_GRAY", ()),
        ("CAM_RELEASE", ()),
        ("OS_WAIT", (INT_MAX,)),
        ("OS_GET_COUNT", ()),
        ("OS_MACHINE_NAME", ()),
        ("OS_MACHINE_ID", ()),
        ("OS_MACHINE_TYPE", ()),
        ("OS_SLEEP", (U32_MAX, 999_999_999)),
        ("TIMER_ATTACH", (1,)),
        ("TIMER_WAIT", ()),
        ("TIMER_DETACH", (INT_MAX,)),
        ("SER_INIT", (0, 230400, 1)),
        ("SER_SEND", lambda: (0, big_bytes(most("SER_SEND", "data")))),
        ("SER_RECEIVE_CHAR", (0,)),
        ("SER_RECEIVE", (0, INT_MAX)),
        ("SER_CHECK", (0,)),
        ("SER_FLUSH", (0,)),
        ("SER_CLOSE", (0,)),
        ("AU_BEEP", ()),
        ("AU_PLAY", lambda: ("x" * most("AU_PLAY", "name"), big_bytes(MAX_SOUND_BYTES))),
        ("AU_PLAY", lambda: ("x", smallest_mp3_frames(MAX_SOUND_BYTES))),
        ("AU_DONE", ()),
        ("AU_MICROPHONE", ()),
        ("PSD_GET", (1,)),
        ("PSD_GET_RAW", (INT_MAX,)),
        ("LIDAR_SET", (360, 0, 3600)),
        ("LIDAR_GET", ()),
        ("SIM_LASER_SCAN", ()),
        ("SERVO_SET", (INT_MAX, 255)),
        ("SERVO_SET_RAW", (INT_MAX, 255)),
        ("SERVO_RANGE", (INT_MAX, 0, 255)),
        ("MOTOR_DRIVE", (1, INT_MAX)),
        ("MOTOR_DRIVE_RAW", (1, INT_MIN)),
        ("MOTOR_PID", (1, INT_MAX, INT_MAX, INT_MAX)),
        ("MOTOR_SPEED", (1, 10_000_000)),
        ("MOTOR_PID_OFF", (1,)),
        ("ENCODER_READ", (1,)),
        ("ENCODER_RESET", (1,)),
        ("VW_SET_SPEED", (RANGE_SPEED, RANGE_TURN)),
        ("VW_GET_SPEED", ()),
        ("VW_SET_POSITION", (RANGE_MM, -RANGE_MM, RANGE_DEG)),
        ("VW_GET_POSITION", ()),
        ("VW_STRAIGHT", (RANGE_MM, RANGE_SPEED)),
        ("VW_TURN", (RANGE_DEG, RANGE_TURN)),
        ("VW_CURVE", (RANGE_MM, RANGE_DEG, RANGE_SPEED)),
        ("VW_DRIVE", (RANGE_MM, -RANGE_MM, RANGE_SPEED)),
        ("VW_REMAIN", ()),
        ("VW_DONE", ()),
        ("VW_STALLED", ()),
        ("VW_WAIT", ()),
        ("DIGITAL_SETUP", (16, ord("O"))),
        ("DIGITAL_READ", (16,)),
        ("DIGITAL_READ_ALL", ()),
        ("DIGITAL_WRITE", (16, 1)),
        ("ANALOG_READ", (8,)),
        ("ANALOG_VOLTAGE", ()),
        ("ANALOG_RECORD", (8, 100_000)),
        ("ANALOG_TRANSFER", ()),
        ("IRTV_GET", ()),
        ("IRTV_READ", ()),
        ("IRTV_FLUSH", ()),
        ("IRTV_GET_STATUS", ()),
        ("RADIO_INIT", ()),
        ("RADIO_GET_ID", ()),
        ("RADIO_SEND", (robot_id, bytes(1024))),
        ("RADIO_RECEIVE", ()),
        ("RADIO_CHECK", ()),
        ("RADIO_STATUS", ()),
        ("RADIO_RELEASE", ()),
        ("SIM_GET_ROBOT", (INT_MAX,)),
        ("SIM_SET_ROBOT", (robot_id, RANGE_MM, RANGE_MM, RANGE_MM, RANGE_DEG)),
        ("SIM_GET_OBJECT", (INT_MAX,)),
        ("SIM_SET_OBJECT", (1, -RANGE_MM, -RANGE_MM, -RANGE_MM, -RANGE_DEG)),
        ("SIM_GET_ROBOT_COUNT", ()),
        ("SIM_GET_OBJECT_COUNT", ()),
    ]
    missing = set(g.OPS_BY_NAME) - {name for name, _ in steps} - {"HELLO", "THREADS"}
    assert not missing, f"no worst request for {sorted(missing)}"
    for name, args in steps:
        yield name, args() if callable(args) else args


def worst_hello(robot_id: int = 1, token: str = "") -> tuple:
    """HELLO with the robot chosen by number and the longest program name a frame carries."""
    selector = str(robot_id)
    return (g.VERSION, selector, "p" * (LARGEST - 4 - 4 - len(selector) - 4 - 4 - len(token)), U32_MAX, token)
