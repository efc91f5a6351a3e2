// window.eyesimViewer: a read-only view of the viewer's state, for tests and for debugging.

import type { ViewMode } from "./camera_modes";
import type { ConnectionState } from "./connection";
import type { RunSettings } from "./generated/viewer_protocol";
import type { DragTarget } from "./interaction";
import type { Pose } from "./interpolation";
import { meshBox, meshCount } from "./mesh_loader";
import type { IoMessage, Quat, SceneWarning, SensorRays, StatusMessage, Vec3 } from "./protocol";
import type { ProgramState } from "./robot_panel";
import type { TimelineState } from "./timeline_bar";
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
  /** the object's pose in the newest snapshot, exactly as received */
  objectPose(object: number): ReceivedPose | null;
  /** how many robot bodies (arm links, fingers, wheels) are drawn, and the water's surface height */
  robotBodiesAndWater(): { bodies: number; water: number | null };
  /** where the robot's centre is on the page (CSS pixels); null without WebGL */
  robotScreenPosition(robot: number): { x: number; y: number } | null;
  /** where a world point (metres, z up) is on the page (CSS pixels); null without WebGL */
  worldScreenPosition(x: number, y: number, z: number): { x: number; y: number } | null;
  /** the robot or object the mouse is dragging now, or null */
  dragging(): DragTarget | null;
  /** the scene warnings the toolbar badge lists, and whether the list is open */
  sceneWarnings(): { warnings: SceneWarning[]; listOpen: boolean };
  /** whether the controls help is showing */
  helpVisible(): boolean;
  menuLabels(robot: number): string[] | null;
  consoleText(robot: number): string | null;
  programState(robot: number): ProgramState | null;
  /** how many LCD images have loaded into the robot's panel */
  lcdUpdates(robot: number): number | null;
  /** what the robot sent on a serial interface */
  serialText(robot: number, interfaceNumber: number): string | null;
  /** the robot's digital lines and analog channels as last received */
  ioState(robot: number): IoMessage | null;
  /** beeps and files the robot has played since the page opened */
  soundsPlayed(robot: number): number;
  /** sensor ray segments drawn now (scene setting VIS) */
  raySegments(): number;
  /** the sensor rays drawn now, as received (world coordinates, m) */
  sensorRays(): SensorRays[];
  /** how many .obj models are drawn, and one's bounding box in world coordinates (m, z up) */
  meshesDrawn(): number;
  meshBox(kind: "robot" | "object", id: number): { min: number[]; max: number[] } | null;
  /** points of the robot's drawn path (scene setting TRACE) */
  tracePoints(robot: number): number;
  /** how many camera images have loaded into the robot's panel */
  cameraImages(robot: number): number | null;
  status(): StatusMessage | null;
  /** the timeline: live, review (looking back) or replay, the shown time and the range */
  timeline(): TimelineState;
  /** timeline frames shown so far */
  framesShown(): number;
  /** what the plot panel draws: signal ids and their number of points */
  plotted(): { id: string; points: number }[];
  /** the plot's legend entries and its hover readout, as they show, and the signals drawn as steps */
  plotShown(): { legend: string[]; readout: string; stepped: string[] };
  /** where a time is on the plot (page CSS pixels, the chart's middle height); null with no chart */
  plotPosition(time: number): { x: number; y: number } | null;
  /** the floor image's URL (null: none) and whether it has loaded */
  floorTexture(): { url: string | null; loaded: boolean };
  /** each robot's label in the 3D view, by id */
  robotLabels(): Record<number, string>;
  /** how many robot panels are open side by side */
  panelColumns(): number;
  /** the plot panel's note on why a click in the 3D view added nothing ("" if none) */
  plotNotice(): string;
  /** the last video made with the Video button: its size in bytes, or null */
  lastVideoSize(): number | null;
  /** the last video as base64 (for tests that check its frames) */
  lastVideo(): Promise<string | null>;
  /** the 3D view as a PNG data URL, or null without WebGL */
  screenshot(): string | null;
  /** what sending a recording from the page ended with ("" before any) */
  uploadStatus(): string;
  /** messages dropped as malformed or of an unknown type */
  ignoredMessages(): number;
  /** the robot whose panel is open, and which panels are open */
  selectedRobot(): number | null;
  expandedPanels(): number[];
  /** the 3D camera: free, top-down or following a robot, where it is and looks (three.js frame) */
  cameraState(): { mode: ViewMode; following: number | null; position: number[]; direction: number[] };
  /** what a robot's program controls say now, and the compiler's file:line findings */
  programMessage(robot: number): string | null;
  compilerLines(robot: number): string[] | null;
  /** the settings panel: open or not, and the settings it last showed */
  settingsShown(): { visible: boolean; settings: RunSettings | null };
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
    objectPose: (object) => {
      const snapshot = viewer.snapshots.latest();
      const body = snapshot?.objects.find((o) => o.id === object);
      return snapshot && body ? { time: snapshot.time, pos: [...body.pos], quat: [...body.quat] } : null;
    },
    robotBodiesAndWater: () => viewer.world.robotBodiesAndWater(),
    robotScreenPosition: (robot) => viewer.world.robotScreenPosition(robot),
    worldScreenPosition: (x, y, z) => viewer.world.screenPosition(x, y, z),
    dragging: () => viewer.world.draggedThing(),
    sceneWarnings: () => ({ warnings: viewer.warnings.warnings, listOpen: viewer.warnings.listOpen }),
    helpVisible: () => viewer.help.visible,
    menuLabels: (robot) => viewer.panels.find(robot)?.lcd.menuLabels() ?? null,
    consoleText: (robot) => viewer.panels.find(robot)?.console.text() ?? null,
    programState: (robot) => viewer.panels.find(robot)?.programState() ?? null,
    lcdUpdates: (robot) => viewer.panels.find(robot)?.lcd.imageUpdates() ?? null,
    serialText: (robot, interfaceNumber) => viewer.panels.find(robot)?.io.serialText(interfaceNumber) ?? null,
    ioState: (robot) => viewer.panels.find(robot)?.io.state() ?? null,
    soundsPlayed: (robot) => viewer.audio.soundsPlayed(robot),
    raySegments: () => viewer.overlays.raySegments(),
    sensorRays: () => structuredClone(viewer.overlays.drawnRays()),
    meshesDrawn: () => meshCount(),
    meshBox: (kind, id) => meshBox(`${kind} ${id}`),
    tracePoints: (robot) => viewer.overlays.tracePoints(robot),
    cameraImages: (robot) => viewer.panels.find(robot)?.camera.imagesShown ?? null,
    status: () => (viewer.status ? structuredClone(viewer.status) : null),
    timeline: () => viewer.timeline.current,
    framesShown: () => viewer.framesShown,
    plotted: () => viewer.plots.plottedSeries(),
    plotShown: () => viewer.plots.shown(),
    plotPosition: (time) => viewer.plots.pagePosition(time),
    robotLabels: () => viewer.world.robotLabels(),
    floorTexture: () => ({ ...viewer.world.floorTexture }),
    panelColumns: () => viewer.panels.columns,
    plotNotice: () => viewer.plots.noticeText(),
    lastVideoSize: () => viewer.video.last?.size ?? null,
    lastVideo: async () => {
      const video = viewer.video.last;
      if (!video) return null;
      const bytes = new Uint8Array(await video.arrayBuffer());
      let text = "";
      for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return btoa(text);
    },
    screenshot: () => viewer.world.screenshot(),
    uploadStatus: () => viewer.upload.status,
    ignoredMessages: () => viewer.ignoredMessages,
    selectedRobot: () => viewer.panels.selected,
    expandedPanels: () => viewer.panels.ids().filter((id) => viewer.panels.find(id)?.expanded),
    cameraState: () => viewer.world.cameraState(),
    programMessage: (robot) => viewer.panels.find(robot)?.programs.messageText() ?? null,
    compilerLines: (robot) => viewer.panels.find(robot)?.programs.compilerLines() ?? null,
    settingsShown: () => ({ visible: viewer.settings.visible, settings: viewer.settings.settings }),
  };
  window.eyesimViewer = Object.freeze(handle);
}
