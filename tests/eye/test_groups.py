"""Each RoBIOS group from Python against a running simulator: scripted input goes in at simulation
times, and what the program prints is checked against the simulator's own state (LCD pixels, ...)."""

from __future__ import annotations

import numpy as np
from support.scenes import arena


from eyesim.core import robot_input
from eyesim.robot.components.lcd import Lcd
from eyesim.robot.components.serial_ports import SerialPorts

KEY1, KEY2, KEY3, KEY4 = 1, 2, 4, 8


def screen(run) -> np.ndarray:
    return run.on_sim(lambda sim: sim.robot_by_id(1).component(Lcd).screen().copy())


def assert_ended_cleanly(run, robot: int = 1):
    result = run.results[robot]
    assert result.returncode == 0, result.stdout + result.stderr


LCD = """
    import ctypes
    import numpy as np
    from eye import *

    print("size", *LCDGetSize())
    LCDPixel(10, 20, ORANGE)
    print("pixel", LCDGetPixel(10, 20), LCDGetPixel(11, 20))
    LCDLine(0, 100, 99, 100, RED)
    LCDArea(200, 10, 209, 19, BLUE, 1)
    LCDCircle(300, 50, 10, GREEN, 1)
    print("shapes", LCDGetPixel(50, 100), LCDGetPixel(205, 15), LCDGetPixel(300, 50), LCDGetPixel(300, 65))
    print("pos", LCDSetPos(2, 7), *LCDGetPos())
    row, column = ctypes.c_int(), ctypes.c_int()
    print("pos-eye.py", LCDGetPos(row, column), row.value, column.value)
    print("settings", LCDSetColor(YELLOW, NAVY), LCDSetFont(COURIER, BOLD), LCDSetFontSize(12), LCDSetMode(0),
          LCDMenuI(2, "B", RED, WHITE), LCDRefresh(), LCDSetFontSize(99))

    rng = np.random.default_rng(1)
    colour = rng.integers(0, 256, (120, 160, 3), dtype=np.uint8)
    gray = rng.integers(0, 256, (120, 160), dtype=np.uint8)
    LCDImageSize(QQVGA)
    LCDImageStart(0, 120, 160, 120)
    print("image", LCDImage(colour))
    LCDImageStart(160, 120, 160, 120)
    print("gray", LCDImageGray(gray.tobytes()))
    LCDImageStart(320, 120, 160, 120)
    print("binary", LCDImageBinary([1, 0] * (160 * 60)))   # a list of ints, as eye.py programs built them
    signed = (ctypes.c_byte * (160 * 120))(*([-1] * 80 + [0] * 80) * 120)  # eye.py's c_byte buffers
    LCDImageStart(0, 0, 160, 120)
    print("signed", LCDImageGray(signed))
    LCDImageStart(320, 0, 128, 120)                    # the data size too, as in EyeSim
    print("map", LCDImageBinary(bytes(128 * 120)))
    np.save("colour.npy", colour)
    np.save("gray.npy", gray)
    try:
        LCDImage(gray)
    except ValueError as error:
        print("short", error)
"""


def test_lcd(run_python, tmp_path):
    run = run_python(LCD)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["size"] == ["480", "320"]
    assert out["pixel"] == [str(0xFFA500), "0"]
    assert out["shapes"] == [str(0xFF0000), str(0x0000FF), str(0x00FF00), "0"]
    assert out["pos"] == ["0", "2", "7"]
    assert out["pos-eye.py"] == ["0", "2", "7"]
    assert out["settings"] == ["0"] * 6 + ["1"]
    assert out["image"] == out["gray"] == out["binary"] == out["signed"] == ["0"]
    assert " ".join(out["short"]) == (
        "LCDImage: the image has 19200 bytes, but 46080 are needed (a 128 x 120 image, LCDImageStart/LCDImageSize)"
    )
    shown = screen(run)
    np.testing.assert_array_equal(shown[120:240, 0:160], np.load(tmp_path / "colour.npy"))
    np.testing.assert_array_equal(shown[120:240, 160:320], np.repeat(np.load(tmp_path / "gray.npy")[..., None], 3, 2))
    assert (shown[120:240, 320:480:2] == 0).all() and (shown[120:240, 321:480:2] == 255).all()  # 1 = black
    assert (shown[0:120, 0:80] == 255).all() and (shown[0:120, 80:160] == 0).all()  # -1 is byte 255
    assert out["map"] == ["0"] and (shown[0:120, 320:448] == 255).all() and (shown[0:120, 448:] == 0).all()


