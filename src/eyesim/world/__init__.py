"""Building the MuJoCo world from a scene: the physics of its walls and objects plus its robots."""
