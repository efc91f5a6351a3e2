"""Grading strangers' programs: each hostile submission below tries one attack that worked before
the sandbox (sandbox.py), and each now fails, while the honest submissions beside them get exactly
the scores they get when graded alone."""

from __future__ import annotations

import json
import os
import subprocess
import uuid
from pathlib import Path

import pytest
from support.grading import grade

from eyesim.grade import sandbox


SPEC = """
title = "sandbox"
[programs.prog]
sources = ["*.c"]
[limits]
time = 3
wall_clock = 60
cpu = 5
[[cases]]
name = "drive"
scene = "default"
robots = [{ robot = 1, program = "prog" }]
[[cases.checks]]
kind = "lcd_text"
robot = 1
text = "done"
[[cases.checks]]
kind = "exit_code"
robot = 1
"""

HONEST = """#include "eyebot.h"
/* %s */
int main(void) { VWStraight(%d, 300); VWWait(); LCDPrintf("done"); return 0; }
"""

# Each prints what it managed on the LCD, where the report keeps it as evidence.
HOSTILE = {
    "reader": r"""#include "eyebot.h"
#include <stdio.h>
int main(void) {
  char text[200] = "";
  FILE *f = fopen("{alice}", "r");
  if (f) { fgets(text, sizeof text, f); fclose(f); }
  char cmd[200] = "";
  FILE *p = fopen("/proc/1/cmdline", "r"), *q = fopen("/proc/{grader}/cmdline", "r");
  if (q) { fread(cmd, 1, sizeof cmd - 1, q); fclose(q); }
  if (p) fclose(p);
  LCDPrintf("classmate:%s grader:%s done", f ? "READ" : "none", q ? "READ" : "none");
  return 0;
}""",
    "planter": r"""#include "eyebot.h"
#include <stdio.h>
int main(void) {
  FILE *f = fopen("{alice_dir}/planted.c", "w");
  FILE *g = fopen("{out}/cases/alice/drive.json", "w");
  if (f) { fputs("int x = ;", f); fclose(f); }
  if (g) { fputs("{}", g); fclose(g); }
  LCDPrintf("plant:%s forge:%s done", f ? "YES" : "no", g ? "YES" : "no");
  return 0;
}""",
    "writer": r"""#include "eyebot.h"
#include <stdio.h>
#include <stdlib.h>
int main(void) {
  FILE *outside = fopen("{host_tmp}", "w");
  LCDPrintf("outside:%s ", outside ? "YES" : "no");
  char *block = calloc(1, 1 << 20);
  FILE *big = fopen("big.bin", "w");
  long written = 0;
  for (int i = 0; big && i < 300; i++) written += fwrite(block, 1, 1 << 20, big);
  LCDPrintf("wrote %ld MB done", written >> 20);
  return 0;
}""",
    "forker": r"""#include "eyebot.h"
#include <unistd.h>
#include <signal.h>
int main(void) {
  int made = 0;
  for (int i = 0; i < 300; i++) { pid_t p = fork(); if (p == 0) { pause(); _exit(0); } if (p < 0) break; made++; }
  LCDPrintf("forked %d done", made);
  return 0;
}""",
    "lingerer": r"""#include "eyebot.h"
#include <unistd.h>
#include <stdio.h>
int main(void) {
  if (fork() == 0) {
    setsid();
    for (int i = 0; i < 200; i++) {
      sleep(1);
      FILE *r = fopen("{out}/index.html", "a");
      if (r) { fputs("100/100", r); fclose(r); }
    }
    execl("/bin/sleep", "sleep", "{marker}", (char *)0);
    _exit(0);
  }
  LCDPrintf("done");
  return 0;
}""",
    "devzero": '#include "/dev/zero"\nint main(void) { return 0; }\n',
}


def write_submission(folder: Path, name: str, source: str) -> None:
    (folder / name).mkdir(parents=True)
    (folder / name / "prog.c").write_text(source)


@pytest.fixture(scope="module")
def classes(tmp_path_factory):
    """Three honest students graded alone, then with the hostile ones beside them."""
    assert sandbox.bwrap() is not None, "the sandbox needs bubblewrap: make test installs it (apt install bubblewrap)"
    root = tmp_path_factory.mktemp("class")
    (root / "spec.toml").write_text(SPEC)
    honest = {f"student{k}": HONEST % (f"SECRET_{k}", 200 + 100 * k) for k in range(3)}
    honest["alice"] = HONEST % ("SECRET_ALICE", 250)
    alone, mixed = root / "alone", root / "mixed"
    for name, source in honest.items():
        write_submission(alone, name, source)
        write_submission(mixed, name, source)
    out_alone, out_mixed = root / "out-alone", root / "out-mixed"
    host_tmp, marker = write_hostile(mixed, out_mixed)
    for submissions, out in ((alone, out_alone), (mixed, out_mixed)):
        done = grade(str(root / "spec.toml"), str(submissions), "--out", str(out), "--workers", "2", cwd=root)
        assert done.returncode == 0, done.stdout + done.stderr
    return {
        "alone": json.loads((out_alone / "report.json").read_text()),
        "mixed": json.loads((out_mixed / "report.json").read_text()),
        "out": out_mixed,
        "mixed_dir": mixed,
        "host_tmp": host_tmp,
        "marker": marker,
    }