KEYS = """
    import ctypes
    from eye import *

    print("read", KEYRead())
    print("wait", KEYWait(KEY3) == KEY3)            # KEY1 comes first and is ignored
    print("any", KEYWait(ANYKEY))
    print("get", KEYGet())
    print("touch", *KEYGetXY())
    print("none", KEYReadXY())
    OSWait(300)                                    # a touch comes meanwhile
    x, y = ctypes.c_int(), ctypes.c_int()
    print("eye.py", KEYReadXY(x, y), x.value, y.value)
"""


def test_keys_and_touches(run_python):
    run = run_python(
        KEYS,
        inputs=[
            (0.1, lambda s: robot_input.key(s, 1, KEY1)),
            (0.2, lambda s: robot_input.key(s, 1, KEY3)),
            (0.3, lambda s: robot_input.key(s, 1, KEY2)),
            (0.4, lambda s: robot_input.key(s, 1, KEY4)),
            (0.5, lambda s: robot_input.touch(s, 1, 123, 45)),
            (0.7, lambda s: robot_input.touch(s, 1, 7, 8)),
        ],
    )
    assert_ended_cleanly(run)
    out = run.output()
    assert out["read"] == ["0"]
    assert out["wait"] == ["True"]
    assert out["any"] == ["2"]
    assert out["get"] == ["8"]
    assert out["touch"] == ["123", "45"]
    assert out["none"] == ["None"]
    assert out["eye.py"] == ["0", "7", "8"]


SYSTEM = """
    import gc
    from eye import *

    print("machine", OSMachineName(), OSMachineID(), OSMachineType() == VEHICLE, OSMachineSpeed() == MACHINE_SPEED)
    print("version", bool(OSVersion()), isinstance(OSVersionIO(), str))
    print("execute", repr(OSExecute("echo hello")))
    ticks = []
    handle = OSAttachTimer(100, lambda: ticks.append(1))   # no reference kept by the program
    gc.collect()

    def fails():
        raise RuntimeError("boom in a timer")

    failing = OSAttachTimer(500, fails)
    start = OSGetCount()
    OSWait(1050)
    print("ticks", handle > 0, len(ticks), OSGetCount() - start)
    print("detach", OSDetachTimer(handle), OSDetachTimer(failing))
    OSWait(500)
    print("after", len(ticks))
    h, m, s, ms = OSGetTime()
    print("time", OSGetCount() - (((h * 60 + m) * 60 + s) * 1000 + ms))  # read again at once
"""


def test_system_time_and_timers(run_python):
    run = run_python(SYSTEM)
    assert_ended_cleanly(run)
    out = run.output()
    name = run.on_sim(lambda sim: sim.robot_by_id(1).name)
    assert out["machine"] == [name, "1", "True", "True"]
    assert out["version"] == ["True", "True"]
    assert out["execute"] == ["'hello\\n'"]
    # reading the clock is local (10 us): the OSGetCount before the wait adds nothing
    assert out["ticks"][0] == "True" and out["ticks"][1] == "10" and int(out["ticks"][2]) == 1050
    assert out["detach"] == ["0", "0"]
    assert out["after"] == ["10"]
    assert out["time"] == ["1"]  # a clock read never shows the same millisecond twice in a row
    assert "RuntimeError: boom in a timer" in run.results[1].stderr  # printed; the program went on


