"""One submission x one case, in a process of its own (isolation.py starts it): build the
submission's programs, simulate the case, judge its checks, and collect the evidence.

Everything in the result except `timing` depends only on the spec and the submission, never on
the machine or the wall clock, so a case graded anywhere gives the same result (docs/grading.md).

    python -m eyesim.grade.case_run CASE_FOLDER < TASK.pickle > RESULT.json
"""

from __future__ import annotations

import base64
import contextlib
import io
import json
import os
import pickle
import shutil
import subprocess
import sys
import time
import traceback
from pathlib import Path

PATH_PERIOD = 0.1  # s between the path points kept for the report's plot
TAIL = 4000  # characters of a program's output kept in the result
COMPILE_TIMEOUT = 120  # s
# The compiler's limits: `#include "/dev/zero"` makes cc1 ask for gigabytes, a generated source for hours.
COMPILE_LIMITS = dict(cpu_seconds=60, memory_bytes=2 << 30, file_bytes=256 << 20)
FILE_BYTES = 64 << 20  # the largest file a graded program may write
# A case is recorded while it is graded, at rates that keep that cheap: `eyesim run --record`'s
# 100 Hz poses and 30 Hz LCD images cost 4-6 times the simulation (PNG-encoding a changing LCD),
# these about as much as the simulation (the viewer interpolates between poses). That is less than
# running the failed cases again to record them once about half of the cases fail.
RECORDING_POSE_RATE = 25.0  # Hz of simulated time
RECORDING_LCD_RATE = 5.0  # at most, per robot


def _tail(text: str) -> str:
    return text if len(text) <= TAIL else "..." + text[-TAIL:]


def build(
    program, submission_files: dict[str, bytes], directory: Path, task_processes: int | None = None
) -> tuple[Path | None, dict]:
    """Build one of the spec's programs from the submission's files in `directory`, the compiler
    under COMPILE_LIMITS (and `task_processes`); returns (executable or None, build record)."""
    from eyesim.programs import toolchain

    sources: list[str] = []
    missing = []
    for pattern in program.sources:
        found = [n for n in _matching(submission_files, pattern) if n not in sources]
        if not found:
            missing.append(pattern)
        sources += found
    if missing:
        listed = ", ".join(sorted(submission_files)) or "none"
        return None, {
            "ok": False,
            "status": "missing_sources",
            "output": f"no file matching {', '.join(map(repr, missing))} in the submission (its files: {listed})",
        }
    if program.language == "python":
        return directory / sources[0], {"ok": True, "status": "ok", "output": ""}
    output = toolchain.executable_name(directory.parent / "build" / program.name)
    output.parent.mkdir(exist_ok=True)
    language = "c++" if program.language == "c++" else "cc"
    try:
        # Relative paths, run in the submission's copy: messages name the student's files, not
        # a temporary directory, so they are the same wherever the case runs.
        args = [*program.flags, *map(toolchain.source_argument, sources), "-o", str(output)]
        command = toolchain.compiler_command(language, args)
        result = _run_limited(command, directory, task_processes)
    except (toolchain.LibraryMissing, toolchain.CompilerMissing) as error:
        return None, {"ok": False, "status": "grader_error", "output": str(error)}
    except FileNotFoundError:
        return None, {"ok": False, "status": "grader_error", "output": "the C compiler is not installed on this worker"}
    except subprocess.TimeoutExpired:
        return None, {"ok": False, "status": "compile_error", "output": f"compiling took over {COMPILE_TIMEOUT} s"}
    text = _tail((result.stdout + result.stderr).replace(str(output.parent), "build"))
    if result.returncode != 0:
        return None, {"ok": False, "status": "compile_error", "output": text}
    toolchain.place_library(args, cwd=directory)
    return output, {"ok": True, "status": "ok", "output": text}


def _run_limited(command: list[str], cwd: Path, processes: int | None) -> subprocess.CompletedProcess:
    from eyesim import platform

    process = platform.start(
        command,
        own_group=True,
        limits=platform.Limits(**COMPILE_LIMITS, processes=processes),
        cwd=cwd,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        errors="replace",
    )
    try:
        stdout, stderr = process.communicate(timeout=COMPILE_TIMEOUT)
    finally:
        platform.kill_tree(process, own_group=True)
        process.wait()
    return subprocess.CompletedProcess(command, process.returncode, stdout, stderr)


