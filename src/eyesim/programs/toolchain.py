"""`eyesim cc` / `eyesim c++`: a C/C++ compiler with the RoBIOS headers and libeyesim added.

The compiler is $CC / $CXX when set, else the system's (cc, gcc, clang), else Zig's clang from
the `ziglang` package (a dependency on Windows and macOS, the `zig` extra on Linux), so that a
laptop with nothing but Python still compiles RoBIOS programs."""

from __future__ import annotations

import argparse
import importlib.util
import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from eyesim import paths, platform

# language -> (environment variable naming the compiler, system compilers in order of preference)
COMPILERS = {"cc": ("CC", ("cc", "gcc", "clang")), "c++": ("CXX", ("c++", "g++", "clang++"))}

# Arguments after which the compiler does not link (or does nothing but report).
NO_LINK_ARGS = frozenset(
    {
        "-c",
        "-E",
        "-S",
        "-M",
        "-MM",
        "-fsyntax-only",
        "--version",
        "-dumpversion",
        "-dumpfullversion",
        "-dumpmachine",
        "--help",
    }
)

LIBRARY_FILES = ("libeyesim.so", "libeyesim.a", "libeyesim.dylib", "eyesim.lib", "libeyesim.dll.a")


class LibraryMissing(Exception):
    """The RoBIOS headers or libeyesim are not where eyesim.paths says."""


class CompilerMissing(Exception):
    """No C/C++ compiler: none named by $CC/$CXX, none on PATH, and no ziglang package."""


def find_compiler(language: str) -> list[str]:
    """The command that runs the compiler for `language` ("cc" or "c++")."""
    variable, system = COMPILERS[language]
    if os.environ.get(variable):
        return shlex.split(os.environ[variable])  # $CC may carry flags: "ccache gcc"
    for name in system:
        if shutil.which(name):
            return [name]
    if importlib.util.find_spec("ziglang") is not None:
        return [sys.executable, "-m", "ziglang", language]
    raise CompilerMissing(
        f"no {'C' if language == 'cc' else 'C++'} compiler found (looked for ${variable}, "
        f"{', '.join(system)} and the ziglang package). Install one:\n"
        f"  pip install ziglang            (any system: Zig's clang, which eyesim {language} then uses)\n"
        f"  or the system's compiler: Debian/Ubuntu `sudo apt install build-essential`, "
        f"Fedora `sudo dnf install gcc gcc-c++`, macOS `xcode-select --install`"
    )


# glibc's feature-test macros: a program that sets one has chosen which names it wants.
FEATURE_MACROS = (
    "_DEFAULT_SOURCE",
    "_GNU_SOURCE",
    "_POSIX_C_SOURCE",
    "_POSIX_SOURCE",
    "_XOPEN_SOURCE",
    "_BSD_SOURCE",
    "_SVID_SOURCE",
    "_ISOC99_SOURCE",
    "_ISOC11_SOURCE",
)


def chooses_features(args: list[str]) -> bool:
    """Whether the arguments define or undefine a feature-test macro themselves."""
    for previous, arg in zip(["", *args], args):
        if previous in ("-D", "-U"):  # `-D NAME` as two arguments
            arg = previous + arg
        if arg.startswith(("-D", "-U")) and arg[2:].split("=", 1)[0] in FEATURE_MACROS:
            return True
    return False


def links(args: list[str]) -> bool:
    """Whether a compiler run with these arguments links a program."""
    return not any(arg in NO_LINK_ARGS or arg.startswith("-print-") for arg in args)


def check_library(prefix: Path) -> None:
    header = prefix / "include" / "eyebot.h"
    lib_dir = prefix / "lib"
    if header.is_file() and any((lib_dir / name).is_file() for name in LIBRARY_FILES):
        return
    how = "EYESIM_ROBIOS points there" if os.environ.get("EYESIM_ROBIOS") else "the installed eyesim package"
    raise LibraryMissing(
        f"the RoBIOS C library is not installed: looked for {header} and {lib_dir}/libeyesim.* "
        f"({how}). Reinstall eyesim with pip, or build it for development with\n"
        f"  cmake -S robios -B build/robios-build && cmake --build build/robios-build && "
        f"cmake --install build/robios-build --prefix build/robios\n"
        f"and set EYESIM_ROBIOS=<checkout>/build/robios"
    )


# On by default: a missing LCDPrintf argument or an uninitialised variable is worth a word. Not
# -Wextra: EyeSim-era programs' `int main(int argc, char *argv[])` and int/unsigned comparisons
# would each earn a warning that teaches nothing.
WARNINGS = ("-Wall",)


