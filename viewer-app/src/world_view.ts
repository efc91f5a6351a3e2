// The live 3D view: renderer, camera, orbit controls, lights, and the world placed from poses.

import {
  Color,
  DirectionalLight,
  HemisphereLight,
  Object3D,
  PerspectiveCamera,
  Plane,
  Raycaster,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
} from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { CSS2DObject, CSS2DRenderer } from "three/addons/renderers/CSS2DRenderer.js";
import { CameraModes, type ViewMode } from "./camera_modes";
import { DragToPlace, yawOf, type DragSnap, type DragTarget, type PickTarget } from "./interaction";
import type { Pose, Poses } from "./interpolation";
import type { BrowserCommand, Floor, SceneMessage, SensorRays } from "./protocol";
import { buildWorld, disposeWorld, type BuiltWorld } from "./world_builder";
import { createWorldRoot, worldToThree } from "./world_frame";

export interface WorldCounts {
  robots: number;
  walls: number;
  objects: number;
  markers: number;
}

/** What the renderer needs; absent when the browser cannot give us WebGL. */
interface Display {
  renderer: WebGLRenderer;
  labels: CSS2DRenderer;
  controls: OrbitControls;
}

const FIELD_OF_VIEW = 45;
const CAMERA_ELEVATION = (55 * Math.PI) / 180;

function createDisplay(container: HTMLElement, camera: PerspectiveCamera): Display | null {
  let renderer: WebGLRenderer;
  try {
    renderer = new WebGLRenderer({ antialias: true });
  } catch (error) {
    console.warn("EyeSim viewer: WebGL is not available, the 3D view is off.", error);
    return null;
  }
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.domElement.classList.add("world-canvas");
  const labels = new CSS2DRenderer();
  labels.domElement.classList.add("world-labels");
  container.append(renderer.domElement, labels.domElement);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = true;
  // Keep the camera above the floor.
  controls.maxPolarAngle = Math.PI / 2 - 0.02;
  return { renderer, labels, controls };
}

function showNotice(container: HTMLElement, message: string): HTMLElement {
  const notice = document.createElement("div");
  notice.className = "world-notice";
  notice.textContent = message;
  container.append(notice);
  return notice;
}

function poseOf(thing: Object3D): Pose {
  const { position: p, quaternion: q } = thing;
  return { pos: [p.x, p.y, p.z], quat: [q.w, q.x, q.y, q.z] };
}

/** Moves a robot or object to `pose`; says whether anything changed. */
function place(thing: Object3D, pose: Pose): boolean {
  const [x, y, z] = pose.pos;
  const [qw, qx, qy, qz] = pose.quat;
  const p = thing.position;
  const q = thing.quaternion;
  const unchanged =
    p.x === x && p.y === y && p.z === z && q.w === qw && q.x === qx && q.y === qy && q.z === qz;
  if (thing.visible && unchanged) return false;
  p.set(x, y, z);
  q.set(qx, qy, qz, qw);
  thing.visible = true;
  return true;
}

/**
 * The scene graph is built and posed whether or not WebGL works (it needs no GPU), so what the
 * view would show can always be queried; only drawing needs a renderer.
 */
export class WorldView {
  private readonly scene = new Scene();
  private readonly root = createWorldRoot();
  private readonly camera = new PerspectiveCamera(FIELD_OF_VIEW, 1, 0.01, 1000);
  private readonly display: Display | null;
  private readonly dragging: DragToPlace | null = null;
  private readonly cameraModes: CameraModes | null = null;
  private world: BuiltWorld | null = null;
  private sceneMessage: SceneMessage | null = null;
  private floor: Floor | null = null;
  private needsRender = true;
  /** the scene's floor image: its URL, and whether it has loaded (for tests) */
  floorTexture: { url: string | null; loaded: boolean } = { url: null, loaded: false };
  /** the robot whose name label stands out (the selected one) */
  private highlighted: number | null = null;

  constructor(
    private readonly container: HTMLElement,
    send: (command: BrowserCommand) => void,
    picked: (target: PickTarget) => void = () => {},
    rays: () => SensorRays[] = () => [],
  ) {
    this.scene.background = new Color(0xdde3ea);
    this.scene.add(new HemisphereLight(0xffffff, 0x8a8f96, 2.2));
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.copy(worldToThree(-3, -5, 10));
    this.scene.add(sun, this.root);

    this.display = createDisplay(container, this.camera);
    if (this.display) {
      const notice = showNotice(container, "The 3D view lost its graphics context.");
      notice.hidden = true;
      const canvas = this.display.renderer.domElement;
      canvas.addEventListener("webglcontextlost", () => (notice.hidden = false));
      canvas.addEventListener("webglcontextrestored", () => {
        notice.hidden = true;
        this.needsRender = true;
      });
      this.display.controls.addEventListener("change", () => (this.needsRender = true));
      this.dragging = new DragToPlace(
        {
          camera: this.camera,
          canvas,
          controls: this.display.controls,
          root: this.root,
          world: () => this.world,
          scene: () => this.sceneMessage,
          requestRender: () => (this.needsRender = true),
          picked,
          rays,
        },
        send,
      );
      this.cameraModes = new CameraModes({
        camera: this.camera,
        controls: this.display.controls,
        floor: () => this.floor,
        robot: (id) => {
          const robot = this.world?.robots.get(id);
          if (!robot?.visible) return null;
          const q = robot.quaternion;
          return { position: robot.getWorldPosition(new Vector3()), heading: yawOf([q.w, q.x, q.y, q.z]) };
        },
      });
      new ResizeObserver(() => this.resize()).observe(container);
      this.resize();
    } else {
      container.classList.add("unavailable");
      showNotice(
        container,
        "3D view unavailable: this browser could not start WebGL. " +
          "The robot panels (LCD, keys, console) still work.",
      );
    }
  }

