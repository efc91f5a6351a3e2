// The robot editor page: open or create a robot, edit it with forms generated from the robot
// schema, see it built in 3D, test-drive it and save it as .robi or JSON (docs/viewer.md).

import "../style.css";
import "./editor.css";
import { element } from "../dom";
import { call, RouteError } from "../api";
import type { RobotCheck, RobotProblem, RobotSensors } from "../generated/viewer_protocol";
import { RobotPreview } from "./preview";
import { SchemaForm, pointerOf, type Json, type JsonObject, type Schema } from "./schema_form";
import { TestDrive } from "./test_drive";

const CHECK_DELAY_MS = 250;
/** Where the PSD presets put a sensor on the chassis box [x0, y0, x1, y1] (mm), and its heading. */
const PSD_PRESETS: [string, (box: number[]) => { x: number; y: number; heading: number }][] = [
  ["Front", ([, , x1]) => ({ x: x1, y: 0, heading: 0 })],
  ["Left", ([x0, , x1, y1]) => ({ x: (x0 + x1) / 2, y: y1, heading: 90 })],
  ["Right", ([x0, y0, x1]) => ({ x: (x0 + x1) / 2, y: y0, heading: -90 })],
  ["Back", ([x0]) => ({ x: x0, y: 0, heading: 180 })],
];

/** A file name made of a robot's name: "My bot" -> "My_bot". */
function fileNameOf(name: string): string {
  return name.trim().replace(/[^\w.-]+/g, "_").replace(/^[.]+/, "") || "robot";
}

function byId<T extends HTMLElement>(id: string): T {
  const found = document.getElementById(id);
  if (!found) throw new Error(`robot editor: no #${id} in the page`);
  return found as T;
}

class RobotEditorPage {
  private schema: Schema = {};
  private form: SchemaForm | null = null;
  private robot: JsonObject | null = null;
  private origin: string | null = null;
  private builtin: string | null = null;
  private problems: RobotProblem[] = [];
  private checks = 0; // answered checks (tests wait for them)
  private pending = 0;
  private timer: number | null = null;
  private robi = "";
  /** by drive, the drive-dependent values it can use; other drives' parts are not offered */
  private driveParts: Record<string, string[]> = {};
  /** the robot's chassis box on the floor plan (mm), for the PSD presets */
  private chassis: number[] | null = null;
  /** the file name last proposed for saving: it follows the robot's name until the user types another */
  private proposed = "";
  private readonly preview: RobotPreview;
  private readonly drive: TestDrive;
  private readonly formBox = byId<HTMLElement>("forms");
  private readonly status = byId<HTMLElement>("editor-status");
  private readonly problemList = byId<HTMLElement>("problems");

  constructor() {
    this.preview = new RobotPreview(
      byId("preview"),
      (pointer) => this.select(pointer),
      (pointer, change) => this.moveSensor(pointer, change),
    );
    this.drive = new TestDrive(
      (state) => this.preview.show(state.scene, state, "drive"),
      (state) => this.preview.place(state),
      () => this.check(),
      () => ({ v: Number(this.robot?.max_speed ?? 300) / 2, w: Number(this.robot?.max_turn ?? 90) / 2 }),
      () => this.robot,
    );
    byId("side").append(this.drive.panel);
    byId("open").addEventListener("click", () => void this.open());
    byId("try").addEventListener("click", () => void this.tryIt());
    byId("save").addEventListener("click", () => void this.save(false));
    byId("add-to-scene").addEventListener("click", () => void this.addToScene());
  }

