// The scene's settings from the page: PSD noise and seed, sensor rays (VIS) and paths (TRACE), with
// the clock shown. Applying changes the running scene's settings, which a saved scene keeps.

import { call, RouteError } from "./api";
import { element } from "./dom";
import type { RunSettings } from "./generated/viewer_protocol";

function field(label: string, input: HTMLElement, hint = ""): HTMLElement {
  const row = element("label", "setting");
  row.append(element("span", "setting-name", label), input);
  if (hint) row.append(element("span", "setting-hint", hint));
  return row;
}

export class SettingsPanel {
  readonly element = element("section", "settings-panel");
  private readonly vis = element("input", "setting-vis");
  private readonly trace = element("input", "setting-trace");
  private readonly noise = element("input", "setting-psd-noise");
  private readonly seed = element("input", "setting-seed");
  private readonly clock = element("p", "setting-clock");
  private readonly apply = element("button", "settings-apply", "Apply");
  private readonly close = element("button", "settings-close", "Close");
  private readonly message = element("p", "settings-message");
  private shown: RunSettings | null = null;

  constructor(container: HTMLElement, toggle: HTMLElement) {
    this.element.setAttribute("aria-label", "Settings");
    this.element.hidden = true;
    this.vis.type = this.trace.type = "checkbox";
    this.noise.type = this.seed.type = "number";
    this.noise.min = "0";
    this.noise.step = "any";
    this.seed.min = "0";
    this.seed.step = "1";
    this.apply.type = this.close.type = "button";
    this.message.setAttribute("role", "status");
    const buttons = element("div", "settings-buttons");
    buttons.append(this.apply, this.close);
    this.element.append(
      element("h2", "", "Settings"),
      field("Sensor rays (VIS)", this.vis),
      field("Robot paths (TRACE)", this.trace),
      field("PSD noise", this.noise, "mm, standard deviation"),
      field("Random seed", this.seed),
      this.clock,
      buttons,
      this.message,
    );
    container.append(this.element);
    toggle.addEventListener("click", () => (this.element.hidden ? void this.open() : this.hide()));
    this.close.addEventListener("click", () => this.hide());
    this.apply.addEventListener("click", () => void this.save());
  }

  get visible(): boolean {
    return !this.element.hidden;
  }

  /** The settings as the simulator last reported them. */
  get settings(): RunSettings | null {
    return this.shown && { ...this.shown };
  }

  async open(): Promise<void> {
    this.element.hidden = false;
    this.say("");
    try {
      this.show(await call("GET /api/settings"));
    } catch (error) {
      this.say(error instanceof RouteError ? error.message : String(error), "error");
    }
  }

  hide(): void {
    this.element.hidden = true;
  }

  /** Apply needs the simulator: off while it is away. */
  setEnabled(enabled: boolean): void {
    this.apply.disabled = !enabled;
  }

  private show(settings: RunSettings): void {
    this.shown = settings;
    this.vis.checked = settings.vis;
    this.trace.checked = settings.trace;
    this.noise.value = String(settings.psd_noise);
    this.seed.value = String(settings.seed);
    const speed = settings.speed === "max" ? "as fast as possible" : `${settings.speed}× speed`;
    this.clock.textContent = `Clock: ${settings.clock}, ${speed}${settings.paused ? ", paused" : ""} (speed: toolbar)`;
  }

  private async save(): Promise<void> {
    const noise = Number(this.noise.value);
    const seed = Number(this.seed.value);
    if (this.noise.value === "" || !(noise >= 0)) return this.say("PSD noise: enter 0 or more (mm)", "error");
    if (this.seed.value === "" || !Number.isInteger(seed) || seed < 0) {
      return this.say("Random seed: enter a whole number, 0 or more", "error");
    }
    try {
      this.show(
        await call("POST /api/settings", {
          vis: this.vis.checked,
          trace: this.trace.checked,
          psd_noise: noise,
          seed,
        }),
      );
      this.say("applied", "done");
    } catch (error) {
      this.say(error instanceof RouteError ? error.message : String(error), "error");
    }
  }

  private say(text: string, kind = ""): void {
    this.message.textContent = text;
    this.message.dataset.kind = kind;
  }
}
