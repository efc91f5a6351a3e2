"""Robots: an entity with a list of components, built from a robot type (data, never a class)."""