  async start(): Promise<void> {
    this.schema = (await call("GET /robot-editor/api/schema")) as Schema;
    const sources = await call("GET /robot-editor/api/sources");
    this.driveParts = sources.drive_parts;
    this.form = new SchemaForm(this.schema, (path, value) => this.change(path, value), () => this.renderForms(),
      (key) => this.offered(key));
    const select = byId<HTMLSelectElement>("source");
    const group = (label: string, items: [string, string][]) => {
      if (items.length === 0) return;
      const optgroup = element("optgroup");
      optgroup.label = label;
      for (const [value, text] of items) optgroup.append(new Option(text, value));
      select.append(optgroup);
    };
    group("New robot", sources.drives.map((d) => [`new:${d}`, `empty ${d} robot`]));
    group("Built-in robots", sources.builtins.map((b) => [`builtin:${b}`, b]));
    group("Files in the scene folder", sources.files.map((f) => [`file:${f}`, f]));
    const wanted = new URLSearchParams(location.search).get("open");
    select.value = wanted ?? "builtin:S4";
    if (select.selectedIndex < 0) select.selectedIndex = 0;
    await this.open();
  }

  async open(): Promise<void> {
    const source = byId<HTMLSelectElement>("source").value;
    try {
      await this.drive.stop();
      const opened = await call("POST /robot-editor/api/open", { source });
      this.robot = opened.robot as JsonObject;
      this.origin = opened.origin;
      this.builtin = opened.builtin;
      const name = typeof this.robot.name === "string" ? this.robot.name : "robot";
      this.proposed = opened.origin ?? `${fileNameOf(name)}.robi`;
      byId<HTMLInputElement>("save-path").value = this.proposed;
      this.setStatus(`Opened ${source.replace(/^\w+:/, "")}`);
      this.renderForms();
      await this.check();
    } catch (error) {
      this.setStatus(messageOf(error), true);
    }
  }

  private renderForms(): void {
    if (!this.form || !this.robot) return;
    this.formBox.replaceChildren(...this.form.render(this.robot));
    this.addPsdPresets();
    this.showProblems();
  }

  /** A value or part the robot's drive can use (values of no drive in particular always). */
  private offered(key: string): boolean {
    const dependent = Object.values(this.driveParts).some((parts) => parts.includes(key));
    return !dependent || (this.driveParts[String(this.robot?.drive)] ?? []).includes(key);
  }

  /** Buttons on each PSD that put it on the front, left, right or back edge of the chassis, facing out. */
  private addPsdPresets(): void {
    const psds = Array.isArray(this.robot?.psds) ? (this.robot.psds as JsonObject[]) : [];
    psds.forEach((psd, index) => {
      const box = this.form?.fields.get(`/psds/${index}`);
      if (!box) return;
      const row = element("div", "psd-presets");
      row.append(element("span", "field-name", "Place at"));
      for (const [label, place] of PSD_PRESETS) {
        const button = element("button", "", label);
        button.type = "button";
        button.dataset.preset = label.toLowerCase();
        button.title = `On the chassis' ${label.toLowerCase()} edge, facing out`;
        button.addEventListener("click", () => {
          if (!this.chassis) return;
          const at = place(this.chassis);
          for (const [key, value] of Object.entries(at)) psd[key] = Math.round(value * 10) / 10;
          this.renderForms();
          this.scheduleCheck();
        });
        row.append(button);
      }
      box.querySelector("legend")?.after(row);
    });
  }

  private change(path: (string | number)[], value: Json | undefined): void {
    if (!this.robot) return;
    let owner: Json = this.robot;
    for (const key of path.slice(0, -1)) owner = (owner as Record<string, Json>)[key as string];
    const last = path[path.length - 1];
    if (Array.isArray(owner)) {
      if (value === undefined) owner.splice(Number(last), 1);
      else owner[Number(last)] = value;
    } else if (value === undefined) delete (owner as JsonObject)[last];
    else (owner as JsonObject)[last] = value;
    if (path.length === 1 && last === "drive") this.renderForms(); // another drive offers other parts
    if (path.length === 1 && last === "name") this.followName();
    this.scheduleCheck();
  }

  /** "Save as" follows the robot's name (in the same folder, with the same suffix) until the user
   *  types a file name of their own. */
  private followName(): void {
    const input = byId<HTMLInputElement>("save-path");
    if (input.value !== this.proposed || typeof this.robot?.name !== "string") return;
    const folder = input.value.slice(0, input.value.lastIndexOf("/") + 1);
    const suffix = /\.json$/i.test(input.value) ? ".json" : ".robi";
    this.proposed = input.value = `${folder}${fileNameOf(this.robot.name)}${suffix}`;
  }

