"""Builds EyeSim's binary wheels for Linux x86_64, Windows amd64 and macOS arm64/x86_64 on one Linux
machine: the RoBIOS C library cross-compiled for each system with Zig (robios/cmake/zig.cmake), put
into one copy per system of the package's Python part.

    python tools/build_wheels.py [--out-dir dist] [--platform macos-arm64 ...]

The Python part and the library do not depend on the Python version (the `eye` package loads the
library with ctypes; there are no extension modules), so every wheel is tagged py3-none-<platform>.
The Python part comes from the project's own build backend (scikit-build-core, with its CMake step
turned off), so the wheels' metadata (dependencies, environment markers, extras, entry points) is
what `pip install .` makes. Each wheel is that wheel's files, plus the library and headers under
wheel.install-dir (eyesim/robios/), with its own WHEEL tags and RECORD.

Incremental: the Python part is built again only when its files change, CMake rebuilds only what
changed, and Zig keeps what it compiled in its cache (the first build for a system takes about a
minute, for its C library). `make wheels` runs this with .venv's Python, which needs pip and the
ziglang package.
"""

from __future__ import annotations

import argparse
import base64
import concurrent.futures
import contextlib
import csv
import hashlib
import io
import json
import os
import shutil
import stat
import subprocess
import sys
import time
import zipfile
from dataclasses import dataclass
from pathlib import Path

try:
    import tomllib
except ImportError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]
ROBIOS = ROOT / "robios"
TOOLCHAIN = ROBIOS / "cmake" / "zig.cmake"
DEFAULT_OUT_DIR = ROOT / "dist"
DEFAULT_BUILD_DIR = ROOT / "build" / "wheels"

# Oldest macOS versions supported: Zig targets them (-target aarch64-macos.11.0) and the wheels'
# tags name them (macosx_11_0_arm64), from these same numbers. 11.0 is the first macOS on arm64.
MACOS_ARM64_MIN = (11, 0)
MACOS_X86_64_MIN = (10, 15)
# glibc the Linux library may use at most: built against it (-target x86_64-linux-gnu.2.17), so the
# manylinux_2_17 tag is honest.
GLIBC_MIN = (2, 17)


@dataclass(frozen=True)
class Platform:
    name: str  # as in tests/support/cross.py's TARGETS
    zig_target: str
    tag: str  # the wheel's platform tag
    library: str  # the shared library's file name, as eye/_library.py looks for it

    @property
    def wheel_tag(self) -> str:
        return f"py3-none-{self.tag}"


def _version(numbers: tuple[int, int], separator: str) -> str:
    return separator.join(str(n) for n in numbers)


PLATFORMS = (
    Platform(
        "linux-x86_64",
        f"x86_64-linux-gnu.{_version(GLIBC_MIN, '.')}",
        f"manylinux_{_version(GLIBC_MIN, '_')}_x86_64",
        "libeyesim.so",
    ),
    Platform("windows-x86_64", "x86_64-windows-gnu", "win_amd64", "eyesim.dll"),
    Platform(
        "macos-arm64",
        f"aarch64-macos.{_version(MACOS_ARM64_MIN, '.')}",
        f"macosx_{_version(MACOS_ARM64_MIN, '_')}_arm64",
        "libeyesim.dylib",
    ),
    Platform(
        "macos-x86_64",
        f"x86_64-macos.{_version(MACOS_X86_64_MIN, '.')}",
        f"macosx_{_version(MACOS_X86_64_MIN, '_')}_x86_64",
        "libeyesim.dylib",
    ),
)
PLATFORMS_BY_NAME = {platform.name: platform for platform in PLATFORMS}

# What the Python part is made from: when one of these changes, it is built again.
PURE_INPUTS = ("src/eyesim", "src/eye", "pyproject.toml", "README.md")

# Zip entries' time when the environment does not give one (SOURCE_DATE_EPOCH): the zip format's
# earliest, so that the same inputs give the same wheel.
ZIP_EPOCH = (1980, 1, 1, 0, 0, 0)


class BuildError(RuntimeError):
    def __init__(self, message: str, written: dict[str, Path] | None = None):
        super().__init__(message)
        self.written = written or {}  # the wheels that were written all the same


