// Drag to place: press on a robot or object in the 3D view and drag it across the floor (Shift+drag
// turns it); the simulator moves it on `place` commands, as SIMSetRobot/SIMSetObject would.
// Clicks pick robots and objects, and PSD beams (drawn with the scene setting VIS) for the plots.

import { Matrix4, Object3D, Plane, Quaternion, Raycaster, Vector2, Vector3, type Camera } from "three";
import type { OrbitControls } from "three/addons/controls/OrbitControls.js";
import type { Pose, Poses } from "./interpolation";
import type { BrowserCommand, SceneMessage, SensorRays } from "./protocol";
import type { BuiltWorld } from "./world_builder";

/** What can be dragged: a robot (also when grabbed by an arm link or wheel) or an object. */
export interface DragTarget {
  kind: "robot" | "object";
  id: number;
}

/** What a click picks: a robot or object, or a robot's PSD (`id` as PSDGet takes it) by its beam. */
export type PickTarget = DragTarget | { kind: "psd"; robot: number; id: number };

/** Steps a drag keeps to (the scene editor's snapping): positions on a grid, turns by an angle. */
export interface DragSnap {
  gridMm: number;
  angleDeg: number;
}

/** What the 3D view lends the dragging. */
export interface DragHost {
  camera: Camera;
  canvas: HTMLElement;
  controls: OrbitControls;
  /** the world root: its children are placed in world coordinates (z up) */
  root: Object3D;
  world(): BuiltWorld | null;
  scene(): SceneMessage | null;
  requestRender(): void;
  /** a click on a robot or object (without dragging it), or on a PSD beam; also how a read-only
   *  view picks things */
  picked(target: PickTarget): void;
  /** the sensor rays drawn now (world coordinates) */
  rays(): SensorRays[];
}

/** A press that moves less than this (CSS pixels) before its release is a click. */
const CLICK_DISTANCE = 3;
/** A click this near (CSS pixels) to a PSD beam on the screen is a click on that beam. */
const BEAM_PICK_DISTANCE = 6;

/** Shift+drag turns the thing by one degree per pixel of sideways mouse motion (right = clockwise). */
const TURN_PER_PIXEL = Math.PI / 180;
/** While dragging, `place` goes out at most this often (ms); the final pose always goes on release. */
const SEND_INTERVAL_MS = 40;
/** After release the thing is drawn where it was dropped until the snapshots (which the view shows
 *  a little late) have it there too, but no longer than this (ms): it may be driving away. */
const SETTLE_MS = 600;
const SETTLED_DISTANCE = 0.002;
const SETTLED_ANGLE = 0.01;
const FLOOR = new Plane(new Vector3(0, 0, 1), 0);

interface Drag {
  target: DragTarget;
  pointer: number;
  turning: boolean;
  startClientX: number;
  startPhi: number;
  /** the thing's x, y minus the floor point under the pointer when it was grabbed */
  grab: Vector2;
  x: number;
  y: number;
  phi: number;
  lastSent: number;
  sent: string;
  /** performance.now() of the release; null while the button is down */
  releasedAt: number | null;
}

export function yawOf([w, x, y, z]: Pose["quat"]): number {
  return Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
}

function wrapAngle(angle: number): number {
  return Math.atan2(Math.sin(angle), Math.cos(angle));
}

/** The distance from point p to the segment from a to b. */
function distanceToSegment(p: Vector2, a: Vector2, b: Vector2): number {
  const ab = b.clone().sub(a);
  const length2 = ab.lengthSq();
  const t = length2 > 0 ? Math.min(1, Math.max(0, p.clone().sub(a).dot(ab) / length2)) : 0;
  return a.clone().addScaledVector(ab, t).distanceTo(p);
}

export class DragToPlace {
  private readonly raycaster = new Raycaster();
  private drag: Drag | null = null;
  /** A press on a PSD beam: released without moving, it is a click that picks the PSD. */
  private beamPress: { target: PickTarget; pointer: number; x: number; y: number } | null = null;
  /** Watching a recording or the past: things can be clicked (picked) but not moved. */
  readOnly = false;
  /** Snapping while dragging (null: free); Alt held drags free. */
  snap: DragSnap | null = null;
  private startClientY = 0;

  constructor(
    private readonly host: DragHost,
    private readonly send: (command: BrowserCommand) => void,
  ) {
    // Capture phase on the container: the press is ours before OrbitControls (on the canvas) sees it.
    const container = host.canvas.parentElement ?? host.canvas;
    container.addEventListener("pointerdown", (event) => this.press(event), { capture: true });
    container.addEventListener("pointermove", (event) => this.move(event), { capture: true });
    container.addEventListener("pointerup", (event) => this.release(event), { capture: true });
    container.addEventListener("pointercancel", (event) => this.release(event), { capture: true });
  }

  /** What is being dragged now (button down), or null. */
  get dragging(): DragTarget | null {
    return this.drag && this.drag.releasedAt === null ? { ...this.drag.target } : null;
  }

