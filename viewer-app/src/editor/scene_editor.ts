// The scene editor panel: add robots, objects, markers and walls; select, move, turn, duplicate
// and delete them; floor size; each robot's program; undo/redo; save. Every change is an edit the
// simulator applies to the scene description and answers with the new scene (scene_workspace.py):
// this page keeps no scene model of its own, only the simulator's list of what is in it.

import type { PickTarget } from "../interaction";
import type { BrowserCommand } from "../protocol";
import type { Viewer } from "../viewer";
import { call, errorText, RouteError } from "../api";
import type { EditKind, EditorState, Place, SceneCatalog, SceneEdit, SceneRoot, SceneSave } from "../generated/viewer_protocol";
import { placeText } from "./places";
import { SceneBrowser } from "./scene_browser";
import { SelectionMark } from "./selection_mark";
import { WallTool } from "./wall_tool";

type Kind = EditKind;

interface Selection {
  kind: Kind;
  index: number;
}

const ROTATE_STEP = 15; // degrees per press of a turn button
const SNAP_GRID = 10; // mm: where dragged things and wall ends land while snapping
const SNAP_ANGLE = 15; // degrees: the steps a Shift-drag turns by while snapping
const NEW_THING_SPACING = 300; // mm between things added one after another

function element<T extends HTMLElement>(root: HTMLElement, selector: string): T {
  return root.querySelector<T>(selector)!;
}

/** "#rrggbb" of an [r, g, b(, a)] colour, and back. */
function hexOf(color: number[]): string {
  return "#" + color.slice(0, 3).map((c) => c.toString(16).padStart(2, "0")).join("");
}

function rgbOf(hex: string): [number, number, number] {
  const channel = (i: number) => parseInt(hex.slice(i, i + 2), 16);
  return [channel(1), channel(3), channel(5)];
}

function basename(path: string): string {
  return path.split(/[\\/]/).pop() ?? path;
}

export class SceneEditor {
  readonly browser: SceneBrowser;
  readonly panel: HTMLElement;
  readonly walls: WallTool;
  private readonly mark: SelectionMark;
  private state: EditorState | null = null;
  private catalog: SceneCatalog | null = null;
  private roots: SceneRoot[] = [];
  private selection: Selection | null = null;
  private readonly editButton: HTMLButtonElement;
  private readonly message: HTMLElement;
  /** the last `place` the 3D view sent while dragging; becomes a `move` edit on release */
  private dragged: Extract<BrowserCommand, { type: "place" }> | null = null;
  private busy: Promise<unknown> = Promise.resolve();
  private edits = 0;
  private live = false;

