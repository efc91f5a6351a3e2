"""`eyesim export`, `eyesim plot`, `eyesim render`, `eyesim replay`: what to do with a recording."""

from __future__ import annotations

import sys
from pathlib import Path


def register(subparsers) -> None:
    export = subparsers.add_parser(
        "export",
        help="write a recording's trajectories as CSV",
        description="Write the trajectory CSV of `eyesim run --record x.csv` from an .mcap recording.",
    )
    export.add_argument("recording", help="an .mcap file made with eyesim run --record")
    export.add_argument("--csv", required=True, metavar="FILE", help="the CSV file to write")
    export.set_defaults(func=export_main)

    replay = subparsers.add_parser(
        "replay",
        help="watch a recording in the browser viewer, with a timeline",
        description="Serve the viewer over a recording: play, pause, scrub, plot.",
    )
    replay.add_argument(
        "recording",
        help="an .mcap file made with eyesim run --record, or the folder of a "
        "grading report (eyesim grade --out), to watch its cases' runs",
    )
    replay.add_argument("--host", default="127.0.0.1", help="address to serve on (default 127.0.0.1)")
    replay.add_argument(
        "--viewer-port", type=int, default=8080, help="port of the viewer (default 8080; 0 = any free port)"
    )
    replay.add_argument("--open", action="store_true", help="open the viewer in a web browser")
    replay.add_argument(
        "--no-token",
        action="store_true",
        help="serve without the access token (loopback only; any local user can then use it)",
    )
    replay.set_defaults(func=replay_main)

    render = subparsers.add_parser(
        "render",
        help="make a video of a recording (top-down view)",
        description="Draw a recording from above, frame by frame, into an MP4 or "
        "WebM video (ffmpeg from imageio-ffmpeg).",
    )
    render.add_argument("recording", help="an .mcap file made with eyesim run --record")
    render.add_argument("-o", "--output", required=True, metavar="VIDEO", help="the video file: .mp4 or .webm")
    render.add_argument("--fps", type=float, default=30, help="frames per second of video (default 30)")
    render.add_argument("--speed", type=float, default=1.0, help="simulated seconds per second of video (default 1)")
    render.add_argument("--size", type=int, default=720, help="pixels on the picture's longer side (default 720)")
    render.add_argument("--start", type=float, metavar="SECONDS", help="first simulation time (default: the start)")
    render.add_argument("--end", type=float, metavar="SECONDS", help="last simulation time (default: the end)")
    render.set_defaults(func=render_main)

    plot = subparsers.add_parser(
        "plot",
        help="draw the robots' paths over the world map",
        description="Draw every robot's path in a recording over the world map.",
    )
    plot.add_argument("recording", help="an .mcap file made with eyesim run --record")
    plot.add_argument("-o", "--output", required=True, metavar="IMAGE", help="the image file: .png, .svg or .pdf")
    plot.set_defaults(func=plot_main)


def open_recording(path: str, command: str):
    """The recording (record.Recording), or None after printing why it cannot be read."""
    from eyesim.record.recording import Recording, RecordingError  # on use: not every command reads one

    try:
        return Recording(path)
    except RecordingError as error:
        print(f"eyesim {command}: {error}", file=sys.stderr)
        return None


def missing_folder(output: str, command: str) -> bool:
    """Says so when the folder an output file goes into does not exist (ffmpeg would only report
    a broken pipe, or an invalid argument on Windows)."""
    folder = Path(output).absolute().parent
    if folder.is_dir():
        return False
    print(f"eyesim {command}: cannot write {output}: the folder {folder} does not exist", file=sys.stderr)
    return True


def export_main(args) -> int:
    from eyesim.record.csv_export import export_csv

    if missing_folder(args.csv, "export"):
        return 2
    recording = open_recording(args.recording, "export")
    if recording is None:
        return 2
    with recording:
        try:
            rows = export_csv(recording, args.csv)
        except OSError as error:
            print(f"eyesim export: cannot write {args.csv}: {error.strerror}", file=sys.stderr)
            return 2
    print(f"eyesim export: {rows} rows to {args.csv}")
    return 0


def replay_main(args) -> int:
    from eyesim.web.replay_server import serve_until_interrupted

    report = Path(args.recording) if Path(args.recording).is_dir() else None
    return serve_until_interrupted(args.recording, args.host, args.viewer_port, args.open, report, not args.no_token)


def render_main(args) -> int:
    from eyesim.record.video import render

    if missing_folder(args.output, "render"):
        return 2
    recording = open_recording(args.recording, "render")
    if recording is None:
        return 2
    with recording:
        try:
            frames = render(
                recording, args.output, fps=args.fps, speed=args.speed, size=args.size, start=args.start, end=args.end
            )
        except ValueError as error:
            print(f"eyesim render: {error}", file=sys.stderr)
            return 2
        except OSError as error:
            print(f"eyesim render: cannot write {args.output}: {error}", file=sys.stderr)
            return 2
    print(f"eyesim render: {frames} frames to {args.output}")
    return 0


def plot_main(args) -> int:
    from eyesim.record.path_plot import plot_paths

    if missing_folder(args.output, "plot"):
        return 2
    recording = open_recording(args.recording, "plot")
    if recording is None:
        return 2
    with recording:
        try:
            plot_paths(recording, args.output)
        except ValueError as error:
            print(f"eyesim plot: {error}", file=sys.stderr)
            return 2
        except OSError as error:
            print(f"eyesim plot: cannot write {args.output}: {error.strerror or error}", file=sys.stderr)
            return 2
    print(f"eyesim plot: paths to {args.output}")
    return 0