  /** A new scene: whatever was dragged may be gone. */
  cancel(): void {
    if (this.drag?.releasedAt === null) this.host.controls.enabled = true;
    this.drag = null;
    this.host.canvas.style.cursor = "";
  }

  /**
   * Draws the dragged thing where the pointer put it, over the (late) interpolated `poses` the
   * view has just applied, moving a robot's arm links and wheels along. Says whether it drew.
   */
  applyPreview(poses: Poses): boolean {
    const drag = this.drag;
    const world = this.host.world();
    if (!drag || !world) return false;
    const { kind, id } = drag.target;
    const model = (kind === "robot" ? world.robots : world.objects).get(id);
    const shown = (kind === "robot" ? poses.robots : poses.objects).get(id);
    if (!model || !shown) return false;
    if (drag.releasedAt !== null) {
      const settled =
        Math.hypot(shown.pos[0] - drag.x, shown.pos[1] - drag.y) < SETTLED_DISTANCE &&
        Math.abs(wrapAngle(yawOf(shown.quat) - drag.phi)) < SETTLED_ANGLE;
      if (settled || performance.now() - drag.releasedAt > SETTLE_MS) {
        this.drag = null;
        return false;
      }
    }
    const before = new Matrix4().compose(
      new Vector3(...shown.pos),
      new Quaternion(shown.quat[1], shown.quat[2], shown.quat[3], shown.quat[0]),
      new Vector3(1, 1, 1),
    );
    // Upright at its height (never below the floor), as the simulator sets it.
    model.position.set(drag.x, drag.y, Math.max(shown.pos[2], 0));
    model.quaternion.setFromAxisAngle(new Vector3(0, 0, 1), drag.phi);
    model.updateMatrix();
    if (kind === "robot") {
      const moved = model.matrix.clone().multiply(before.invert());
      for (const body of this.host.scene()?.bodies ?? []) {
        const part = body.robot === id ? world.bodies.get(body.id) : undefined;
        if (!part) continue;
        part.updateMatrix();
        part.matrix.premultiply(moved).decompose(part.position, part.quaternion, part.scale);
      }
    }
    return true;
  }

  private press(event: PointerEvent): void {
    // Only presses on the 3D picture itself (not on the help, labels or notices over it).
    if (event.target !== this.host.canvas || event.button !== 0 || !event.isPrimary) return;
    if (this.drag?.releasedAt === null) return;
    // A beam before the robot it starts on: a beam is a thin line, the robot is easy to hit beside it.
    // The press still goes on to the camera controls, so dragging from a beam turns the view.
    const beam = this.pickBeam(event);
    this.beamPress = beam && { target: beam, pointer: event.pointerId, x: event.clientX, y: event.clientY };
    if (beam) return;
    const target = this.pick(event);
    const world = this.host.world();
    const floor = this.floorPoint(event);
    if (!target || !world || !floor) return;
    const model = (target.kind === "robot" ? world.robots : world.objects).get(target.id);
    if (!model) return;
    if (this.readOnly) {
      this.host.picked(target);
      return;
    }
    event.stopPropagation();
    event.preventDefault();
    this.startClientY = event.clientY;
    this.host.canvas.setPointerCapture(event.pointerId);
    this.host.controls.enabled = false;
    this.host.canvas.style.cursor = "grabbing";
    const q = model.quaternion;
    const phi = yawOf([q.w, q.x, q.y, q.z]);
    this.drag = {
      target,
      pointer: event.pointerId,
      turning: event.shiftKey,
      startClientX: event.clientX,
      startPhi: phi,
      grab: new Vector2(model.position.x - floor.x, model.position.y - floor.y),
      x: model.position.x,
      y: model.position.y,
      phi,
      lastSent: 0,
      sent: "",
      releasedAt: null,
    };
  }

  private move(event: PointerEvent): void {
    const drag = this.drag;
    if (!drag || drag.releasedAt !== null) {
      if (event.buttons === 0 && event.target === this.host.canvas) {
        this.host.canvas.style.cursor = this.pickBeam(event) ? "pointer" : this.pick(event) ? "grab" : "";
      }
      return;
    }
    if (event.pointerId !== drag.pointer) return;
    event.stopPropagation();
    this.follow(drag, event);
    if (performance.now() - drag.lastSent >= SEND_INTERVAL_MS) this.sendPlace(drag);
  }

  private release(event: PointerEvent): void {
    const pressed = this.beamPress;
    if (pressed && event.pointerId === pressed.pointer) {
      this.beamPress = null;
      const still = Math.hypot(event.clientX - pressed.x, event.clientY - pressed.y) < CLICK_DISTANCE;
      if (event.type === "pointerup" && still) this.host.picked(pressed.target);
    }
    const drag = this.drag;
    if (!drag || drag.releasedAt !== null || event.pointerId !== drag.pointer) return;
    event.stopPropagation();
    const click = Math.hypot(event.clientX - drag.startClientX, event.clientY - this.startClientY) < CLICK_DISTANCE;
    if (click) this.host.picked(drag.target);
    if (event.type === "pointerup") this.follow(drag, event);
    this.sendPlace(drag);
    drag.releasedAt = performance.now();
    this.host.controls.enabled = true;
    this.host.canvas.style.cursor = "";
    if (this.host.canvas.hasPointerCapture(event.pointerId)) {
      this.host.canvas.releasePointerCapture(event.pointerId);
    }
  }

