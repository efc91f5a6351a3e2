"""`eyesim grade SPEC SUBMISSIONS/`: grade every submission against a grading spec (docs/grading.md)."""

from __future__ import annotations

import sys
from pathlib import Path


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "grade",
        help="grade student submissions against a grading spec",
        description="Build and run every submission x case of a grading spec in isolation and write "
        "report.json, junit.xml and index.html (docs/grading.md).",
    )
    parser.add_argument("spec", help="grading spec (TOML)")
    parser.add_argument("submissions", nargs="?", help="folder with one directory per submission")
    parser.add_argument(
        "--submission",
        action="append",
        default=[],
        metavar="DIR",
        help="grade this directory as one submission (repeatable)",
    )
    parser.add_argument("--out", "-o", metavar="DIR", help="output directory (default: grading-<spec name>)")
    parser.add_argument("--workers", type=int, metavar="N", help="local case processes at once (default: one per core)")
    parser.add_argument(
        "--cluster",
        metavar="ADDRESS",
        help="run the cases on a Dask cluster: a scheduler address (tcp://host:8786) or local:N",
    )
    parser.add_argument(
        "--case", action="append", default=[], metavar="NAME", help="grade only this case of the spec (repeatable)"
    )
    parser.add_argument("--fresh", action="store_true", help="grade everything again, ignoring stored results")
    parser.add_argument(
        "--require-isolation",
        action="store_true",
        help="refuse to grade where cases cannot be sandboxed (Linux without bubblewrap, macOS, "
        "Windows), also for a local Dask cluster (local:N); on a remote cluster, each worker refuses "
        "cases it cannot sandbox",
    )
    parser.add_argument(
        "--keep-recordings",
        choices=("failed", "all", "none"),
        default="failed",
        help="keep each case's MCAP recording beside its result, to watch with eyesim replay: "
        "of the cases that did not score full marks (default), of all, or of none",
    )
    parser.add_argument(
        "--serve",
        action="store_true",
        help="then serve the report with its cases' replays in the browser (until Ctrl-C)",
    )
    parser.add_argument(
        "--viewer-port", type=int, default=8080, help="port for --serve (default 8080; 0 = any free port)"
    )
    parser.add_argument(
        "--require-pass",
        action="store_true",
        help="exit with status 1 unless every check of every case passed (regression tests)",
    )
    parser.set_defaults(func=main)


def main(args) -> int:
    from eyesim.grade.grader import Interrupted, grade
    from eyesim.grade.spec import SpecError, load_spec
    from eyesim.grade.submissions import SubmissionError, find_submissions, read_submission

    try:
        spec = load_spec(args.spec)
    except SpecError as error:
        for problem in error.problems:
            print(problem, file=sys.stderr)
        print(f"eyesim grade: {len(error.problems)} problem(s) in the grading spec", file=sys.stderr)
        return 2
    if args.case:
        unknown = [name for name in args.case if name not in {c.name for c in spec.cases}]
        if unknown:
            return _usage(
                f"no case {', '.join(map(repr, unknown))} in {args.spec} "
                f"(cases: {', '.join(c.name for c in spec.cases)})"
            )
        spec.cases = [c for c in spec.cases if c.name in args.case]
    if args.workers is not None and args.workers < 1:
        return _usage("--workers must be at least 1")
    if args.workers is not None and args.cluster:
        return _usage("--workers is for the local pool; a cluster has its own workers")
    try:
        folders = [Path(p) for p in args.submission]
        if args.submissions:
            folders += find_submissions(Path(args.submissions))
        if not folders:
            return _usage("name a folder of submissions or --submission DIR")
        submissions = [read_submission(folder) for folder in folders]
    except SubmissionError as error:
        return _usage(str(error))
    names = [s.name for s in submissions]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        return _usage(f"two submissions are named {', '.join(duplicates)}")
    out = Path(args.out or f"grading-{Path(args.spec).stem}")
    if not args.cluster or args.cluster.startswith("local:"):  # the cases run on this machine
        from eyesim.grade.sandbox import why_not_isolated

        unisolated = why_not_isolated()
        if unisolated and args.require_isolation:
            return _usage(f"--require-isolation: {unisolated}")
        if unisolated:
            print(f"eyesim grade: warning: {unisolated}", file=sys.stderr)
    try:
        executor = _executor(args)
    except Exception as error:  # ExecutorError, and whatever a Dask address can raise
        return _usage(str(error))
    try:
        run = grade(
            spec,
            submissions,
            out,
            executor,
            resume=not args.fresh,
            require_isolation=args.require_isolation,
            keep_recordings=args.keep_recordings,
        )
    except Interrupted as error:
        print(f"\neyesim grade: {error}", file=sys.stderr)
        return 130
    summary = run.summary
    width = max(len(s["name"]) for s in summary["students"])
    for student in summary["students"]:
        print(
            f"{student['name']:<{width}}  {student['score']:6.1f}  ({student['passed_checks']}/{student['checks']} checks)"
        )
    print(
        f"eyesim grade: {run.ran} case(s) graded, {run.reused} reused; report: {out / 'index.html'}, "
        f"{out / 'report.json'}, {out / 'junit.xml'}"
    )
    if args.serve:
        from eyesim.web.replay_server import serve_until_interrupted

        serve_until_interrupted(str(out), "127.0.0.1", args.viewer_port, False, report=out)
    if args.require_pass:
        failed = [
            (s["name"], c["case"], check)
            for s in summary["students"]
            for c in s["cases"]
            for check in c["checks"]
            if not check["passed"]
        ]
        for student, case, check in failed:
            print(f"FAILED {student}/{case}: {check['name']}: {check['message']}", file=sys.stderr)
        if failed:
            return 1
    return 0


def _executor(args):
    from eyesim.grade.executors import DaskCluster, LocalPool

    if args.cluster:
        return DaskCluster(args.cluster)
    return LocalPool(args.workers)


def _usage(message: str) -> int:
    print(f"eyesim grade: {message}", file=sys.stderr)
    return 2