def log(message: str) -> None:
    print(f"build_wheels: {message}", flush=True)


# ---- The Python part --------------------------------------------------------------------------


def _fingerprint(paths: list[Path]) -> str:
    """Names, sizes and modification times of every file under the given paths."""
    entries = []
    for path in paths:
        files = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file())
        for file in files:
            if "__pycache__" in file.parts:
                continue
            info = file.stat()
            entries.append([file.relative_to(ROOT).as_posix(), info.st_size, info.st_mtime_ns])
    return hashlib.sha256(json.dumps(entries).encode()).hexdigest()


def pure_wheel(build_dir: Path) -> Path:
    """The package's Python part as the build backend makes it (py3-none-any, without the C
    library): built again only when its inputs changed."""
    wheel_dir = build_dir / "pure"
    stamp = wheel_dir / "inputs.sha256"
    fingerprint = _fingerprint([ROOT / name for name in PURE_INPUTS])
    wheels = sorted(wheel_dir.glob("*.whl"))
    if len(wheels) == 1 and stamp.is_file() and stamp.read_text() == fingerprint:
        return wheels[0]
    for old in wheels:
        old.unlink()
    wheel_dir.mkdir(parents=True, exist_ok=True)
    log("building the Python part (the build backend without its CMake step)")
    (build_dir / "pure.log").write_text("")
    # wheel.cmake=false: scikit-build-core copies the packages and writes the metadata only.
    _run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--quiet",
            "--no-deps",
            "--wheel-dir",
            str(wheel_dir),
            "--config-settings=wheel.cmake=false",
            f"--config-settings=build-dir={build_dir / 'pure-build'}",
            str(ROOT),
        ],
        log_file=build_dir / "pure.log",
    )
    wheels = sorted(wheel_dir.glob("*.whl"))
    if len(wheels) != 1:
        raise BuildError(f"the build backend made {len(wheels)} wheels in {wheel_dir}, expected one")
    _check_pure(wheels[0])
    stamp.write_text(fingerprint)
    return wheels[0]


def _check_pure(wheel: Path) -> None:
    """The binary wheels' py3-none tag holds only if the Python part is pure Python."""
    with zipfile.ZipFile(wheel) as archive:
        compiled = [name for name in archive.namelist() if name.endswith((".so", ".pyd", ".dll", ".dylib"))]
    if compiled or not wheel.name.endswith("-py3-none-any.whl"):
        raise BuildError(
            f"{wheel.name} is not pure Python ({compiled or 'its tag'}); the binary wheels could not be tagged py3-none"
        )


# ---- The C library ----------------------------------------------------------------------------


def build_library(platform: Platform, build_dir: Path) -> Path:
    """libeyesim and its headers for a platform, cross-compiled with Zig; returns the install
    prefix (include/, lib/)."""
    if not TOOLCHAIN.is_file():
        raise BuildError(f"the Zig toolchain file {TOOLCHAIN} is missing")
    cmake_dir = build_dir / platform.name / "cmake"
    prefix = build_dir / platform.name / "prefix"
    log_file = build_dir / platform.name / "build.log"
    log_file.parent.mkdir(parents=True, exist_ok=True)
    log_file.write_text("")
    _run(
        [
            "cmake",
            "-S",
            str(ROBIOS),
            "-B",
            str(cmake_dir),
            f"-DCMAKE_TOOLCHAIN_FILE={TOOLCHAIN}",
            f"-DZIG_TARGET={platform.zig_target}",
            f"-DZIG_PYTHON={sys.executable}",
            "-DCMAKE_BUILD_TYPE=Release",
        ],
        log_file=log_file,
    )
    _run(["cmake", "--build", str(cmake_dir), "--parallel", str(os.cpu_count() or 1)], log_file=log_file)
    # A fresh prefix, so that nothing of an earlier install stays behind.
    shutil.rmtree(prefix, ignore_errors=True)
    _run(["cmake", "--install", str(cmake_dir), "--prefix", str(prefix)], log_file=log_file)
    library = prefix / "lib" / platform.library
    if not library.is_file():
        raise BuildError(f"{platform.name}: the build installed no {library}")
    return prefix


