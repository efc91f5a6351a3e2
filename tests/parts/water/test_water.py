"""Water alone: a hull lighter than the water it displaces rises, and floats at the surface with
as much of it under water as displaces its mass."""

from pathlib import Path

from support.driving import EXAMPLE_ROBOTS

SURFACE = 1500  # mm: the pool's walls are 1.5 m high and the water fills it to the rim
HEIGHT = 200  # mm: Minnow's hull


def test_a_buoyant_submarine_rises_and_floats_at_the_surface(drive, tmp_path: Path):
    buoyant = (EXAMPLE_ROBOTS / "Minnow.robi").read_text().replace("name Minnow", "name Bobber")
    buoyant = buoyant.replace("buoyancy 4.0", "buoyancy 5.0")  # 5 litres displaced, 4 kg
    (tmp_path / "Bobber.robi").write_text(buoyant)
    run = drive(
        ["Bobber 1500 1500 0"], {1: "float_up"}, extra=[f"robi {tmp_path / 'Bobber.robi'}"], wall_height=SURFACE
    )
    depths = [z for second, z in run.values(1, "depth")]
    assert depths[0] == 300
    assert depths[3] > depths[0] + 200  # rising
    # Afloat it sticks out so far that the part under water displaces its 4 kg: 4/5 of its height.
    assert abs(depths[-1] - (SURFACE - 0.8 * HEIGHT)) <= 10
    assert abs(depths[-1] - depths[-2]) <= 2  # and stays there
