// Programs from the page: the files under the scene roots, and per robot a choice of program with
// Start, Stop, Restart and Compile (`eyesim cc` on the simulator's machine, errors with file:line).

import { call, RouteError } from "./api";
import { element } from "./dom";
import type { CompileResult, Place, ProgramFile, ProgramRoot, ProgramsOverview, RobotProgramState } from "./generated/viewer_protocol";

const SOURCE_KINDS = new Set(["c", "c++"]);
const EDITABLE_KINDS = new Set(["c", "c++", "python"]);

/** The event an Edit button sends up the page: open this source (null: the robot's program's). */
export const EDIT_PROGRAM = "eyesim-edit-program";
export interface EditProgram {
  robot: number;
  file: Place | null;
}

function fileKey(file: { root: number | null; path: string }): string {
  return `${file.root ?? ""}:${file.path}`;
}

/** The program files under the scene roots, fetched once and shared by every robot's controls. */
export class ProgramCatalog {
  private overview: ProgramsOverview = { roots: [], files: [], robots: [] };
  private readonly listeners = new Set<() => void>();
  private loading: Promise<void> | null = null;
  private answered = false;

  /** Whether the server runs programs for the page (`eyesim run` does; a replay does not). */
  get available(): boolean {
    return this.answered;
  }

  get files(): ProgramFile[] {
    return this.overview.files;
  }

  get roots(): ProgramRoot[] {
    return this.overview.roots;
  }

  robot(id: number): RobotProgramState | null {
    return this.overview.robots.find((r) => r.id === id) ?? null;
  }

  onChange(listener: () => void): void {
    this.listeners.add(listener);
  }

  /** Another scene: its robots' programs are not known until the list is read again. */
  forgetRobots(): void {
    this.overview = { ...this.overview, robots: [] };
  }

  /** Reads the list again (after a compile, a new scene, or on request). */
  refresh(): Promise<void> {
    this.loading ??= call("GET /api/programs")
      .then((overview) => {
        this.overview = overview;
        this.answered = true;
      })
      .catch((error: Error) => {
        this.answered = false;
        console.info("EyeSim viewer: no program controls:", error.message ?? error);
      })
      .then(() => {
        for (const listener of this.listeners) listener();
      })
      .finally(() => (this.loading = null));
    return this.loading;
  }
}

/** One robot's program controls, in its panel. */
export class ProgramControls {
  readonly element = element("div", "program-controls");
  private readonly choice = element("select", "program-choice");
  private readonly startButton = element("button", "program-start", "Start");
  private readonly stopButton = element("button", "program-stop", "Stop");
  private readonly restartButton = element("button", "program-restart", "Restart");
  private readonly compileButton = element("button", "program-compile", "Compile");
  private readonly editButton = element("button", "program-edit", "Edit");
  private readonly refreshButton = element("button", "program-refresh", "↻");
  private readonly message = element("p", "program-message");
  private readonly compilerOutput = element("div", "compiler-output");
  private enabled = true;
  private running = false;
  /** a file chosen in the list by hand (else the list shows the robot's own program) */
  private chosen = false;

  constructor(
    private readonly robot: number,
    private readonly catalog: ProgramCatalog,
  ) {
    this.choice.setAttribute("aria-label", "program");
    for (const button of [this.startButton, this.stopButton, this.restartButton, this.compileButton, this.editButton, this.refreshButton]) {
      button.type = "button";
    }
    this.refreshButton.title = "List the programs again";
    this.compileButton.title = "Compile the chosen C/C++ source with eyesim cc";
    this.startButton.title = "Start the chosen program for this robot (stops the one running)";
    this.restartButton.title = "Stop this robot's program and start it again";
    this.editButton.title = "Open the chosen source, or the robot's program source, in the program editor";
    this.message.setAttribute("role", "status");
    const row = element("div", "program-row");
    row.append(this.choice, this.refreshButton);
    const buttons = element("div", "program-buttons");
    buttons.append(this.startButton, this.stopButton, this.restartButton, this.compileButton, this.editButton);
    this.element.append(row, buttons, this.message, this.compilerOutput);
    this.compilerOutput.hidden = true;

    this.choice.addEventListener("change", () => {
      this.chosen = this.choice.value !== "";
      this.updateButtons();
    });
    this.refreshButton.addEventListener("click", () => void catalog.refresh());
    this.startButton.addEventListener("click", () => void this.act("start"));
    this.stopButton.addEventListener("click", () => void this.act("stop"));
    this.restartButton.addEventListener("click", () => void this.act("restart"));
    this.compileButton.addEventListener("click", () => void this.compile());
    // The program editor (main.ts loads it on first use) opens the chosen source, else the robot's.
    this.editButton.addEventListener("click", () => {
      const file = this.selected();
      const source = file && EDITABLE_KINDS.has(file.kind) ? { root: file.root, path: file.path } : null;
      this.element.dispatchEvent(new CustomEvent<EditProgram>(EDIT_PROGRAM, { bubbles: true, detail: { robot: this.robot, file: source } }));
    });
    catalog.onChange(() => this.showFiles());
    this.showFiles();
  }

