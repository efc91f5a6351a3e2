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
        return (
            "cases are not isolated from each other on this system: a submission can read and change "
            "files of other submissions and of the grader. Grade on Linux with bubblewrap "
            "(apt install bubblewrap), or in a Linux container or virtual machine"
        )
    if bwrap() is None:
        return (
            "cases are not isolated from each other: bubblewrap is not installed "
            "(apt install bubblewrap / dnf install bubblewrap)"
        )
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

    folders = {
        Path(sys.prefix).resolve(),
        Path(sys.base_prefix).resolve(),
        paths.robios_dir().resolve(),
        paths.PACKAGE_DIR.resolve(),
    }
    return sorted(folder for folder in folders if not any(folder.is_relative_to(Path(s)) for s in SYSTEM_FOLDERS))


ROOT_NAMESPACES = ["--unshare-pid", "--unshare-ipc", "--unshare-net", "--unshare-uts", "--unshare-cgroup-try"]


def command(inner: list[str], work: Path, uid: int | None) -> list[str]:
    """`inner` run in a sandbox whose only writable folder is `work` (also its home and TMPDIR). With
    `uid` (the grader is root) the sandbox keeps root's user namespace, so that `inner` can become
    that user; without, it gets a user namespace of its own and no capabilities."""
    if uid is None:
        unshare = ["--unshare-all", "--cap-drop", "ALL"]
    else:
        unshare = [*ROOT_NAMESPACES, "--setenv", CASE_UID_VARIABLE, str(uid)]
    return _file_system(unshare, work) + ["--chdir", str(work), *case_environment(work), "--"] + inner


def warm_command(inner: list[str], spool: Path) -> list[str]:
    """A warm case runner (warm.py; the grader is root): `inner` in the sandbox `command` makes,
    with `spool` (where the folders of the cases it will run are made) writable, as root. Each case
    it forks gives that up first: namespaces of its own, only its own folder (enter_case_namespaces,
    case_file_system), then its own user."""
    return _file_system(ROOT_NAMESPACES, spool) + ["--chdir", str(spool), "--"] + inner


def case_environment(work: Path) -> list[str]:
    return [
        "--setenv",
        "HOME",
        str(work),
        "--setenv",
        "TMPDIR",
        str(work),
        "--setenv",
        "MPLCONFIGDIR",
        str(work / ".matplotlib"),
    ]


def _file_system(unshare: list[str], work: Path) -> list[str]:
    # Empty /run and /tmp first: what is bound below them afterwards (a Python environment or the
    # work folder under /tmp, as in a CI checkout made with mktemp) stays visible.
    program = bwrap()
    assert program is not None, "a case is sandboxed only where bwrap() found bubblewrap"
    args = [
        program,
        *unshare,
        "--die-with-parent",
        "--new-session",
        "--proc",
        "/proc",
        "--dev",
        "/dev",
        "--tmpfs",
        "/run",
        "--tmpfs",
        "/tmp",
    ]
    for system in SYSTEM_FOLDERS:
        args += ["--ro-bind-try", system, system]
    for folder in readable_folders():
        # bwrap makes missing parent folders private (0700); the case's user must pass through them
        for parent in reversed(folder.parents[:-1]):
            args += ["--perms", "0755", "--dir", str(parent)]
        args += ["--ro-bind", str(folder), str(folder)]
    return args + ["--bind", str(work), str(work)]


# Linux's clone flags and mount flags (<sched.h>, <sys/mount.h>) and interface ioctls (<linux/sockios.h>)
CLONE_NEWNS, CLONE_NEWCGROUP, CLONE_NEWUTS = 0x00020000, 0x02000000, 0x04000000
CLONE_NEWIPC, CLONE_NEWPID, CLONE_NEWNET = 0x08000000, 0x20000000, 0x40000000
MS_RDONLY, MS_NOSUID, MS_NODEV, MS_NOEXEC, MS_REMOUNT = 1, 2, 4, 8, 32
MS_BIND, MS_MOVE, MS_REC, MS_PRIVATE = 4096, 8192, 16384, 1 << 18
SIOCGIFFLAGS, SIOCSIFFLAGS, IFF_UP = 0x8913, 0x8914, 0x1
PROC_READ_ONLY = ("/proc/sys", "/proc/sysrq-trigger", "/proc/irq", "/proc/bus")  # as bwrap leaves them


def _libc(name: str, *args) -> None:
    import ctypes

    function = getattr(ctypes.CDLL(None, use_errno=True), name)
    if function(*args) != 0:
        error = ctypes.get_errno()
        raise OSError(error, f"{name}{args}: {os.strerror(error)}")


def enter_case_namespaces() -> None:
    """In a process forked by a warm case runner: new mount, PID, network, IPC and UTS namespaces
    (and cgroup, where the kernel has them), as bwrap gives a case. The PID namespace is that of
    the next process this one forks, which is its first process, its init."""
    _libc("unshare", CLONE_NEWNS | CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWIPC | CLONE_NEWUTS)
    try:
        _libc("unshare", CLONE_NEWCGROUP)
    except OSError:
        pass  # as --unshare-cgroup-try


def case_file_system(spool: Path, folder: Path) -> None:
    """In the first process of a case's namespaces (enter_case_namespaces): its own /proc, the
    read-only parts of /proc that bwrap makes read-only, only its own `folder` of the runner's
    `spool`, and its loopback up. What the runner's sandbox has besides is read-only or root's."""
    import fcntl
    import socket
    import struct

    _libc("mount", None, b"/", None, MS_REC | MS_PRIVATE, None)  # nothing here reaches the runner
    _libc("mount", b"proc", b"/proc", b"proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, None)
    for place in PROC_READ_ONLY:
        if os.path.exists(place):
            _libc("mount", place.encode(), place.encode(), None, MS_BIND | MS_REC, None)
            _libc("mount", None, place.encode(), None, MS_BIND | MS_REMOUNT | MS_RDONLY, None)
    # /run afresh (it holds the staging point), as each bwrap sandbox has; /tmp is root's, read-only to the case
    _libc("mount", b"tmpfs", b"/run", b"tmpfs", MS_NOSUID | MS_NODEV, b"mode=0755")
    staging = b"/run/case"
    os.mkdir(staging, 0o700)
    _libc("mount", bytes(folder), staging, None, MS_BIND, None)
    _libc(
        "mount", b"tmpfs", bytes(spool), b"tmpfs", MS_NOSUID | MS_NODEV, b"mode=0755"
    )  # the other cases' folders hidden
    os.mkdir(folder, 0o700)
    _libc("mount", staging, bytes(folder), None, MS_MOVE, None)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        request = struct.pack("16sH14x", b"lo", 0)
        flags = struct.unpack("16sH14x", fcntl.ioctl(sock, SIOCGIFFLAGS, request))[1]
        fcntl.ioctl(sock, SIOCSIFFLAGS, struct.pack("16sH14x", b"lo", flags | IFF_UP))


def become_case_user() -> None:
    """In the case process, first thing: become the case's own user when the sandbox says which
    (root's capabilities go with root)."""
    uid = os.environ.pop(CASE_UID_VARIABLE, None)
    if uid is not None and os.geteuid() == 0:
        os.setgroups([])
        os.setgid(int(uid))
        os.setuid(int(uid))
