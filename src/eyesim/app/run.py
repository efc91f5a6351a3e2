"""`eyesim run`: its options, and the command, which simulate.py carries out.

This module imports only what the options need, so that the `eyesim` command, which registers
every subcommand, does not load the simulator (MuJoCo) for `eyesim export`, `plot` or `--help`."""

from __future__ import annotations

import os

from eyesim.core.clock import DEFAULT_CALL_TIME_US, DETERMINISTIC, REALTIME
from eyesim.protocol import generated as g

DEFAULT_VIEWER_PORT = 8080


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "run",
        help="run the simulator on a scene (default: the bundled arena)",
        description="Run the simulator on a scene file (.sim, .wld, .maz or JSON).",
    )
    parser.add_argument(
        "scene",
        nargs="?",
        help="scene file, or the name of a bundled scene (mako_pool); default: the bundled arena with one S4",
    )
    parser.add_argument("--headless", action="store_true", help="no viewer; print a status line per robot at the end")
    parser.add_argument("--until", type=float, metavar="SECONDS", help="stop at this simulation time")
    parser.add_argument(
        "--wall-limit",
        type=float,
        metavar="SECONDS",
        help="end the run after this many seconds of real time, whatever the programs do",
    )
    parser.add_argument("--host", default=g.DEFAULT_HOST, help=f"address to serve on (default {g.DEFAULT_HOST})")
    parser.add_argument(
        "--port",
        type=int,
        default=int(os.environ.get("EYESIM_PORT", g.DEFAULT_PORT)),
        help=f"port for programs (default {g.DEFAULT_PORT}, or $EYESIM_PORT; 0 = any free port)",
    )
    parser.add_argument(
        "--viewer-port",
        type=int,
        default=DEFAULT_VIEWER_PORT,
        help=f"port for the browser viewer (default {DEFAULT_VIEWER_PORT}; 0 = any free port)",
    )
    parser.add_argument("--speed", default="1", help="realtime speed factor, or 'max' for as fast as possible")
    parser.add_argument(
        "--clock",
        choices=(REALTIME, DETERMINISTIC),
        help="realtime (default with the viewer) or deterministic (default headless)",
    )
    parser.add_argument(
        "--program",
        action="append",
        default=[],
        metavar="ROBOT=PATH",
        help="run PATH for ROBOT (id or name); repeatable; overrides the scene's program",
    )
    _add_scripted_input(parser)
    parser.add_argument(
        "--psd-noise",
        type=float,
        metavar="MM",
        help="standard deviation of Gaussian noise on PSD readings (default: the scene's PSDNOISE, else 0)",
    )
    parser.add_argument(
        "--seed", type=int, help="seed of the simulator's random numbers (default: the scene's SEED, else 0)"
    )
    parser.add_argument(
        "--eyesim6-psd",
        action="store_true",
        help="number PSDs as EyeSim 6 programs do: 1 left, 2 front (as the scene setting EYESIM6PSD)",
    )
    parser.add_argument(
        "--call-time",
        type=float,
        metavar="MS",
        help="ms of simulation time every ordinary RoBIOS call takes (default: the scene's CALLTIME, "
        f"else {DEFAULT_CALL_TIME_US / 1000:g}; 0 = none beyond the protocol's 0.1 ms)",
    )
    parser.add_argument(
        "--record",
        action="append",
        default=[],
        metavar="FILE",
        help="record the run: FILE.mcap (poses, sensors, LCDs, console, ...; docs/recording.md) "
        "or FILE.csv (every robot's true pose every 10 ms); repeatable",
    )
    parser.add_argument(
        "--record-rate",
        type=float,
        default=None,
        metavar="HZ",
        help="pose samples per simulated second in an .mcap recording (default 100)",
    )
    parser.add_argument("--save-lcd", metavar="DIR", help="at the end, save each robot's LCD as DIR/robot<id>-lcd.png")
    parser.add_argument(
        "--scenes",
        action="append",
        default=[],
        metavar="DIR",
        help="another folder whose scene files the viewer's scene browser lists and may save into "
        "(besides the current folder and the bundled examples); repeatable",
    )
    parser.add_argument("--open", action="store_true", help="open the viewer in a web browser")
    parser.add_argument(
        "--no-token",
        action="store_true",
        help="serve the viewer without its access token and let programs connect without the "
        "program token (loopback only; any local user can then use both)",
    )
    parser.add_argument("--verbose", "-v", action="store_true", help="log connections and internal events")
    parser.set_defaults(func=main)


def main(args) -> int:
    from eyesim.app import simulate

    return simulate.main(args)


def _add_scripted_input(parser) -> None:
    """--key, --touch, --irtv, --serial, --digital, ...: read by app/scripted_input.py."""
    parser.add_argument(
        "--key",
        action="append",
        default=[],
        metavar="ROBOT:KEY@SECONDS",
        help="press a soft key at a simulation time, e.g. 1:KEY1@2.5; repeatable",
    )
    parser.add_argument(
        "--touch",
        action="append",
        default=[],
        metavar="ROBOT:X,Y@SECONDS",
        help="touch the LCD at pixel X,Y at a simulation time, e.g. 1:100,50@2; repeatable",
    )
    parser.add_argument(
        "--irtv",
        action="append",
        default=[],
        metavar="ROBOT:BUTTON@SECONDS",
        help="press an IR remote button (0-9, RED, GREEN, YELLOW, BLUE, LEFT, RIGHT, UP, DOWN, "
        "OK, POWER) at a simulation time, e.g. 1:OK@1.5; repeatable",
    )
    parser.add_argument(
        "--serial",
        action="append",
        default=[],
        metavar="ROBOT:INTERFACE:TEXT@SECONDS",
        help="bytes arriving on a serial interface at a simulation time; TEXT may use \\n, \\r, "
        "\\xNN; e.g. '1:0:hello\\n@2'; repeatable",
    )
    parser.add_argument(
        "--serial-loopback",
        action="append",
        default=[],
        metavar="ROBOT:INTERFACE",
        help="plug a loopback into a serial interface: what the robot sends comes back",
    )
    parser.add_argument(
        "--digital",
        action="append",
        default=[],
        metavar="ROBOT:LINE=LEVEL@SECONDS",
        help="drive digital input line 1..16 to 0 or 1 (- lets go) at a simulation time; repeatable",
    )
    parser.add_argument(
        "--analog",
        action="append",
        default=[],
        metavar="ROBOT:CHANNEL=VALUE@SECONDS",
        help="set analog channel 1..8 to 0..1023 at a simulation time; repeatable",
    )