SERIAL = """
    from eye import *

    print("init", SERInit(0, 115200, 0), SERInit(1, 9600, RTSCTS))
    print("send", SERSend(0, "hello \\xe9"), SERSendChar(0, "x"), SERSendChar(0, 0x41))
    print("check", SERCheck(0))
    print("receive", repr(SERReceive(0, 7)))
    print("char", SERReceiveChar(0), SERReceiveChar(0))
    print("empty", repr(SERReceive(0)), SERCheck(0))
    print("outside", repr(SERReceive(1)))
    SERSend(0, "dropped")
    print("flush", SERFlush(0), repr(SERReceive(0)), SERClose(0), SERClose(1))
    try:
        SERSend(0, "\\u20ac")
    except ValueError as error:
        print("euro", error)
"""


def test_serial_loopback_and_scripted_input(run_python):
    def plug_loopback(sim):
        sim.robot_by_id(1).component(SerialPorts).port(0).loopback = True
        robot_input.serial(sim, 1, 1, b"from outside")

    run = run_python(SERIAL, setup=plug_loopback)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["init"] == ["0", "0"]
    assert out["send"] == ["0", "0", "0"]
    assert out["check"] == ["True"]
    assert out["receive"] == ["'hello", "é'"]
    assert out["char"] == ["x", "A"]
    assert out["empty"] == ["''", "False"]
    assert out["outside"] == ["'from", "outside'"]
    assert out["flush"] == ["0", "''", "0", "0"]
    assert "characters above \\xff cannot be sent" in " ".join(out["euro"])


PORTS = """
    from eye import *

    print("out", DIGITALSetup(1, "o"), DIGITALWrite(1, 1), DIGITALRead(1))
    print("in", DIGITALSetup(3, "i"), DIGITALRead(3), DIGITALReadAll() & 0b101)
    print("analog", ANALOGRead(2), ANALOGVoltage() > 0)
    print("record", ANALOGRecord(2, 10))
    samples = ANALOGTransfer()
    print("samples", len(samples), set(int.from_bytes(samples[k:k + 2], "little") for k in range(0, 20, 2)))
"""


def test_digital_and_analog_io(run_python):
    def wire(sim):
        robot_input.digital(sim, 1, 3, 1)
        robot_input.analog(sim, 1, 2, 700)

    run = run_python(PORTS, setup=wire)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["out"] == ["0", "0", "1"]
    assert out["in"] == ["0", "1", "5"]
    assert out["analog"] == ["700", "True"]
    assert out["record"] == ["0"]
    assert out["samples"] == ["20", "{700}"]


IRTV = """
    from eye import *

    print("read", IRTVRead(), IRTVGetStatus())
    print("get", IRTVGet() == IRTV_5, IRTVGet() == IRTV_OK)
    print("flush", IRTVFlush(), IRTVRead())
"""


def test_ir_remote(run_python):
    run = run_python(
        IRTV,
        inputs=[
            (0.2, lambda s: robot_input.irtv(s, 1, ord("5"))),
            (0.3, lambda s: robot_input.irtv(s, 1, ord("O"))),
            (0.3, lambda s: robot_input.irtv(s, 1, ord("9"))),
        ],
    )
    assert_ended_cleanly(run)
    out = run.output()
    assert out["read"][0] == "0" and out["read"][1] in ("0", "1")
    assert out["get"] == ["True", "True"]
    assert out["flush"] == ["0", "0"]


AUDIO = """
    import wave
    from eye import *

    with wave.open("tone.wav", "wb") as sound:   # half a second of silence
        sound.setnchannels(1)
        sound.setsampwidth(2)
        sound.setframerate(8000)
        sound.writeframes(bytes(8000))
    print("beep", AUBeep(), AUDone())
    OSWait(300)
    print("beeped", AUDone())
    print("play", AUPlay("tone.wav"), AUDone())
    OSWait(600)
    print("played", AUDone())
    print("microphone", 0 <= AUMicrophone() <= 1023)
"""


