"""`eyesim run` finds the same files for a scene named relative to the working directory as for its
full path (EyeSim 6 examples rely on %sim% fallbacks that search the folders above the scene)."""

import shutil

from support.corpus import CORPUS
from support.programs import build, run_headless
from support.rooms import Run


def test_a_scene_run_by_its_name_from_its_folder_sees_the_same_world(tmp_path):
    shutil.copytree(CORPUS / "ASAX21__VRRoboticProject/Test Assets", tmp_path / "Test Assets")
    folder = tmp_path / "Test Assets/examples/drivemodes"
    program = build("psd_all", tmp_path)
    # Diff.sim: world %sim%/worlds/worlds/Soccer1998.wld, an S4 at (600, 500) facing east
    by_path = Run(run_headless(str(folder / "Diff.sim"), "--program", f"1={program}", cwd=tmp_path))
    by_name = Run(run_headless("Diff.sim", "--program", f"1={program}", cwd=folder))
    assert by_path.returncode == 0 and by_name.returncode == 0, by_name.stderr
    assert by_name.lines(1) == by_path.lines(1)
    [[front, left, right, back, five, six]] = by_name.values(1, "psd")
    assert front < 9999 and right < 9999  # walls of the soccer field, not an empty world
    assert (five, six) == (-1, -1)  # S4 has four PSDs
    warnings = sorted(
        line.replace(str(folder / "Diff.sim"), "Diff.sim") for line in by_path.stderr.splitlines() if "warning" in line
    )
    assert sorted(line for line in by_name.stderr.splitlines() if "warning" in line) == warnings
    assert not any("world file not found" in line for line in warnings)
