// The test drive: the robot in a scratch arena of its own on the server. Arrow keys or the buttons
// drive it through VW; robots without VW get a slider per motor; every servo (arm joints, gripper,
// steering, camera pan/tilt) gets a slider. PSD, LIDAR and camera read-outs follow live.

import { call, RouteError } from "../api";
import { element } from "../dom";
import type { DriveCommand, DriveState, RobotCheck, SceneMessage } from "../generated/viewer_protocol";

const POLL_MS = 150;
const KEYS: Record<string, [number, number]> = {
  ArrowUp: [1, 0],
  ArrowDown: [-1, 0],
  ArrowLeft: [0, 1],
  ArrowRight: [0, -1],
};

export class TestDrive {
  readonly panel = element("section", "test-drive");
  private readonly readouts = element("div", "drive-readouts");
  private readonly controls = element("div", "drive-controls");
  private readonly message = element("p", "drive-message");
  private readonly cameraImage = element("img", "drive-camera");
  private readonly lidarCanvas = element("canvas", "drive-lidar");
  private timer: number | null = null;
  private sliders = "";
  private readonly held = new Set<string>(); // arrow keys held down
  running = false;
  last: DriveState | null = null;

  constructor(
    private readonly started: (state: DriveState & { scene: SceneMessage }) => void,
    private readonly updated: (state: DriveState) => void,
    private readonly stopped: () => void,
    private readonly speeds: () => { v: number; w: number },
    private readonly robot: () => unknown,
  ) {
    this.panel.hidden = true;
    this.cameraImage.alt = "the robot's camera";
    this.lidarCanvas.width = 160;
    this.lidarCanvas.height = 160;
    this.panel.append(element("h3", "", "Test drive"), this.message, this.controls, this.readouts);
    window.addEventListener("keydown", (event) => this.key(event, true));
    window.addEventListener("keyup", (event) => this.key(event, false));
  }

  async start(body: RobotCheck): Promise<void> {
    await this.stop();
    const { scene } = await call("POST /robot-editor/api/drive/start", body);
    this.running = true;
    this.panel.hidden = false;
    this.sliders = "";
    this.message.textContent = "Arrow keys or the buttons drive the robot (VW).";
    const state = await call("GET /robot-editor/api/drive/state");
    this.last = state;
    this.started({ ...state, scene });
    this.show(state);
    this.timer = window.setInterval(() => void this.poll(), POLL_MS);
  }

  async stop(): Promise<void> {
    if (this.timer !== null) window.clearInterval(this.timer);
    this.timer = null;
    if (this.running) {
      this.running = false;
      await call("POST /robot-editor/api/drive/stop", {});
      this.stopped();
    }
    this.panel.hidden = true;
  }

  async command(body: DriveCommand): Promise<void> {
    try {
      await call("POST /robot-editor/api/drive/command", body);
    } catch (error) {
      this.message.textContent = error instanceof RouteError ? error.message : String(error);
    }
  }

  private async poll(): Promise<void> {
    if (!this.running) return;
    try {
      const state = await call("GET /robot-editor/api/drive/state");
      this.last = state;
      this.updated(state);
      this.show(state);
    } catch (error) {
      this.message.textContent = String(error);
    }
  }

  /** Arrow keys held together add up: up and left drive an arc (all a car can do). */
  private key(event: KeyboardEvent, down: boolean): void {
    if (!this.running || !(event.key in KEYS)) return;
    const target = event.target as HTMLElement | null;
    if (target && (target.tagName === "INPUT" || target.tagName === "SELECT")) return;
    event.preventDefault();
    if (event.repeat) return;
    if (down) this.held.add(event.key);
    else this.held.delete(event.key);
    let v = 0;
    let w = 0;
    for (const key of this.held) {
      v += KEYS[key][0];
      w += KEYS[key][1];
    }
    const { v: speed, w: turn } = this.speeds();
    void this.command({ type: "vw", v: v * speed, w: w * turn });
  }

