"""`eyesim export`, `eyesim plot`, `eyesim render`, `eyesim replay`: what to do with a recording."""

from __future__ import annotations

import sys

from eyesim.record.recording import Recording, RecordingError


def register(subparsers) -> None:
    export = subparsers.add_parser("export", help="write a recording's trajectories as CSV",
                                   description="Write the trajectory CSV of `eyesim run --record x.csv` from an "
                                               ".mcap recording.")
    export.add_argument("recording", help="an .mcap file made with eyesim run --record")
    export.add_argument("--csv", required=True, metavar="FILE", help="the CSV file to write")
    export.set_defaults(func=export_main)


def open_recording(path: str, command: str) -> Recording | None:
    """The recording, or None after printing why it cannot be read."""
    try:
        return Recording(path)
    except RecordingError as error:
        print(f"eyesim {command}: {error}", file=sys.stderr)
        return None


def export_main(args) -> int:
    from eyesim.record.csv_export import export_csv

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
