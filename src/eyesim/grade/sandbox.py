"""A sandbox for each graded case (Linux, bubblewrap): the case process (compiler, simulator and the
student's programs) runs in namespaces of its own, so that a submission cannot read, plant or
forge anything outside its case.

- PID, IPC, UTS, network (only a loopback of its own) and mount namespaces: a private /proc shows
  only the case's processes; when the case process ends, the namespace and everything left in it
  (a setsid() child included) die with it.
- The file system is read-only: the system's /usr, /etc and libraries, and the Pythons EyeSim
  runs on. The one writable place is the case's own work folder, which holds its copy of the
  submission. The submissions folder, the grader's outputs and home folders are not there at all.
- No capabilities. Run as root, the grader gives each case an unprivileged user of its own (the
  case process becomes it first thing, case_run.become_case_user), so that RLIMIT_NPROC counts
  the case's processes and nothing else; run as anyone else, the case stays that user in a user
  namespace of its own.

Without bwrap (macOS, Windows, a Linux without it) cases run unisolated: `eyesim grade` says so,
and `--require-isolation` refuses to grade."""

from __future__ import annotations

import itertools
import os
import shutil
import sys
import threading
from pathlib import Path

# Read-only system folders a case needs (those that exist): the C compiler, libraries, fonts, ld.so's cache.
SYSTEM_FOLDERS = ("/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32", "/etc")
FIRST_CASE_UID = 200_000  # unprivileged users for cases when the grader is root (no such accounts needed)
CASE_UIDS = 50_000
CASE_UID_VARIABLE = "EYESIM_CASE_UID"

_uids = itertools.count()
_uids_lock = threading.Lock()


def bwrap() -> str | None:
    return shutil.which("bwrap") if sys.platform.startswith("linux") else None


def why_not_isolated() -> str | None:
    """None when cases can be sandboxed here; else why not and what to do instead."""
    if not sys.platform.startswith("linux"):
        return ("cases are not isolated from each other on this system: a submission can read and change "
                "files of other submissions and of the grader. Grade on Linux with bubblewrap "
                "(apt install bubblewrap), or in a Linux container or virtual machine")
    if bwrap() is None:
        return ("cases are not isolated from each other: bubblewrap is not installed "
                "(apt install bubblewrap / dnf install bubblewrap)")
    return None


def case_uid() -> int | None:
    """A user id for one case's sandbox when the grader runs as root, else None (the sandbox then
    runs as the grader's user, in a user namespace)."""
    if os.geteuid() != 0:
        return None
    with _uids_lock:
        return FIRST_CASE_UID + (os.getpid() * 64 + next(_uids)) % CASE_UIDS


def readable_folders() -> list[Path]:
    """What the case process needs to read besides the system: the Python environment EyeSim runs
    in and the Python it was made from, and the RoBIOS library if it lives elsewhere."""
    from eyesim import paths

    folders = {Path(sys.prefix).resolve(), Path(sys.base_prefix).resolve(), paths.robios_dir().resolve(),
               paths.PACKAGE_DIR.resolve()}
    return sorted(folder for folder in folders if not any(folder.is_relative_to(Path(s)) for s in SYSTEM_FOLDERS))


def command(inner: list[str], work: Path, uid: int | None) -> list[str]:
    """`inner` run in a sandbox whose only writable folder is `work` (also its home and TMPDIR). With
    `uid` (the grader is root) the sandbox keeps root's user namespace, so that `inner` can become
    that user; without, it gets a user namespace of its own and no capabilities."""
    if uid is None:
        unshare = ["--unshare-all", "--cap-drop", "ALL"]
    else:
        unshare = ["--unshare-pid", "--unshare-ipc", "--unshare-net", "--unshare-uts", "--unshare-cgroup-try",
                   "--setenv", CASE_UID_VARIABLE, str(uid)]
    # Empty /run and /tmp first: what is bound below them afterwards (a Python environment or the
    # work folder under /tmp, as in a CI checkout made with mktemp) stays visible.
    args = [bwrap(), *unshare, "--die-with-parent", "--new-session", "--proc", "/proc", "--dev", "/dev",
            "--tmpfs", "/run", "--tmpfs", "/tmp"]
    for folder in SYSTEM_FOLDERS:
        args += ["--ro-bind-try", folder, folder]
    for folder in readable_folders():
        # bwrap makes missing parent folders private (0700); the case's user must pass through them
        for parent in reversed(folder.parents[:-1]):
            args += ["--perms", "0755", "--dir", str(parent)]
        args += ["--ro-bind", str(folder), str(folder)]
    args += ["--bind", str(work), str(work), "--chdir", str(work),
             "--setenv", "HOME", str(work), "--setenv", "TMPDIR", str(work),
             "--setenv", "MPLCONFIGDIR", str(work / ".matplotlib"), "--"]
    return args + inner


def become_case_user() -> None:
    """In the case process, first thing: become the case's own user when the sandbox says which
    (root's capabilities go with root)."""
    uid = os.environ.pop(CASE_UID_VARIABLE, None)
    if uid is not None and os.geteuid() == 0:
        os.setgroups([])
        os.setgid(int(uid))
        os.setuid(int(uid))