def _run(command: list[str], log_file: Path) -> None:
    """Runs a command with its output going to log_file; on failure, raises with the log's end."""
    with open(log_file, "a") as out:
        out.write(f"$ {' '.join(command)}\n")
        out.flush()
        status = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT, cwd=ROOT)
    if status != 0:
        tail = "\n".join(log_file.read_text(errors="replace").splitlines()[-30:])
        raise BuildError(f"{command[0]} failed (exit status {status}); the end of {log_file}:\n{tail}")


# ---- Wheels -----------------------------------------------------------------------------------


def install_dir() -> str:
    """Where in the wheel the C library goes: pyproject.toml's tool.scikit-build wheel.install-dir,
    as for `pip install .`."""
    with open(ROOT / "pyproject.toml", "rb") as file:
        settings = tomllib.load(file)["tool"]["scikit-build"]
    value = settings.get("wheel", {}).get("install-dir")
    if not value:
        raise BuildError("pyproject.toml has no tool.scikit-build wheel.install-dir")
    return value.strip("/")


def _zip_time() -> tuple[int, int, int, int, int, int]:
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if not epoch:
        return ZIP_EPOCH
    return max(ZIP_EPOCH, time.gmtime(int(epoch))[:6])


def record_hash(data: bytes) -> str:
    """A RECORD file's hash of a file: sha256, urlsafe base64 without padding."""
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode("ascii")
    return f"sha256={digest}"


class WheelWriter:
    """Writes a wheel: the files, then the dist-info's WHEEL and RECORD (RECORD last)."""

    def __init__(self, path: Path, dist_info: str):
        self.path = path
        self.dist_info = dist_info
        self.archive = zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED)
        self.records: list[tuple[str, str, str]] = []

    def add(self, name: str, data: bytes, mode: int = 0o644, date_time=None) -> None:
        info = zipfile.ZipInfo(name, date_time=date_time or _zip_time())
        info.compress_type = zipfile.ZIP_DEFLATED
        info.external_attr = (stat.S_IFREG | mode) << 16
        self.archive.writestr(info, data)
        self.records.append((name, record_hash(data), str(len(data))))

    def close(self, tags: list[str], generator: str) -> None:
        wheel = [
            "Wheel-Version: 1.0",
            f"Generator: {generator}",
            "Root-Is-Purelib: false",
            *(f"Tag: {tag}" for tag in tags),
        ]
        self.add(f"{self.dist_info}/WHEEL", ("\n".join(wheel) + "\n").encode())
        record_name = f"{self.dist_info}/RECORD"
        text = io.StringIO()
        writer = csv.writer(text, lineterminator="\n")
        writer.writerows(self.records)
        writer.writerow((record_name, "", ""))
        self.add(record_name, text.getvalue().encode())
        self.archive.close()


def assemble(pure: Path, platform: Platform, prefix: Path, out_dir: Path) -> Path:
    """The platform's wheel: the Python part's files, the library and headers, WHEEL and RECORD."""
    distribution, version = pure.name.split("-")[:2]
    dist_info = f"{distribution}-{version}.dist-info"
    target = out_dir / f"{distribution}-{version}-{platform.wheel_tag}.whl"
    partial = target.with_name(f".{target.name}.partial")
    out_dir.mkdir(parents=True, exist_ok=True)
    library_root = install_dir()
    with zipfile.ZipFile(pure) as source:
        entries = [info for info in source.infolist() if not info.is_dir()]
        replaced = {f"{dist_info}/WHEEL", f"{dist_info}/RECORD"}
        if not replaced <= {info.filename for info in entries}:
            raise BuildError(f"{pure.name} has no {dist_info}/WHEEL and RECORD")
        clashes = [info.filename for info in entries if info.filename.startswith(f"{library_root}/")]
        if clashes:
            raise BuildError(f"{pure.name} already has files under {library_root}/: {clashes[:3]}")
        writer = WheelWriter(partial, dist_info)
        try:
            package = [info for info in entries if not info.filename.startswith(f"{dist_info}/")]
            metadata = [
                info for info in entries if info.filename.startswith(f"{dist_info}/") and info.filename not in replaced
            ]
            for info in package:
                writer.add(info.filename, source.read(info), _mode(info), info.date_time)
            for file in sorted(p for p in prefix.rglob("*") if p.is_file()):
                name = f"{library_root}/{file.relative_to(prefix).as_posix()}"
                writer.add(name, file.read_bytes(), stat.S_IMODE(file.stat().st_mode) | 0o644)
            for info in metadata:
                writer.add(info.filename, source.read(info), _mode(info), info.date_time)
            writer.close([platform.wheel_tag], "eyesim tools/build_wheels.py")
        except BaseException:
            writer.archive.close()
            partial.unlink(missing_ok=True)
            raise
    os.replace(partial, target)
    # Earlier versions' wheels for this platform would be mistaken for this one's.
    for old in out_dir.glob(f"{distribution}-*-{platform.wheel_tag}.whl"):
        if old != target:
            old.unlink()
    return target


