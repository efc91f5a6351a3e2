"""The messages the viewer is sent, built from the world and its robots (used live by web/ and
stored by record/)."""
