"""Scene description -> MuJoCo model; stepping, ray casts and pose access."""
