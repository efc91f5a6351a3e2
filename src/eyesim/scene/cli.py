"""The `eyesim check`, `eyesim convert` and `eyesim schema` subcommands."""

from __future__ import annotations

import sys
from pathlib import Path

from eyesim.scene import builtins, summary
from eyesim.scene.convert import convert, default_output
from eyesim.scene.description import Diagnostic, Location
from eyesim.scene.diagnostics import Diagnostics, SceneError, sorted_diagnostics
from eyesim.scene.json_format import KINDS, export_schemas, schema_text
from eyesim.scene.loader import kind_of, load_scene, read_definition, read_document

SCHEMA_ALIASES = {"sim": "scene", "wld": "world", "maz": "maze", "robi": "robot", "esobj": "object"}


def register(subparsers) -> None:
    check = subparsers.add_parser("check", help="validate scene, world, robot and object files and summarise them")
    check.add_argument("files", nargs="+", metavar="FILE")
    check.set_defaults(func=run_check)
    conv = subparsers.add_parser("convert", help="convert a scene file to JSON, or JSON back to its text format")
    conv.add_argument("file", metavar="FILE")
    conv.add_argument("-o", "--output", metavar="OUT", help="output file ('-' or none: print it)")
    conv.set_defaults(func=run_convert)
    sch = subparsers.add_parser(
        "schema", help="print the JSON Schema of a file kind, or write them all: 'eyesim schema export DIR'"
    )
    sch.add_argument(
        "kind", metavar="KIND", help="scene, world, maze, robot or object (or sim, wld, maz, robi, esObj), or export"
    )
    sch.add_argument("dir", metavar="DIR", nargs="?", help="export: the folder to write <kind>.schema.json to")
    sch.set_defaults(func=run_schema)


def run_check(args) -> int:
    failed = False
    for name in args.files:
        try:
            ok, lines, diagnostics = check_file(builtins.scene_argument(name))
        except Exception as e:  # a bug of ours must not show a traceback to a student
            ok, lines, diagnostics = False, [], [_internal(name, e)]
        failed |= not ok
        warnings = sum(d.kind == "warning" for d in diagnostics)
        errors = sum(d.kind == "error" for d in diagnostics)
        status = "ok" if ok else f"{errors} error{'s' if errors != 1 else ''}"
        if warnings:
            status += f", {warnings} warning{'s' if warnings != 1 else ''}"
        print(f"{name}: {status}")
        for line in lines:
            print("  " + line)
        for d in sorted_diagnostics(diagnostics):
            print("  " + str(d))
    return 1 if failed else 0


def check_file(path: Path) -> tuple[bool, list[str], list[Diagnostic]]:
    """(ok, summary lines, diagnostics) of one file of any kind."""
    kind = kind_of(path)
    if kind == "json":
        probe = Diagnostics()
        kind, _ = read_document(path, probe)
        if kind is None:
            return False, [], probe.items
    if kind in ("robot", "object"):
        diagnostics = Diagnostics()
        definition = read_definition(path, kind, diagnostics)
        if definition is None:
            return False, [], diagnostics.items
        lines = summary.robot_lines(definition) if kind == "robot" else summary.object_lines(definition)
        return True, lines, diagnostics.items
    try:
        scene = load_scene(path)
    except SceneError as e:
        return False, [], e.diagnostics
    return True, summary.scene_lines(scene), list(scene.warnings)


def run_convert(args) -> int:
    diagnostics = Diagnostics()
    try:
        result = convert(args.file, diagnostics)
    except Exception as e:
        diagnostics.items.append(_internal(args.file, e))
        result = None
    for d in sorted_diagnostics(diagnostics.items):
        print(str(d), file=sys.stderr)
    if result is None:
        return 1
    text, suffix = result
    if args.output in (None, "-"):
        sys.stdout.write(text)
    else:
        out = Path(args.output)
        if out.is_dir():
            out = out / default_output(args.file, suffix).name
        out.write_text(text, encoding="utf-8")
        print(f"wrote {out}", file=sys.stderr)
    return 0


def run_schema(args) -> int:
    if args.kind == "export":
        if args.dir is None:
            print("eyesim schema export: expected the folder to write the schemas to", file=sys.stderr)
            return 2
        try:
            for path in export_schemas(Path(args.dir)):
                print(path)
        except OSError as e:
            print(f"eyesim schema export: cannot write {e.filename}: {e.strerror}", file=sys.stderr)
            return 1
        return 0
    kind = SCHEMA_ALIASES.get(args.kind.lower(), args.kind.lower())
    if kind not in KINDS:
        print(
            f"eyesim schema: unknown kind {args.kind!r}: expected one of {', '.join(KINDS)} (or export DIR)",
            file=sys.stderr,
        )
        return 2
    if args.dir is not None:
        print(f"eyesim schema: unexpected argument {args.dir!r} (only 'export' takes a folder)", file=sys.stderr)
        return 2
    sys.stdout.write(schema_text(kind))
    return 0


def _internal(name: str, error: Exception) -> Diagnostic:
    return Diagnostic(
        "error",
        Location(str(name)),
        f"internal error while reading this file ({type(error).__name__}: {error}); please report it",
        "internal",
    )
