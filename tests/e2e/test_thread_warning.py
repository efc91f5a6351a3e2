"""A deterministic run says when it may not repeat: a program whose own threads call RoBIOS at the
same time (the library's timer thread does not count)."""

from support.programs import build, run_headless

WARNING = "RoBIOS calls come from more than one thread of the program"


def test_two_program_threads_calling_get_one_warning_naming_the_robot(tmp_path):
    program = build("two_threads", tmp_path, "-Wall", "-Werror")
    result = run_headless("--program", f"1={program}", cwd=tmp_path, timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    output = result.stdout + result.stderr
    assert output.count(WARNING) == 1
    assert f"robot 1 ({program.name}): {WARNING}" in output


def test_one_thread_with_timer_callbacks_is_reproducible_and_says_nothing(tmp_path):
    program = build("two_threads", tmp_path, "-Wall", "-Werror")
    wrapper = tmp_path / "main_only.sh"
    wrapper.write_text(f"#!/bin/sh\nexec {program} main-only\n")
    wrapper.chmod(0o755)
    result = run_headless("--program", f"1={wrapper}", cwd=tmp_path, timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "[robot 1] ticks 1" in result.stdout
    assert WARNING not in result.stdout + result.stderr
