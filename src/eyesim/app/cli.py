"""The `eyesim` command: one subcommand per job, each registered by the module that owns it."""

from __future__ import annotations

import argparse
import importlib
import sys

# Modules that add subcommands; each has `register(subparsers)` setting `func` on its parser.
SUBCOMMAND_MODULES = (
    "eyesim.app.run",
    "eyesim.programs.toolchain",
    "eyesim.scene.cli",
    "eyesim.app.record_cli",
    "eyesim.grade.cli",
    "eyesim.app.examples",
)


def build_parser() -> argparse.ArgumentParser:
    from eyesim import __version__

    parser = argparse.ArgumentParser(prog="eyesim", description="EyeSim robot simulator")
    parser.add_argument("--version", action="version", version=f"eyesim {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in SUBCOMMAND_MODULES:
        importlib.import_module(name).register(subparsers)
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    for stream in (sys.stdout, sys.stderr):
        # Programs print what they like; a Windows console or pipe in its ANSI code page must not
        # make a character it lacks end the run (UnicodeEncodeError).
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="replace")
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return int(args.func(args) or 0)
    except KeyboardInterrupt:  # Ctrl-C: the shell's status for SIGINT, as other tools give
        print("\neyesim: interrupted", file=sys.stderr)
        return INTERRUPTED


INTERRUPTED = 130


if __name__ == "__main__":
    sys.exit(main())
