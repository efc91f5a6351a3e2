// The robot in 3D as the simulator built it: the viewer's own world builder draws the scene message
// the server made from the built robot; PSD beams, the lidar's scan plane and the camera's field of
// view are drawn over it. Parts are picked with a click; a selected PSD or camera shows two
// handles: drag the ball at the sensor to move it, the ball at the beam's tip to turn it.

import {
  BufferGeometry,
  Color,
  DirectionalLight,
  Float32BufferAttribute,
  Group,
  HemisphereLight,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  Object3D,
  PerspectiveCamera,
  Plane,
  Raycaster,
  Scene,
  SphereGeometry,
  Vector2,
  Vector3,
  WebGLRenderer,
} from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import type { RobotSensors, SceneMessage } from "../protocol";
import { buildWorld, disposeWorld, type BuiltWorld } from "../world_builder";
import { createWorldRoot, worldToThree } from "../world_frame";

/** A handle was dragged: the sensor at `pointer` goes to (x, y) mm in the robot frame, or turns
 * to `heading` degrees. */
export type HandleMove = (pointer: string, change: { x?: number; y?: number; heading?: number }) => void;

const BEAM_LENGTH = 0.3; // m drawn of a beam that hits nothing
const CAMERA_DEPTH = 0.15; // m: how far the field-of-view pyramid reaches
const HANDLE_RADIUS = 0.009;
const SELECTED = 0xff8c1a;

interface Handle {
  mesh: Mesh;
  pointer: string;
  kind: "move" | "turn";
  height: number; // world z of the sensor
}

export class RobotPreview {
  private readonly scene = new Scene();
  private readonly root = createWorldRoot();
  private readonly overlay = new Group();
  private readonly camera = new PerspectiveCamera(40, 1, 0.01, 100);
  private readonly renderer: WebGLRenderer | null;
  private readonly controls: OrbitControls | null;
  private world: BuiltWorld | null = null;
  private handles: Handle[] = [];
  private dragging: Handle | null = null;
  private robotPos: number[] = [0, 0, 0];
  private robotYaw = 0;
  private framedFor = "";
  selected = "";

  constructor(
    private readonly container: HTMLElement,
    private readonly picked: (pointer: string) => void,
    private readonly moved: HandleMove,
  ) {
    this.scene.background = new Color(0xdde3ea);
    this.scene.add(new HemisphereLight(0xffffff, 0x8a8f96, 2.2));
    const sun = new DirectionalLight(0xffffff, 1.6);
    sun.position.copy(worldToThree(-3, -5, 10));
    this.root.add(this.overlay);
    this.scene.add(sun, this.root);
    let renderer: WebGLRenderer | null = null;
    try {
      renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    } catch (error) {
      console.warn("EyeSim robot editor: no WebGL, no 3D preview", error);
    }
    this.renderer = renderer;
    this.controls = null;
    if (renderer) {
      renderer.setPixelRatio(window.devicePixelRatio);
      container.append(renderer.domElement);
      this.controls = new OrbitControls(this.camera, renderer.domElement);
      this.controls.addEventListener("change", () => this.draw());
      new ResizeObserver(() => this.resize()).observe(container);
      const canvas = renderer.domElement;
      canvas.addEventListener("pointerdown", (event) => this.pointerDown(event));
      canvas.addEventListener("pointermove", (event) => this.pointerMove(event));
      canvas.addEventListener("pointerup", () => this.pointerUp());
      this.resize();
    }
  }

  /** Draws a built robot (or the test-drive arena) and its sensors. */
  show(scene: SceneMessage, sensors: RobotSensors, frameKey: string): void {
    if (this.world) disposeWorld(this.world);
    this.world = buildWorld(scene, () => this.draw());
    this.root.add(this.world.group);
    this.place(sensors);
    if (frameKey !== this.framedFor) {
      this.framedFor = frameKey;
      this.frame(scene);
    }
  }

  /** New poses and sensor lines for the drawn world (the test drive's state). */
  place(sensors: RobotSensors): void {
    if (!this.world) return;
    for (const pose of sensors.snapshot.robots) {
      const thing = this.world.robots.get(pose.id);
      if (!thing) continue;
      thing.position.set(pose.pos[0], pose.pos[1], pose.pos[2]);
      thing.quaternion.set(pose.quat[1], pose.quat[2], pose.quat[3], pose.quat[0]);
      thing.visible = true;
      thing.userData.pointer = "";
      this.robotPos = pose.pos;
      const [w, , , z] = pose.quat;
      this.robotYaw = 2 * Math.atan2(z, w);
    }
    for (const pose of sensors.snapshot.bodies) {
      const thing = this.world.bodies.get(pose.id);
      if (!thing) continue;
      thing.position.set(pose.pos[0], pose.pos[1], pose.pos[2]);
      thing.quaternion.set(pose.quat[1], pose.quat[2], pose.quat[3], pose.quat[0]);
      thing.visible = true;
    }
    this.drawSensors(sensors);
    this.draw();
  }