def test_audio(run_python):
    run = run_python(AUDIO)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["beep"] == ["0", "0"]
    assert out["beeped"] == ["1"]
    assert out["play"] == ["0", "0"]
    assert out["played"] == ["1"]
    assert out["microphone"] == ["True"]


RADIO_1 = """
    from eye import *

    print("init", RADIOInit(), RADIOGetID())
    while RADIOStatus()[0] < 2:
        OSWait(10)
    count, ids = RADIOStatus()
    print("status", count, sorted(ids[:count]))
    print("send", RADIOSend(2, "hello robot 2"))
    print("reply", *RADIOReceive())
    print("check", RADIOCheck(), RADIORelease())
"""

RADIO_2 = """
    from eye import *

    RADIOInit()
    sender, message = RADIOReceive()
    RADIOSend(sender, "got: " + message)
"""


def test_radio_between_two_python_programs(run_python):
    run = run_python({1: RADIO_1, 2: RADIO_2}, scene=arena(robots=((500, 500, 0), (1500, 500, 180))))
    assert_ended_cleanly(run, 1)
    assert_ended_cleanly(run, 2)
    out = run.output(1)
    assert out["init"] == ["0", "1"]
    assert out["status"] == ["2", "[1,", "2]"]
    assert out["send"] == ["0"]
    assert out["reply"] == ["2", "got:", "hello", "robot", "2"]
    assert out["check"] == ["0", "0"]


CAMERA = """
    import eye
    from eye import *

    print("before", CAMWIDTH, eye.CAMWIDTH)
    print("init", CAMInit(QQVGA), eye.CAMWIDTH, eye.CAMHEIGHT, eye.CAMPIXELS, eye.CAMSIZE)
    frame = CAMGet()
    gray = CAMGetGray()
    print("frames", len(frame), len(gray), max(frame) > 0)
    print("shown", LCDImage(frame))
    edges = IPLaplace(gray)                 # CAMInit set the IP size
    print("edges", len(edges))
    open("frame.raw", "wb").write(bytes(frame))
"""


def test_camera_frames_reach_the_lcd_and_ip(run_python, tmp_path):
    run = run_python(CAMERA)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["before"] == ["0", "0"]
    assert out["init"] == ["0", "160", "120", "19200", "57600"]
    assert out["frames"] == ["57600", "19200", "True"]
    assert out["shown"] == ["0"]
    assert out["edges"] == ["19200"]
    frame = np.frombuffer((tmp_path / "frame.raw").read_bytes(), np.uint8).reshape(120, 160, 3)
    np.testing.assert_array_equal(screen(run)[0:120, 0:160], frame)


DISTANCES = """
    from eye import *

    scan = LIDARGet()
    print("lidar", len(scan), min(scan) > 0, len(list(scan)))
    print("set", LIDARSet(180, 0, 90), len(LIDARGet()))
    print("psd", PSDGet(PSD_FRONT) > 0, 0 < PSDGetRaw(PSD_FRONT) <= 1023)
"""


def test_distance_sensors(run_python):
    run = run_python(DISTANCES)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["lidar"] == ["360", "True", "360"]
    assert out["set"] == ["0", "90"]
    assert out["psd"] == ["True", "True"]


TOO_LONG = """
    from eye import *

    print("long", LCDPrintf("x" * 65537), SERSend(0, "y" * 65537))
    print("longest", LCDPrintf("x" * 65536))
"""


def test_a_field_longer_than_the_simulator_takes_is_refused_with_its_limit(run_python):
    """protocol.json's lengths, checked by the C library under eye before anything is sent."""
    run = run_python(TOO_LONG)
    assert_ended_cleanly(run)
    out = run.output()
    assert out["long"] == ["1", "1"] and out["longest"] == ["0"]
    assert (
        "eyesim: LCDPrintf: text of 65537 bytes is too large (the simulator takes at most 65536)"
        in run.results[1].stderr
    )
    assert (
        "eyesim: SERSend: data of 65537 bytes is too large (the simulator takes at most 65536)" in run.results[1].stderr
    )
