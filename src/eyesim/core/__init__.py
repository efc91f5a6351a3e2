"""The simulation core: the engine that steps the world and serves programs' requests, simulated
time, the events it reports, and the table of outside inputs (docs/architecture.md, "Layers")."""