def _matching(files: dict[str, bytes], pattern: str) -> list[str]:
    from eyesim.grade.submissions import Submission

    return Submission("", Path(), files, "").matching(pattern)


def _schedule_inputs(sim, inputs: list[dict]) -> None:
    for entry in inputs:
        robot, at = entry["robot"], entry["at"]
        if "key" in entry:
            sim.key(robot, entry["key"], at=at)
        elif "touch" in entry:
            sim.touch(robot, *entry["touch"], at=at)
        elif "irtv" in entry:
            sim.irtv(robot, entry["irtv"], at=at)
        elif "serial" in entry:
            sim.serial(robot, entry.get("interface", 0), entry["serial"].encode("latin-1"), at=at)
        elif "digital" in entry:
            level = entry["digital"]["level"]
            sim.digital(robot, entry["digital"]["line"], None if level == "-" else level, at=at)
        elif "analog" in entry:
            sim.analog(robot, entry["analog"]["channel"], entry["analog"]["value"], at=at)


def _png(pixels) -> bytes:
    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, format="PNG")
    return buffer.getvalue()


def _not_run(case, reason: str) -> list[dict]:
    from eyesim.grade.checks import describe

    return [
        {
            "name": describe(c),
            "kind": c["kind"],
            "weight": c.get("weight", 1.0),
            "passed": False,
            "score": 0.0,
            "message": f"not run: {reason}",
            "evidence": {},
        }
        for c in case.checks
    ]


def _status(end, runs) -> str:
    """ok; timeout (the wall-clock watchdog ended it); cpu_limit or crashed (a program was
    killed by its CPU limit or by a crash of its own making)."""
    from eyesim import platform

    if end.reason == "watchdog":
        return "timeout"
    ended = [run.exit_code for run in runs if run.crash is not None]
    if any(platform.over_limit(code) for code in ended):
        return "cpu_limit"
    return "crashed" if ended else "ok"


def score_of(checks: list[dict]) -> float:
    total = sum(c["weight"] for c in checks)
    return sum(c["weight"] * c["score"] for c in checks) / total if total else 0.0


def run_case(task: dict, directory: Path) -> dict:
    """The case's result (a dict of plain data, `artifacts` holding file contents)."""
    from eyesim.core.stalls import hung_status
    from eyesim.grade.checks import judge
    from eyesim.paths import CASE_RECORDING as RECORDING
    from eyesim.testing.assertions import describe_exit

    case, programs = task["case"], task["programs"]
    result = {
        "student": task["student"],
        "case": case.name,
        "weight": case.weight,
        "key": task["key"],
        "status": "ok",
        "build": {},
        "programs": {},
        "robots": {},
        "contacts": [],
        "artifacts": {},
    }
    work = directory / "work"
    work.mkdir(parents=True)
    for name, data in task["submission_files"].items():
        target = work / name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
    executables = {}
    for entry in case.robots:
        name = entry["program"]
        if name not in result["build"]:
            executables[name], result["build"][name] = build(
                programs[name], task["submission_files"], work, task.get("processes")
            )
    failed = [name for name, record in result["build"].items() if not record["ok"]]
    if failed:
        record = result["build"][failed[0]]
        result["status"] = record["status"]
        result["checks"] = _not_run(
            case,
            f"program {failed[0]!r} "
            + {
                "missing_sources": "has no source files",
                "compile_error": "does not compile",
                "grader_error": "could not be built",
            }[record["status"]],
        )
        result["score"] = 0.0
        return result

    keep = task.get("keep_recording", "failed")
    with _simulated(case, executables, work, task, directory / RECORDING if keep != "none" else None) as (sim, end):
        result["end"] = {"reason": end.reason, "time": round(end.time, 6)}
        result["status"] = _status(end, [robot.program for robot in sim.robots if robot.program is not None])
        if end.reason == "watchdog" and end.stalled:
            # why the watchdog had to end it, in the teacher's words: "waiting for a key", "hung: ...";
            # only then, as any other run's result must not depend on the wall clock
            result["hung"] = hung_status(list(end.stalled))
            result["end"]["stalled"] = list(end.stalled)
        context = {"workdir": work, "python_checks": task["python_checks"], "python_modules": {}}
        result["checks"] = [judge(sim, check, context) for check in case.checks]
        result["score"] = score_of(result["checks"])
        for robot in sim.robots:
            run = robot.program
            if run is not None:
                result["programs"][str(robot.id)] = {
                    "name": next(e["program"] for e in case.robots if e["robot"] == robot.id),
                    "status": describe_exit(run),
                    "exit_code": robot.exit_code,
                    "stopped": run.stopped_by_us,
                    "crashed": run.crash is not None,
                    "stdout": _tail(robot.stdout),
                    "stderr": _tail(robot.stderr),
                }
            pose = robot.pose
            step = max(1, round(PATH_PERIOD / 0.01))
            result["robots"][str(robot.id)] = {
                "name": robot.name,
                "final": {"x": round(pose.x, 1), "y": round(pose.y, 1), "phi": round(pose.phi, 1)},
                "path": [[round(p.t, 3), round(p.x, 1), round(p.y, 1)] for p in robot.path[::step]],
                "lcd_text": robot.lcd_text(),
            }
            result["artifacts"][f"robot{robot.id}-lcd.png"] = _png(robot.lcd_image())
        result["contacts"] = [c.as_dict() for c in sim.contacts[:100]]
    failed = result["status"] != "ok" or result["score"] < 1.0
    if (directory / RECORDING).exists() and (keep == "all" or failed):
        result["artifacts"][RECORDING] = (directory / RECORDING).read_bytes()
    return result


