// Entry point: builds the viewer on the page and starts it.

import "./style.css";
import { installDebugHandle } from "./debug_handle";
import { SceneEditor } from "./editor/scene_editor";
import { EDIT_PROGRAM, type EditProgram } from "./program_controls";
import type { ProgramEditor } from "./program_editor/program_editor";
import { Viewer } from "./viewer";

function byId(id: string): HTMLElement {
  const found = document.getElementById(id);
  if (!found) throw new Error(`EyeSim viewer: the page has no #${id}`);
  return found;
}

const viewer = new Viewer({
  toolbar: byId("toolbar"),
  timeline: byId("timeline"),
  world: byId("world"),
  plots: byId("plots"),
  panels: byId("robots"),
});
installDebugHandle(viewer);
const layout = byId("world").closest("main") ?? document.body;
// the scene browser and editor: also a handle for tests, as window.eyesimViewer is for the view
(window as unknown as { eyesimEditor: SceneEditor }).eyesimEditor = new SceneEditor(viewer, byId("toolbar"), layout, byId("world"));
// The program editor, loaded with CodeMirror when an Edit button is first clicked.
let programEditor: Promise<ProgramEditor> | null = null;
document.addEventListener(EDIT_PROGRAM, (event) => {
  const { robot, file } = (event as CustomEvent<EditProgram>).detail;
  programEditor ??= import("./program_editor/program_editor").then(({ ProgramEditor }) => {
    const editor = new ProgramEditor(byId("world").parentElement!, viewer.panels.catalog);
    viewer.connectionWatchers.push((connected) => editor.setEnabled(connected));
    viewer.sceneWatchers.push((scene) => editor.sceneChanged(scene.new_scene, scene.robots.map((r) => r.id)));
    (window as unknown as { eyesimProgramEditor: ProgramEditor }).eyesimProgramEditor = editor;
    return editor;
  });
  programEditor.then((editor) => editor.open(robot, file)).catch((error) => {
    programEditor = null; // the next click tries again (the simulator may have been restarting)
    console.warn("EyeSim viewer: the program editor could not be loaded:", error);
  });
});
viewer.start();
