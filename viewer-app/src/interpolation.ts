// Smooth motion: keeps the last few snapshots and blends poses at a time slightly in the past.

import { Quaternion } from "three";
import type { BodyPose, Quat, SnapshotMessage, Vec3 } from "./protocol";

export interface Pose {
  pos: Vec3;
  quat: Quat;
}

export interface Poses {
  robots: Map<number, Pose>;
  objects: Map<number, Pose>;
  /** robots' moving parts, by body id */
  bodies: Map<number, Pose>;
}

interface Arrival {
  snapshot: SnapshotMessage;
  /** performance.now() when it arrived */
  at: number;
}

/** How far behind the newest snapshot the view runs, so there is usually a later one to blend to. */
const RENDER_DELAY_MS = 100;
const CAPACITY = 16;

/** A unit quaternion, so a sender's rounding never scales a model. */
function normalized([w, x, y, z]: Quat): Quat {
  const length = Math.hypot(w, x, y, z);
  return length > 0 ? [w / length, x / length, y / length, z / length] : [1, 0, 0, 0];
}

function byId(bodies: BodyPose[]): Map<number, Pose> {
  return new Map(bodies.map((b) => [b.id, { pos: b.pos, quat: normalized(b.quat) }]));
}

const qa = new Quaternion();
const qb = new Quaternion();

function blend(a: Pose, b: Pose, t: number): Pose {
  // three.js orders quaternions (x, y, z, w); the wire orders them (w, x, y, z).
  qa.set(a.quat[1], a.quat[2], a.quat[3], a.quat[0]);
  qb.set(b.quat[1], b.quat[2], b.quat[3], b.quat[0]);
  qa.slerp(qb, t);
  return {
    pos: [0, 1, 2].map((i) => a.pos[i] + (b.pos[i] - a.pos[i]) * t) as Vec3,
    quat: [qa.w, qa.x, qa.y, qa.z],
  };
}

function blendAll(from: Map<number, Pose>, to: Map<number, Pose>, t: number): Map<number, Pose> {
  const result = new Map<number, Pose>();
  for (const [id, b] of to) {
    const a = from.get(id);
    result.set(id, a ? blend(a, b, t) : b);
  }
  return result;
}

/**
 * Timing uses arrival times rather than simulation time, so pausing, speed changes and resets
 * (where simulation time jumps) need no special cases.
 */
export class SnapshotBuffer {
  private arrivals: Arrival[] = [];

  push(snapshot: SnapshotMessage, at: number): void {
    this.arrivals.push({ snapshot, at });
    if (this.arrivals.length > CAPACITY) this.arrivals.shift();
  }

  clear(): void {
    this.arrivals = [];
  }

  latest(): SnapshotMessage | null {
    return this.arrivals.at(-1)?.snapshot ?? null;
  }

  /** Poses to draw at `now` (performance.now()), or null before the first snapshot. */
  posesAt(now: number): Poses | null {
    const renderAt = now - RENDER_DELAY_MS;
    const next = this.arrivals.findIndex((a) => a.at > renderAt);
    if (next === -1) {
      const last = this.arrivals.at(-1);
      if (!last) return null;
      const { robots, objects, bodies } = last.snapshot;
      return { robots: byId(robots), objects: byId(objects), bodies: byId(bodies) };
    }
    const b = this.arrivals[next];
    const a = next > 0 ? this.arrivals[next - 1] : b;
    const t = a === b ? 1 : (renderAt - a.at) / (b.at - a.at);
    return {
      robots: blendAll(byId(a.snapshot.robots), byId(b.snapshot.robots), t),
      objects: blendAll(byId(a.snapshot.objects), byId(b.snapshot.objects), t),
      bodies: blendAll(byId(a.snapshot.bodies), byId(b.snapshot.bodies), t),
    };
  }
}
