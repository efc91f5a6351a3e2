// Drawing a wall: press on the floor, drag to its other end, release. Ends snap to a grid (mm)
// unless snapping is switched off or Alt is held. The wall is drawn as a line while dragging.

import { BufferGeometry, Group, Line, LineBasicMaterial, Vector3 } from "three";
import type { WorldView } from "../world_view";

/** A drag shorter than this (mm) draws no wall: it was a click. */
const MIN_WALL_MM = 20;
const PREVIEW_HEIGHT = 0.01; // m above the floor

export class WallTool {
  active = false;
  snap = true;
  gridMm = 10;
  private start: { x: number; y: number } | null = null;
  private readonly preview = new Line(new BufferGeometry(), new LineBasicMaterial({ color: 0xd04010 }));
  private readonly overlay = new Group();

  constructor(
    private readonly world: WorldView,
    worldElement: HTMLElement,
    private readonly drawn: (wall: { x1: number; y1: number; x2: number; y2: number }) => void,
  ) {
    this.overlay.add(this.preview);
    this.preview.visible = false;
    world.addOverlay(this.overlay);
    // Capture on the parent: the press is ours before the 3D view's dragging and camera see it.
    const stage = worldElement.parentElement ?? worldElement;
    const inWorld = (event: PointerEvent) => worldElement.contains(event.target as Node);
    stage.addEventListener("pointerdown", (event) => this.active && inWorld(event) && this.press(event),
      { capture: true });
    stage.addEventListener("pointermove", (event) => this.start && this.move(event), { capture: true });
    stage.addEventListener("pointerup", (event) => this.start && this.release(event), { capture: true });
  }

  /** A floor point in mm, on the grid when snapping. */
  private pointAt(event: PointerEvent): { x: number; y: number } | null {
    const metres = this.world.floorPointAt(event.clientX, event.clientY);
    if (!metres) return null;
    const snap = this.snap && !event.altKey && this.gridMm > 0; // Alt draws freely
    const snapped = (v: number) => (snap ? Math.round(v / this.gridMm) * this.gridMm : Math.round(v));
    return { x: snapped(metres.x * 1000), y: snapped(metres.y * 1000) };
  }

  private press(event: PointerEvent): void {
    const point = this.pointAt(event);
    if (!point) return;
    event.stopPropagation();
    event.preventDefault();
    this.start = point;
    this.show(point, point);
  }

  private move(event: PointerEvent): void {
    event.stopPropagation();
    const point = this.pointAt(event);
    if (point && this.start) this.show(this.start, point);
  }

  private release(event: PointerEvent): void {
    event.stopPropagation();
    const start = this.start!;
    this.start = null;
    this.preview.visible = false;
    this.world.requestRender();
    const end = this.pointAt(event);
    if (end && Math.hypot(end.x - start.x, end.y - start.y) >= MIN_WALL_MM) {
      this.drawn({ x1: start.x, y1: start.y, x2: end.x, y2: end.y });
    }
  }

  private show(a: { x: number; y: number }, b: { x: number; y: number }): void {
    this.preview.geometry.setFromPoints([
      new Vector3(a.x / 1000, a.y / 1000, PREVIEW_HEIGHT),
      new Vector3(b.x / 1000, b.y / 1000, PREVIEW_HEIGHT),
    ]);
    this.preview.visible = true;
    this.world.requestRender();
  }
}