  constructor(private readonly viewer: Viewer, toolbar: HTMLElement, layout: HTMLElement, worldElement: HTMLElement) {
    this.browser = new SceneBrowser((state) => this.show(state));
    const controls = toolbar.querySelector(".controls") ?? toolbar;
    const openButton = document.createElement("button");
    openButton.id = "open-scenes";
    openButton.type = "button";
    openButton.textContent = "Scenes…";
    openButton.title = "Open a scene file";
    openButton.addEventListener("click", () => this.browser.show());
    this.editButton = document.createElement("button");
    this.editButton.id = "edit-scene";
    this.editButton.type = "button";
    this.editButton.textContent = "Edit scene";
    this.editButton.title = "Add, move and delete robots, objects and walls (pauses the simulation)";
    this.editButton.addEventListener("click", () => this.setEditing(!this.state?.editing));
    openButton.hidden = this.editButton.hidden = true; // until the simulator answers (a replay has no scenes)
    controls.prepend(openButton, this.editButton);

    this.panel = document.createElement("aside");
    this.panel.id = "editor";
    this.panel.className = "editor";
    this.panel.hidden = true;
    this.panel.setAttribute("aria-label", "Scene editor");
    this.panel.innerHTML = `
      <h2>Scene editor <span id="editor-file" class="editor-file"></span></h2>
      <div class="editor-row">
        <button id="editor-undo" type="button" title="Undo (Ctrl+Z)">Undo</button>
        <button id="editor-redo" type="button" title="Redo (Ctrl+Y)">Redo</button>
        <button id="editor-save" type="button">Save…</button>
        <button id="editor-done" type="button" title="Leave the editor: the programs start and the simulation goes on">Done</button>
      </div>
      <h3>Add</h3>
      <div class="editor-row"><select id="editor-robot-type" aria-label="robot type"></select>
        <button id="editor-add-robot" type="button">Add robot</button></div>
      <div class="editor-row"><select id="editor-object-type" aria-label="object type"></select>
        <button id="editor-add-object" type="button">Add object</button></div>
      <div class="editor-row"><button id="editor-add-marker" type="button">Add marker</button>
        <button id="editor-draw-wall" type="button" aria-pressed="false" title="Drag on the floor to draw a wall">Draw walls</button></div>
      <div class="editor-row" title="Dragged things and wall ends keep to the grid, turns to the angle; hold Alt to drag freely">
        <label><input id="editor-snap" type="checkbox" checked /> snap to</label>
        <input id="editor-grid" type="number" min="1" value="${SNAP_GRID}" aria-label="grid in mm" /> mm
        <input id="editor-angle" type="number" min="1" max="180" value="${SNAP_ANGLE}" aria-label="angle step in degrees" /> °</div>
      <h3>Floor</h3>
      <div class="editor-row"><input id="editor-floor-width" type="number" aria-label="floor width in mm" /> ×
        <input id="editor-floor-height" type="number" aria-label="floor height in mm" /> mm
        <button id="editor-set-floor" type="button">Set</button></div>
      <h3>In the scene</h3>
      <ul id="editor-items" class="editor-items"></ul>
      <div id="editor-selected" class="editor-selected" hidden>
        <h3 id="editor-selected-title"></h3>
        <div class="editor-row" id="editor-pose">
          <label>x <input id="editor-x" type="number" /></label>
          <label>y <input id="editor-y" type="number" /></label>
          <label id="editor-phi-label">φ <input id="editor-phi" type="number" /></label>
          <span id="editor-footprint" class="editor-note" title="the floor its type takes: change a robot's size in the robot editor"></span>
        </div>
        <div class="editor-row" id="editor-wall-ends" hidden>
          <label>x1 <input id="editor-x1" type="number" /></label><label>y1 <input id="editor-y1" type="number" /></label>
          <label>x2 <input id="editor-x2" type="number" /></label><label>y2 <input id="editor-y2" type="number" /></label>
        </div>
        <div class="editor-row" id="editor-wall-size" hidden>
          <label>thickness <input id="editor-thickness" type="number" min="1" /></label>
          <label>height <input id="editor-height" type="number" min="1" /></label> mm
          <span id="editor-length" class="editor-note"></span>
        </div>
        <div class="editor-row" id="editor-color-row" hidden>
          <label>colour <input id="editor-color" type="color" /></label></div>
        <div class="editor-row">
          <button id="editor-apply" type="button">Apply</button>
          <button id="editor-turn-left" type="button" title="Turn ${ROTATE_STEP}° left">⟲</button>
          <button id="editor-turn-right" type="button" title="Turn ${ROTATE_STEP}° right">⟳</button>
          <button id="editor-duplicate" type="button">Duplicate</button>
          <button id="editor-delete" type="button">Delete</button>
        </div>
        <div class="editor-row" id="editor-program-row"><label>Program
          <select id="editor-program" aria-label="program"></select></label></div>
      </div>
      <dialog id="editor-save-dialog" class="scene-dialog">
        <form method="dialog">
          <h2>Save the scene</h2>
          <label>Folder <select id="save-root"></select></label>
          <label>Name <input id="save-name" value="my_scene.sim" /></label>
          <label>Format <select id="save-format"><option value="sim">EyeSim .sim (+ .wld)</option>
            <option value="json">JSON</option></select></label>
          <div class="editor-row"><button id="save-confirm" value="save">Save</button><button value="cancel">Cancel</button></div>
        </form>
      </dialog>
      <pre id="editor-message" class="editor-message" role="status"></pre>`;
    layout.insertBefore(this.panel, layout.querySelector("#robots"));
    this.message = element(this.panel, "#editor-message");
    this.mark = new SelectionMark(viewer.world);
    this.walls = new WallTool(viewer.world, worldElement, (wall) => this.edit({ op: "add-wall", ...wall }));
    this.wire();
    viewer.commandWatchers.push((command) => {
      if (this.state?.editing && command.type === "place") this.dragged = command;
    });
    // The 3D view keeps its pointerup to itself and sends the final pose on it: look right after.
    window.addEventListener("pointerup", () => window.setTimeout(() => this.dropped()), { capture: true });
    viewer.pickWatchers.push((target) => this.picked(target));
    // A replay has no scenes to open or edit: nothing is asked for until the run is known to be live.
    viewer.onMode((mode) => {
      this.live = mode === "live";
      if (this.live) void this.start();
    });
    viewer.sceneWatchers.push(() => this.live && void this.refresh());
    viewer.connectionWatchers.push((connected) => {
      openButton.disabled = this.editButton.disabled = !connected;
      for (const control of this.panel.querySelectorAll<HTMLButtonElement | HTMLSelectElement | HTMLInputElement>(
        "button, select, input",
      )) {
        control.disabled = !connected || (control.id === "editor-undo" && !this.state?.can_undo) ||
          (control.id === "editor-redo" && !this.state?.can_redo);
      }
    });
  }

