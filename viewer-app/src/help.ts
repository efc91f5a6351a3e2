// The "?" button in the 3D view's corner and the list of mouse and keyboard controls it shows.

const CONTROLS: [string, string][] = [
  ["Drag", "orbit the camera around the floor"],
  ["Scroll", "zoom in and out"],
  ["Right-drag, Shift+drag", "pan the camera"],
  ["Drag a robot or object", "move it across the floor (also while paused)"],
  ["Shift+drag a robot or object", "turn it: right is clockwise"],
  ["Click an LCD, soft key", "touch the LCD, press KEY1..KEY4"],
  ["Click the IR remote, then type", "digits, arrow keys, Enter = OK, R/G/Y/B, P = power"],
  ["?", "show or hide this help"],
  ["Esc", "close this help"],
];

export class HelpOverlay {
  readonly button = document.createElement("button");
  readonly panel = document.createElement("div");

  constructor(container: HTMLElement) {
    this.button.type = "button";
    this.button.className = "help-button";
    this.button.textContent = "?";
    this.button.title = "Mouse and keyboard controls (?)";
    this.button.setAttribute("aria-expanded", "false");
    this.panel.className = "help-panel";
    this.panel.hidden = true;
    this.panel.setAttribute("role", "dialog");
    this.panel.setAttribute("aria-label", "Controls");
    const title = document.createElement("h2");
    title.textContent = "Controls";
    const list = document.createElement("dl");
    for (const [input, effect] of CONTROLS) {
      const term = document.createElement("dt");
      term.textContent = input;
      const meaning = document.createElement("dd");
      meaning.textContent = effect;
      list.append(term, meaning);
    }
    this.panel.append(title, list);
    container.append(this.button, this.panel);

    this.button.addEventListener("click", () => this.toggle());
    document.addEventListener("keydown", (event) => {
      if (event.defaultPrevented || typing(event.target) || event.ctrlKey || event.metaKey || event.altKey) return;
      if (event.key === "?") this.toggle();
      else if (event.key === "Escape") this.show(false);
    });
  }

  get visible(): boolean {
    return !this.panel.hidden;
  }

  toggle(): void {
    this.show(this.panel.hidden);
  }

  private show(visible: boolean): void {
    this.panel.hidden = !visible;
    this.button.setAttribute("aria-expanded", String(visible));
  }
}

/** Keys typed into a text field (serial terminal, analog value) are not commands. */
function typing(target: EventTarget | null): boolean {
  return (
    target instanceof HTMLElement &&
    (target.isContentEditable || ["INPUT", "TEXTAREA", "SELECT"].includes(target.tagName))
  );
}
