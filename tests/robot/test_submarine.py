"""The example submarine under real C programs: depth holding, thrust, floating and falling."""

from pathlib import Path

from support.driving import EXAMPLE_ROBOTS

SURFACE = 1500  # mm: the pool's walls are 1.5 m high and the water fills it to the rim
HEIGHT = 200  # mm: Minnow's hull


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


def test_a_buoyant_submarine_rises_and_floats_at_the_surface(drive, tmp_path: Path):
    buoyant = (EXAMPLE_ROBOTS / "Minnow.robi").read_text().replace("name Minnow", "name Bobber")
    buoyant = buoyant.replace("buoyancy 4.0", "buoyancy 5.0")  # 5 litres displaced, 4 kg
    (tmp_path / "Bobber.robi").write_text(buoyant)
    run = drive(["Bobber 1500 1500 0"], {1: "float_up"}, extra=[f"robi {tmp_path / 'Bobber.robi'}"],
                wall_height=SURFACE)
    depths = [z for second, z in run.values(1, "depth")]
    assert depths[0] == 300
    assert depths[3] > depths[0] + 200  # rising
    # Afloat it sticks out so far that the part under water displaces its 4 kg: 4/5 of its height.
    assert abs(depths[-1] - (SURFACE - 0.8 * HEIGHT)) <= 10
    assert abs(depths[-1] - depths[-2]) <= 2  # and stays there