  /** Edits answered so far (tests wait for it). */
  get editCount(): number {
    return this.edits;
  }

  get current(): EditorState | null {
    return this.state;
  }

  private async start(): Promise<void> {
    await this.refresh();
    if (this.state?.browse_at_start) this.browser.show();
  }

  private wire(): void {
    const on = (id: string, action: () => void) => element(this.panel, id).addEventListener("click", action);
    on("#editor-undo", () => this.run(() => call("POST /scenes/undo", {})));
    on("#editor-redo", () => this.run(() => call("POST /scenes/redo", {})));
    on("#editor-done", () => this.setEditing(false));
    on("#editor-save", () => this.openSave());
    on("#editor-add-robot", () => this.addRobot());
    on("#editor-add-object", () => this.addObject());
    on("#editor-add-marker", () => this.edit({ op: "add-marker", ...this.newPosition() }));
    on("#editor-draw-wall", () => this.setWallDrawing(!this.walls.active));
    on("#editor-set-floor", () =>
      this.edit({ op: "set-floor", width: this.numberOf("#editor-floor-width"), height: this.numberOf("#editor-floor-height") }),
    );
    on("#editor-apply", () => this.applyFields());
    on("#editor-turn-left", () => this.turn(ROTATE_STEP));
    on("#editor-turn-right", () => this.turn(-ROTATE_STEP));
    on("#editor-duplicate", () => this.selection && this.edit({ op: "duplicate", ...this.selection }));
    on("#editor-delete", () => this.deleteSelected());
    const snap = element<HTMLInputElement>(this.panel, "#editor-snap");
    const grid = element<HTMLInputElement>(this.panel, "#editor-grid");
    const angle = element<HTMLInputElement>(this.panel, "#editor-angle");
    for (const input of [snap, grid, angle]) input.addEventListener("change", () => this.setSnap());
    element<HTMLSelectElement>(this.panel, "#editor-program").addEventListener("change", (event) => {
      const value = (event.target as HTMLSelectElement).value;
      if (this.selection?.kind !== "robot") return;
      this.edit({ op: "set-program", index: this.selection.index, program: value ? (JSON.parse(value) as Place) : null });
    });
    element(this.panel, "#editor-save-dialog").addEventListener("close", () => {
      const dialog = element<HTMLDialogElement>(this.panel, "#editor-save-dialog");
      if (dialog.returnValue === "save") void this.save(false);
    });
    window.addEventListener("keydown", (event) => {
      if (!this.state?.editing || (event.target as HTMLElement).closest("input, select, textarea")) return;
      const key = event.key.toLowerCase();
      if ((event.ctrlKey || event.metaKey) && key === "z") this.run(() => call("POST /scenes/undo", {}));
      else if ((event.ctrlKey || event.metaKey) && key === "y") this.run(() => call("POST /scenes/redo", {}));
      else if (key === "delete") this.deleteSelected();
      else return;
      event.preventDefault();
    });
  }

  // -- talking to the simulator ----------------------------------------------------------------
  private async refresh(): Promise<void> {
    try {
      this.state = await call("GET /scenes/state");
      for (const button of this.panel.ownerDocument.querySelectorAll<HTMLElement>("#open-scenes, #edit-scene")) {
        button.hidden = false;
      }
      this.render();
    } catch (error) {
      this.say(errorText(error));
    }
  }

  /** One request at a time, in order; its answer becomes the state. */
  private run(request: () => Promise<EditorState>): Promise<void> {
    const next = this.busy.then(async () => {
      try {
        this.show(await request());
        const warnings = (this.state?.warnings ?? []).map((d) => d.text);
        this.say([this.state?.moved ?? "", ...warnings].filter((text) => text).join("\n"), warnings.length > 0);
      } catch (error) {
        this.say(errorText(error));
      }
      this.edits++;
    });
    this.busy = next;
    return next;
  }

