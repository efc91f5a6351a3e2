// window.eyesimViewer: a read-only view of the viewer's state, for tests and for debugging.

import type { ConnectionState } from "./connection";
import type { Pose } from "./interpolation";
import type { Quat, StatusMessage, Vec3 } from "./protocol";
import type { ProgramState } from "./robot_panel";
import type { Viewer } from "./viewer";
import type { WorldCounts } from "./world_view";

export interface ReceivedPose {
  /** simulation time of the snapshot it came in */
  time: number;
  pos: Vec3;
  quat: Quat;
}

export interface EyesimViewerDebug {
  connectionState(): ConnectionState;
  /** connections established so far, reconnects included */
  connections(): number;
  webglActive(): boolean;
  /** what the current scene holds; the floor is null before the first scene */
  scene(): WorldCounts & { floor: { width: number; height: number } | null };
  robotIds(): number[];
  /** the robot's pose in the newest snapshot, exactly as received */
  robotPose(robot: number): ReceivedPose | null;
  /** the robot's pose as drawn now (interpolated, a little behind the newest snapshot) */
  displayedRobotPose(robot: number): Pose | null;
  /** where the robot's centre is on the page (CSS pixels); null without WebGL */
  robotScreenPosition(robot: number): { x: number; y: number } | null;
  menuLabels(robot: number): string[] | null;
  consoleText(robot: number): string | null;
  programState(robot: number): ProgramState | null;
  /** how many LCD images have loaded into the robot's panel */
  lcdUpdates(robot: number): number | null;
  status(): StatusMessage | null;
  /** messages dropped as malformed or of an unknown type */
  ignoredMessages(): number;
}

declare global {
  interface Window {
    eyesimViewer: EyesimViewerDebug;
  }
}

export function installDebugHandle(viewer: Viewer): void {
  const handle: EyesimViewerDebug = {
    connectionState: () => viewer.connection.state,
    connections: () => viewer.connection.openings,
    webglActive: () => viewer.world.webglActive,
    scene: () => {
      const floor = viewer.scene?.floor;
      return { ...viewer.world.counts(), floor: floor ? { width: floor.width, height: floor.height } : null };
    },
    robotIds: () => viewer.panels.ids(),
    robotPose: (robot) => {
      const snapshot = viewer.snapshots.latest();
      const body = snapshot?.robots.find((r) => r.id === robot);
      return snapshot && body ? { time: snapshot.time, pos: [...body.pos], quat: [...body.quat] } : null;
    },
    displayedRobotPose: (robot) => viewer.world.displayedRobotPose(robot),
    robotScreenPosition: (robot) => viewer.world.robotScreenPosition(robot),
    menuLabels: (robot) => viewer.panels.find(robot)?.lcd.menuLabels() ?? null,
    consoleText: (robot) => viewer.panels.find(robot)?.console.text() ?? null,
    programState: (robot) => viewer.panels.find(robot)?.programState() ?? null,
    lcdUpdates: (robot) => viewer.panels.find(robot)?.lcd.imageUpdates() ?? null,
    status: () => (viewer.status ? structuredClone(viewer.status) : null),
    ignoredMessages: () => viewer.ignoredMessages,
  };
  window.eyesimViewer = Object.freeze(handle);
}
