// The toolbar: the scene's name, pause/resume, speed and reset, the simulation's clock, and the
// connection state.

import type { ConnectionState } from "./connection";
import type { BrowserCommand, StatusMessage } from "./protocol";

function find<T extends HTMLElement>(root: HTMLElement, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`EyeSim viewer: the page has no ${selector}`);
  return found;
}

const CONNECTION_TEXT: Record<ConnectionState, string> = {
  connecting: "connecting…",
  open: "connected",
  closed: "disconnected, reconnecting…",
};

export class Toolbar {
  private readonly pause: HTMLButtonElement;
  private readonly speed: HTMLSelectElement;
  private readonly reset: HTMLButtonElement;
  private readonly time: HTMLElement;
  private readonly rate: HTMLElement;
  private readonly clock: HTMLElement;
  private readonly connection: HTMLElement;
  private readonly sceneName: HTMLElement;
  /** what only a live run has: hidden in a replay */
  private readonly liveOnly: HTMLElement[];
  private replay = false;
  private state: ConnectionState = "connecting";
  /** Shows a speed the server reports that is not one of the choices (e.g. "max"). */
  private readonly otherSpeed = document.createElement("option");
  private paused = false;

  constructor(root: HTMLElement, send: (command: BrowserCommand) => void) {
    this.pause = find(root, "#pause");
    this.speed = find(root, "#speed");
    this.reset = find(root, "#reset");
    this.time = find(root, "#sim-time");
    this.rate = find(root, "#real-time-factor");
    this.clock = find(root, "#clock");
    this.connection = find(root, "#connection");
    this.sceneName = find(root, "#scene-name");
    this.liveOnly = [this.pause.parentElement ?? this.pause, this.time, this.rate,
      find(root, "#settings-toggle"), find(root, "#robot-editor-link")];
    this.otherSpeed.disabled = true;

    this.pause.addEventListener("click", () => send({ type: this.paused ? "resume" : "pause" }));
    this.speed.addEventListener("change", () => {
      if (this.speed.value === "max") {
        send({ type: "speed", value: "max" });
        return;
      }
      const value = Number(this.speed.value);
      if (value > 0) send({ type: "speed", value });
    });
    this.reset.addEventListener("click", () => send({ type: "reset" }));
  }

  showStatus(status: StatusMessage): void {
    this.paused = status.paused;
    this.pause.textContent = status.paused ? "Resume" : "Pause";
    this.pause.classList.toggle("paused", status.paused);
    this.showSpeed(status.speed);
    if (this.replay) return;
    this.time.textContent = `t = ${status.time.toFixed(2)} s`;
    const rate = status.real_time_factor;  // null until the server could measure it
    this.rate.textContent = rate === null ? "" : `${rate.toFixed(2)}× real time`;
    this.clock.textContent = status.paused ? `${status.clock}, paused` : status.clock;
  }

  showConnection(state: ConnectionState): void {
    this.state = state;
    this.connection.textContent = CONNECTION_TEXT[state];
    this.connection.dataset.state = state;
    for (const control of [this.pause, this.speed, this.reset]) control.disabled = state !== "open" || this.replay;
  }

  /** The running scene's file name (a replay: the recording's scene). */
  showSceneName(name: string | undefined): void {
    this.sceneName.textContent = name ?? "";
    this.sceneName.title = name ? `Scene: ${name}` : "";
  }

  /** A replay has no simulation to pause, speed up, reset or set up, nor a robot editor: those go. */
  setReplay(replay: boolean, name?: string): void {
    this.replay = replay;
    for (const control of this.liveOnly) control.hidden = replay;
    this.clock.textContent = replay ? `replay${name ? ` of ${name}` : ""}` : this.clock.textContent;
    this.showConnection(this.state);
  }

  private showSpeed(speed: number | "max"): void {
    const value = String(speed);
    const listed = [...this.speed.options].some((o) => o !== this.otherSpeed && o.value === value);
    if (listed) {
      this.otherSpeed.remove();
    } else {
      this.otherSpeed.value = value;
      this.otherSpeed.textContent = speed === "max" ? "max" : `${speed}×`;
      this.speed.append(this.otherSpeed);
    }
    // Only on change: rewriting it would disturb a student who has the list open.
    if (this.speed.value !== value) this.speed.value = value;
  }
}
