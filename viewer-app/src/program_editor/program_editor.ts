// The program editor: a robot's program source (C, C++ or Python) beside its LCD, with syntax
// highlighting (CodeMirror 6), Save (Ctrl-S), Compile with the compiler's errors and warnings
// marked at their lines, and Restart with the new build (docs/viewer.md, "Program editor").
// The simulator reads, writes, checks and runs the files (/api/sources, program_sources.py).

import { indentWithTab } from "@codemirror/commands";
import { cpp } from "@codemirror/lang-cpp";
import { python } from "@codemirror/lang-python";
import { type Diagnostic, forEachDiagnostic, lintGutter, setDiagnostics } from "@codemirror/lint";
import { Compartment, EditorState, type Text } from "@codemirror/state";
import { EditorView, keymap } from "@codemirror/view";
import { basicSetup } from "codemirror";
import { call, RouteError } from "../api";
import { element } from "../dom";
import type { CompileResult, CompilerDiagnostic, Place, SourceFile } from "../generated/viewer_protocol";
import type { ProgramCatalog } from "../program_controls";
import "./program_editor.css";

/** The file open in the editor; its root by folder, as root numbers change with the scene's folder. */
interface OpenFile {
  rootFolder: string;
  path: string;
  kind: SourceFile["kind"];
  version: string;
}

/** What the editor shows, for tests and debugging (window.eyesimProgramEditor). */
export interface ProgramEditorState {
  open: boolean;
  robot: number | null;
  file: string | null;
  dirty: boolean;
  message: string;
  /** the diagnostics marked in the text: line (1..), severity and message */
  marked: { line: number; severity: string; message: string }[];
}

const SOURCE_KINDS = new Set(["c", "c++", "python"]);

function baseName(path: string): string {
  return path.split(/[\\/]/).pop() ?? path;
}

/** The compiler's findings about this file as CodeMirror diagnostics: from the column to the end
 * of the word there (a whole line when no column is given). */
function marks(doc: Text, found: CompilerDiagnostic[], name: string): Diagnostic[] {
  return found
    .filter((d) => baseName(d.file) === name && d.line >= 1 && d.line <= doc.lines)
    .map((d) => {
      const line = doc.line(d.line);
      let from = line.from;
      let to = line.to;
      if (d.column !== null) {
        from = Math.min(line.from + d.column - 1, line.to);
        const word = /^\w+/.exec(line.text.slice(from - line.from));
        to = word ? from + word[0].length : Math.min(from + 1, line.to);
      }
      const severity = d.kind === "note" ? "info" : d.kind;
      return { from, to, severity, message: d.message };
    });
}

export class ProgramEditor {
  readonly element = element("section", "program-editor");
  private readonly title = element("h2", "program-editor-title");
  private readonly choice = element("select", "program-editor-file");
  private readonly saveButton = element("button", "program-editor-save", "Save");
  private readonly compileButton = element("button", "program-editor-compile", "Compile");
  private readonly restartButton = element("button", "program-editor-restart", "Restart");
  private readonly closeButton = element("button", "program-editor-close", "Close");
  private readonly message = element("p", "program-editor-message");
  private readonly problems = element("ul", "program-editor-problems");
  private readonly language = new Compartment();
  private readonly view: EditorView;
  private robot: number | null = null;
  private file: OpenFile | null = null;
  private savedText = "";
  private enabled = true;
  private busy = false;

  constructor(
    container: HTMLElement,
    private readonly catalog: ProgramCatalog,
  ) {
    this.element.hidden = true;
    this.element.setAttribute("aria-label", "Program editor");
    for (const button of [this.saveButton, this.compileButton, this.restartButton, this.closeButton]) button.type = "button";
    this.saveButton.title = "Save the file (Ctrl-S)";
    this.compileButton.title = "Save, then compile: errors and warnings are marked at their lines";
    this.restartButton.title = "Save, compile, and start this program for the robot (stopping the one running)";
    this.choice.setAttribute("aria-label", "source file");
    this.choice.title = "Open another source from the scene folders";
    this.message.setAttribute("role", "status");
    const header = element("header", "program-editor-header");
    const buttons = element("div", "program-editor-buttons");
    buttons.append(this.saveButton, this.compileButton, this.restartButton, this.closeButton);
    header.append(this.title, this.choice, buttons);
    this.view = new EditorView({ parent: element("div") });
    const body = element("div", "program-editor-text");
    body.append(this.view.dom);
    this.element.append(header, body, this.message, this.problems);
    container.append(this.element);

    this.saveButton.addEventListener("click", () => void this.act(() => this.save()));
    this.compileButton.addEventListener("click", () => void this.act(() => this.compile()));
    this.restartButton.addEventListener("click", () => void this.act(() => this.restart()));
    this.closeButton.addEventListener("click", () => this.close());
    this.choice.addEventListener("change", () => {
      const [root, ...path] = this.choice.value.split(":");
      if (this.robot !== null && this.choice.value) void this.open(this.robot, { root: Number(root), path: path.join(":") });
    });
    // Keys typed here are the program's text, not the page's shortcuts (?, Delete, Ctrl-Z of the scene editor).
    this.element.addEventListener("keydown", (event) => event.stopPropagation());
    catalog.onChange(() => this.showFiles());
    this.updateButtons();
  }

