"""`eyesim cc` / `eyesim c++` (eyesim/programs/toolchain.py): command lines, pass-through, errors."""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
from pathlib import Path

import pytest

from eyesim.programs import toolchain

ROOT = Path(__file__).resolve().parents[2]


def test_linking_adds_the_library_after_the_arguments(robios_prefix, monkeypatch):
    monkeypatch.delenv("CC", raising=False)
    command = toolchain.compiler_command("cc", ["prog.c", "-o", "prog"], robios_prefix)
    lib = robios_prefix / "lib"
    assert command == [
        "cc",
        "-Wall",
        f"-I{robios_prefix / 'include'}",
        "-D_DEFAULT_SOURCE",
        "prog.c",
        "-o",
        "prog",
        f"-L{lib}",
        f"-Wl,-rpath,{lib}",
        "-leyesim",
        "-lpthread",
        "-lm",
    ]


@pytest.mark.parametrize(
    "args,added",
    [
        (["prog.c"], True),
        (["-D_POSIX_C_SOURCE=200112L", "prog.c"], False),
        (["-D", "_GNU_SOURCE", "prog.c"], False),
        (["-U_DEFAULT_SOURCE", "prog.c"], False),
        (["-DDEBUG", "-D", "N=3", "prog.c"], True),
    ],
)
def test_c_programs_get_the_default_feature_set_unless_they_choose_one(robios_prefix, args, added):
    # usleep and M_PI need _DEFAULT_SOURCE under strict -std=c99; C++ compilers set _GNU_SOURCE themselves.
    assert ("-D_DEFAULT_SOURCE" in toolchain.compiler_command("cc", args, robios_prefix)) == added
    assert "-D_DEFAULT_SOURCE" not in toolchain.compiler_command("c++", args, robios_prefix)


@pytest.mark.parametrize("flag", ["-c", "-E", "-S", "-fsyntax-only", "--version"])
def test_compile_only_runs_get_no_link_flags(robios_prefix, flag):
    command = toolchain.compiler_command("cc", [flag, "prog.c"], robios_prefix)
    assert f"-I{robios_prefix / 'include'}" in command
    assert not any(arg.startswith(("-L", "-l", "-Wl,")) for arg in command)


def test_compilers_come_from_cc_and_cxx(robios_prefix, monkeypatch):
    monkeypatch.setenv("CC", "ccache gcc -m64")
    monkeypatch.setenv("CXX", "clang++")
    assert toolchain.compiler_command("cc", ["-c", "a.c"], robios_prefix)[:3] == ["ccache", "gcc", "-m64"]
    assert toolchain.compiler_command("c++", ["-c", "a.cpp"], robios_prefix)[0] == "clang++"
    monkeypatch.delenv("CXX")
    assert toolchain.compiler_command("c++", ["-c", "a.cpp"], robios_prefix)[0] == "c++"


def test_missing_library_is_a_clear_error(tmp_path, capsys):
    assert toolchain.run_compiler("cc", ["prog.c"], tmp_path) == 1
    err = capsys.readouterr().err
    assert "RoBIOS C library is not installed" in err
    assert str(tmp_path / "include" / "eyebot.h") in err and str(tmp_path / "lib") in err


def test_missing_compiler_is_a_clear_error(robios_prefix, monkeypatch, capsys):
    monkeypatch.setenv("CC", "no-such-compiler-here")
    assert toolchain.run_compiler("cc", ["prog.c"], robios_prefix) == 1
    assert "compiler 'no-such-compiler-here' not found" in capsys.readouterr().err


def test_compiler_exit_status_is_returned(robios_prefix, tmp_path):
    bad = tmp_path / "bad.c"
    bad.write_text("int main(void) { return undeclared; }\n")
    assert toolchain.run_compiler("cc", ["-c", str(bad), "-o", str(tmp_path / "bad.o")], robios_prefix) != 0