  private edit(op: SceneEdit): Promise<void> {
    return this.run(() => call("POST /scenes/edit", op));
  }

  /** The snap settings to the wall tool and, while editing, to dragging in the 3D view. */
  private setSnap(): void {
    const on = element<HTMLInputElement>(this.panel, "#editor-snap").checked;
    const gridMm = Math.max(1, this.numberOf("#editor-grid") || SNAP_GRID);
    const angleDeg = Math.max(1, this.numberOf("#editor-angle") || SNAP_ANGLE);
    this.walls.snap = on;
    this.walls.gridMm = gridMm;
    this.viewer.world.dragSnap = on && this.state?.editing ? { gridMm, angleDeg } : null;
  }

  private setEditing(editing: boolean): void {
    if (editing) void this.loadCatalog();
    if (!editing) this.setWallDrawing(false);
    void this.run(() => call("POST /scenes/edit", { editing }));
  }

  private show(state: EditorState): void {
    this.state = state;
    if (state.editing && !this.catalog) void this.loadCatalog();
    this.render();
  }

  private async loadCatalog(): Promise<void> {
    try {
      const [catalog, files] = await Promise.all([call("GET /scenes/catalog"), call("GET /scenes/files")]);
      this.catalog = catalog;
      this.roots = files.roots;
      this.fillCatalog();
    } catch (error) {
      this.say(errorText(error));
    }
  }

  /** A message under the panel: what went wrong (red), or what was done. */
  private say(text: string, problem = true): void {
    this.message.textContent = text;
    this.message.classList.toggle("problem", problem);
  }

  // -- what the panel shows --------------------------------------------------------------------
  private render(): void {
    const state = this.state;
    if (!state) return;
    this.panel.hidden = !state.editing;
    this.setSnap();
    // While editing, the editor takes the robot panels' place beside the 3D view (style.css).
    document.body.classList.toggle("editing", state.editing);
    this.editButton.textContent = state.editing ? "Done editing" : "Edit scene";
    this.editButton.classList.toggle("paused", state.editing);
    element(this.panel, "#editor-file").textContent = basename(state.file);
    element<HTMLButtonElement>(this.panel, "#editor-undo").disabled = !state.can_undo;
    element<HTMLButtonElement>(this.panel, "#editor-redo").disabled = !state.can_redo;
    const floor = state.items.floor;
    element<HTMLInputElement>(this.panel, "#editor-floor-width").value = floor.width ? String(floor.width) : "";
    element<HTMLInputElement>(this.panel, "#editor-floor-height").value = floor.height ? String(floor.height) : "";
    const list = element(this.panel, "#editor-items");
    const entries: HTMLElement[] = [];
    const add = (kind: Kind, index: number, text: string) => {
      const item = document.createElement("li");
      item.textContent = text;
      item.dataset.kind = kind;
      item.dataset.index = String(index);
      item.classList.toggle("selected", this.selection?.kind === kind && this.selection.index === index);
      item.addEventListener("click", () => this.select({ kind, index }));
      entries.push(item);
    };
    const at = (x: number, y: number) => `(${Math.round(x)}, ${Math.round(y)})`;
    state.items.robots.forEach((r, i) =>
      add("robot", i, `Robot ${i + 1}: ${r.type} ${at(r.x, r.y)} ${Math.round(r.phi)}°${r.program ? ` ▶ ${basename(r.program)}` : ""}`),
    );
    state.items.objects.forEach((o, i) => add("object", i, `Object ${i + 1}: ${o.type} ${at(o.x, o.y)} ${Math.round(o.phi)}°`));
    state.items.markers.forEach((m, i) => add("marker", i, `Marker ${i + 1} ${at(m.x, m.y)}`));
    state.items.walls.forEach((w, i) => add("wall", i, `Wall ${i + 1} ${at(w.x1, w.y1)} → ${at(w.x2, w.y2)}`));
    list.replaceChildren(...entries);
    if (this.selection && !this.selected()) this.selection = null;
    this.showSelection();
  }

  private fillCatalog(): void {
    const catalog = this.catalog;
    if (!catalog) return;
    const option = (text: string, value: string) => {
      const o = document.createElement("option");
      o.textContent = text;
      o.value = value;
      return o;
    };
    const files = (places: Place[]) => places.map((p) => option(placeText(p, this.roots), JSON.stringify(p)));
    element(this.panel, "#editor-robot-type").replaceChildren(
      ...catalog.robots.map((name) => option(name, name)), ...files(catalog.robot_files));
    element(this.panel, "#editor-object-type").replaceChildren(
      ...catalog.objects.map((name) => option(name, name)), ...files(catalog.object_files));
    element(this.panel, "#editor-program").replaceChildren(option("(none)", ""), ...files(catalog.programs));
    element(this.panel, "#save-root").replaceChildren(
      ...this.roots.filter((r) => r.writable).map((r) => option(`${r.name} (${r.path})`, String(r.index))));
    this.showSelection();
  }