  private scheduleCheck(): void {
    if (this.timer !== null) window.clearTimeout(this.timer);
    else this.pending += 1; // one pending check however often the robot changes before it
    this.timer = window.setTimeout(() => {
      this.timer = null;
      this.pending -= 1;
      void this.check();
    }, CHECK_DELAY_MS);
  }

  /** Validates the robot on the server (the loader's JSON path) and shows it as built. */
  async check(): Promise<void> {
    if (!this.robot || this.drive.running) return;
    this.pending += 1;
    try {
      const checked = await call("POST /robot-editor/api/check", this.request());
      this.problems = checked.problems;
      this.robi = checked.robi ?? "";
      this.chassis = checked.chassis ?? this.chassis;
      this.showProblems();
      if (checked.preview) {
        this.preview.show(checked.preview.scene, checked.preview, `robot:${this.origin}:${this.builtin}`);
        this.lastPreview = checked.preview;
      }
      byId("robi-text").textContent = this.robi;
    } catch (error) {
      this.setStatus(messageOf(error), true);
    } finally {
      this.pending -= 1;
      this.checks += 1;
    }
  }

  private lastPreview: RobotSensors | null = null;

  private request(): RobotCheck {
    return { robot: this.robot ?? {}, origin: this.origin, builtin: this.builtin };
  }

  private showProblems(): void {
    if (!this.form) return;
    for (const field of this.form.fields.values()) {
      field.classList.remove("invalid", "warned");
      const message = field.closest(".field")?.querySelector(".field-message");
      if (message) message.textContent = "";
    }
    const general: RobotProblem[] = [];
    for (const problem of this.problems) {
      let pointer = problem.pointer;
      let field = this.form.fields.get(pointer);
      while (!field && pointer) {
        pointer = pointer.slice(0, pointer.lastIndexOf("/"));
        field = this.form.fields.get(pointer);
      }
      const message = field?.closest(".field")?.querySelector(".field-message");
      if (field && message) {
        field.classList.add(problem.kind === "error" ? "invalid" : "warned");
        message.textContent = message.textContent ? `${message.textContent}; ${problem.message}` : problem.message;
      } else {
        field?.classList.add(problem.kind === "error" ? "invalid" : "warned");
        general.push(problem);
      }
    }
    this.problemList.replaceChildren(
      ...general.map((p) => {
        const item = element("li", p.kind, `${p.kind}: ${p.pointer ? p.pointer + ": " : ""}${p.message}`);
        item.dataset.pointer = p.pointer;
        return item;
      }),
    );
    const errors = this.problems.filter((p) => p.kind === "error").length;
    byId<HTMLButtonElement>("save").disabled = errors > 0;
    byId<HTMLButtonElement>("try").disabled = errors > 0;
    byId<HTMLButtonElement>("add-to-scene").disabled = errors > 0;
  }

  /** A part picked in the preview: its section of the form comes into view, highlighted. */
  select(pointer: string): void {
    this.preview.selected = pointer;
    for (const old of this.formBox.querySelectorAll(".selected")) old.classList.remove("selected");
    const section = this.form?.fields.get(pointer);
    if (section) {
      section.classList.add("selected");
      section.scrollIntoView({ block: "nearest" });
    }
    byId("selection").textContent = pointer ? `Selected ${pointer}` : "Selected the body";
    if (this.lastPreview) this.preview.place(this.lastPreview);
  }

