"""The application: the `eyesim` command line and `eyesim run`, which wire the core, the
viewer server, recording and programs together."""
