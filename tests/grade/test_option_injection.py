"""The grader compiles files whose names students chose: none of them can be an option or a
response file (`@inj.c`, whose contents gcc would read as options, such as `-wrapper` that runs a
command as the teacher)."""

from __future__ import annotations

from eyesim.grade.case_run import build
from eyesim.grade.spec import ProgramSpec

MAIN = b'#include "eyebot.h"\nint main(void) { LCDPrintf("hi"); return 0; }\n'
INJECTED = b"-wrapper /bin/sh,-c,touch${IFS}INJECTED\n"


def test_a_response_file_name_in_a_glob_is_compiled_as_a_file(tmp_path):
    directory = tmp_path / "submission"
    directory.mkdir()
    files = {"main.c": MAIN, "@inj.c": INJECTED, "inj.c": INJECTED}
    for name, data in files.items():
        (directory / name).write_bytes(data)
    executable, record = build(ProgramSpec("follower", ("*.c",)), files, directory)
    assert executable is None and record["status"] == "compile_error"  # inj.c is no C
    assert not (directory / "INJECTED").exists() and not (tmp_path / "INJECTED").exists()


def test_an_option_like_name_is_a_file_too(tmp_path):
    directory = tmp_path / "submission"
    directory.mkdir()
    files = {"-Dmain=nothing.c": MAIN}
    (directory / "-Dmain=nothing.c").write_bytes(MAIN)
    executable, record = build(ProgramSpec("prog", ("*.c",)), files, directory)
    assert record["status"] == "ok" and executable.is_file(), record["output"]
