"""The binary wheels `make wheels` writes (tools/build_wheels.py): one per system, each with the RoBIOS
C library cross-compiled for it by Zig, valid tags and RECORD, the package's files and metadata;
pip takes each on its platform, the Linux one works installed, and C programs link against the
Windows and macOS libraries."""

from __future__ import annotations

import base64
import csv
import hashlib
import importlib.util
import io
import os
import re
import struct
import subprocess
import sys
import zipfile
from email.parser import Parser
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.tags import parse_tag
from packaging.utils import parse_wheel_filename

from support.cross import TARGETS, zig_cc

try:
    import tomllib
except ImportError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]

# What each wheel must be: its platform tag, the library's file and the library's binary format.
EXPECTED = {
    "linux-x86_64": ("manylinux_2_17_x86_64", "libeyesim.so"),
    "windows-x86_64": ("win_amd64", "eyesim.dll"),
    "macos-arm64": ("macosx_11_0_arm64", "libeyesim.dylib"),
    "macos-x86_64": ("macosx_10_15_x86_64", "libeyesim.dylib"),
}
LIBRARY_DIR = "eyesim/robios"

# Mach-O
MH_MAGIC_64 = 0xFEEDFACF
CPU_TYPE_X86_64 = 0x01000007
CPU_TYPE_ARM64 = 0x0100000C
MH_EXECUTE, MH_DYLIB = 2, 6
LC_LOAD_DYLIB, LC_ID_DYLIB, LC_VERSION_MIN_MACOSX, LC_BUILD_VERSION = 0xC, 0xD, 0x24, 0x32
MACHO_CPU = {"macos-arm64": CPU_TYPE_ARM64, "macos-x86_64": CPU_TYPE_X86_64}


