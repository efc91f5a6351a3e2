// How the 3D view's camera moves: free (the mouse orbits), top-down over the floor, or following
// one robot (the camera keeps its angle and distance and moves along with the robot).

import { Vector3, type PerspectiveCamera } from "three";
import type { OrbitControls } from "three/addons/controls/OrbitControls.js";
import type { Floor } from "./protocol";
import { worldToThree } from "./world_frame";

export type ViewMode = "free" | "top" | "follow";

/** Following starts this far (m) behind and above the robot, steep enough to see over 0.3 m walls. */
const FOLLOW_DISTANCE = 1.2;
const FOLLOW_ELEVATION = (60 * Math.PI) / 180;
/** Top-down leaves this much room around the floor. */
const TOP_MARGIN = 1.08;

export interface CameraHost {
  camera: PerspectiveCamera;
  controls: OrbitControls;
  floor(): Floor | null;
  /** the robot's centre in three.js coordinates and its heading (rad), or null if it is not drawn */
  robot(id: number): { position: Vector3; heading: number } | null;
}

export class CameraModes {
  private current: ViewMode = "free";
  private followed: number | null = null;
  /** where the followed robot was at the last frame (three.js coordinates) */
  private lastRobot: Vector3 | null = null;

  constructor(private readonly host: CameraHost) {}

  get mode(): ViewMode {
    return this.current;
  }

  get followedRobot(): number | null {
    return this.current === "follow" ? this.followed : null;
  }

  /** Switches the camera; `robot` is the one to follow (kept from before when not given). */
  set(mode: ViewMode, robot: number | null = this.followed): void {
    this.current = mode;
    this.followed = robot;
    this.lastRobot = null;
    this.host.controls.enableRotate = mode !== "top";
    if (mode === "top") this.lookDown();
  }

  /** Follows another robot (the selected one) when following. */
  follow(robot: number): void {
    if (this.followed === robot) return;
    this.followed = robot;
    this.lastRobot = null;
  }

  /** Moves the camera for this frame; says whether it moved. */
  update(): boolean {
    if (this.current !== "follow" || this.followed === null) return false;
    const robot = this.host.robot(this.followed);
    if (!robot) return false;
    const { camera, controls } = this.host;
    if (this.lastRobot === null) {
      // Behind the robot, looking the way it faces.
      const back = worldToThree(-Math.cos(robot.heading), -Math.sin(robot.heading), 0).multiplyScalar(
        FOLLOW_DISTANCE * Math.cos(FOLLOW_ELEVATION),
      );
      camera.position.copy(robot.position).add(back).add(worldToThree(0, 0, FOLLOW_DISTANCE * Math.sin(FOLLOW_ELEVATION)));
      controls.target.copy(robot.position);
      this.lastRobot = robot.position.clone();
      return true;
    }
    const moved = robot.position.clone().sub(this.lastRobot);
    if (moved.lengthSq() === 0) return false;
    camera.position.add(moved);
    controls.target.add(moved);
    this.lastRobot.copy(robot.position);
    return true;
  }

  /** Straight down on the floor's centre, north up, the whole floor in view. */
  private lookDown(): void {
    const floor = this.host.floor();
    if (!floor) return;
    const { camera, controls } = this.host;
    const halfHeight = Math.tan((camera.fov * Math.PI) / 360);
    const distance =
      Math.max(floor.height / 2 / halfHeight, floor.width / 2 / (halfHeight * camera.aspect)) * TOP_MARGIN;
    const centre = worldToThree(floor.width / 2, floor.height / 2, 0);
    // A hair south of straight above: the orbit controls keep "up" as north from there.
    camera.position.copy(centre).add(worldToThree(0, -distance * 1e-4, distance));
    camera.near = distance / 500;
    camera.far = distance * 20;
    camera.updateProjectionMatrix();
    controls.target.copy(centre);
    controls.update();
  }
}