  private show(state: DriveState): void {
    const r = state.readings;
    const key = `${r.servos.join(",")}|${r.motors.join(",")}|${r.vw !== undefined}`;
    if (key !== this.sliders) this.buildControls(state, key);
    const rows = Object.entries(r.psd).map(([id, mm]) => {
      const name = state.psds.find((p) => String(p.id) === id)?.name ?? `PSD ${id}`;
      return `<tr><td>${escape(name)}</td><td class="reading" data-psd="${id}">${mm} mm</td></tr>`;
    });
    const table = rows.length ? `<table class="psd-readings"><tr><th>PSD</th><th>distance</th></tr>${rows.join("")}</table>` : "";
    const vw = r.vw ? `<p class="vw-reading">v ${r.vw[0]} mm/s, ω ${r.vw[1]} °/s · t ${state.time.toFixed(1)} s</p>` : "";
    this.readouts.innerHTML = vw + table;
    if (r.lidar) {
      this.drawLidar(r.lidar);
      this.readouts.append(this.lidarCanvas);
    }
    if (r.camera) {
      this.cameraImage.src = `data:image/jpeg;base64,${r.camera}`;
      this.readouts.append(this.cameraImage);
    }
  }

  private buildControls(state: DriveState, key: string): void {
    this.sliders = key;
    this.controls.replaceChildren();
    const r = state.readings;
    if (r.vw !== undefined) {
      const pad = element("div", "drive-pad");
      const buttons: [string, string, number, number][] = [
        ["forward", "▲", 1, 0],
        ["left", "◀", 0, 1],
        ["stop", "■", 0, 0],
        ["right", "▶", 0, -1],
        ["back", "▼", -1, 0],
      ];
      for (const [name, label, v, w] of buttons) {
        const button = element("button", `drive-${name}`, label);
        button.type = "button";
        button.title = name;
        button.addEventListener("click", () => {
          const { v: speed, w: turn } = this.speeds();
          void this.command({ type: "vw", v: v * speed, w: w * turn });
        });
        pad.append(button);
      }
      this.controls.append(pad);
    } else {
      for (const motor of r.motors) this.controls.append(this.slider(`Motor ${motor}`, -100, 100, 0, "motor", motor));
    }
    for (const servo of r.servos) {
      const user = this.servoUser(servo);
      this.controls.append(this.slider(`Servo ${servo}${user ? ` (${user})` : ""}`, 0, 255, 128, "servo", servo));
    }
    const reset = element("button", "drive-reset", "Back to start");
    reset.type = "button";
    reset.addEventListener("click", () => void this.command({ type: "reset" }));
    this.controls.append(reset);
  }

  /** What a servo moves, from the robot's values: the part with that `servo` (an arm joint's
   * name, "gripper"), or the value that names it ("pan_servo" -> "camera pan"). */
  private servoUser(servo: number): string {
    let found = "";
    const visit = (value: unknown, key: string, owner: string): void => {
      if (found || typeof value !== "object" || value === null) return;
      for (const [k, v] of Object.entries(value)) {
        if (v === servo && k === "servo") {
          const name = (value as Record<string, unknown>).name;
          found = typeof name === "string" ? name : key;
        } else if (v === servo && k.endsWith("_servo")) {
          found = `${owner || key} ${k.slice(0, -"_servo".length)}`;
        } else visit(v, Array.isArray(value) ? key : k, Array.isArray(value) ? owner : key);
      }
    };
    visit(this.robot(), "", "");
    return found;
  }

  private slider(label: string, min: number, max: number, value: number, type: "motor" | "servo", number: number): HTMLElement {
    const row = element("label", "drive-slider");
    const input = element("input");
    input.type = "range";
    input.min = String(min);
    input.max = String(max);
    input.value = String(value);
    input.dataset[type] = String(number);
    const shown = element("span", "", String(value));
    input.addEventListener("input", () => {
      shown.textContent = input.value;
      const level = Number(input.value);
      void this.command(type === "motor" ? { type, motor: number, speed: level } : { type, servo: number, position: level });
    });
    row.append(element("span", "", label), input, shown);
    return row;
  }

  private drawLidar(distances: number[]): void {
    const g = this.lidarCanvas.getContext("2d");
    if (!g) return;
    const size = this.lidarCanvas.width;
    g.fillStyle = "#10161d";
    g.fillRect(0, 0, size, size);
    const scale = size / 2 / Math.max(...distances.filter((d) => d < 9999), 1000);
    g.fillStyle = "#5fe08a";
    const n = distances.length;
    distances.forEach((d, i) => {
      if (d >= 9999) return;
      // beam n/2 looks ahead (up on the plot), indices grow clockwise
      const angle = ((i - Math.floor(n / 2)) * 2 * Math.PI) / n;
      g.fillRect(size / 2 + Math.sin(angle) * d * scale - 1, size / 2 - Math.cos(angle) * d * scale - 1, 2, 2);
    });
  }
}

function escape(text: string): string {
  return text.replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
}