  /** Off while disconnected or replaying: there is nothing to run the program on. */
  setEnabled(enabled: boolean): void {
    this.enabled = enabled;
    this.updateButtons();
  }

  /** Whether the robot's program runs now (from the program events): Stop only then. */
  setRunning(running: boolean): void {
    this.running = running;
    this.updateButtons();
  }

  /** What the controls last said (an error, a crash, a compile result). */
  messageText(): string {
    return this.message.textContent ?? "";
  }

  /** The compiler's findings shown now, as "file:line: message" lines. */
  compilerLines(): string[] {
    return [...this.compilerOutput.querySelectorAll(".diagnostic")].map((d) => d.textContent ?? "");
  }

  /** Chooses a file by its path (relative to its root), as a click in the list would. */
  choose(path: string): boolean {
    const option = [...this.choice.options].find((o) => o.dataset.path === path);
    if (!option) return false;
    this.choice.value = option.value;
    this.chosen = true;
    this.updateButtons();
    return true;
  }

  private selected(): ProgramFile | null {
    return this.catalog.files.find((f) => fileKey(f) === this.choice.value) ?? null;
  }

  private showFiles(): void {
    this.element.hidden = !this.catalog.available;
    const previous = (this.chosen && this.choice.value) || this.currentProgramKey();
    const groups = this.catalog.roots.map((root, index) => {
      const group = element("optgroup");
      group.label = `${root.name}: ${root.path}`;
      for (const file of this.catalog.files.filter((f) => f.root === index)) {
        const option = element("option", "", SOURCE_KINDS.has(file.kind) ? `${file.path} (${file.kind} source)` : file.path);
        option.value = fileKey(file);
        option.dataset.path = file.path;
        option.dataset.kind = file.kind;
        group.append(option);
      }
      return group;
    });
    const none = element("option", "", this.catalog.files.length ? "choose a program…" : "no programs in the scene folders");
    none.value = "";
    this.choice.replaceChildren(none, ...groups.filter((g) => g.children.length));
    this.choice.value = [...this.choice.options].some((o) => o.value === previous) ? previous : "";
    this.updateButtons();
  }

  private currentProgramKey(): string {
    const program = this.catalog.robot(this.robot)?.program;
    return program && program.root !== null ? fileKey(program) : "";
  }

  private updateButtons(): void {
    const file = this.selected();
    const source = file !== null && SOURCE_KINDS.has(file.kind);
    this.choice.disabled = !this.enabled;
    this.refreshButton.disabled = !this.enabled;
    this.startButton.disabled = !this.enabled || file === null || source;
    this.compileButton.disabled = !this.enabled || !source;
    this.stopButton.disabled = !this.enabled || !this.running;
    this.restartButton.disabled = !this.enabled;
    this.editButton.disabled = !this.enabled;
  }

  private async act(action: "start" | "stop" | "restart"): Promise<void> {
    const file = this.selected();
    if (action === "start" && !file) return;
    this.say(`${action === "stop" ? "stopping" : "starting"}…`, "busy");
    try {
      const state = action === "start" && file
        ? await call("POST /api/programs/start", { robot: this.robot, root: file.root, path: file.path })
        : await call(`POST /api/programs/${action === "stop" ? "stop" : "restart"}`, { robot: this.robot });
      this.say(state.state === "failed" ? (state.reason ?? "could not start") : "", state.state === "failed" ? "error" : "");
    } catch (error) {
      this.say(error instanceof RouteError ? error.message : String(error), "error");
    }
  }

  private async compile(): Promise<void> {
    const file = this.selected();
    if (!file) return;
    this.say(`compiling ${file.path}…`, "busy");
    this.compilerOutput.replaceChildren();
    this.compilerOutput.hidden = true;
    let result: CompileResult;
    try {
      result = await call("POST /api/programs/compile", { root: file.root, path: file.path });
    } catch (error) {
      this.say(error instanceof RouteError ? error.message : String(error), "error");
      return;
    }
    this.showCompilerOutput(result);
    if (!result.ok) {
      const errors = result.diagnostics.filter((d) => d.kind === "error").length;
      this.say(`${file.path} did not compile${errors ? ` (${errors} error${errors > 1 ? "s" : ""})` : ""}`, "error");
      return;
    }
    await this.catalog.refresh();
    if (result.program) this.choose(result.program.path);
    this.say(`compiled ${result.program?.path ?? ""}`, "done");
  }

  private showCompilerOutput(result: CompileResult): void {
    const lines = result.diagnostics.map((d) => {
      const where = `${d.file}:${d.line}${d.column === null ? "" : `:${d.column}`}`;
      const line = element("div", `diagnostic ${d.kind}`, `${where}: ${d.kind}: ${d.message}`);
      return line;
    });
    const raw = element("details", "compiler-raw");
    raw.append(element("summary", "", "compiler output"), element("pre", "", result.output));
    this.compilerOutput.replaceChildren(...lines, ...(result.output.trim() ? [raw] : []));
    this.compilerOutput.hidden = lines.length === 0 && !result.output.trim();
  }

  private say(text: string, kind: string): void {
    this.message.textContent = text;
    this.message.dataset.kind = kind;
  }
}
