// Drawn over the world when the scene asks: what the robots' parts draw (settings VIS: PSD beams,
// lidar scans, pressed bumpers; any part kind, in its colour) and robot paths (TRACE).

import { BufferGeometry, Float32BufferAttribute, Group, Line, LineBasicMaterial, LineSegments } from "three";
import type { BodyPose, PathsMessage, SceneSettings, SensorRays } from "./protocol";

/** Colours of the rays that do not bring their own: PSD beams red, lidar beams green, others grey. */
const RAY_COLORS: Record<string, number> = { psd: 0xe53935, lidar: 0x2e9e44 };
const OTHER_RAYS = 0x757575;
const TRACE_COLOR = 0x1e63c8;
/** A path gets a new point once the robot moved this far (m); the oldest points go beyond MAX. */
const TRACE_STEP = 0.005;
const MAX_TRACE_POINTS = 20000;
/** Lifts paths above the floor so they do not flicker against it. */
const TRACE_HEIGHT = 0.002;

interface Trace {
  points: number[];
  /** when each point was reached (s of simulation time), so the timeline can cut the path there */
  times: number[];
  line: Line;
}

export class Overlays {
  /** Add to the world root: everything here is in world coordinates. */
  readonly group = new Group();
  private readonly rays = new Group();
  /** the rays drawn now, as received */
  private shownRays: SensorRays[] = [];
  private readonly traces = new Map<number, Trace>();
  private settings: SceneSettings = { vis: false, trace: false };

  constructor() {
    this.group.name = "overlays";
    this.group.add(this.rays);
  }

  /** A new or reset scene: paths start again. */
  reset(settings: SceneSettings): void {
    this.settings = settings;
    this.showRays([]);
    for (const trace of this.traces.values()) {
      this.group.remove(trace.line);
      trace.line.geometry.dispose();
    }
    this.traces.clear();
  }

  /** Applies a snapshot; says whether anything drawn changed. `extend`: add to the paths (live). */
  update(robots: BodyPose[], rays: SensorRays[] | undefined, time: number, extend = true): boolean {
    let changed = false;
    if (this.settings.vis) {
      this.showRays(rays ?? []);
      changed = true;
    }
    if (this.settings.trace && extend) {
      for (const robot of robots) changed = this.extendTrace(robot, time) || changed;
    }
    return changed;
  }

  /** Replaces the paths with whole recorded ones (the timeline's `paths`); drawn up to `cutAt`'s time. */
  loadPaths(paths: PathsMessage["robots"]): void {
    if (!this.settings.trace) return;
    for (const path of paths) {
      const trace = this.traceOf(path.id);
      trace.points = [];
      for (let i = 0; i + 1 < path.points.length; i += 2) trace.points.push(path.points[i], path.points[i + 1], TRACE_HEIGHT);
      trace.times = [...path.times];
      this.rebuild(trace);
    }
  }

  /** Draws each path only up to `time` (s): where the robots had been by then. */
  cutAt(time: number): void {
    for (const trace of this.traces.values()) {
      let count = trace.times.length;
      while (count > 0 && trace.times[count - 1] > time) count--;
      trace.line.geometry.setDrawRange(0, count);
    }
  }

  /** Number of points of a robot's path drawn now (for tests). */
  tracePoints(robot: number): number {
    const trace = this.traces.get(robot);
    if (!trace) return 0;
    const range = trace.line.geometry.drawRange;
    return Math.min(trace.points.length / 3, range.count === Infinity ? Infinity : range.start + range.count);
  }

  /** The sensor rays drawn now (what a click in the 3D view can pick a PSD beam from). */
  drawnRays(): SensorRays[] {
    return this.shownRays;
  }

  /** Number of ray segments drawn (for tests). */
  raySegments(): number {
    let count = 0;
    for (const child of this.rays.children) {
      count += (child as LineSegments).geometry.getAttribute("position").count / 2;
    }
    return count;
  }

  private showRays(rays: SensorRays[]): void {
    this.shownRays = rays;
    for (const child of [...this.rays.children]) {
      this.rays.remove(child);
      (child as LineSegments).geometry.dispose();
    }
    // One set of line segments per colour, whatever part kind drew them.
    const byColor = new Map<number, number[]>();
    for (const ray of rays) {
      const color = ray.color ? (ray.color[0] << 16) | (ray.color[1] << 8) | ray.color[2] : (RAY_COLORS[ray.kind] ?? OTHER_RAYS);
      let points = byColor.get(color);
      if (!points) byColor.set(color, (points = []));
      for (let i = 0; i + 2 < ray.ends.length; i += 3) {
        points.push(...ray.origin, ray.ends[i], ray.ends[i + 1], ray.ends[i + 2]);
      }
    }
    for (const [color, points] of byColor) {
      if (points.length === 0) continue;
      const geometry = new BufferGeometry();
      geometry.setAttribute("position", new Float32BufferAttribute(points, 3));
      const material = new LineBasicMaterial({ color, transparent: true, opacity: 0.8 });
      this.rays.add(new LineSegments(geometry, material));
    }
  }

  private traceOf(robot: number): Trace {
    let trace = this.traces.get(robot);
    if (!trace) {
      trace = { points: [], times: [], line: new Line(new BufferGeometry(), new LineBasicMaterial({ color: TRACE_COLOR })) };
      this.traces.set(robot, trace);
      this.group.add(trace.line);
    }
    return trace;
  }

  private extendTrace(robot: BodyPose, time: number): boolean {
    const trace = this.traceOf(robot.id);
    const [x, y] = robot.pos;
    const n = trace.points.length;
    if (n >= 3 && Math.hypot(x - trace.points[n - 3], y - trace.points[n - 2]) < TRACE_STEP) return false;
    trace.points.push(x, y, TRACE_HEIGHT);
    trace.times.push(time);
    if (trace.points.length > MAX_TRACE_POINTS * 3) {
      trace.points.splice(0, 3);
      trace.times.shift();
    }
    this.rebuild(trace);
    return true;
  }

  private rebuild(trace: Trace): void {
    trace.line.geometry.dispose();
    trace.line.geometry = new BufferGeometry();
    trace.line.geometry.setAttribute("position", new Float32BufferAttribute(trace.points, 3));
  }
}