  private selected(): { x?: number; y?: number; phi?: number; x1?: number; program?: string | null; type?: string } | null {
    const s = this.selection;
    const items = this.state?.items;
    if (!s || !items) return null;
    const list = { robot: items.robots, object: items.objects, marker: items.markers, wall: items.walls }[s.kind];
    return (list[s.index] as never) ?? null;
  }

  private select(selection: Selection | null): void {
    this.selection = selection;
    this.render();
  }

  private showSelection(): void {
    const box = element(this.panel, "#editor-selected");
    const thing = this.selected();
    box.hidden = !thing;
    this.mark.show(this.state?.editing && thing ? (thing as { x: number; y: number }) : null);
    if (!thing || !this.selection) return;
    const { kind, index } = this.selection;
    element(this.panel, "#editor-selected-title").textContent =
      `${kind[0].toUpperCase()}${kind.slice(1)} ${index + 1}${thing.type ? `: ${thing.type}` : ""}`;
    const wall = kind === "wall";
    element(this.panel, "#editor-pose").hidden = wall;
    element(this.panel, "#editor-wall-ends").hidden = !wall;
    element(this.panel, "#editor-phi-label").hidden = kind === "marker";
    element(this.panel, "#editor-turn-left").hidden = wall || kind === "marker";
    element(this.panel, "#editor-turn-right").hidden = wall || kind === "marker";
    element(this.panel, "#editor-program-row").hidden = kind !== "robot";
    element(this.panel, "#editor-wall-size").hidden = !wall;
    element(this.panel, "#editor-color-row").hidden = !wall && kind !== "marker";
    const set = (id: string, value: number | undefined) => {
      element<HTMLInputElement>(this.panel, id).value = value === undefined ? "" : String(Math.round(value * 100) / 100);
    };
    const fields = thing as Record<string, number>;
    for (const name of wall ? ["x1", "y1", "x2", "y2", "thickness", "height"] : ["x", "y", "phi"]) {
      set(`#editor-${name}`, fields[name]);
    }
    const color = (thing as { color?: number[] }).color;
    if (color) element<HTMLInputElement>(this.panel, "#editor-color").value = hexOf(color);
    const size = (thing as { footprint?: number[] }).footprint;
    element(this.panel, "#editor-footprint").textContent = size ? `${size.map(Math.round).join(" × ")} mm` : "";
    element(this.panel, "#editor-length").textContent = wall
      ? `length ${Math.round(Math.hypot(fields.x2 - fields.x1, fields.y2 - fields.y1))}` : "";
    if (kind === "robot") {
      const program = element<HTMLSelectElement>(this.panel, "#editor-program");
      const path = thing.program ?? null;
      const match = [...program.options].find((o) => {
        if (!o.value || !path) return !o.value && !path;
        const place = JSON.parse(o.value) as Place;
        return path === `${this.roots[place.root]?.path}/${place.path}`;
      });
      program.value = match ? match.value : "";
    }
  }

  // -- edits -------------------------------------------------------------------------------------
  private numberOf(id: string): number {
    return Number(element<HTMLInputElement>(this.panel, id).value);
  }

  /** Where a new thing goes: near the floor's centre, each one a little beside the last. */
  private newPosition(): { x: number; y: number } {
    const floor = this.state?.items.floor;
    const width = floor?.width ?? 2000;
    const height = floor?.height ?? 2000;
    const count = (this.state?.items.robots.length ?? 0) + (this.state?.items.objects.length ?? 0);
    return { x: width / 2 + ((count % 5) - 2) * NEW_THING_SPACING, y: height / 2 + NEW_THING_SPACING };
  }

  private typeChoice(id: string): { file: Place } | { type: string } {
    const value = element<HTMLSelectElement>(this.panel, id).value;
    return value.startsWith("{") ? { file: JSON.parse(value) as Place } : { type: value };
  }

  private addRobot(): void {
    void this.edit({ op: "add-robot", ...this.typeChoice("#editor-robot-type"), ...this.newPosition(), phi: 0 }).then(() =>
      this.select({ kind: "robot", index: (this.state?.items.robots.length ?? 1) - 1 }),
    );
  }