  private frame(scene: SceneMessage): void {
    const [length, width, height] = scene.robots[0]?.size ?? [0.2, 0.2, 0.1];
    const reach = Math.max(length, width, height, 0.15) * 2.6 + 0.1;
    const [x, y] = this.robotPos;
    const target = worldToThree(x, y, height / 2);
    this.camera.position.copy(worldToThree(x - reach * 0.9, y - reach * 0.9, reach * 0.8));
    this.camera.lookAt(target);
    this.controls?.target.copy(target);
    this.controls?.update();
  }

  private drawSensors(sensors: RobotSensors): void {
    for (const child of [...this.overlay.children]) {
      child.removeFromParent();
      if (child instanceof Mesh || child instanceof LineSegments) {
        child.geometry.dispose();
        (child.material as LineBasicMaterial).dispose();
      }
    }
    this.handles = [];
    sensors.psds.forEach((beam, index) => {
      const pointer = `/psds/${index}`;
      const length = beam.hit ?? BEAM_LENGTH;
      const end = beam.origin.map((v, i) => v + beam.direction[i] * length);
      const selected = this.selected === pointer;
      const line = lines([...beam.origin, ...end], selected ? SELECTED : 0xd0202a);
      line.userData.pointer = pointer;
      this.overlay.add(line);
      if (selected) {
        const tip = beam.origin.map((v, i) => v + beam.direction[i] * Math.min(length, 0.12));
        this.addHandle(pointer, "move", beam.origin);
        this.addHandle(pointer, "turn", tip);
      } else {
        this.addPickBall(pointer, beam.origin);
      }
    });
    if (sensors.lidar) {
      const { origin, directions } = sensors.lidar;
      const points: number[] = [];
      const step = Math.max(1, Math.floor(directions.length / 3 / 72));
      for (let i = 0; i < directions.length / 3; i += step) {
        points.push(...origin, ...[0, 1, 2].map((k) => origin[k] + directions[3 * i + k] * BEAM_LENGTH));
      }
      const fan = lines(points, this.selected === "/lidar" ? SELECTED : 0x2a9d4b);
      fan.userData.pointer = "/lidar";
      this.overlay.add(fan);
    }
    if (sensors.camera) {
      const pointer = "/camera";
      const c = sensors.camera;
      const f = new Vector3(...(c.forward as [number, number, number]));
      const u = new Vector3(...(c.up as [number, number, number]));
      const r = new Vector3().crossVectors(f, u);
      const half = Math.tan((Math.min(c.fov, 170) * Math.PI) / 360) * CAMERA_DEPTH;
      const p = new Vector3(...(c.position as [number, number, number]));
      const corners = [
        [1, 1],
        [1, -1],
        [-1, -1],
        [-1, 1],
      ].map(([a, b]) =>
        p
          .clone()
          .addScaledVector(f, CAMERA_DEPTH)
          .addScaledVector(r, a * half)
          .addScaledVector(u, (b * half) / c.aspect),
      );
      const points: number[] = [];
      corners.forEach((corner, i) => {
        const next = corners[(i + 1) % 4];
        points.push(p.x, p.y, p.z, corner.x, corner.y, corner.z, corner.x, corner.y, corner.z, next.x, next.y, next.z);
      });
      const selected = this.selected === pointer;
      const pyramid = lines(points, selected ? SELECTED : 0x2255cc);
      pyramid.userData.pointer = pointer;
      this.overlay.add(pyramid);
      if (selected) {
        this.addHandle(pointer, "move", c.position);
        this.addHandle(pointer, "turn", [p.x + f.x * 0.12, p.y + f.y * 0.12, p.z + f.z * 0.12]);
      } else {
        this.addPickBall(pointer, c.position);
      }
    }
  }

  private addHandle(pointer: string, kind: Handle["kind"], at: number[]): void {
    const mesh = new Mesh(
      new SphereGeometry(HANDLE_RADIUS * (kind === "move" ? 1.2 : 1), 16, 12),
      new MeshBasicMaterial({ color: kind === "move" ? SELECTED : 0xffd21a, depthTest: false }),
    );
    mesh.renderOrder = 10;
    mesh.position.set(at[0], at[1], at[2]);
    mesh.userData.pointer = pointer;
    this.overlay.add(mesh);
    this.handles.push({ mesh, pointer, kind, height: at[2] });
  }

  /** A small ball that makes a sensor easy to click. */
  private addPickBall(pointer: string, at: number[]): void {
    const ball = new Mesh(new SphereGeometry(HANDLE_RADIUS * 0.7, 12, 8), new MeshBasicMaterial({ color: 0x444444 }));
    ball.position.set(at[0], at[1], at[2]);
    ball.userData.pointer = pointer;
    this.overlay.add(ball);
  }