def write_hostile(submissions: Path, out: Path) -> tuple[Path, str]:
    """The six hostile submissions beside alice's in `submissions`, aimed at her files and at the
    grader writing `out`; returns the file outside the sandbox the writer tries and the lingerer's
    marker (what must not exist, or run, afterwards)."""
    host_tmp = Path("/tmp") / f"eyesim-attack-{uuid.uuid4().hex}"
    marker = f"{os.getpid() % 1000}.{uuid.uuid4().int % 100000:05d}"
    values = {
        "alice": str(submissions / "alice" / "prog.c"),
        "alice_dir": str(submissions / "alice"),
        "out": str(out),
        "grader": str(os.getpid()),
        "host_tmp": str(host_tmp),
        "marker": marker,
    }
    for name, source in HOSTILE.items():
        for key, value in values.items():
            source = source.replace("{" + key + "}", value)
        write_submission(submissions, f"hostile_{name}", source)
    return host_tmp, marker


def case_of(report: dict, student: str) -> dict:
    return next(s for s in report["students"] if s["name"] == student)["cases"][0]


def lcd(report: dict, student: str) -> str:
    return " ".join(case_of(report, student)["robots"]["1"]["lcd_text"])


def test_honest_students_get_the_same_results_beside_hostile_ones(classes):
    for student in ("student0", "student1", "student2", "alice"):
        alone, mixed = case_of(classes["alone"], student), case_of(classes["mixed"], student)
        assert mixed["score"] == alone["score"] == 1.0
        assert mixed["robots"] == alone["robots"] and mixed["checks"] == alone["checks"]


def test_a_submission_cannot_read_a_classmates_files_or_the_graders_command_line(classes):
    assert "classmate:none grader:none" in lcd(classes["mixed"], "hostile_reader")


def test_a_submission_cannot_plant_files_or_forge_stored_results(classes):
    assert "plant:no forge:no" in lcd(classes["mixed"], "hostile_planter")
    assert not (classes["mixed_dir"] / "alice" / "planted.c").exists()
    stored = json.loads((classes["out"] / "cases" / "alice" / "drive.json").read_text())
    assert stored["score"] == 1.0


def test_a_submission_writes_nothing_outside_its_work_folder_and_no_huge_file(classes):
    case = case_of(classes["mixed"], "hostile_writer")
    assert "outside:no" in lcd(classes["mixed"], "hostile_writer")
    assert not classes["host_tmp"].exists()
    assert "wrote 300 MB" not in lcd(classes["mixed"], "hostile_writer")
    assert case["programs"]["1"]["crashed"]  # SIGXFSZ at the file size limit


def test_a_submission_cannot_fork_hundreds_of_processes(classes):
    text = lcd(classes["mixed"], "hostile_forker")
    made = int(text.split("forked ")[1].split()[0])
    assert made < 300


def test_nothing_a_submission_started_outlives_its_case(classes):
    found = subprocess.run(["pgrep", "-f", f"sleep {classes['marker']}"], capture_output=True, text=True)
    assert found.stdout == ""
    assert "100/100" not in (classes["out"] / "index.html").read_text()


def test_the_compiler_runs_with_limits(classes):
    case = case_of(classes["mixed"], "hostile_devzero")
    assert case["status"] == "compile_error"
    assert case["timing"]["case_seconds"] < 60


LEAVER = r"""#include "eyebot.h"
#include <stdio.h>
int main(void) {
  const char *places[] = {"/tmp/left", "/run/left", "/dev/shm/left", "../../../left", "left"};
  int made = 0;
  for (int i = 0; i < 5; i++) { FILE *f = fopen(places[i], "w"); if (f) { fputs("x", f); fclose(f); made++; } }
  LCDPrintf("left %d done", made);
  return 0;
}"""

FINDER = r"""#include "eyebot.h"
#include <dirent.h>
#include <string.h>
#include <unistd.h>
int main(void) {
  const char *places[] = {"/tmp/left", "/run/left", "/dev/shm/left", "../../../left", "left"};
  int found = 0, others = 0;
  for (int i = 0; i < 5; i++) found += access(places[i], F_OK) == 0;
  char here[4096];
  getcwd(here, sizeof here);
  DIR *up = opendir("../../..");  /* where the cases' folders are made: the grader's, or a warm runner's */
  for (struct dirent *e; up && (e = readdir(up));)
    if ((!strncmp(e->d_name, "case", 4) || !strncmp(e->d_name, "eyesim-", 7)) && !strstr(here, e->d_name)) others++;
  LCDPrintf("found %d others %d done", found, others);
  return 0;
}"""


def test_one_case_leaves_nothing_for_the_next(tmp_path):
    """Graded one after the other by one worker (a warm runner's cases, where the grader is root):
    what the first case wrote is not there for the second, nor are other cases' folders."""
    (tmp_path / "spec.toml").write_text(SPEC)
    write_submission(tmp_path / "class", "a_leaver", LEAVER)
    write_submission(tmp_path / "class", "b_finder", FINDER)
    done = grade(
        str(tmp_path / "spec.toml"),
        str(tmp_path / "class"),
        "--out",
        str(tmp_path / "out"),
        "--workers",
        "1",
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert lcd(report, "a_leaver") == "left 1 done"  # only in its own folder
    assert lcd(report, "b_finder") == "found 0 others 0 done"