def _mode(info: zipfile.ZipInfo) -> int:
    mode = stat.S_IMODE(info.external_attr >> 16)
    return mode or 0o644


# ---- All of it --------------------------------------------------------------------------------


@contextlib.contextmanager
def _locked(build_dir: Path):
    """One build at a time in a build folder (`make wheels` beside the packaging tests)."""
    build_dir.mkdir(parents=True, exist_ok=True)
    try:
        import fcntl
    except ImportError:  # Windows: no lock
        yield
        return
    with open(build_dir / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def check_zig() -> None:
    try:
        import ziglang  # noqa: F401
    except ImportError:
        raise BuildError(
            f"the ziglang package is missing from {sys.executable}: pip install ziglang "
            f"(it is in eyesim's [test] and [zig] extras)"
        ) from None


def build(
    out_dir: Path = DEFAULT_OUT_DIR, build_dir: Path = DEFAULT_BUILD_DIR, platforms: tuple[Platform, ...] = PLATFORMS
) -> dict[str, Path]:
    """Builds the wheels for the platforms; returns {platform name: wheel}. Raises BuildError
    naming every platform that failed (after writing the others' wheels)."""
    out_dir, build_dir = Path(out_dir).resolve(), Path(build_dir).resolve()
    check_zig()
    with _locked(build_dir):
        pure = pure_wheel(build_dir)
        written: dict[str, Path] = {}
        failures: dict[str, BaseException] = {}
        # The systems build side by side (each is mostly one Zig process at a time).
        with concurrent.futures.ThreadPoolExecutor(max_workers=len(platforms) or 1) as pool:
            futures = {pool.submit(build_library, platform, build_dir): platform for platform in platforms}
            for future in concurrent.futures.as_completed(futures):
                platform = futures[future]
                try:
                    prefix = future.result()
                except (BuildError, OSError) as error:
                    failures[platform.name] = error
                    continue
                written[platform.name] = assemble(pure, platform, prefix, out_dir)
    if failures:
        details = "\n\n".join(f"{name}: {error}" for name, error in failures.items())
        raise BuildError(f"no wheel for {', '.join(failures)}:\n{details}", written)
    return {platform.name: written[platform.name] for platform in platforms}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out-dir", type=Path, default=DEFAULT_OUT_DIR, help="where the wheels go (dist/)")
    parser.add_argument(
        "--build-dir",
        type=Path,
        default=DEFAULT_BUILD_DIR,
        help="intermediate files, kept for the next build (build/wheels/)",
    )
    parser.add_argument(
        "--platform",
        action="append",
        choices=sorted(PLATFORMS_BY_NAME),
        dest="platforms",
        help="build only for this platform (repeatable; default: all)",
    )
    args = parser.parse_args(argv)
    platforms = tuple(PLATFORMS_BY_NAME[name] for name in args.platforms) if args.platforms else PLATFORMS
    started = time.monotonic()
    failure = None
    try:
        wheels = build(args.out_dir, args.build_dir, platforms)
    except BuildError as error:
        failure, wheels = error, error.written
    for wheel in wheels.values():
        try:
            shown = wheel.relative_to(Path.cwd())
        except ValueError:
            shown = wheel
        print(f"wrote {shown}")
    if failure is not None:
        print(f"build_wheels: {failure}", file=sys.stderr)
        return 1
    log(f"{len(wheels)} wheels in {time.monotonic() - started:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