  /** Opens `file` (null: the source of the robot's program) for the robot. */
  async open(robot: number, file: Place | null): Promise<void> {
    if (this.dirty && !window.confirm(`Discard the unsaved changes to ${this.file?.path}?`)) {
      this.showFiles();
      return;
    }
    this.robot = robot;
    this.element.hidden = false;
    this.say(file ? `opening ${file.path}…` : `opening robot ${robot}'s program…`, "busy");
    let source: SourceFile;
    try {
      source = file ? await call("POST /api/sources/read", file) : await call("POST /api/sources/robot", { robot });
    } catch (error) {
      this.showFiles(); // to choose another source instead
      this.updateButtons();
      this.say(error instanceof RouteError ? error.message : String(error), "error");
      return;
    }
    const root = this.catalog.roots[source.root];
    this.file = { rootFolder: root?.path ?? "", path: source.path, kind: source.kind, version: source.version };
    this.savedText = source.text;
    this.view.setState(EditorState.create({ doc: source.text, extensions: this.extensions(source.kind) }));
    this.problems.replaceChildren();
    this.showFiles();
    this.updateButtons();
    this.say(`${source.path}${root ? ` in ${root.name}` : ""}`, "");
    this.view.focus();
  }

  close(): void {
    if (this.dirty && !window.confirm(`Discard the unsaved changes to ${this.file?.path}?`)) return;
    this.element.hidden = true;
    this.file = null;
    this.robot = null;
  }

  /** Another scene, or the same one with other robots: a robot that is not the same one any more
   * is let go (Restart off; the file stays open to save and compile). */
  sceneChanged(newScene: boolean, robots: number[]): void {
    if (this.robot === null || (!newScene && robots.includes(this.robot))) return;
    this.say(`robot ${this.robot} of the last scene is gone: Restart is off, Save and Compile still work`, "");
    this.robot = null;
    this.updateButtons();
  }

  /** Off while disconnected: nothing can be saved or run. */
  setEnabled(enabled: boolean): void {
    this.enabled = enabled;
    this.updateButtons();
  }

  get dirty(): boolean {
    return this.file !== null && this.view.state.doc.toString() !== this.savedText;
  }

  state(): ProgramEditorState {
    const marked: ProgramEditorState["marked"] = [];
    forEachDiagnostic(this.view.state, (d, from) =>
      marked.push({ line: this.view.state.doc.lineAt(from).number, severity: d.severity, message: d.message }));
    return {
      open: !this.element.hidden,
      robot: this.robot,
      file: this.file?.path ?? null,
      dirty: this.dirty,
      message: this.message.textContent ?? "",
      marked,
    };
  }

  private extensions(kind: SourceFile["kind"]) {
    return [
      basicSetup,
      this.language.of(kind === "python" ? python() : cpp()),
      lintGutter(),
      keymap.of([{ key: "Mod-s", preventDefault: true, run: () => (void this.act(() => this.save()), true) }, indentWithTab]),
      EditorView.updateListener.of((update) => {
        if (update.docChanged) this.updateButtons();
      }),
    ];
  }

  /** The open file as the simulator names it now (its folder's root number may have changed). */
  private place(): Place {
    const file = this.file!;
    const root = this.catalog.roots.findIndex((r) => r.path === file.rootFolder);
    if (root < 0) throw new Error(`${file.path}: its folder ${file.rootFolder} is no longer a scene folder`);
    return { root, path: file.path };
  }

  /** One request at a time; what went wrong is said under the text. */
  private async act(action: () => Promise<boolean>): Promise<void> {
    if (this.busy || !this.file || !this.enabled) return;
    this.busy = true;
    this.updateButtons();
    try {
      await action();
    } catch (error) {
      this.say(error instanceof Error ? error.message : String(error), "error");
    } finally {
      this.busy = false;
      this.updateButtons();
    }
  }

