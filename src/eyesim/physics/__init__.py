"""MuJoCo building blocks for a scene (floor, walls, objects, water, meshes, units); ray casts, rendering and pose access. The world is assembled from them in eyesim/world/."""