  get webglActive(): boolean {
    return this.display !== null;
  }

  /** Replaces the world; keeps the camera unless the floor changed size. */
  showScene(scene: SceneMessage): void {
    if (this.world) disposeWorld(this.world);
    this.dragging?.cancel();
    this.floorTexture = { url: scene.floor.texture, loaded: false };
    const texture = this.floorTexture;
    this.world = buildWorld(scene, () => (this.needsRender = true), () => (texture.loaded = true));
    this.sceneMessage = scene;
    this.root.add(this.world.group);
    const { width, height } = scene.floor;
    const resized = this.floor?.width !== width || this.floor?.height !== height;
    this.floor = scene.floor;
    this.highlightRobot(this.highlighted);
    if (resized && this.cameraModes?.mode === "top") this.cameraModes.set("top");
    else if (resized) this.frameFloor(scene.floor);
    this.needsRender = true;
  }

  /** Free camera, top-down, or following `robot`; "free" keeps the camera where it is. */
  setViewMode(mode: ViewMode, robot: number | null = null): void {
    if (!this.cameraModes) return;
    this.cameraModes.set(mode, robot);
    this.needsRender = true;
  }

  /** Makes the robot's name label stand out (the robot whose panel is open). */
  highlightRobot(robot: number | null): void {
    this.highlighted = robot;
    for (const [id, model] of this.world?.robots ?? []) {
      model.traverse((part) => {
        if (part instanceof CSS2DObject) part.element.classList.toggle("selected", id === robot);
      });
    }
    this.needsRender = true;
  }

  /** The text of the robot's label in the 3D view. */
  setRobotLabel(robot: number, text: string): void {
    this.world?.robots.get(robot)?.traverse((part) => {
      if (part instanceof CSS2DObject && part.element.textContent !== text) {
        part.element.textContent = text;
        this.needsRender = true;
      }
    });
  }

  /** The labels of the robots as they show now, by robot id (for tests). */
  robotLabels(): Record<number, string> {
    const labels: Record<number, string> = {};
    for (const [id, model] of this.world?.robots ?? []) {
      model.traverse((part) => {
        if (part instanceof CSS2DObject) labels[id] = part.element.textContent ?? "";
      });
    }
    return labels;
  }

  /** Back to the view the page starts with: the whole floor from the south (or straight down in top-down mode). */
  resetView(): void {
    if (!this.cameraModes || !this.floor || !this.display) return;
    // What the mouse set going (damped orbit, zoom, pan) stops first, so it cannot carry the camera off again.
    const { controls } = this.display;
    controls.enableDamping = false;
    controls.update();
    controls.enableDamping = true;
    if (this.cameraModes.mode === "top") {
      this.cameraModes.set("top");
    } else {
      this.cameraModes.set("free");
      this.frameFloor(this.floor);
    }
    this.needsRender = true;
  }

  /** Follows another robot when following one (the selection changed). */
  followRobot(robot: number): void {
    this.cameraModes?.follow(robot);
  }

  /** The camera's mode, the robot it follows, and where it is and looks (three.js coordinates). */
  cameraState(): { mode: ViewMode; following: number | null; position: number[]; direction: number[] } {
    const direction = this.camera.getWorldDirection(new Vector3());
    return {
      mode: this.cameraModes?.mode ?? "free",
      following: this.cameraModes?.followedRobot ?? null,
      position: this.camera.position.toArray(),
      direction: direction.toArray(),
    };
  }

  /** Adds drawings in world coordinates (sensor rays, paths) that stay across scenes. */
  addOverlay(overlay: Object3D): void {
    this.root.add(overlay);
    this.needsRender = true;
  }

  /** Something drawn changed outside applyPoses: draw the next frame. */
  requestRender(): void {
    this.needsRender = true;
  }

  applyPoses(poses: Poses): void {
    if (!this.world) return;
    for (const [id, pose] of poses.robots) {
      const robot = this.world.robots.get(id);
      if (robot && place(robot, pose)) this.needsRender = true;
    }
    for (const [id, pose] of poses.objects) {
      const object = this.world.objects.get(id);
      if (object && place(object, pose)) this.needsRender = true;
    }
    for (const [id, pose] of poses.bodies) {
      const body = this.world.bodies.get(id);
      if (body && place(body, pose)) this.needsRender = true;
    }
    // What is being dragged is drawn where the pointer has it, not where the (late) snapshots do.
    if (this.dragging?.applyPreview(poses)) this.needsRender = true;
  }

