// The toolbar's "⚠ N scene warnings" badge and the list it opens: what the scene loader found wrong.

import type { SceneWarning } from "./protocol";

/** "room.wld:3" — the file's name and line; the full path is in the item's tooltip. */
function shortLocation(warning: SceneWarning): string {
  const name = warning.file.split(/[\\/]/).pop() || warning.file;
  return warning.line > 0 ? `${name}:${warning.line}` : name;
}

export class SceneWarnings {
  readonly badge = document.createElement("button");
  readonly list = document.createElement("ol");
  private shown: SceneWarning[] = [];

  constructor(toolbar: HTMLElement) {
    this.badge.type = "button";
    this.badge.className = "warnings-badge";
    this.badge.hidden = true;
    this.badge.setAttribute("aria-expanded", "false");
    this.list.className = "warnings-list";
    this.list.hidden = true;
    this.list.setAttribute("aria-label", "Scene warnings");
    // Before the connection state, which sits at the toolbar's right end.
    toolbar.insertBefore(this.badge, toolbar.querySelector("#connection"));
    toolbar.append(this.list);
    this.badge.addEventListener("click", () => this.open(this.list.hidden));
    document.addEventListener("keydown", (event) => {
      if (event.key === "Escape") this.open(false);
    });
  }

  /** The warnings of a new scene (none: the badge goes away). */
  show(warnings: SceneWarning[]): void {
    this.shown = warnings;
    const count = warnings.length;
    this.badge.hidden = count === 0;
    this.badge.textContent = `⚠ ${count} scene warning${count === 1 ? "" : "s"}`;
    this.badge.title = "Problems the simulator found in the scene files: click to list them";
    this.list.replaceChildren(
      ...warnings.map((warning) => {
        const item = document.createElement("li");
        const where = document.createElement("code");
        where.textContent = shortLocation(warning);
        where.title = warning.column > 0 ? `${warning.file}:${warning.line}:${warning.column}` : warning.file;
        item.append(where, ` ${warning.message}`);
        return item;
      }),
    );
    if (count === 0) this.open(false);
  }

  get warnings(): SceneWarning[] {
    return this.shown.map((w) => ({ ...w }));
  }

  get listOpen(): boolean {
    return !this.list.hidden;
  }

  private open(visible: boolean): void {
    this.list.hidden = !visible;
    this.badge.setAttribute("aria-expanded", String(visible));
  }
}