  /** A handle was dragged: the sensor's values change in the form and the robot is checked. */
  private moveSensor(pointer: string, change: { x?: number; y?: number; heading?: number }): void {
    if (!this.robot) return;
    const path = pointer.split("/").slice(1);
    let sensor: Json = this.robot;
    for (const key of path) sensor = (sensor as Record<string, Json>)[key];
    if (typeof sensor !== "object" || sensor === null || Array.isArray(sensor)) return;
    const angleKey = "heading" in sensor ? "heading" : "pan";
    for (const [key, value] of Object.entries(change)) {
      const target = key === "heading" ? angleKey : key;
      sensor[target] = value as number;
      const input = this.form?.fields.get(`${pointer}/${target}`);
      if (input instanceof HTMLInputElement) input.value = String(value);
    }
    this.scheduleCheck();
  }

  async tryIt(): Promise<void> {
    try {
      await this.drive.start(this.request());
      this.setStatus("Test drive: a scratch arena of its own; the running scene is not touched.");
      byId<HTMLButtonElement>("end-try").hidden = false;
      byId("end-try").onclick = async () => {
        await this.drive.stop();
        byId<HTMLButtonElement>("end-try").hidden = true;
        this.setStatus("Test drive ended");
      };
    } catch (error) {
      this.setStatus(messageOf(error), true);
    }
  }

  /** Saves the robot; the path saved (relative to the scene folder), or null when it was not. */
  async save(overwrite: boolean): Promise<string | null> {
    const path = byId<HTMLInputElement>("save-path").value.trim();
    try {
      const saved = await call("POST /robot-editor/api/save", { ...this.request(), path, overwrite });
      const warnings = saved.problems.filter((p) => p.kind === "warning").length;
      this.setStatus(`Saved ${saved.path}${saved.loads ? " (it loads" : " (it does not load"}` +
        `${warnings ? `, ${warnings} warning(s)` : ""})`);
      this.origin = saved.path;
      return saved.loads ? saved.path : null;
    } catch (error) {
      if (error instanceof RouteError && error.status === 409 && !overwrite) {
        if (window.confirm(`${path} exists. Overwrite it?`)) return this.save(true);
        this.setStatus(`Not saved: ${path} exists`);
        return null;
      }
      this.setStatus(messageOf(error), true);
      return null;
    }
  }

  /** Saves the robot, then places it in the scene the simulator runs, on a free spot near the
   *  floor's centre (the simulator moves it clear of walls and bodies); a running scene goes on. */
  async addToScene(): Promise<void> {
    const path = await this.save(false);
    if (path === null) return;
    try {
      const before = await call("GET /scenes/state");
      const { width, height } = before.items.floor;
      // robot files are saved in the folder the simulator started in: the first scene root
      const state = await call("POST /scenes/edit", {
        op: "add-robot", file: { root: 0, path }, x: (width ?? 2000) / 2, y: (height ?? 2000) / 2, phi: 0,
      });
      const robot = state.items.robots[state.items.robots.length - 1];
      if (!before.editing) await call("POST /scenes/edit", { editing: false });
      this.setStatus(`Added to the scene as robot ${state.items.robots.length} at ` +
        `(${Math.round(robot.x)}, ${Math.round(robot.y)})${state.moved ? ", clear of what was there" : ""}`);
      this.added += 1;
    } catch (error) {
      this.setStatus(`Not added to the scene: ${messageOf(error)}`, true);
    }
  }

  private added = 0; // robots added to the scene (tests wait for it)

  private setStatus(text: string, error = false): void {
    this.status.textContent = text;
    this.status.classList.toggle("error", error);
  }

  /** For tests: the page's state. */
  debug() {
    return {
      robot: () => this.robot,
      problems: () => this.problems,
      checks: () => this.checks,
      idle: () => this.pending === 0 && this.timer === null,
      handleAt: (pointer: string, kind: "move" | "turn") => this.preview.handleAt(pointer, kind),
      screenOf: (point: number[]) => this.preview.screenOf(point),
      preview: () => this.lastPreview,
      drive: () => this.drive.last,
      added: () => this.added,
      select: (pointer: string) => this.select(pointer),
      pointerOf,
    };
  }
}

function messageOf(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

const page = new RobotEditorPage();
(window as unknown as { eyesimRobotEditor: ReturnType<RobotEditorPage["debug"]> }).eyesimRobotEditor = page.debug();
void page.start();
