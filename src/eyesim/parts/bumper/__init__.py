"""The bumper: a contact strip on the chassis edge, wired to a digital input line (8 + its id)
that reads 0 while the strip touches a wall, an object or another robot, and 1 otherwise."""
