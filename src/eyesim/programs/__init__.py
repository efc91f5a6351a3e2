"""Robot programs as processes: compiling them (toolchain) and starting them (launcher)."""
