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
  }

  async start(): Promise<void> {
    this.schema = (await call("GET /robot-editor/api/schema")) as Schema;
    this.form = new SchemaForm(this.schema, (path, value) => this.change(path, value), () => this.renderForms());
    const sources = await call("GET /robot-editor/api/sources");
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
      byId<HTMLInputElement>("save-path").value = opened.origin ?? `${name}.robi`;
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
    this.showProblems();
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
    this.scheduleCheck();
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

  async save(overwrite: boolean): Promise<void> {
    const path = byId<HTMLInputElement>("save-path").value.trim();
    try {
      const saved = await call("POST /robot-editor/api/save", { ...this.request(), path, overwrite });
      const warnings = saved.problems.filter((p) => p.kind === "warning").length;
      this.setStatus(`Saved ${saved.path}${saved.loads ? " (it loads" : " (it does not load"}` +
        `${warnings ? `, ${warnings} warning(s)` : ""})`);
      this.origin = saved.path;
    } catch (error) {
      if (error instanceof RouteError && error.status === 409 && !overwrite) {
        if (window.confirm(`${path} exists. Overwrite it?`)) await this.save(true);
        else this.setStatus(`Not saved: ${path} exists`);
        return;
      }
      this.setStatus(messageOf(error), true);
    }
  }

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
