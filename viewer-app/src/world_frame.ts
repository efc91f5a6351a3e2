// The one place where the simulator's world frame (z up, metres) meets three.js's (y up).

import { Group, Quaternion, Vector3 } from "three";

/** Turns world z-up into three.js y-up: a -90 degree rotation about x, so (x, y, z) -> (x, z, -y). */
const WORLD_TO_THREE = new Quaternion().setFromAxisAngle(new Vector3(1, 0, 0), -Math.PI / 2);

/**
 * A group whose children are placed in world coordinates: everything the simulator describes
 * (floor, walls, robots, objects) lives under it, so poses from the wire apply unchanged.
 */
export function createWorldRoot(): Group {
  const root = new Group();
  root.name = "world";
  root.quaternion.copy(WORLD_TO_THREE);
  root.updateMatrixWorld();
  return root;
}

/** A world point (z up) in three.js coordinates, for placing the camera. */
export function worldToThree(x: number, y: number, z: number): Vector3 {
  return new Vector3(x, y, z).applyQuaternion(WORLD_TO_THREE);
}