def parser_with_toolchain() -> argparse.ArgumentParser:
    """The way eyesim/app/cli.py builds its parser, with only this module registered."""
    parser = argparse.ArgumentParser(prog="eyesim")
    toolchain.register(parser.add_subparsers(dest="command"))
    return parser


@pytest.mark.parametrize(
    "argv",
    [["cc", "-o", "prog", "prog.c"], ["c++", "-h"], ["cc", "--", "+x", ""], ["cc", "prog.c", "-Wl,-rpath,/x", "-O2"]],
)
def test_every_argument_passes_through(argv):
    args = parser_with_toolchain().parse_args(argv)
    assert args.args == argv[1:]
    assert callable(args.func)


def test_eyesim_cc_builds_a_program_that_runs_without_ld_library_path(
    robios_prefix, tmp_path, monkeypatch, free_port_env
):
    monkeypatch.setenv("EYESIM_ROBIOS", str(robios_prefix))
    source = tmp_path / "hello.c"
    source.write_text('#include "eyebot.h"\n#include <stdio.h>\nint main(void) { printf("%d\\n", KEY4); return 0; }\n')
    exe = tmp_path / "hello"
    args = parser_with_toolchain().parse_args(["cc", str(source), "-o", str(exe)])
    assert args.func(args) == 0
    ran = subprocess.run([str(exe)], capture_output=True, text=True, timeout=10, env=free_port_env)
    assert (ran.returncode, ran.stdout) == (0, "8\n")


