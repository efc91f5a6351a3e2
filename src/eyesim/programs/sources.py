"""Programs given as source: `--program 1=drive.c` (or .cpp) is compiled with `eyesim cc` into a
cache and the executable run; it is rebuilt only when the source, a header beside it, the
compiler or EyeSim changed. A name without an extension (`--program 1=drive`, as EyeSim's scene
files name programs) finds drive.c, drive.cpp or drive.py beside it when there is no such file."""

from __future__ import annotations

import hashlib
import os
import subprocess
from pathlib import Path

from eyesim import __version__, paths

LANGUAGES = {".c": "cc", ".cpp": "c++", ".cc": "c++", ".cxx": "c++"}
HEADERS = (".h", ".hpp", ".hh")
COMPILE_SECONDS = 120
COMPILER_OUTPUT = "compiler-output.txt"  # beside a cached program: what the compiler said building it


class BuildError(Exception):
    """The program's source does not compile (the message holds the compiler's output)."""


def locate(path: Path) -> Path:
    """`path` itself when it is a file, else the one source beside it with its name plus a known
    extension (`drive` -> `drive.c`); `path` again when there is none (the caller reports it)."""
    if path.suffix or _is_file(path):
        return path
    found = [
        path.with_name(path.name + suffix)
        for suffix in paths.PROGRAM_SOURCE_SUFFIXES
        if _is_file(path.with_name(path.name + suffix))
    ]
    return found[0] if len(found) == 1 else path


def _is_file(path: Path) -> bool:
    try:
        return path.is_file()
    except OSError:  # a name the file system refuses (too long): not a file; the launcher says why
        return False


def is_source(path: Path) -> bool:
    return path.suffix.lower() in LANGUAGES


def executable_for(source: Path) -> tuple[Path, str]:
    """The compiled program for a C/C++ source (built when its cache entry is missing), and what
    the compiler said (warnings); BuildError when it does not compile."""
    from eyesim.programs import toolchain

    source = source.resolve()
    language = LANGUAGES[source.suffix.lower()]
    try:
        output = toolchain.executable_name(paths.cache_dir() / "programs" / _key(source, language) / source.stem)
        if output.is_file():
            return output, _compiler_said(output)
        output.parent.mkdir(parents=True, exist_ok=True)
        building = output.with_name(f".{output.name}.{os.getpid()}")
        args = [toolchain.source_argument(source.name), "-o", str(building)]
        command = toolchain.compiler_command(language, args)
        result = subprocess.run(
            command, cwd=source.parent, capture_output=True, text=True, errors="replace", timeout=COMPILE_SECONDS
        )
    except (toolchain.LibraryMissing, toolchain.CompilerMissing) as error:
        raise BuildError(str(error)) from None
    except subprocess.TimeoutExpired:
        raise BuildError(f"compiling {source.name} took longer than {COMPILE_SECONDS} s") from None
    said = (result.stdout + result.stderr).replace(str(building), source.stem)
    if result.returncode != 0:
        building.unlink(missing_ok=True)
        raise BuildError(said.strip() or f"the compiler failed with status {result.returncode}")
    # its warnings stay with it: a build taken from the cache warns as the first one did
    output.with_name(COMPILER_OUTPUT).write_text(said, encoding="utf-8")
    os.replace(building, output)  # whole or not at all, whoever builds the same program at once
    toolchain.place_library(["-o", str(output)])
    return output, said


def _compiler_said(output: Path) -> str:
    try:
        return output.with_name(COMPILER_OUTPUT).read_text(encoding="utf-8")
    except OSError:  # built before the compiler's words were kept
        return ""


def _key(source: Path, language: str) -> str:
    """What the program is built from: the source, the headers beside it, the compiler, EyeSim."""
    from eyesim.programs import toolchain

    digest = hashlib.sha256()
    digest.update(f"{__version__}\0{language}\0{toolchain.find_compiler(language)}\0{paths.robios_dir()}\0".encode())
    for path in [source, *sorted(p for p in source.parent.iterdir() if p.suffix.lower() in HEADERS)]:
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:24]
