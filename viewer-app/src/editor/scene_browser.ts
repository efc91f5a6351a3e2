// The scene browser: the scene files under the scene roots and the recent ones, a search box;
// choosing one replaces the running scene. A file that fails to load leaves the scene running and
// its errors show here with file:line.

import { call, errorText } from "../api";
import type { EditorState, Place, SceneFiles } from "../generated/viewer_protocol";
import { placeText } from "./places";

const SEARCH_DELAY_MS = 200;

export class SceneBrowser {
  readonly element: HTMLDialogElement;
  private readonly search: HTMLInputElement;
  private readonly recent: HTMLUListElement;
  private readonly files: HTMLUListElement;
  private readonly message: HTMLElement;
  private searchTimer = 0;
  private listed = 0;

  constructor(private readonly opened: (state: EditorState) => void) {
    this.element = document.createElement("dialog");
    this.element.id = "scene-browser";
    this.element.className = "scene-dialog";
    this.element.innerHTML = `
      <form method="dialog" class="dialog-head"><h2>Open a scene</h2><button id="scene-browser-close">Close</button></form>
      <div class="editor-row"><input id="scene-search" type="search" placeholder="Search scene files…" aria-label="Search scene files" />
        <button id="scene-new" type="button" title="An empty 2 m × 2 m floor to build a scene on">New empty scene</button></div>
      <h3>Recent</h3><ul id="scene-recent" class="file-list"></ul>
      <h3>Scene files</h3><ul id="scene-files" class="file-list"></ul>
      <pre id="scene-browser-message" class="editor-message" role="status"></pre>`;
    document.body.append(this.element);
    this.search = this.element.querySelector("#scene-search")!;
    this.recent = this.element.querySelector("#scene-recent")!;
    this.files = this.element.querySelector("#scene-files")!;
    this.message = this.element.querySelector("#scene-browser-message")!;
    this.element.querySelector("#scene-new")!.addEventListener("click", () => void this.create());
    this.search.addEventListener("input", () => {
      window.clearTimeout(this.searchTimer);
      this.searchTimer = window.setTimeout(() => void this.refresh(), SEARCH_DELAY_MS);
    });
  }

  /** Times the lists were filled (tests wait for it). */
  get listings(): number {
    return this.listed;
  }

  show(): void {
    this.message.textContent = "";
    if (!this.element.open) this.element.showModal();
    void this.refresh();
  }

  private async refresh(): Promise<void> {
    try {
      const listing = await call("GET /scenes/files", `q=${encodeURIComponent(this.search.value)}`);
      this.fill(this.recent, listing.recent, listing);
      this.fill(this.files, listing.files, listing);
      this.listed++;
    } catch (error) {
      this.message.textContent = errorText(error);
    }
  }

  private fill(list: HTMLUListElement, places: Place[], listing: SceneFiles): void {
    list.replaceChildren(
      ...places.map((place) => {
        const item = document.createElement("li");
        const button = document.createElement("button");
        button.type = "button";
        button.textContent = placeText(place, listing.roots);
        button.title = `${listing.roots[place.root]?.path}/${place.path}`;
        button.dataset.path = place.path;
        button.addEventListener("click", () => void this.open(place));
        item.append(button);
        return item;
      }),
    );
    if (!places.length) list.innerHTML = `<li class="empty">none</li>`;
  }

  private async create(): Promise<void> {
    try {
      const state = await call("POST /scenes/new", {});
      this.element.close();
      this.opened(state);
    } catch (error) {
      this.message.textContent = errorText(error);
    }
  }

  private async open(place: Place): Promise<void> {
    this.message.textContent = `opening ${place.path}…`;
    try {
      const state = await call("POST /scenes/open", place);
      this.element.close();
      this.opened(state);
    } catch (error) {
      this.message.textContent = `${errorText(error)}\nThe current scene keeps running.`;
    }
  }
}
