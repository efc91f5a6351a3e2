"""Resident memory of a process, for tests and benchmarks that bound it (Linux /proc)."""

from __future__ import annotations

import ctypes


def rss_mb(pid: int | str = "self") -> float:
    """VmRSS of process `pid` in MB. For this process, after the C allocator has given back what it
    only keeps for later (glibc keeps freed 16 MiB blocks once its threshold for them has grown)."""
    if pid == "self":
        ctypes.CDLL(None).malloc_trim(0)
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    raise RuntimeError(f"no VmRSS in /proc/{pid}/status")
