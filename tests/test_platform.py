"""eyesim.platform: each system's branch, including those of systems this machine is not (their
pure parts: names, environments, exit reasons), and the POSIX process handling for real."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from eyesim import platform


@pytest.mark.parametrize(
    "code,words",
    [
        (0xC0000005, "crashed: access violation (0xC0000005)"),
        (-1073741819, "crashed: access violation (0xC0000005)"),  # the same status read as a signed int
        (0xC00000FD, "crashed: stack overflow (0xC00000FD)"),
        (0xC0000094, "crashed: integer division by zero (0xC0000094)"),
        (1816, "was ended: its CPU time limit"),
        (0xC000013A, "was ended: Ctrl-C (0xC000013A)"),
    ],
)
def test_windows_exit_codes_in_words(monkeypatch, code, words):
    monkeypatch.setattr(platform, "WINDOWS", True)
    assert platform.exit_reason(code) == words
    assert platform.crashed(code)


def test_ordinary_windows_exits_are_not_crashes(monkeypatch):
    monkeypatch.setattr(platform, "WINDOWS", True)
    for code in (0, 1, 3, 255):
        assert platform.exit_reason(code) is None
    assert platform.over_limit(1816) and not platform.over_limit(0xC0000005)


def test_posix_signals_in_words():
    assert platform.exit_reason(-signal.SIGSEGV) == "crashed: segmentation fault (SIGSEGV)"
    assert platform.exit_reason(-signal.SIGXCPU) == "was ended: its CPU time limit (SIGXCPU)"
    assert platform.exit_reason(-signal.SIGTERM).startswith("was ended: ")
    assert platform.exit_reason(0) is None and platform.exit_reason(3) is None and platform.exit_reason(None) is None
    assert platform.over_limit(-signal.SIGXCPU) and platform.over_limit(-signal.SIGKILL)
    assert not platform.over_limit(-signal.SIGSEGV)


@pytest.mark.parametrize("system,variable", [("windows", "PATH"), ("macos", None), ("linux", "LD_LIBRARY_PATH")])
def test_where_each_system_looks_for_the_library(monkeypatch, tmp_path, system, variable):
    monkeypatch.setattr(platform, "WINDOWS", system == "windows")
    monkeypatch.setattr(platform, "MACOS", system == "macos")
    env = platform.library_environment({"PATH": "/bin", "LD_LIBRARY_PATH": "/x"}, tmp_path)
    if variable is None:  # macOS: the rpath of `eyesim cc` and eye's full path; nothing to add
        assert env == {"PATH": "/bin", "LD_LIBRARY_PATH": "/x"}
    else:
        assert env[variable].split(os.pathsep)[0] == str(tmp_path)


def test_limits_are_false_when_empty():
    assert not platform.Limits() and platform.Limits(cpu_seconds=1) and platform.Limits(memory_bytes=1 << 20)


def test_a_group_is_ended_with_everything_in_it(tmp_path):
    """A program of its own group that started a child: kill_tree ends both."""
    marker = tmp_path / "child.pid"
    script = (
        "import subprocess, sys, time\n"
        f"child = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(600)'])\n"
        f"open({str(marker)!r}, 'w').write(str(child.pid))\n"
        "time.sleep(600)\n"
    )
    process = platform.start([sys.executable, "-c", script], own_group=True)
    deadline = time.monotonic() + 30
    while not (marker.exists() and marker.read_text()) and time.monotonic() < deadline:
        time.sleep(0.05)
    child = int(marker.read_text())
    platform.kill_tree(process, own_group=True)
    assert process.wait(timeout=10) == -signal.SIGKILL
    deadline = time.monotonic() + 10
    while Path(f"/proc/{child}").exists() and _state(child) != "Z" and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not Path(f"/proc/{child}").exists() or _state(child) == "Z"


def _state(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return "gone"


def test_cpu_limits_end_a_spinning_program():
    process = platform.start([sys.executable, "-c", "while True: pass"], limits=platform.Limits(cpu_seconds=1))
    code = process.wait(timeout=30)
    assert platform.over_limit(code)
    assert platform.exit_reason(code).startswith("was ended")


def test_output_is_read_without_blocking(tmp_path):
    process = subprocess.Popen(
        [sys.executable, "-c", "print('hello', flush=True); import time; time.sleep(2)"], stdout=subprocess.PIPE
    )
    source = platform.readable(process.stdout)
    received = b""
    deadline = time.monotonic() + 10
    while not received.endswith(b"\n") and time.monotonic() < deadline:
        received += platform.read_available(source, 100) or b""
    assert received == b"hello\n"
    assert platform.read_available(source, 100) is None  # nothing more yet, and no wait
    process.kill()
    process.wait()


FRAGMENTED_HEAP = """
import sys
from eyesim import platform

def resident_mb():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096 / 2**20

blocks = [bytearray(64 * 1024) for _ in range(3000)]  # about 190 MB from the heap (not mmap)
kept = blocks[::16]  # a block in use every 1 MB keeps the heap from shrinking by itself
del blocks
before = resident_mb()
trimmed = platform.return_free_memory()
print(trimmed, round(before - resident_mb()))
"""


def test_free_heap_memory_goes_back_to_the_system():
    """The pages freed blocks leave between blocks in use go back when asked (glibc's malloc_trim;
    Linux here, where CI runs: the call exists in glibc only)."""
    done = subprocess.run([sys.executable, "-c", FRAGMENTED_HEAP], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    trimmed, released_mb = done.stdout.split()
    assert trimmed == "True" and int(released_mb) > 100