  /** Moves the drag's pose to where the pointer says, kept on the floor (and on the snap grid). */
  private follow(drag: Drag, event: PointerEvent): void {
    const snap = event.altKey ? null : this.snap;
    const step = (value: number, size: number) => (snap && size > 0 ? Math.round(value / size) * size : value);
    if (drag.turning) {
      const turned = drag.startPhi - (event.clientX - drag.startClientX) * TURN_PER_PIXEL;
      drag.phi = wrapAngle(step(turned, ((snap?.angleDeg ?? 0) * Math.PI) / 180));
    } else {
      const floor = this.floorPoint(event);
      const size = this.host.scene()?.floor;
      if (!floor || !size) return;
      const grid = (snap?.gridMm ?? 0) / 1000;
      drag.x = Math.min(size.width, Math.max(0, step(floor.x + drag.grab.x, grid)));
      drag.y = Math.min(size.height, Math.max(0, step(floor.y + drag.grab.y, grid)));
    }
    this.host.requestRender();
  }

  private sendPlace(drag: Drag): void {
    const { kind, id } = drag.target;
    const command: BrowserCommand =
      kind === "robot"
        ? { type: "place", robot: id, x: drag.x, y: drag.y, phi: drag.phi }
        : { type: "place", object: id, x: drag.x, y: drag.y, phi: drag.phi };
    const text = JSON.stringify(command);
    drag.lastSent = performance.now();
    if (text === drag.sent) return;
    drag.sent = text;
    this.send(command);
  }

  private aim(event: PointerEvent): void {
    const rect = this.host.canvas.getBoundingClientRect();
    const ndc = new Vector2(
      ((event.clientX - rect.left) / rect.width) * 2 - 1,
      1 - ((event.clientY - rect.top) / rect.height) * 2,
    );
    this.raycaster.setFromCamera(ndc, this.host.camera);
  }

  /** The robot or object under the pointer, if any. */
  private pick(event: PointerEvent): DragTarget | null {
    const world = this.host.world();
    if (!world) return null;
    const owners = new Map<Object3D, DragTarget>();
    for (const [id, model] of world.robots) owners.set(model, { kind: "robot", id });
    for (const [id, model] of world.objects) owners.set(model, { kind: "object", id });
    for (const body of this.host.scene()?.bodies ?? []) {
      const part = world.bodies.get(body.id);
      if (part) owners.set(part, { kind: "robot", id: body.robot });
    }
    this.aim(event);
    const hits = this.raycaster.intersectObjects([...owners.keys()].filter((o) => o.visible), true);
    for (const hit of hits) {
      for (let thing: Object3D | null = hit.object; thing; thing = thing.parent) {
        const owner = owners.get(thing);
        if (owner) return owner;
      }
    }
    return null;
  }

  /** The PSD whose beam, from the sensor on its robot to where the beam ends, passes within
   *  BEAM_PICK_DISTANCE of the pointer on the screen (the nearest if several), or null. */
  private pickBeam(event: PointerEvent): PickTarget | null {
    const rect = this.host.canvas.getBoundingClientRect();
    const pointer = new Vector2(event.clientX - rect.left, event.clientY - rect.top);
    const { camera, root } = this.host;
    camera.updateMatrixWorld();
    root.updateMatrixWorld();
    const onScreen = ([x, y, z]: number[]): Vector2 | null => {
      const ndc = new Vector3(x, y, z).applyMatrix4(root.matrixWorld).project(camera);
      if (Math.abs(ndc.z) > 1) return null; // behind the camera or beyond its far plane
      return new Vector2(((ndc.x + 1) / 2) * rect.width, ((1 - ndc.y) / 2) * rect.height);
    };
    let nearest: PickTarget | null = null;
    let nearestDistance = BEAM_PICK_DISTANCE;
    for (const ray of this.host.rays()) {
      if (ray.kind !== "psd" || ray.psd === undefined) continue;
      const start = onScreen(ray.origin);
      const end = onScreen(ray.ends.slice(0, 3));
      if (!start || !end) continue;
      const distance = distanceToSegment(pointer, start, end);
      if (distance <= nearestDistance) {
        nearest = { kind: "psd", robot: ray.robot, id: ray.psd };
        nearestDistance = distance;
      }
    }
    return nearest;
  }

  /** The floor point (world coordinates) under the pointer; null when it points above the horizon. */
  private floorPoint(event: PointerEvent): Vector3 | null {
    this.aim(event);
    this.host.root.updateMatrixWorld();
    const ray = this.raycaster.ray.clone().applyMatrix4(this.host.root.matrixWorld.clone().invert());
    return ray.intersectPlane(FLOOR, new Vector3());
  }
}