  /** Watching a recording or the past: clicks pick robots, nothing can be dragged. */
  setReadOnly(readOnly: boolean): void {
    if (this.dragging) this.dragging.readOnly = readOnly;
  }

  /** The 3D canvas (for video capture), or null without WebGL. */
  get canvas(): HTMLCanvasElement | null {
    return this.display?.renderer.domElement ?? null;
  }

  /** The 3D view as a PNG data URL, drawn afresh (the canvas keeps no picture between frames). */
  screenshot(): string | null {
    if (!this.display) return null;
    this.needsRender = true;
    this.render();
    return this.display.renderer.domElement.toDataURL("image/png");
  }

  /** Snapping while dragging things (the scene editor's), or null for free dragging. */
  set dragSnap(snap: DragSnap | null) {
    if (this.dragging) this.dragging.snap = snap;
  }

  /** What the pointer is dragging now, or null. */
  draggedThing(): DragTarget | null {
    return this.dragging?.dragging ?? null;
  }

  /** Where a world point appears on the page, in CSS pixels; null without WebGL. */
  screenPosition(x: number, y: number, z: number): { x: number; y: number } | null {
    return this.pageOf(new Vector3(x, y, z).applyMatrix4(this.root.matrixWorld));
  }

  /** The floor point (world metres, z up) under a page position; null without WebGL or above the horizon. */
  floorPointAt(clientX: number, clientY: number): { x: number; y: number } | null {
    const canvas = this.canvas;
    if (!canvas) return null;
    const rect = canvas.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1, 1 - ((clientY - rect.top) / rect.height) * 2);
    const raycaster = new Raycaster();
    raycaster.setFromCamera(ndc, this.camera);
    this.root.updateMatrixWorld();
    const ray = raycaster.ray.clone().applyMatrix4(this.root.matrixWorld.clone().invert());
    const point = ray.intersectPlane(new Plane(new Vector3(0, 0, 1), 0), new Vector3());
    return point ? { x: point.x, y: point.y } : null;
  }

  /** Draws a frame if anything moved since the last one. */
  render(): void {
    if (!this.display) return;
    if (this.cameraModes?.update()) this.needsRender = true;
    this.display.controls.update();
    if (!this.needsRender) return;
    this.needsRender = false;
    this.display.renderer.render(this.scene, this.camera);
    this.display.labels.render(this.scene, this.camera);
  }

  counts(): WorldCounts {
    return {
      robots: this.world?.robots.size ?? 0,
      walls: this.world?.wallCount ?? 0,
      objects: this.world?.objects.size ?? 0,
      markers: this.world?.markerCount ?? 0,
    };
  }

  robotBodiesAndWater(): { bodies: number; water: number | null } {
    return { bodies: this.world?.bodies.size ?? 0, water: this.world?.waterSurface ?? null };
  }

  /** The robot's pose as drawn (world frame), or null if it is unknown or not yet placed. */
  displayedRobotPose(id: number): Pose | null {
    const robot = this.world?.robots.get(id);
    return robot?.visible ? poseOf(robot) : null;
  }

  /** Where the robot's centre appears on the page, in CSS pixels; null without WebGL. */
  robotScreenPosition(id: number): { x: number; y: number } | null {
    const robot = this.world?.robots.get(id);
    return robot?.visible ? this.pageOf(robot.getWorldPosition(new Vector3())) : null;
  }

  /** Where a point in three.js coordinates appears on the page (CSS pixels); null without WebGL. */
  private pageOf(point: Vector3): { x: number; y: number } | null {
    if (!this.display) return null;
    this.camera.updateMatrixWorld();
    const ndc = point.project(this.camera);
    const rect = this.display.renderer.domElement.getBoundingClientRect();
    return {
      x: rect.left + ((ndc.x + 1) / 2) * rect.width,
      y: rect.top + ((1 - ndc.y) / 2) * rect.height,
    };
  }

  /** Looks at the floor's centre from the south, with its circumscribed circle in view. */
  private frameFloor(floor: Floor): void {
    const centre = worldToThree(floor.width / 2, floor.height / 2, 0);
    const radius = Math.hypot(floor.width, floor.height) / 2;
    const halfHeight = Math.tan((FIELD_OF_VIEW * Math.PI) / 360);
    const halfView = Math.min(halfHeight, halfHeight * this.camera.aspect);
    const distance = radius / halfView;
    const offset = worldToThree(0, -Math.cos(CAMERA_ELEVATION), Math.sin(CAMERA_ELEVATION));
    this.camera.position.copy(centre).addScaledVector(offset, distance);
    this.camera.near = distance / 500;
    this.camera.far = distance * 20;
    this.camera.updateProjectionMatrix();
    this.camera.lookAt(centre);
    this.display?.controls.target.copy(centre);
    this.display?.controls.update();
  }

  private resize(): void {
    if (!this.display) return;
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.display.renderer.setSize(width, height);
    this.display.labels.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.needsRender = true;
  }
}
