// Entry point: builds the viewer on the page and starts it.

import "./style.css";
import { installDebugHandle } from "./debug_handle";
import { SceneEditor } from "./editor/scene_editor";
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
viewer.start();