  private addObject(): void {
    void this.edit({ op: "add-object", ...this.typeChoice("#editor-object-type"), ...this.newPosition(), phi: 0 }).then(() =>
      this.select({ kind: "object", index: (this.state?.items.objects.length ?? 1) - 1 }),
    );
  }

  private applyFields(): void {
    const s = this.selection;
    if (!s) return;
    const names = s.kind === "wall" ? ["x1", "y1", "x2", "y2", "thickness", "height"]
      : s.kind === "marker" ? ["x", "y"] : ["x", "y", "phi"];
    const values = Object.fromEntries(names.map((n) => [n, this.numberOf(`#editor-${n}`)]));
    if (s.kind === "wall" || s.kind === "marker") {
      const color = rgbOf(element<HTMLInputElement>(this.panel, "#editor-color").value);
      void this.edit({ op: "set-properties", kind: s.kind, index: s.index, ...values, color });
    } else {
      void this.edit({ op: "move", ...s, ...values });
    }
  }

  private turn(degrees: number): void {
    const s = this.selection;
    const thing = this.selected();
    if (!s || !thing || thing.phi === undefined) return;
    void this.edit({ op: "move", ...s, x: thing.x, y: thing.y, phi: thing.phi + degrees });
  }

  private deleteSelected(): void {
    const s = this.selection;
    if (!s) return;
    this.selection = null;
    void this.edit({ op: "delete", ...s });
  }

  private setWallDrawing(on: boolean): void {
    this.walls.active = on;
    const button = element<HTMLButtonElement>(this.panel, "#editor-draw-wall");
    button.setAttribute("aria-pressed", String(on));
    button.classList.toggle("active", on);
  }

  /** A click on a robot or object in the 3D view selects it while editing. */
  private picked(target: PickTarget): void {
    if (!this.state?.editing || target.kind === "psd") return;
    this.select({ kind: target.kind, index: target.id - 1 });
  }

  /** A drag of a robot or object in the 3D view ended: its last pose becomes a move. */
  private dropped(): void {
    const place = this.dragged;
    this.dragged = null;
    if (!place || !this.state?.editing) return;
    const kind: Kind = place.robot !== undefined ? "robot" : "object";
    const index = (place.robot ?? place.object ?? 0) - 1;
    this.selection = { kind, index };
    // whole mm and tenths of a degree: what a person can place by hand, and a tidy saved file
    const x = Math.round(place.x * 1000);
    const y = Math.round(place.y * 1000);
    void this.edit({ op: "move", kind, index, x, y, phi: Math.round((place.phi * 1800) / Math.PI) / 10 });
  }

  // -- saving ------------------------------------------------------------------------------------
  private openSave(): void {
    const name = element<HTMLInputElement>(this.panel, "#save-name");
    if (this.state?.place && this.roots[this.state.place.root]?.writable) {
      name.value = this.state.place.path.replace(/\.(wld|maz)$/i, ".sim"); // a bare world is saved as a scene
      element<HTMLSelectElement>(this.panel, "#save-root").value = String(this.state.place.root);
    }
    element<HTMLDialogElement>(this.panel, "#editor-save-dialog").showModal();
  }

  private async save(overwrite: boolean): Promise<void> {
    const root = Number(element<HTMLSelectElement>(this.panel, "#save-root").value);
    const path = element<HTMLInputElement>(this.panel, "#save-name").value;
    const format = element<HTMLSelectElement>(this.panel, "#save-format").value as SceneSave["format"];
    let saved: Place[] = [];
    await this.run(async () => {
      let state: EditorState;
      try {
        state = await call("POST /scenes/save", { root, path, format, overwrite });
      } catch (error) {
        const replace = error instanceof RouteError && error.status === 409 && !overwrite &&
          window.confirm(`${error.exists.map((p) => p.path).join(", ")} already exists. Replace it?`);
        if (!replace) throw error;
        state = await call("POST /scenes/save", { root, path, format, overwrite: true });
      }
      saved = state.saved ?? [];
      return state;
    });
    if (saved.length) this.say(`Saved ${saved.map((p) => placeText(p, this.roots)).join(" and ")}`, false);
    const scene = saved.find((p) => /\.(sim|json)$/i.test(p.path));
    if (scene) this.viewer.showSceneName(scene.path.split("/").pop()!); // the toolbar names what was saved
  }
}