  /** Where a handle is on the page (for tests and for keyboard users): client pixels. */
  handleAt(pointer: string, kind: Handle["kind"]): { x: number; y: number } | null {
    const handle = this.handles.find((h) => h.pointer === pointer && h.kind === kind);
    if (!handle || !this.renderer) return null;
    const world = new Vector3();
    handle.mesh.getWorldPosition(world);
    world.project(this.camera);
    const box = this.renderer.domElement.getBoundingClientRect();
    return { x: box.left + ((world.x + 1) / 2) * box.width, y: box.top + ((1 - world.y) / 2) * box.height };
  }

  /** Where a sensor point (world, m) is on the page. */
  screenOf(point: number[]): { x: number; y: number } | null {
    if (!this.renderer) return null;
    const v = new Vector3(point[0], point[1], point[2]).applyMatrix4(this.root.matrixWorld).project(this.camera);
    const box = this.renderer.domElement.getBoundingClientRect();
    return { x: box.left + ((v.x + 1) / 2) * box.width, y: box.top + ((1 - v.y) / 2) * box.height };
  }

  private ray(event: PointerEvent): Raycaster | null {
    if (!this.renderer) return null;
    const box = this.renderer.domElement.getBoundingClientRect();
    const ndc = new Vector2(((event.clientX - box.left) / box.width) * 2 - 1, -((event.clientY - box.top) / box.height) * 2 + 1);
    const raycaster = new Raycaster();
    raycaster.params.Line = { threshold: 0.006 };
    raycaster.setFromCamera(ndc, this.camera);
    return raycaster;
  }

  private pointerDown(event: PointerEvent): void {
    const raycaster = this.ray(event);
    if (!raycaster) return;
    const handleHit = raycaster.intersectObjects(this.handles.map((h) => h.mesh), false)[0];
    if (handleHit) {
      this.dragging = this.handles.find((h) => h.mesh === handleHit.object) ?? null;
      if (this.controls) this.controls.enabled = false;
      return;
    }
    const things: Object3D[] = [this.overlay, ...(this.world ? this.world.robots.values() : [])];
    for (const hit of raycaster.intersectObjects(things, true)) {
      let thing: Object3D | null = hit.object;
      while (thing && thing.userData.pointer === undefined) thing = thing.parent;
      if (thing) {
        this.picked(thing.userData.pointer as string);
        return;
      }
    }
  }

  private pointerMove(event: PointerEvent): void {
    if (!this.dragging) return;
    const raycaster = this.ray(event);
    if (!raycaster) return;
    // The drag stays in the horizontal plane at the sensor's height (in three.js y is up).
    const plane = new Plane(new Vector3(0, 1, 0), -this.dragging.height);
    const hit = raycaster.ray.intersectPlane(plane, new Vector3());
    if (!hit) return;
    const world = new Vector3(hit.x, -hit.z, hit.y); // three.js -> world (z up)
    const dx = world.x - this.robotPos[0];
    const dy = world.y - this.robotPos[1];
    const c = Math.cos(-this.robotYaw);
    const s = Math.sin(-this.robotYaw);
    const local = [c * dx - s * dy, s * dx + c * dy]; // robot frame, m
    const handle = this.dragging;
    if (handle.kind === "move") {
      handle.mesh.position.set(world.x, world.y, handle.height);
      this.moved(handle.pointer, { x: round(local[0] * 1000), y: round(local[1] * 1000) });
    } else {
      const sensor = this.handles.find((h) => h.pointer === handle.pointer && h.kind === "move");
      if (!sensor) return;
      const sx = sensor.mesh.position.x - this.robotPos[0];
      const sy = sensor.mesh.position.y - this.robotPos[1];
      const sensorLocal = [c * sx - s * sy, s * sx + c * sy];
      const heading = (Math.atan2(local[1] - sensorLocal[1], local[0] - sensorLocal[0]) * 180) / Math.PI;
      handle.mesh.position.set(world.x, world.y, handle.height);
      this.moved(handle.pointer, { heading: round(heading) });
    }
    this.draw();
  }

  private pointerUp(): void {
    this.dragging = null;
    if (this.controls) this.controls.enabled = true;
  }

  get isDragging(): boolean {
    return this.dragging !== null;
  }

  private resize(): void {
    if (!this.renderer) return;
    const { clientWidth: width, clientHeight: height } = this.container;
    if (width === 0 || height === 0) return;
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  draw(): void {
    if (!this.renderer) return;
    this.renderer.render(this.scene, this.camera);
  }
}

function lines(points: number[], color: number): LineSegments {
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new Float32BufferAttribute(points, 3));
  return new LineSegments(geometry, new LineBasicMaterial({ color }));
}

function round(value: number): number {
  return Math.round(value * 10) / 10;
}