@contextlib.contextmanager
def _simulated(case, executables: dict, work: Path, task: dict, recording: Path | None):
    """The case's run, done (and recorded to `recording`): yields (Simulation, RunEnd)."""
    from eyesim.record import Recorder
    from eyesim.testing import Simulation

    with Simulation(case.scene) as sim:
        for entry in case.robots:
            sim.program(
                entry["robot"],
                executables[entry["program"]],
                *entry.get("args", ()),
                stdin=entry.get("stdin"),
                cwd=work,
                env=entry.get("env"),
                cpu_seconds=case.cpu,
                memory_bytes=case.memory_mb << 20,
                processes=task.get("processes"),
                file_bytes=FILE_BYTES,
            )
        _schedule_inputs(sim, case.inputs)
        recorder = (
            Recorder(sim.engine, recording, pose_rate=RECORDING_POSE_RATE, lcd_rate=RECORDING_LCD_RATE)
            if recording is not None
            else None
        )
        end = sim.run(until=case.time, end_with_programs=case.end_with_programs, wall_timeout=case.wall_clock)
        sim.stop_programs()  # the run is over: what still runs is stopped, its output complete
        if recorder is not None:
            recorder.close()
        yield sim, end


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    answer = os.fdopen(os.dup(1), "w")  # the result goes here; anything else printed goes to stderr
    os.dup2(2, 1)
    from eyesim.grade.sandbox import become_case_user

    become_case_user()
    _not_inspectable()
    task = pickle.load(sys.stdin.buffer)
    started = time.perf_counter()
    directory = Path(argv[0])
    try:
        result = run_case(task, directory)
    except Exception:
        result = {
            "student": task["student"],
            "case": task["case"].name,
            "weight": task["case"].weight,
            "key": task["key"],
            "status": "grader_error",
            "score": 0.0,
            "checks": _not_run(task["case"], "the grader failed on this case"),
            "error": traceback.format_exc(),
            "artifacts": {},
        }
    finally:
        shutil.rmtree(directory, ignore_errors=True)
    result["timing"] = {"case_seconds": round(time.perf_counter() - started, 3)}
    if os.name == "posix":
        result["timing"]["cpu_seconds"] = round(_cpu_seconds(), 3)
    result["artifacts"] = {name: base64.b64encode(data).decode() for name, data in result["artifacts"].items()}
    json.dump(result, answer)
    answer.close()
    return 0


def _cpu_seconds() -> float:
    """CPU time of this process since it started (its imports included) and of the compilers and
    programs it ran (POSIX). The benchmark adds it up: a sandboxed case's time does not reach the
    grader's own resource usage."""
    import resource

    return sum(
        usage.ru_utime + usage.ru_stime
        for usage in (resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN))
    )


def _not_inspectable() -> None:
    """Linux: the student's programs, which run as the same user, cannot open this process's
    /proc files (its memory, the pipe of its answer) once it is not dumpable."""
    if sys.platform.startswith("linux"):
        import ctypes

        PR_SET_DUMPABLE = 4
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_DUMPABLE, 0, 0, 0, 0)


if __name__ == "__main__":
    sys.exit(main())