def test_static_library_links_too(robios_prefix, tmp_path, fake_sim):
    source = tmp_path / "static.c"
    source.write_text(
        '#include "eyebot.h"\n#include <stdio.h>\nint main(void) { printf("%d\\n", PSDGet(PSD_LEFT)); return 0; }\n'
    )
    exe = tmp_path / "static"
    command = [
        "cc",
        "-std=c11",
        f"-I{robios_prefix / 'include'}",
        str(source),
        str(robios_prefix / "lib" / "libeyesim.a"),
        "-lpthread",
        "-lm",
        "-o",
        str(exe),
    ]
    built = subprocess.run(command, capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    fake_sim.script["PSD_GET"] = (321,)
    ran = subprocess.run([str(exe)], capture_output=True, text=True, timeout=20, env=fake_sim.env())
    assert (ran.returncode, ran.stdout, ran.stderr) == (0, "321\n", "")


def test_python_m_eyesim_cc(robios_prefix, tmp_path):
    source = tmp_path / "m.c"
    source.write_text('#include "eyebot.h"\nint main(void) { return KEY1 - 1; }\n')
    env = {**os.environ, "EYESIM_ROBIOS": str(robios_prefix)}
    done = subprocess.run(
        [sys.executable, "-m", "eyesim", "cc", "-o", str(tmp_path / "m"), str(source)],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr
    assert subprocess.run([str(tmp_path / "m")]).returncode == 0


# ---- Choosing the compiler --------------------------------------------------------------------


def no_system_compiler(monkeypatch):
    monkeypatch.delenv("CC", raising=False)
    monkeypatch.delenv("CXX", raising=False)
    monkeypatch.setattr(toolchain.shutil, "which", lambda name: None)


def test_without_a_system_compiler_zig_from_the_ziglang_package_is_used(robios_prefix, monkeypatch):
    no_system_compiler(monkeypatch)
    assert toolchain.compiler_command("cc", ["-c", "a.c"], robios_prefix)[:4] == [sys.executable, "-m", "ziglang", "cc"]
    assert toolchain.compiler_command("c++", ["-c", "a.cpp"], robios_prefix)[:4] == [
        sys.executable,
        "-m",
        "ziglang",
        "c++",
    ]


def test_with_no_compiler_at_all_the_error_says_what_to_install(robios_prefix, monkeypatch, capsys):
    no_system_compiler(monkeypatch)
    monkeypatch.setattr(toolchain.importlib.util, "find_spec", lambda name: None)
    assert toolchain.run_compiler("cc", ["prog.c"], robios_prefix) == 1
    err = capsys.readouterr().err
    assert "no C compiler found" in err and "pip install ziglang" in err and "xcode-select --install" in err


def test_a_program_built_with_zig_drives_a_robot(robios_prefix, tmp_path, monkeypatch):
    """A student with nothing but Python: `eyesim cc` falls back to Zig's clang, and the program runs."""
    from support.programs import read_trajectory, run_headless

    no_system_compiler(monkeypatch)
    monkeypatch.setenv("EYESIM_ROBIOS", str(robios_prefix))
    source = tmp_path / "forward.c"
    source.write_text('#include "eyebot.h"\nint main(void) { VWStraight(300, 200); VWWait(); return 0; }\n')
    exe = tmp_path / "forward"
    assert toolchain.run_compiler("cc", [str(source), "-o", str(exe)], robios_prefix) == 0
    result = run_headless("--program", f"1={exe}", "--record", "path.csv", cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    path = read_trajectory(tmp_path / "path.csv")[1]
    moved = ((path[-1]["x"] - path[0]["x"]) ** 2 + (path[-1]["y"] - path[0]["y"]) ** 2) ** 0.5
    assert moved == pytest.approx(0.300, abs=0.010)


def test_verbose_shows_the_command_and_is_not_passed_on(robios_prefix, tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("EYESIM_ROBIOS", str(robios_prefix))
    source = tmp_path / "v.c"
    source.write_text('#include "eyebot.h"\nint main(void) { return 0; }\n')
    args = parser_with_toolchain().parse_args(["cc", "--verbose", str(source), "-o", str(tmp_path / "v")])
    assert args.func(args) == 0
    shown = capsys.readouterr().err.strip().splitlines()[0]
    assert "--verbose" not in shown and str(source) in shown and "-leyesim" in shown


def test_on_windows_the_dll_is_put_beside_the_program(robios_prefix, tmp_path, monkeypatch):
    from eyesim import platform

    monkeypatch.setattr(platform, "WINDOWS", True)
    lib = tmp_path / "robios" / "lib"
    lib.mkdir(parents=True)
    (lib / "eyesim.dll").write_bytes(b"MZ fake dll")
    out = tmp_path / "out"
    out.mkdir()
    toolchain.place_library(["prog.c", "-o", "out/prog.exe"], cwd=tmp_path, prefix=tmp_path / "robios")
    assert (out / "eyesim.dll").read_bytes() == b"MZ fake dll"
    assert toolchain.executable_name(Path("build/prog")) == Path("build/prog.exe")
    command = toolchain.compiler_command("cc", ["prog.c", "-o", "prog.exe"], robios_prefix)
    assert "-lws2_32" in command and not any(arg.startswith("-Wl,-rpath") for arg in command)


def test_warnings_are_on_by_default_and_shown(robios_prefix, tmp_path, monkeypatch, capfd):
    """A missing LCDPrintf argument and an uninitialised variable compile, with a word about each;
    --no-warnings leaves -Wall out."""
    monkeypatch.setenv("EYESIM_ROBIOS", str(robios_prefix))
    source = tmp_path / "sloppy.c"
    source.write_text('#include "eyebot.h"\nint main(void) { int n; LCDPrintf("%d %d\\n", 1); return n; }\n')
    parser = parser_with_toolchain()
    args = parser.parse_args(["cc", str(source), "-o", str(tmp_path / "sloppy")])
    assert args.func(args) == 0
    err = capfd.readouterr().err
    assert "-Wformat" in err and "-Wuninitialized" in err
    args = parser.parse_args(["cc", "--no-warnings", str(source), "-o", str(tmp_path / "sloppy")])
    assert args.func(args) == 0
    assert "warning" not in capfd.readouterr().err
