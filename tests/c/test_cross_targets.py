"""libeyesim for Windows and macOS, cross-built here with Zig (robios/cmake/zig.cmake): the library
and programs build for every target and are the right kind of file, and Windows builds run under
Wine: the codec against the shared vectors, and programs against a fake and a real simulator.

The file formats are read here (PE, Mach-O, ELF headers), so no `file` or binutils are needed."""

from __future__ import annotations

import fcntl
import importlib.util
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import threading
from pathlib import Path
from typing import NamedTuple

import pytest
from support.cross import TARGETS, run_under_wine, wine_command, wine_environment, zig_cc
from support.programs import eyesim_command, read_trajectory


def _api_functions() -> set[str]:
    """The names in eye/_prototypes.py (every function of libeyesim), read without importing the eye
    package, which loads the native library."""
    package = importlib.util.find_spec("eye")
    path = Path(package.submodule_search_locations[0]) / "_prototypes.py"
    spec = importlib.util.spec_from_file_location("_eyesim_prototypes", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return set(module.PROTOTYPES)


ROOT = Path(__file__).resolve().parents[2]
ROBIOS = ROOT / "robios"
CROSS_BUILDS = ROOT / "build" / "cross"
WINDOWS = TARGETS["windows-x86_64"]
MACOS = (TARGETS["macos-arm64"], TARGETS["macos-x86_64"])
LINUX = "x86_64-linux-gnu.2.17"  # the manylinux2014 glibc
VARIABLES = ("LIDAR_RESOLUTION", "CAMWIDTH", "CAMHEIGHT", "CAMSIZE", "IP_WIDTH", "IP_HEIGHT", "IP_SIZE")
SLEEPS = ("es_sleep", "es_usleep", "es_nanosleep")  # where eyebot.h sends sleeps on Windows and macOS


# ---- Reading binaries -------------------------------------------------------------------------


def _cstring(data: bytes, offset: int) -> str:
    return data[offset : data.index(b"\0", offset)].decode()


class PE(NamedTuple):
    machine: int
    optional_magic: int  # 0x20b: PE32+
    characteristics: int
    exports: set[str]
    imports: dict[str, list[str]]  # DLL name (lower case) -> imported names


def read_pe(path: Path) -> PE:
    data = path.read_bytes()
    assert data[:2] == b"MZ", f"{path.name} is not a Windows executable"
    pe = struct.unpack_from("<I", data, 0x3C)[0]
    assert data[pe : pe + 4] == b"PE\0\0"
    machine, section_count, _, _, _, optional_size, characteristics = struct.unpack_from("<HHIIIHH", data, pe + 4)
    optional = pe + 24
    magic = struct.unpack_from("<H", data, optional)[0]
    assert magic == 0x20B, f"{path.name}: not PE32+"
    directory_count = struct.unpack_from("<I", data, optional + 108)[0]
    directories = [struct.unpack_from("<II", data, optional + 112 + 8 * k) for k in range(directory_count)]
    sections = []
    for k in range(section_count):
        _, virtual_size, address, raw_size, raw_offset = struct.unpack_from(
            "<8sIIII", data, optional + optional_size + 40 * k
        )
        sections.append((address, max(virtual_size, raw_size), raw_offset))

    def at(rva: int) -> int:
        for address, size, raw_offset in sections:
            if address <= rva < address + size:
                return raw_offset + rva - address
        raise ValueError(f"RVA {rva:#x} is in no section")

    exports: set[str] = set()
    export_rva = directories[0][0]
    if export_rva:
        name_count, _, names = struct.unpack_from("<III", data, at(export_rva) + 24)
        exports = {_cstring(data, at(struct.unpack_from("<I", data, at(names) + 4 * k)[0])) for k in range(name_count)}
    imports: dict[str, list[str]] = {}
    import_rva = directories[1][0]
    if import_rva:
        entry = at(import_rva)
        while True:
            lookup, _, _, name, address_table = struct.unpack_from("<IIIII", data, entry)
            if name == 0:
                break
            names, thunk = [], at(lookup or address_table)
            while (value := struct.unpack_from("<Q", data, thunk)[0]) != 0:
                if not value >> 63:  # by name, not by ordinal
                    names.append(_cstring(data, at((value & 0x7FFFFFFF) + 2)))
                thunk += 8
            imports[_cstring(data, at(name)).lower()] = names
            entry += 20
    return PE(machine, magic, characteristics, exports, imports)


class MachO(NamedTuple):
    cpu: int
    filetype: int
    install_name: str | None
    dylibs: list[str]  # LC_LOAD_DYLIB and friends, in order (library ordinals count from 1)
    rpaths: list[str]
    exports: set[str]  # without the leading underscore
    undefined: dict[str, int]  # name (without underscore) -> library ordinal


MACHO_ARM64, MACHO_X86_64 = 0x0100000C, 0x01000007
MH_EXECUTE, MH_DYLIB = 2, 6
LC_SYMTAB, LC_LOAD_DYLIB, LC_ID_DYLIB, LC_RPATH = 0x2, 0xC, 0xD, 0x8000001C
LC_DYLIB_LOADS = {LC_LOAD_DYLIB, 0x80000018, 0x8000001F, 0x80000023}  # load, weak, re-export, upward


def read_macho(path: Path) -> MachO:
    data = path.read_bytes()
    magic, cpu, _, filetype, command_count, _, _, _ = struct.unpack_from("<IiiIIIII", data, 0)
    assert magic == 0xFEEDFACF, f"{path.name} is not a 64-bit Mach-O file"
    install_name, dylibs, rpaths, symtab = None, [], [], None
    offset = 32
    for _ in range(command_count):
        command, size = struct.unpack_from("<II", data, offset)
        if command in LC_DYLIB_LOADS or command in (LC_ID_DYLIB, LC_RPATH):
            text = _cstring(data, offset + struct.unpack_from("<I", data, offset + 8)[0])
            if command == LC_ID_DYLIB:
                install_name = text
            elif command == LC_RPATH:
                rpaths.append(text)
            else:
                dylibs.append(text)
        elif command == LC_SYMTAB:
            symtab = struct.unpack_from("<IIII", data, offset + 8)
        offset += size
    exports: set[str] = set()
    undefined: dict[str, int] = {}
    symbols, count, strings, _ = symtab
    for k in range(count):
        name_at, kind, _, description, _ = struct.unpack_from("<IBBHQ", data, symbols + 16 * k)
        if not kind & 1:  # N_EXT
            continue
        name = _cstring(data, strings + name_at).removeprefix("_")
        if kind & 0x0E == 0x0E:  # N_SECT: defined here
            exports.add(name)
        elif kind & 0x0E == 0:  # N_UNDF
            undefined[name] = description >> 8  # two-level namespace: the library ordinal
    return MachO(cpu, filetype, install_name, dylibs, rpaths, exports, undefined)


class ELF(NamedTuple):
    machine: int
    type: int
    soname: str | None
    exports: set[str]
    glibc_versions: set[tuple[int, ...]]


def read_elf(path: Path) -> ELF:
    data = path.read_bytes()
    assert data[:4] == b"\x7fELF" and data[4] == 2 and data[5] == 1, f"{path.name} is not a 64-bit LE ELF file"
    elf_type, machine = struct.unpack_from("<HH", data, 16)
    section_table = struct.unpack_from("<Q", data, 0x28)[0]
    entry_size, section_count = struct.unpack_from("<HH", data, 0x3A)
    # (name, type, flags, address, offset, size, link, info, align, entry size)
    sections = [struct.unpack_from("<IIQQQQIIQQ", data, section_table + k * entry_size) for k in range(section_count)]

    def string(table: int, at: int) -> str:
        return _cstring(data, sections[table][4] + at)

    exports: set[str] = set()
    soname, versions = None, set()
    for _, kind, _, _, offset, size, link, _, _, _ in sections:
        if kind == 11:  # SHT_DYNSYM
            for k in range(size // 24):
                name, info, _, section, _, _ = struct.unpack_from("<IBBHQQ", data, offset + 24 * k)
                if section != 0 and info >> 4 in (1, 2):  # defined, global or weak
                    exports.add(string(link, name))
            # Its string table (.dynstr) also names the symbol versions the library needs.
            strings = sections[link]
            for match in re.finditer(rb"GLIBC_(\d+(?:\.\d+)+)\0", data[strings[4] : strings[4] + strings[5]]):
                versions.add(tuple(int(part) for part in match.group(1).split(b".")))
        elif kind == 6:  # SHT_DYNAMIC
            for k in range(size // 16):
                tag, value = struct.unpack_from("<qQ", data, offset + 16 * k)
                if tag == 14:  # DT_SONAME
                    soname = string(link, value)
    return ELF(machine, elf_type, soname, exports, versions)


def is_ar_archive(path: Path) -> bool:
    return path.read_bytes()[:8] == b"!<arch>\n"


# ---- Building ---------------------------------------------------------------------------------


def cross_build(target: str) -> Path:
    """libeyesim for `target`, built with the toolchain file and installed; returns the prefix.
    Incremental in build/cross/<target> (locked: the tree is shared)."""
    if not shutil.which("cmake"):
        pytest.fail("cmake is needed to cross-build libeyesim")
    build, prefix = CROSS_BUILDS / target, CROSS_BUILDS / f"{target}-prefix"
    CROSS_BUILDS.mkdir(parents=True, exist_ok=True)
    # The toolchain file runs `python -m ziglang` with the Python running these tests.
    steps = [["cmake", "--build", str(build), "-j", "2"], ["cmake", "--install", str(build), "--prefix", str(prefix)]]
    if not (build / "CMakeCache.txt").is_file():
        steps.insert(
            0,
            [
                "cmake",
                "-S",
                str(ROBIOS),
                "-B",
                str(build),
                f"-DCMAKE_TOOLCHAIN_FILE={ROBIOS}/cmake/zig.cmake",
                f"-DZIG_TARGET={target}",
                f"-DZIG_PYTHON={sys.executable}",
                "-DCMAKE_BUILD_TYPE=Release",
                "-DEYESIM_WERROR=ON",
            ],
        )
    with open(CROSS_BUILDS / f"{target}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        for step in steps:
            done = subprocess.run(step, cwd=ROOT, capture_output=True, text=True, timeout=1200)
            assert done.returncode == 0, f"{' '.join(step)} failed:\n{done.stdout}\n{done.stderr}"
    return prefix


_prefixes: dict[str, Path] = {}


def prefix_for(target: str) -> Path:
    if target not in _prefixes:
        _prefixes[target] = cross_build(target)
    return _prefixes[target]


def compile_program(target: str, source: str, out: Path, *flags: str, language: str = "cc") -> Path:
    """A RoBIOS program for `target`, linked against its cross-built libeyesim (as `eyesim cc`
    links: -I, -L, rpath, -leyesim)."""
    prefix = prefix_for(target)
    out.parent.mkdir(parents=True, exist_ok=True)
    src = out.with_suffix(".c" if language == "cc" else ".cpp")
    src.write_text(source)
    link = [] if "-c" in flags else [f"-L{prefix / 'lib'}", "-leyesim"]
    if "-c" not in flags and target not in (WINDOWS,):
        link += [f"-Wl,-rpath,{prefix / 'lib'}", "-lpthread", "-lm"]
    built = zig_cc(
        target,
        "-Wall",
        "-Wextra",
        "-Werror",
        f"-I{prefix / 'include'}",
        *flags,
        str(src),
        "-o",
        str(out),
        *link,
        language=language,
    )
    assert built.returncode == 0, built.stderr
    return out


def windows_program(source: str, directory: Path, name: str = "prog") -> Path:
    """A Windows program with eyesim.dll beside it, where Windows looks for it first."""
    exe = compile_program(WINDOWS, source, directory / f"{name}.exe", "-std=c11")
    shutil.copy2(prefix_for(WINDOWS) / "lib" / "eyesim.dll", directory / "eyesim.dll")
    return exe


def needs_wine():
    if not (shutil.which("wine") or shutil.which("wine64")):
        pytest.fail("wine is missing: `make test` installs Debian's wine64 (apt-get install wine64)")


DRIVE = r"""
#include "eyebot.h"

int main(void)
{
    printf("lidar %d\n", LIDAR_RESOLUTION); /* a variable of the library, before any call */
    fflush(stdout);
    LCDPrintf("driving at %d mm/s\n", 200);
    VWSetSpeed(200, 0);
    usleep(1000000);
    VWSetSpeed(0, 0);
    int x, y, phi;
    VWGetPosition(&x, &y, &phi);
    printf("at x=%d y=%d phi=%d\n", x, y, phi);
    return 0;
}
"""


# ---- The codec under Wine ---------------------------------------------------------------------


def test_the_codec_passes_the_shared_vectors_on_windows(tmp_path):
    needs_wine()
    sources = [str(ROBIOS / "tests" / "test_protocol.c"), str(ROBIOS / "src" / "codec.c")]
    flags = ["-std=c11", "-Wall", "-Wextra", "-Werror", f"-I{ROBIOS / 'src'}", f"-I{ROBIOS / 'tests'}"]
    built = zig_cc(WINDOWS, *flags, *sources, "-o", str(tmp_path / "test_protocol.exe"))
    assert built.returncode == 0, built.stderr
    on_windows = run_under_wine(tmp_path / "test_protocol.exe")
    assert on_windows.returncode == 0, on_windows.stdout + on_windows.stderr

    compiler = os.environ.get("CC") or "cc"
    native = subprocess.run(
        [*compiler.split(), *flags, *sources, "-o", str(tmp_path / "test_protocol")], capture_output=True, text=True
    )
    assert native.returncode == 0, native.stderr
    on_linux = subprocess.run([str(tmp_path / "test_protocol")], capture_output=True, text=True, timeout=60)
    assert on_linux.returncode == 0, on_linux.stdout
    assert re.fullmatch(r"ok: \d+ vectors\n", on_windows.stdout)
    assert on_windows.stdout == on_linux.stdout  # the same vectors, all passing


# ---- The library for each target --------------------------------------------------------------

API = _api_functions() | set(VARIABLES) | {"eyesim_sleep"}


def test_windows_library_is_a_dll_exporting_the_api():
    prefix = prefix_for(WINDOWS)
    assert (prefix / "include" / "eyebot.h").is_file()
    dll = read_pe(prefix / "lib" / "eyesim.dll")
    assert dll.machine == 0x8664 and dll.characteristics & 0x2000  # x86-64, IMAGE_FILE_DLL
    missing = (API | set(SLEEPS) | {"es_clock_nanosleep", "es_Sleep"}) - dll.exports
    assert not missing, f"not exported: {sorted(missing)}"
    # Only the API: not the internals, nor the start-up code's atexit (programs calling it would not link).
    assert not {"es_call", "es_fatal", "atexit", "_CRT_INIT"} & dll.exports
    assert "ws2_32.dll" in dll.imports  # Winsock
    assert is_ar_archive(prefix / "lib" / "libeyesim.dll.a")  # the import library: -leyesim
    assert is_ar_archive(prefix / "lib" / "libeyesim.a")


@pytest.mark.parametrize("target,cpu", [(MACOS[0], MACHO_ARM64), (MACOS[1], MACHO_X86_64)])
def test_macos_library_is_an_rpath_dylib_exporting_the_api(target, cpu):
    prefix = prefix_for(target)
    assert (prefix / "include" / "eyebot.h").is_file()
    dylib = read_macho(prefix / "lib" / "libeyesim.dylib")
    assert (dylib.cpu, dylib.filetype) == (cpu, MH_DYLIB)
    assert dylib.install_name == "@rpath/libeyesim.dylib"
    assert dylib.dylibs == ["/usr/lib/libSystem.B.dylib"]
    missing = (API | set(SLEEPS) | {"sleep", "usleep", "nanosleep"}) - dylib.exports
    assert not missing, f"not exported: {sorted(missing)}"
    assert is_ar_archive(prefix / "lib" / "libeyesim.a")


def test_linux_library_is_a_shared_object_for_old_glibc():
    prefix = prefix_for(LINUX)
    assert (prefix / "include" / "eyebot.h").is_file()
    so = read_elf(prefix / "lib" / "libeyesim.so")
    assert (so.machine, so.type) == (62, 3)  # x86-64, shared object
    assert so.soname == "libeyesim.so"
    missing = (API | {"sleep", "usleep", "nanosleep", "clock_nanosleep"}) - so.exports
    assert not missing, f"not exported: {sorted(missing)}"
    assert "es_call" not in so.exports  # the internals stay hidden
    assert so.glibc_versions and max(so.glibc_versions) <= (2, 17)
    assert is_ar_archive(prefix / "lib" / "libeyesim.a")


# ---- Programs for Windows and macOS -----------------------------------------------------------


def test_a_program_links_against_the_windows_dll(tmp_path):
    exe = compile_program(WINDOWS, DRIVE, tmp_path / "drive.exe", "-std=c11")
    program = read_pe(exe)
    assert not program.characteristics & 0x2000
    used = set(program.imports["eyesim.dll"])
    # usleep went to libeyesim (eyebot.h's macro), the variable is imported from the DLL too.
    assert {"LCDPrintf", "VWSetSpeed", "VWGetPosition", "es_usleep", "LIDAR_RESOLUTION"} <= used
    assert "usleep" not in used


def test_a_program_links_statically_on_windows(tmp_path):
    prefix = prefix_for(WINDOWS)
    source = tmp_path / "drive.c"
    source.write_text(DRIVE)
    built = zig_cc(
        WINDOWS,
        "-std=c11",
        "-Wall",
        "-Wextra",
        "-Werror",
        f"-I{prefix / 'include'}",
        str(source),
        str(prefix / "lib" / "libeyesim.a"),
        "-lws2_32",
        "-o",
        str(tmp_path / "drive.exe"),
    )
    assert built.returncode == 0, built.stderr
    assert "eyesim.dll" not in read_pe(tmp_path / "drive.exe").imports


@pytest.mark.parametrize("target,cpu", [(MACOS[0], MACHO_ARM64), (MACOS[1], MACHO_X86_64)])
def test_a_program_links_against_the_macos_dylib(tmp_path, target, cpu):
    exe = compile_program(target, DRIVE, tmp_path / "drive", "-std=c11")
    program = read_macho(exe)
    assert (program.cpu, program.filetype) == (cpu, MH_EXECUTE)
    assert "@rpath/libeyesim.dylib" in program.dylibs
    assert str(prefix_for(target) / "lib") in program.rpaths
    eyesim = program.dylibs.index("@rpath/libeyesim.dylib") + 1
    # Two-level namespace: each name is bound to one library at link time. Zig's linker puts
    # libSystem first, so a plain usleep would bind there; eyebot.h's macro makes it es_usleep.
    for name in ("LCDPrintf", "VWSetSpeed", "LIDAR_RESOLUTION", "es_usleep"):
        assert program.undefined.get(name) == eyesim, (name, program.undefined, program.dylibs)
    assert "usleep" not in program.undefined


CPP = r"""
#include "eyebot.h" /* first: its sleep macros (Windows, macOS) then meet every standard header */
#include "eyebot++.h"

int main()
{
    std::vector<int> speeds{100, 0};
    for (int speed : speeds) {
        VWSetSpeed(speed, 0);
        usleep(100000);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    LCDPrintf("%s\n", std::string("done").c_str());
    return 0;
}
"""


@pytest.mark.parametrize("target", [WINDOWS, *MACOS])
def test_cpp_programs_compile_for_the_target(tmp_path, target):
    compile_program(target, CPP, tmp_path / "prog.o", "-std=c++17", "-Wpedantic", "-c", language="c++")


SLEEPS_C = r"""
#include <windows.h>
#include "eyebot.h"

int main(void)
{
    Sleep(10);
    usleep(10);
    sleep(0);
    struct timespec t = {0, 10};
    nanosleep(&t, NULL);
    clock_nanosleep(CLOCK_MONOTONIC, 0, &t, NULL);
    return 0;
}
"""


def test_windows_sleeps_go_to_the_library_also_with_windows_h(tmp_path):
    exe = compile_program(WINDOWS, SLEEPS_C, tmp_path / "sleeps.exe", "-std=c11")
    imports = read_pe(exe).imports
    # Every sleep of the program's (kernel32's Sleep is still imported: MinGW's start-up code uses it).
    assert set(imports["eyesim.dll"]) == {"es_Sleep", "es_usleep", "es_sleep", "es_nanosleep", "es_clock_nanosleep"}


def test_windows_h_may_also_come_after_eyebot_h(tmp_path):
    source = SLEEPS_C.replace('#include <windows.h>\n#include "eyebot.h"', '#include "eyebot.h"\n#include <windows.h>')
    exe = compile_program(WINDOWS, source, tmp_path / "sleeps.exe", "-std=c11")
    imports = read_pe(exe).imports
    # Then Sleep is Windows' own, in wall time (docs/c-library.md); the others still go to the library.
    assert set(imports["eyesim.dll"]) == {"es_usleep", "es_sleep", "es_nanosleep", "es_clock_nanosleep"}


# ---- Windows programs under Wine --------------------------------------------------------------


def wine_env(**extra: str) -> dict[str, str]:
    env = {k: v for k, v in wine_environment().items() if not k.startswith("EYESIM_")}
    env.update(extra)
    return env


def test_no_simulator_under_wine_exits_with_the_librarys_status(tmp_path, unused_port):
    needs_wine()
    exe = windows_program(DRIVE, tmp_path)
    done = run_under_wine(exe, env=wine_env(EYESIM_PORT=str(unused_port), EYESIM_CONNECT_TIMEOUT="1"), timeout=120)
    assert done.returncode == 3, done.stdout + done.stderr  # ES_EXIT_NO_SIMULATOR
    assert done.stdout == "lidar 360\n"
    assert (
        f"eyesim: no simulator answered at 127.0.0.1:{unused_port} within 1 s (Connection refused); start "
        f"the simulator first, or set EYESIM_HOST/EYESIM_PORT"
    ) in done.stderr


THREADS_C = r"""
#include <windows.h>
#include <stdatomic.h>
#include "eyebot.h"

static atomic_int ticks;

static void tick(void)
{
    ticks++;
}

static void goodbye(void)
{
    printf("atexit handler\n");
}

static void *worker(void *unused)
{
    (void)unused;
    LCDPrintf("worker\n");
    printf("worker done\n");
    return NULL;
}

int main(int argc, char **argv)
{
    atexit(goodbye);
    VWSetSpeed(100, 0);
    printf("connected\n"); /* no fflush: piped stdout is unbuffered on Windows (console.c) */
    if (argc > 1 && strcmp(argv[1], "compute") == 0) {
        volatile unsigned long n = 0;
        for (;;) /* no calls: only the library's watcher can see the simulator go */
            n++;
    }
    usleep(250000);
    Sleep(1500);
    struct timespec t = {2, 5};
    nanosleep(&t, NULL);
    struct timespec c = {0, 7000};
    clock_nanosleep(CLOCK_MONOTONIC, 0, &c, NULL);
    sleep(3);
    TIMER timer = OSAttachTimer(10, tick);
    while (!ticks)
        OSWait(1);
    printf("timer %d ticked\n", timer);
    pthread_t thread;
    pthread_create(&thread, NULL, worker, NULL);
    pthread_exit(NULL); /* the program ends with the worker, though the timer thread waits on */
}
"""


def test_windows_program_against_a_fake_simulator(tmp_path, fake_sim):
    needs_wine()
    exe = windows_program(THREADS_C, tmp_path)
    waits = []

    def timer_wait(values):  # timer 1 is due once, then never again
        waits.append(values)
        return ([1],) if len(waits) == 1 else fake_sim.HOLD

    fake_sim.script.update(TIMER_ATTACH=(1,), TIMER_WAIT=timer_wait)
    done = run_under_wine(exe, env=wine_env(EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(fake_sim.port)), timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    # exit(0) once only the library's threads are left: output flushed, atexit handlers run
    assert done.stdout.splitlines() == ["connected", "timer 1 ticked", "worker done", "atexit handler"]
    assert done.stderr == ""

    version, robot, program, pid, token = fake_sim.hellos[0]
    assert (robot, program) == ("", "prog") and pid > 0  # the name without ".exe"
    assert token == ""  # no EYESIM_TOKEN, no token file of a run on that port
    sleeps = [r.values for r in fake_sim.requests if r.op == "OS_SLEEP"]
    # usleep, Sleep, nanosleep, clock_nanosleep, sleep: all in simulation time
    assert sleeps == [(0, 250_000_000), (1, 500_000_000), (2, 5), (0, 7000), (3, 0)]
    ops = fake_sim.ops()
    assert ops.count("TIMER_WAIT") == 2  # the timer thread waits on in the second one
    assert ops.count("THREADS") == 1 and ops.index("THREADS") < ops.index("LCD_PRINTF")  # the worker
    assert [r.values for r in fake_sim.requests if r.op == "LCD_PRINTF"] == [("worker\n",)]


def test_windows_program_ends_when_the_simulator_goes_while_it_computes(tmp_path, fake_sim):
    needs_wine()
    exe = windows_program(THREADS_C, tmp_path)
    env = wine_env(EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(fake_sim.port))
    process = subprocess.Popen(
        [wine_command(), str(exe), "compute"], env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    stopper = threading.Timer(120, process.kill)  # were "connected" held in a buffer, readline would wait
    stopper.start()
    try:
        # Printed once its call has returned: the program computes from then on.
        connected = process.stdout.readline()
        assert connected == "connected\n", "the program's piped output did not appear as it was printed"
        fake_sim.close_clients()
        stdout, stderr = process.communicate(timeout=60)
        stdout = connected + stdout
    finally:
        stopper.cancel()
        if process.poll() is None:
            process.kill()
            process.communicate()
    assert process.returncode == 5, stdout + stderr  # ES_EXIT_CONNECTION_LOST
    assert stdout == "connected\natexit handler\n"
    assert (
        f"eyesim: lost the connection to the simulator at 127.0.0.1:{fake_sim.port} (connection closed); "
        f"the program ends"
    ) in stderr


def test_windows_program_drives_in_the_real_simulator(tmp_path):
    """`eyesim run` on Linux starts a Windows program through Wine (whose sockets are Linux's)."""
    needs_wine()
    exe = windows_program(DRIVE, tmp_path, name="drive")
    launcher = tmp_path / "drive-under-wine"
    launcher.write_text(f'#!/bin/sh\nexec "{wine_command()}" "{exe}" "$@"\n')
    launcher.chmod(0o755)
    done = subprocess.run(
        [
            *eyesim_command("run"),
            "--headless",
            "--port",
            "0",
            "--until",
            "3",
            "--program",
            f"1={launcher}",
            "--record",
            "path.csv",
        ],
        cwd=tmp_path,
        env=wine_env(),
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert "program drive-under-wine: exit code 0" in done.stdout
    assert "lidar 360" in done.stdout
    reported = re.search(r"at x=(-?\d+) y=(-?\d+) phi=(-?\d+)", done.stdout)
    assert reported, done.stdout
    # 200 mm/s for 1 s of simulation time (usleep waits in simulation time), then stopped
    assert 150 <= int(reported.group(1)) <= 210 and reported.group(2, 3) == ("0", "0"), done.stdout
    path = read_trajectory(tmp_path / "path.csv")[1]
    assert path[-1]["time_s"] == 3.0
    moved = math.hypot(path[-1]["x"] - path[0]["x"], path[-1]["y"] - path[0]["y"])
    assert 0.15 <= moved <= 0.23


def test_windows_program_reads_the_token_file_of_the_run(tmp_path, fake_sim):
    """Started by hand (no EYESIM_TOKEN), a Windows program sends the token its run wrote to
    EyeSim's state folder (here EYESIM_STATE_DIR, a Windows path, as the run's own would be)."""
    needs_wine()
    exe = windows_program(DRIVE, tmp_path)
    state = tmp_path / "state folder"
    state.mkdir()
    (state / f"program-token-{fake_sim.port}").write_text("token-from-the-file\r\n")
    windows_state = "Z:" + str(state).replace("/", "\\")
    done = run_under_wine(
        exe,
        env=wine_env(EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(fake_sim.port), EYESIM_STATE_DIR=windows_state),
        timeout=120,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    assert fake_sim.hellos[0][4] == "token-from-the-file"