  private async save(): Promise<boolean> {
    const file = this.file!;
    const text = this.view.state.doc.toString();
    let saved;
    try {
      saved = await call("POST /api/sources/save", { ...this.place(), text, version: file.version });
    } catch (error) {
      if (!(error instanceof RouteError && error.status === 409 && window.confirm(`${error.message}. Replace it?`))) throw error;
      saved = await call("POST /api/sources/save", { ...this.place(), text });
    }
    file.version = saved.version;
    this.savedText = text;
    this.say(`saved ${file.path}`, "done");
    return true;
  }

  /** Saves unsaved changes, then compiles; true when it compiled. */
  private async compile(): Promise<boolean> {
    if (this.dirty && !(await this.save())) return false;
    const file = this.file!;
    this.say(`compiling ${file.path}…`, "busy");
    const result = await call("POST /api/sources/check", this.place());
    this.showResult(result);
    const count = (kind: string) => result.diagnostics.filter((d) => d.kind === kind).length;
    const errors = count("error");
    const warnings = count("warning");
    const summary = [errors && `${errors} error${errors > 1 ? "s" : ""}`, warnings && `${warnings} warning${warnings > 1 ? "s" : ""}`]
      .filter(Boolean).join(", ");
    if (result.ok) this.say(`${file.path} compiled${summary ? ` (${summary})` : ""}`, warnings ? "warning" : "done");
    else this.say(`${file.path} did not compile${summary ? ` (${summary})` : ""}`, "error");
    return result.ok;
  }

  private async restart(): Promise<boolean> {
    if (!(await this.compile())) return false;
    const file = this.file!;
    const state = await call("POST /api/sources/run", { robot: this.robot!, ...this.place() });
    if (state.state === "failed") {
      this.say(state.reason ?? `${file.path} could not start`, "error");
      return false;
    }
    this.say(`robot ${this.robot} runs ${file.path}`, "done");
    return true;
  }

  private showResult(result: CompileResult): void {
    const name = baseName(this.file!.path);
    const doc = this.view.state.doc;
    this.view.dispatch(setDiagnostics(this.view.state, marks(doc, result.diagnostics, name)));
    const items = result.diagnostics.map((d) => {
      const where = `${d.file}:${d.line}${d.column === null ? "" : `:${d.column}`}`;
      const item = element("li", `problem ${d.kind}`, `${where}: ${d.kind}: ${d.message}`);
      if (baseName(d.file) === name && d.line >= 1 && d.line <= doc.lines) {
        item.tabIndex = 0;
        item.title = "Go to this line";
        item.addEventListener("click", () => this.goTo(d.line));
      }
      return item;
    });
    if (!result.ok && !items.length && result.output.trim()) items.push(element("li", "problem error", result.output.trim()));
    this.problems.replaceChildren(...items);
  }

  private goTo(line: number): void {
    const at = this.view.state.doc.line(line).from;
    this.view.dispatch({ selection: { anchor: at }, scrollIntoView: true });
    this.view.focus();
  }

  /** The sources under the scene roots to open instead, the open file chosen. */
  private showFiles(): void {
    const current = this.currentKey();
    const groups = this.catalog.roots.map((root, index) => {
      const group = element("optgroup");
      group.label = `${root.name}: ${root.path}`;
      for (const file of this.catalog.files.filter((f) => f.root === index && SOURCE_KINDS.has(f.kind))) {
        const option = element("option", "", file.path);
        option.value = `${file.root}:${file.path}`;
        group.append(option);
      }
      return group;
    }).filter((group) => group.children.length);
    const listed = groups.some((group) => [...group.children].some((option) => (option as HTMLOptionElement).value === current));
    // a file the list does not hold (a header) is shown as the first choice
    const first = element("option", "", this.file && !listed ? this.file.path : "open a source…");
    first.value = listed ? "" : current;
    this.choice.replaceChildren(first, ...groups);
    this.choice.value = current;
  }

  private currentKey(): string {
    const file = this.file;
    const root = file ? this.catalog.roots.findIndex((r) => r.path === file.rootFolder) : -1;
    return file && root >= 0 ? `${root}:${file.path}` : "";
  }

  private updateButtons(): void {
    const off = !this.enabled || this.busy || !this.file;
    this.saveButton.disabled = off || !this.dirty;
    this.compileButton.disabled = off || this.file?.kind === "header";
    this.restartButton.disabled = off || this.file?.kind === "header" || this.robot === null;
    this.choice.disabled = !this.enabled || this.busy;
    const robot = this.robot === null ? "" : `robot ${this.robot}`;
    this.title.textContent = this.file ? `${this.file.path}${this.dirty ? " •" : ""}${robot ? ` · ${robot}` : ""}` : robot;
    this.title.title = this.dirty ? "unsaved changes" : "";
  }

  private say(text: string, kind: string): void {
    this.message.textContent = text;
    this.message.dataset.kind = kind;
  }
}
