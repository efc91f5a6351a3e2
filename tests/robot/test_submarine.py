"""The example submarine under real C programs: depth holding, thrust and falling; thrust and drag
keeping a hull level. (Floating alone: tests/parts/water/test_water.py.)"""

from pathlib import Path

from support.water import under_water_run

from eyesim.scene import load_robot_type

SURFACE = 1500  # mm: the pool's walls are 1.5 m high and the water fills it to the rim


def test_a_neutral_submarine_holds_depth_and_moves_by_its_thrusters(drive):
    run = drive(["Minnow 1500 1500 0"], {1: "submarine"}, robots=["Minnow"], wall_height=SURFACE)
    depths = [z for x, y, z, phi in run.values(1, "hold")]
    assert len(depths) == 11  # 10 s
    assert max(depths) - min(depths) <= 10 and abs(depths[0] - 600) <= 1
    [[x, y, up, phi]] = run.values(1, "up")
    assert up > depths[-1] + 50  # the vertical thrusters push up
    [[ahead, y, z, phi]] = run.values(1, "ahead")
    assert ahead > x + 200  # the horizontal thrusters push forward (+x at heading 0)
    [[x, y, falling, phi]] = run.values(1, "falling")
    assert falling < 2500 - 300  # out of the water it drops (0.3 s: more than 0.4 m in free fall)
    # no speed control for thrusters, no encoders, no motor 5
    assert run.values(1, "errors") == [[1, 1, 1]]


# A Mako-like hull of our own, neutrally buoyant: its centre of mass 100 mm up, its thrusters level
# with the middle of its 400 mm hull (200 mm up), its centre of buoyancy above both.
GROUPER = """dialect eyesim
drive SUBMARINE
name Grouper
size 1200 600 400
mass 30 0 0 100
buoyancy 30 0 0 220
thruster LEFT  1 -500  250 200  1 0 0  40
thruster RIGHT 2 -500 -250 200  1 0 0  40
thruster FRONT 3  450    0 200  0 0 1  30
thruster BACK  4 -450    0 200  0 0 1  30
drag 80 200 130 20
"""


def test_thrust_above_the_centre_of_mass_drives_a_submarine_level_ahead_and_astern(tmp_path: Path):
    # The water's drag acts at the middle of the hull, where the thrust does: steady thrust leaves
    # no lever to pitch it. With the drag at the centre of mass it pitched 8 degrees nose down
    # going ahead and dived 0.75 m into the pool floor within 10 s.
    (tmp_path / "Grouper.robi").write_text(GROUPER)
    heights, pitches = under_water_run(load_robot_type(tmp_path / "Grouper.robi"), ahead=(1, 2))
    for phase in (heights[:100], heights[140:]):  # 10 s ahead, 10 s astern: within a few cm each
        assert max(phase) - min(phase) <= 40, (min(phase), max(phase))
    assert max(abs(p) for p in pitches) <= 3  # speeding up and slowing down only
    steady = pitches[30:100] + pitches[170:]  # 3 s after each change of thrust
    assert max(abs(p) for p in steady) <= 0.2
