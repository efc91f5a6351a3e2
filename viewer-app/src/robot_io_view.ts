// A robot's outside world: IR remote (buttons and keyboard), serial terminal, digital lines,
// analog channels and battery voltage.

import { element } from "./dom";
import type { BrowserCommand, IoMessage, SerialMessage } from "./protocol";

/** The remote's buttons as the simulator names them, with their labels. */
const REMOTE: [string, string][] = [
  ["1", "1"], ["2", "2"], ["3", "3"], ["4", "4"], ["5", "5"],
  ["6", "6"], ["7", "7"], ["8", "8"], ["9", "9"], ["0", "0"],
  ["LEFT", "◀"], ["UP", "▲"], ["OK", "OK"], ["DOWN", "▼"], ["RIGHT", "▶"],
  ["RED", "R"], ["GREEN", "G"], ["YELLOW", "Y"], ["BLUE", "B"], ["POWER", "PWR"],
];
const KEYBOARD: Record<string, string> = {
  ArrowLeft: "LEFT", ArrowRight: "RIGHT", ArrowUp: "UP", ArrowDown: "DOWN", Enter: "OK",
  r: "RED", g: "GREEN", y: "YELLOW", b: "BLUE", p: "POWER",
};
const INTERFACES = 21;
const MAX_SERIAL_CHARACTERS = 20_000;

/** A command for one robot, without the `robot` field: the panel adds its own. */
type RobotCommand = BrowserCommand extends infer C ? (C extends { robot: number } ? Omit<C, "robot"> : never) : never;

export class RobotIoView {
  readonly element = element("details", "robot-io");
  private readonly serialOutput = element("pre", "serial-output");
  private readonly serialTexts: string[] = Array.from({ length: INTERFACES }, () => "");
  private readonly interfaceChoice = element("select", "serial-interface");
  private readonly digitalCells: HTMLButtonElement[] = [];
  private readonly analogInputs: HTMLInputElement[] = [];
  private readonly battery = element("span", "battery");
  private io: IoMessage | null = null;
  private readonly remoteBox = element("div", "ir-remote");
  private enabled = true;

  constructor(private readonly send: (command: RobotCommand) => void) {
    const summary = element("summary", "", "Remote, serial, I/O");
    summary.append(this.battery);
    this.element.append(summary, this.remote(), this.serial(), this.digital(), this.analog());
  }

  appendSerial(message: SerialMessage): void {
    const texts = this.serialTexts;
    texts[message.interface] = (texts[message.interface] + message.text).slice(-MAX_SERIAL_CHARACTERS);
    if (message.interface === Number(this.interfaceChoice.value)) this.showSerial();
  }

  showIo(message: IoMessage): void {
    this.io = message;
    message.digital.forEach((line, i) => {
      const cell = this.digitalCells[i];
      if (!cell) return;
      const output = line.direction === "o";
      cell.textContent = `${i + 1}:${line.level}`;
      cell.dataset.level = String(line.level);
      cell.dataset.output = String(output);
      cell.title = output
        ? `line ${i + 1}: output, the program writes ${line.level}`
        : `line ${i + 1}: input (${line.direction}), ${line.driven === null ? "not driven" : `driven to ${line.driven}`}; click to change`;
    });
    message.analog.forEach((value, i) => {
      const input = this.analogInputs[i];
      if (input && document.activeElement !== input) input.value = String(value);
    });
  }

  /** Off while disconnected or replaying: the buttons and fields would send nowhere. */
  setEnabled(enabled: boolean): void {
    for (const control of this.element.querySelectorAll<HTMLButtonElement | HTMLInputElement>(
      ".ir-button, .serial-input, .digital-line, .analog-channel input",
    )) {
      control.disabled = !enabled;
    }
    this.remoteBox.tabIndex = enabled ? 0 : -1;
    this.enabled = enabled;
  }

  showBattery(volts: number): void {
    this.battery.textContent = `battery ${volts.toFixed(2)} V`;
  }

  serialText(interfaceNumber: number): string {
    return this.serialTexts[interfaceNumber] ?? "";
  }

  state(): IoMessage | null {
    return this.io && structuredClone(this.io);
  }

  private remote(): HTMLElement {
    const box = this.remoteBox;
    box.tabIndex = 0;
    box.title = "IR remote: click the buttons, or focus here and type 0-9, arrows, Enter (OK), R G Y B, P";
    for (const [code, label] of REMOTE) {
      const button = element("button", "ir-button", label);
      button.type = "button";
      button.dataset.code = code;
      button.addEventListener("click", () => this.send({ type: "irtv", code }));
      box.append(button);
    }
    box.addEventListener("keydown", (event) => {
      if (!this.enabled) return;
      const code = /^[0-9]$/.test(event.key) ? event.key : KEYBOARD[event.key] ?? KEYBOARD[event.key.toLowerCase()];
      if (!code) return;
      event.preventDefault();
      this.send({ type: "irtv", code });
    });
    return this.section("IR remote", box);
  }

  private serial(): HTMLElement {
    for (let i = 0; i < INTERFACES; i++) {
      this.interfaceChoice.append(new Option(i === 0 ? "0 serial" : `${i} USB`, String(i)));
    }
    this.interfaceChoice.addEventListener("change", () => this.showSerial());
    const input = element("input", "serial-input");
    input.placeholder = "text to send (Enter sends it with a newline)";
    input.addEventListener("keydown", (event) => {
      if (event.key !== "Enter") return;
      this.send({ type: "serial", interface: Number(this.interfaceChoice.value), text: `${input.value}\n` });
      input.value = "";
    });
    const row = element("div", "serial-row");
    row.append(this.interfaceChoice, input);
    const box = element("div");
    box.append(this.serialOutput, row);
    return this.section("Serial", box);
  }

  private digital(): HTMLElement {
    const box = element("div", "digital-lines");
    for (let line = 1; line <= 16; line++) {
      const cell = element("button", "digital-line", `${line}:0`);
      cell.type = "button";
      cell.addEventListener("click", () => this.cycleInput(line));
      this.digitalCells.push(cell);
      box.append(cell);
    }
    return this.section("Digital lines", box);
  }

  /** An input goes undriven -> 1 -> 0 -> undriven; outputs are the program's. */
  private cycleInput(line: number): void {
    const state = this.io?.digital[line - 1];
    if (!state || state.direction === "o") return;
    const next = state.driven === null ? 1 : state.driven === 1 ? 0 : null;
    this.send({ type: "digital", line, level: next });
  }

  private analog(): HTMLElement {
    const box = element("div", "analog-channels");
    for (let channel = 1; channel <= 8; channel++) {
      const label = element("label", "analog-channel", channel === 8 ? "8 mic" : String(channel));
      const input = element("input");
      input.type = "number";
      input.min = "0";
      input.max = "1023";
      input.value = "0";
      input.addEventListener("change", () => {
        const value = Math.round(Number(input.value));
        if (value >= 0 && value <= 1023) this.send({ type: "analog", channel, value });
      });
      this.analogInputs.push(input);
      label.append(input);
      box.append(label);
    }
    return this.section("Analog channels (0..1023)", box);
  }

  private section(title: string, content: HTMLElement): HTMLElement {
    const section = element("section", "io-section");
    section.append(element("h3", "io-title", title), content);
    return section;
  }

  private showSerial(): void {
    const box = this.serialOutput;
    box.textContent = this.serialTexts[Number(this.interfaceChoice.value)];
    box.scrollTop = box.scrollHeight;
  }
}