def compiler_command(language: str, args: list[str], prefix: Path | None = None, warnings: bool = True) -> list[str]:
    """The full compiler command line for `eyesim <language> args...`; `warnings`: add -Wall
    before the arguments (so that their -Wno-... still win)."""
    prefix = paths.robios_dir() if prefix is None else Path(prefix)
    check_library(prefix)
    command = [*find_compiler(language), *(WARNINGS if warnings else ()), f"-I{prefix / 'include'}"]
    if language == "cc" and not chooses_features(args):
        # EyeSim programs call usleep and use M_PI, which strict -std=c99/c11 hides; this asks for
        # them whatever the program includes first (C++ compilers define _GNU_SOURCE anyway).
        command.append("-D_DEFAULT_SOURCE")
    command += args
    if links(args):
        lib_dir = prefix / "lib"
        # Libraries after the sources (static linking needs that order). The rpath lets the
        # program find libeyesim without LD_LIBRARY_PATH; Windows has none: the DLL is put beside
        # the program instead (place_library).
        if platform.WINDOWS:
            command += [f"-L{lib_dir}", "-leyesim", "-lws2_32"]
        else:
            command += [f"-L{lib_dir}", f"-Wl,-rpath,{lib_dir}", "-leyesim", "-lpthread", "-lm"]
    return command


def source_argument(name: str) -> str:
    """A source file's name as a compiler argument that can only be a file: `./-x.c` and
    `./@opts.c`, never an option (`-wrapper ...`) or a response file (`@opts.c`, whose contents gcc
    and clang read as more options). For the grader and the viewer, which pass file names that a
    student chose."""
    return f"./{name}" if name.startswith(("-", "@")) else name


def executable_name(path: Path) -> Path:
    """A program's file name on this system: `prog.exe` on Windows, `prog` elsewhere."""
    return path.with_name(path.name + ".exe") if platform.WINDOWS and path.suffix.lower() != ".exe" else path


def output_of(args: list[str], cwd: Path | None = None) -> Path:
    """The program a linking run writes (`-o NAME`, else the compiler's default)."""
    for previous, arg in zip(["", *args], args):
        if previous == "-o":
            name = arg
            break
        if arg.startswith("-o") and len(arg) > 2:
            name = arg[2:]
            break
    else:
        name = "a.exe" if platform.WINDOWS else "a.out"
    return Path(cwd or ".") / name


def place_library(args: list[str], cwd: Path | None = None, prefix: Path | None = None) -> None:
    """Windows finds a program's DLLs beside it (or on PATH): after linking, copy eyesim.dll next
    to the program, so it runs from a terminal or Explorer too. Elsewhere the rpath does this."""
    if not platform.WINDOWS or not links(args):
        return
    lib_dir = (paths.robios_dir() if prefix is None else Path(prefix)) / "lib"
    dll = lib_dir / "eyesim.dll"
    target = output_of(args, cwd).resolve().parent / dll.name
    if dll.is_file() and target != dll.resolve():
        shutil.copy2(dll, target)


def run_compiler(
    language: str, args: list[str], prefix: Path | None = None, verbose: bool = False, warnings: bool = True
) -> int:
    """Runs the compiler; returns its exit status (1 when the library or compiler is missing)."""
    try:
        command = compiler_command(language, args, prefix, warnings)
    except (LibraryMissing, CompilerMissing) as error:
        print(f"eyesim {language}: {error}", file=sys.stderr)
        return 1
    if verbose:
        print(shlex.join(command), file=sys.stderr)
    try:
        status = subprocess.call(command)
    except FileNotFoundError:
        variable = COMPILERS[language][0]
        print(f"eyesim {language}: compiler {command[0]!r} not found; install one or set {variable}", file=sys.stderr)
        return 1
    if status == 0:
        place_library(args, prefix=prefix)
    return 128 - status if status < 0 else status  # killed by a signal: the shell's convention


OUR_OPTIONS = ("--verbose", "--no-warnings")


def _compile(language: str, args: list[str]) -> int:
    """`eyesim cc [--verbose] [--no-warnings] ARGS...`: those two are ours (show the command; leave
    out -Wall); the rest is the compiler's."""
    return run_compiler(
        language,
        [arg for arg in args if arg not in OUR_OPTIONS],
        verbose="--verbose" in args,
        warnings="--no-warnings" not in args,
    )


def register(subparsers) -> None:
    for language, what in (("cc", "C"), ("c++", "C++")):
        variable, system = COMPILERS[language]
        parser = subparsers.add_parser(
            language,
            help=f"compile a {what} RoBIOS program",
            description=(
                f"Runs ${variable} (else {', '.join(system)}, else Zig's clang from the ziglang "
                f"package) with the RoBIOS headers and libeyesim, e.g. `eyesim {language} prog.c -o prog`. "
                f"It adds -Wall (--no-warnings leaves it out); --verbose shows the command; every other "
                f"argument goes to the compiler."
            ),
            add_help=False,  # -h/--help belong to the compiler too
            prefix_chars="\0",  # no argument looks like an option: all of them pass through
        )
        parser.add_argument("args", nargs=argparse.REMAINDER, metavar="COMPILER_ARG")
        parser.set_defaults(func=lambda ns, language=language: _compile(language, ns.args))
