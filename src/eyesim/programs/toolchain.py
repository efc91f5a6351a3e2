"""`eyesim cc` / `eyesim c++`: the system C/C++ compiler with the RoBIOS headers and libeyesim added."""

from __future__ import annotations

import argparse
import os
import shlex
import subprocess
import sys
from pathlib import Path

from eyesim import paths

# language -> (environment variable naming the compiler, default compiler)
COMPILERS = {"cc": ("CC", "cc"), "c++": ("CXX", "c++")}

# Arguments after which the compiler does not link (or does nothing but report).
NO_LINK_ARGS = frozenset({
    "-c", "-E", "-S", "-M", "-MM", "-fsyntax-only",
    "--version", "-dumpversion", "-dumpfullversion", "-dumpmachine", "--help",
})

LIBRARY_FILES = ("libeyesim.so", "libeyesim.a", "libeyesim.dylib", "eyesim.lib", "libeyesim.dll.a")


class LibraryMissing(Exception):
    """The RoBIOS headers or libeyesim are not where eyesim.paths says."""


# glibc's feature-test macros: a program that sets one has chosen which names it wants.
FEATURE_MACROS = ("_DEFAULT_SOURCE", "_GNU_SOURCE", "_POSIX_C_SOURCE", "_POSIX_SOURCE", "_XOPEN_SOURCE",
                  "_BSD_SOURCE", "_SVID_SOURCE", "_ISOC99_SOURCE", "_ISOC11_SOURCE")


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
    how = ("EYESIM_ROBIOS points there" if os.environ.get("EYESIM_ROBIOS")
           else "the installed eyesim package")
    raise LibraryMissing(
        f"the RoBIOS C library is not installed: looked for {header} and {lib_dir}/libeyesim.* "
        f"({how}). Reinstall eyesim with pip, or build it for development with\n"
        f"  cmake -S robios -B build/robios-build && cmake --build build/robios-build && "
        f"cmake --install build/robios-build --prefix build/robios\n"
        f"and set EYESIM_ROBIOS=<checkout>/build/robios")


def compiler_command(language: str, args: list[str], prefix: Path | None = None) -> list[str]:
    """The full compiler command line for `eyesim <language> args...`."""
    prefix = paths.robios_dir() if prefix is None else Path(prefix)
    check_library(prefix)
    variable, default = COMPILERS[language]
    compiler = shlex.split(os.environ.get(variable) or default)  # $CC may carry flags: "ccache gcc"
    command = [*compiler, f"-I{prefix / 'include'}"]
    if language == "cc" and not chooses_features(args):
        # EyeSim programs call usleep and use M_PI, which strict -std=c99/c11 hides; this asks for
        # them whatever the program includes first (C++ compilers define _GNU_SOURCE anyway).
        command.append("-D_DEFAULT_SOURCE")
    command += args
    if links(args):
        lib_dir = prefix / "lib"
        # Libraries after the sources (static linking needs that order); the rpath lets the
        # program find libeyesim.so without LD_LIBRARY_PATH.
        command += [f"-L{lib_dir}", f"-Wl,-rpath,{lib_dir}", "-leyesim", "-lpthread", "-lm"]
    return command


def run_compiler(language: str, args: list[str], prefix: Path | None = None) -> int:
    """Runs the compiler; returns its exit status (1 when the library or compiler is missing)."""
    try:
        command = compiler_command(language, args, prefix)
    except LibraryMissing as error:
        print(f"eyesim {language}: {error}", file=sys.stderr)
        return 1
    try:
        status = subprocess.call(command)
    except FileNotFoundError:
        variable = COMPILERS[language][0]
        print(f"eyesim {language}: compiler {command[0]!r} not found; install one or set {variable}",
              file=sys.stderr)
        return 1
    return 128 - status if status < 0 else status  # killed by a signal: the shell's convention


def register(subparsers) -> None:
    for language, what in (("cc", "C"), ("c++", "C++")):
        variable, default = COMPILERS[language]
        parser = subparsers.add_parser(
            language,
            help=f"compile a {what} RoBIOS program",
            description=(f"Runs ${variable} (default {default}) with the RoBIOS headers and libeyesim, "
                         f"e.g. `eyesim {language} prog.c -o prog`. Every argument goes to the compiler."),
            add_help=False,  # -h/--help belong to the compiler too
            prefix_chars="\0",  # no argument looks like an option: all of them pass through
        )
        parser.add_argument("args", nargs=argparse.REMAINDER, metavar="COMPILER_ARG")
        parser.set_defaults(func=lambda ns, language=language: run_compiler(language, ns.args))