def load_build_wheels():
    spec = importlib.util.spec_from_file_location("build_wheels", ROOT / "tools" / "build_wheels.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def wheels(tmp_path_factory) -> dict[str, Path]:
    """The four wheels, built once a session by `make wheels`'s code into a folder of the session
    (its intermediate files stay in build/wheels/, so a later session builds only what changed)."""
    build_wheels = load_build_wheels()
    return build_wheels.build(out_dir=tmp_path_factory.mktemp("dist"))


def wheel_files(wheel: Path) -> dict[str, bytes]:
    with zipfile.ZipFile(wheel) as archive:
        return {info.filename: archive.read(info) for info in archive.infolist() if not info.is_dir()}


def dist_info(files: dict[str, bytes]) -> str:
    (name,) = {name.split("/")[0] for name in files if name.split("/")[0].endswith(".dist-info")}
    return name


# ---- Binary formats, from their headers -------------------------------------------------------


def elf_header(data: bytes) -> dict:
    assert data[:4] == b"\x7fELF", "not ELF"
    e_type, e_machine = struct.unpack_from("<HH", data, 16)
    return {"class": data[4], "little_endian": data[5] == 1, "type": e_type, "machine": e_machine}


def glibc_versions(data: bytes) -> set[tuple[int, ...]]:
    """The glibc symbol versions an ELF file asks for (their names are in its string table)."""
    return {
        tuple(int(part) for part in match.split(b".")) for match in re.findall(rb"\x00GLIBC_(\d+(?:\.\d+)+)\x00", data)
    }


def pe_header(data: bytes) -> dict:
    assert data[:2] == b"MZ", "not a PE file"
    (offset,) = struct.unpack_from("<I", data, 0x3C)
    assert data[offset : offset + 4] == b"PE\x00\x00", "no PE signature"
    machine, _, _, _, _, _, characteristics = struct.unpack_from("<HHIIIHH", data, offset + 4)
    (optional_magic,) = struct.unpack_from("<H", data, offset + 24)
    return {"machine": machine, "dll": bool(characteristics & 0x2000), "pe32_plus": optional_magic == 0x20B}


def macho(data: bytes) -> dict:
    """A 64-bit Mach-O file's CPU, file type, install name, linked dylibs and minimum macOS."""
    magic, cpu, _, filetype, ncmds, _, _, _ = struct.unpack_from("<IiiIIIII", data, 0)
    assert magic == MH_MAGIC_64, f"not 64-bit little-endian Mach-O (magic {magic:#x})"
    info = {"cpu": cpu, "filetype": filetype, "id": None, "loads": [], "minos": None}
    offset = 32
    for _ in range(ncmds):
        command, size = struct.unpack_from("<II", data, offset)
        if command in (LC_ID_DYLIB, LC_LOAD_DYLIB):
            (name_offset,) = struct.unpack_from("<I", data, offset + 8)
            name = data[offset + name_offset : offset + size].split(b"\x00")[0].decode()
            if command == LC_ID_DYLIB:
                info["id"] = name
            else:
                info["loads"].append(name)
        elif command in (LC_BUILD_VERSION, LC_VERSION_MIN_MACOSX):
            (version,) = struct.unpack_from("<I", data, offset + (12 if command == LC_BUILD_VERSION else 8))
            info["minos"] = (version >> 16, (version >> 8) & 0xFF)
        offset += size
    return info


def tag_macos_version(tag: str) -> tuple[int, int]:
    _, major, minor, _ = tag.split("_", 3)
    return int(major), int(minor)


# ---- What every wheel is ----------------------------------------------------------------------


def test_one_wheel_per_system(wheels):
    assert set(wheels) == set(EXPECTED)
    for name, wheel in wheels.items():
        distribution, version, build, tags = parse_wheel_filename(wheel.name)
        assert (str(distribution), str(version), build) == ("eyesim", project()["version"], ())
        assert {str(tag) for tag in tags} == {f"py3-none-{EXPECTED[name][0]}"}


@pytest.mark.parametrize("name", EXPECTED)
def test_wheel_file_and_record(wheels, name):
    """WHEEL names the tag of the file name and a platform-specific (non-purelib) root; RECORD
    lists every file once with its sha256 and size, and itself without."""
    wheel = wheels[name]
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
        assert archive.testzip() is None
    assert len(names) == len(set(names)), "duplicate entries"
    files = wheel_files(wheel)
    info = dist_info(files)
    assert info == "eyesim-" + project()["version"] + ".dist-info"
    fields = Parser().parsestr(files[f"{info}/WHEEL"].decode())
    assert fields["Wheel-Version"] == "1.0"
    assert fields["Root-Is-Purelib"] == "false"
    assert fields.get_all("Tag") == [f"py3-none-{EXPECTED[name][0]}"]
    assert {str(tag) for tag in parse_tag(fields["Tag"])} == {str(tag) for tag in parse_wheel_filename(wheel.name)[3]}

    rows = list(csv.reader(io.StringIO(files[f"{info}/RECORD"].decode())))
    recorded = {row[0]: row for row in rows}
    assert len(recorded) == len(rows), "a file is listed twice in RECORD"
    assert set(recorded) == set(files)
    assert recorded[f"{info}/RECORD"][1:] == ["", ""]
    for file, data in files.items():
        if file == f"{info}/RECORD":
            continue
        _, digest, size = recorded[file]
        algorithm, _, value = digest.partition("=")
        assert algorithm == "sha256", file
        assert base64.urlsafe_b64decode(value + "=" * (-len(value) % 4)) == hashlib.sha256(data).digest(), file
        assert int(size) == len(data), file


@pytest.mark.parametrize("name", EXPECTED)
def test_wheel_has_the_package(wheels, name):
    """Every file of the eyesim and eye packages (Python modules, viewer bundle, scenes, robots)
    and the headers, and nothing outside the packages and the dist-info."""
    files = wheel_files(wheels[name])
    tracked = subprocess.run(
        ["git", "ls-files", "src/eyesim", "src/eye"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.split()
    expected = {path.removeprefix("src/") for path in tracked if (ROOT / path).is_file()}
    assert expected, "git lists no package files"
    missing = expected - set(files)
    assert not missing, f"missing from the wheel: {sorted(missing)[:10]}"
    for required in (
        "eyesim/web/static/index.html",
        "eye/_prototypes.py",
        "eyesim/paths.py",
        "eyesim/protocol/viewer.schema.json",
        f"{LIBRARY_DIR}/include/eyebot.h",
        f"{LIBRARY_DIR}/include/eyebot++.h",
    ):
        assert required in files
    assert any(file.startswith("eyesim/web/static/assets/") for file in files)
    assert any(file.startswith("eyesim/data/scenes/") for file in files)
    assert files[f"{LIBRARY_DIR}/include/eyebot.h"] == (ROOT / "robios/include/eyebot.h").read_bytes()
    info = dist_info(files)
    assert {file.split("/")[0] for file in files} == {"eyesim", "eye", info}
    # Nothing compiled but the C library (the py3-none tag says the files suit any Python 3).
    compiled = [
        file
        for file in files
        if file.endswith((".so", ".pyd", ".dll", ".dylib")) and not file.startswith(f"{LIBRARY_DIR}/lib/")
    ]
    assert not compiled


@pytest.mark.parametrize("name", EXPECTED)
def test_metadata_keeps_dependencies_and_markers(wheels, name):
    """METADATA's requirements are pyproject.toml's, with their environment markers and extras."""
    files = wheel_files(wheels[name])
    info = dist_info(files)
    metadata = Parser().parsestr(files[f"{info}/METADATA"].decode())
    declared = project()
    assert metadata["Name"] == "eyesim" and metadata["Version"] == declared["version"]
    assert metadata["Requires-Python"] == declared["requires-python"]
    wanted = {str(Requirement(text)) for text in declared["dependencies"]}
    for extra, requirements in declared["optional-dependencies"].items():
        for text in requirements:
            requirement = Requirement(text)
            marker = f'extra == "{extra}"'
            if requirement.marker is not None:
                marker = f"({requirement.marker}) and {marker}"
            requirement.marker = None
            wanted.add(str(Requirement(f"{requirement}; {marker}")))
    got = {str(Requirement(text)) for text in metadata.get_all("Requires-Dist")}
    assert got == wanted
    assert set(metadata.get_all("Provides-Extra")) == set(declared["optional-dependencies"])
    ziglang = [
        Requirement(text)
        for text in metadata.get_all("Requires-Dist")
        if Requirement(text).name == "ziglang" and "extra" not in str(Requirement(text).marker)
    ]
    assert len(ziglang) == 1 and ziglang[0].marker is not None
    assert ziglang[0].marker.evaluate({"sys_platform": "win32"})
    assert ziglang[0].marker.evaluate({"sys_platform": "darwin"})
    assert not ziglang[0].marker.evaluate({"sys_platform": "linux"})
    entry_points = files[f"{info}/entry_points.txt"].decode()
    assert "eyesim = eyesim.app.cli:main" in entry_points


def project() -> dict:
    with open(ROOT / "pyproject.toml", "rb") as file:
        return tomllib.load(file)["project"]


# ---- The libraries ----------------------------------------------------------------------------


def library(wheels, name: str) -> bytes:
    return wheel_files(wheels[name])[f"{LIBRARY_DIR}/lib/{EXPECTED[name][1]}"]


def test_linux_library_is_x86_64_elf_for_glibc_2_17(wheels):
    data = library(wheels, "linux-x86_64")
    header = elf_header(data)
    assert header == {"class": 2, "little_endian": True, "type": 3, "machine": 62}  # ELF64, ET_DYN, x86-64
    versions = glibc_versions(data)
    assert versions, "the library names no glibc versions"
    assert max(versions) <= (2, 17), f"needs glibc {max(versions)}, newer than manylinux_2_17 allows"


def test_windows_library_is_x86_64_pe32_plus_dll(wheels):
    data = library(wheels, "windows-x86_64")
    assert pe_header(data) == {"machine": 0x8664, "dll": True, "pe32_plus": True}
    assert b"VWSetSpeed\x00" in data  # exported by name
    files = wheel_files(wheels["windows-x86_64"])
    assert f"{LIBRARY_DIR}/lib/libeyesim.dll.a" in files  # the import library programs link with


@pytest.mark.parametrize("name", ["macos-arm64", "macos-x86_64"])
def test_macos_library_is_mach_o_dylib_for_the_tagged_version(wheels, name):
    info = macho(library(wheels, name))
    assert info["cpu"] == MACHO_CPU[name]
    assert info["filetype"] == MH_DYLIB
    # Programs find it through the rpath `eyesim cc` gives them.
    assert info["id"] == "@rpath/libeyesim.dylib"
    # The oldest macOS it runs on is the one its tag names.
    assert info["minos"] == tag_macos_version(EXPECTED[name][0])


# ---- pip, an installed wheel, programs linked against the libraries ---------------------------

PIP_PLATFORM = {name: tag for name, (tag, _) in EXPECTED.items()}


@pytest.mark.parametrize("name", EXPECTED)
def test_pip_takes_the_wheel_on_its_platform(wheels, name, tmp_path):
    result = pip_dry_run(wheels[name], PIP_PLATFORM[name], tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "eyesim-" + project()["version"] in result.stdout


def test_pip_refuses_a_wheel_of_another_platform(wheels, tmp_path):
    """The check above means something: pip does look at the platform."""
    result = pip_dry_run(wheels["windows-x86_64"], PIP_PLATFORM["macos-arm64"], tmp_path)
    assert result.returncode != 0
    assert "is not a supported wheel on this platform" in result.stderr


def pip_dry_run(wheel: Path, platform: str, tmp_path: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "install",
            "--dry-run",
            "--only-binary=:all:",
            "--platform",
            platform,
            "--python-version",
            "3.13",
            "--no-deps",
            "--no-index",
            "--target",
            str(tmp_path / "target"),
            str(wheel),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )


PROGRAM = r"""
#include "eyebot.h"

int main(void) {
    LCDPrintf("driving %d\n", 1);
    VWSetSpeed(100, 0);
    OSWait(500);
    VWSetSpeed(0, 0);
    return KEYGet() == KEY1 ? 1 : 0;
}
"""


def test_linux_wheel_installed_finds_its_library_and_links_programs(wheels, tmp_path):
    """Installed into a new virtual environment (without its dependencies: those of the test
    environment are seen after the new environment's own packages), the eye package loads the
    wheel's library and `eyesim cc` links a program against it."""
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    python = venv / "bin" / "python"
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "--python",
            str(python),
            "install",
            "--quiet",
            "--no-deps",
            "--no-index",
            str(wheels["linux-x86_64"]),
        ],
        check=True,
        timeout=300,
    )
    site = Path(
        subprocess.run(
            [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
    )
    here = subprocess.run(
        [sys.executable, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    (site / "test-environment.pth").write_text(here + "\n")
    env = {key: value for key, value in os.environ.items() if key != "EYESIM_ROBIOS"}

    check = subprocess.run(
        [
            str(python),
            "-c",
            "import eye, eye._library as l; print(l.library_path()); print(eye.__file__); "
            "print(l.lib.VWSetSpeed is not None)",
        ],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )
    assert check.returncode == 0, check.stderr
    library_path, eye_file, bound = check.stdout.split("\n")[:3]
    assert Path(library_path) == site / LIBRARY_DIR / "lib" / "libeyesim.so"
    assert Path(eye_file).is_relative_to(site)
    assert bound == "True"

    (tmp_path / "prog.c").write_text(PROGRAM)
    compiled = subprocess.run(
        [str(venv / "bin" / "eyesim"), "cc", "-Wall", "prog.c", "-o", "prog"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )
    assert compiled.returncode == 0, compiled.stdout + compiled.stderr
    linked = subprocess.run(["ldd", str(tmp_path / "prog")], capture_output=True, text=True, check=True).stdout
    assert re.search(rf"libeyesim\.so => {re.escape(str(site / LIBRARY_DIR / 'lib' / 'libeyesim.so'))}", linked), linked


@pytest.fixture
def unpacked(wheels, tmp_path):
    """A wheel's files unpacked into a folder: unpacked(name) -> the library prefix (include/, lib/)."""

    def unpack(name: str) -> Path:
        with zipfile.ZipFile(wheels[name]) as archive:
            archive.extractall(tmp_path / name)
        return tmp_path / name / LIBRARY_DIR

    return unpack


@pytest.mark.parametrize("name", ["macos-arm64", "macos-x86_64"])
def test_program_links_against_macos_wheel(unpacked, name, tmp_path):
    prefix = unpacked(name)
    (tmp_path / "prog.c").write_text(PROGRAM)
    result = zig_cc(
        TARGETS[name],
        "-Wall",
        "prog.c",
        f"-I{prefix / 'include'}",
        f"-L{prefix / 'lib'}",
        "-leyesim",
        f"-Wl,-rpath,{prefix / 'lib'}",
        "-o",
        "prog",
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stderr
    program = macho((tmp_path / "prog").read_bytes())
    assert program["cpu"] == MACHO_CPU[name] and program["filetype"] == MH_EXECUTE
    assert "@rpath/libeyesim.dylib" in program["loads"]


def test_program_links_against_windows_wheel(unpacked, tmp_path):
    prefix = unpacked("windows-x86_64")
    (tmp_path / "prog.c").write_text(PROGRAM)
    result = zig_cc(
        TARGETS["windows-x86_64"],
        "-Wall",
        "prog.c",
        f"-I{prefix / 'include'}",
        f"-L{prefix / 'lib'}",
        "-leyesim",
        "-o",
        "prog.exe",
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stderr
    data = (tmp_path / "prog.exe").read_bytes()
    assert pe_header(data) == {"machine": 0x8664, "dll": False, "pe32_plus": True}
    assert b"eyesim.dll\x00" in data  # imports the wheel's DLL
