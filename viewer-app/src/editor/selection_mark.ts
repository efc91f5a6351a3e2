// Marks the thing selected in the editor on the floor of the 3D view: a ring around a robot,
// object or marker where the scene places it, a line along a wall.

import { BufferGeometry, Group, Line, LineBasicMaterial, LineLoop, Vector3 } from "three";
import type { WorldView } from "../world_view";

const COLOR = 0x2f6fd0;
const HEIGHT = 0.012; // m above the floor (over the wall tool's line)
const RING_RADIUS = 0.16; // m
const RING_SEGMENTS = 40;

export class SelectionMark {
  private readonly ring = new LineLoop(new BufferGeometry(), new LineBasicMaterial({ color: COLOR }));
  private readonly wall = new Line(new BufferGeometry(), new LineBasicMaterial({ color: COLOR }));
  private readonly group = new Group();

  constructor(private readonly world: WorldView) {
    const points = [];
    for (let i = 0; i < RING_SEGMENTS; i++) {
      const angle = (i / RING_SEGMENTS) * 2 * Math.PI;
      points.push(new Vector3(RING_RADIUS * Math.cos(angle), RING_RADIUS * Math.sin(angle), 0));
    }
    this.ring.geometry.setFromPoints(points);
    this.group.add(this.ring, this.wall);
    this.group.visible = false;
    world.addOverlay(this.group);
  }

  /** Around the point (mm), or along the wall (mm), or nothing (null). */
  show(at: { x: number; y: number } | { x1: number; y1: number; x2: number; y2: number } | null): void {
    this.group.visible = at !== null;
    if (at && "x1" in at) {
      this.ring.visible = false;
      this.wall.visible = true;
      this.wall.geometry.setFromPoints([
        new Vector3(at.x1 / 1000, at.y1 / 1000, HEIGHT),
        new Vector3(at.x2 / 1000, at.y2 / 1000, HEIGHT),
      ]);
    } else if (at) {
      this.wall.visible = false;
      this.ring.visible = true;
      this.ring.position.set(at.x / 1000, at.y / 1000, HEIGHT);
    }
    this.world.requestRender();
  }
}
