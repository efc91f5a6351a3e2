// One robot's panel: its name, program state, LCD with soft keys, camera image, console, and remote,
// serial and I/O.

import { CameraView } from "./camera_view";
import { ConsoleView } from "./console_view";
import { element } from "./dom";
import { LcdView } from "./lcd_view";
import { ProgramControls, type ProgramCatalog } from "./program_controls";
import type { BrowserCommand, ConsoleMessage, ProgramMessage, RobotInfo } from "./protocol";
import { RobotIoView } from "./robot_io_view";
import { download } from "./snapshot_files";

export type ProgramState = Pick<ProgramMessage, "event" | "name" | "exit_code">;

/** Signals that end crashed programs, by their Linux numbers (the console says more). */
const SIGNAL_NAMES: Record<number, string> = {
  4: "SIGILL", 6: "SIGABRT", 7: "SIGBUS", 8: "SIGFPE", 9: "SIGKILL", 11: "SIGSEGV", 15: "SIGTERM", 24: "SIGXCPU",
};

function describe(program: ProgramState | null): { text: string; kind: string } {
  if (!program) return { text: "no program", kind: "idle" };
  if (program.event === "started") return { text: `running ${program.name}`, kind: "running" };
  if (program.exit_code !== null && program.exit_code < 0) {
    const signal = -program.exit_code;
    const name = SIGNAL_NAMES[signal] ?? `signal ${signal}`;
    // SIGTERM and SIGKILL are how Stop (or the end of the run) ends a program.
    if (signal === 15 || signal === 9) return { text: `${program.name} stopped (${name})`, kind: "exited" };
    return { text: `${program.name} crashed: ${name}`, kind: "failed" };
  }
  const code = program.exit_code === null ? "" : ` with code ${program.exit_code}`;
  return { text: `${program.name} exited${code}`, kind: program.exit_code ? "failed" : "exited" };
}

export class RobotPanel {
  readonly element = element("section", "robot-panel");
  readonly lcd: LcdView;
  readonly console = new ConsoleView();
  readonly camera = new CameraView();
  readonly io: RobotIoView;
  readonly programs: ProgramControls;
  private readonly name = element("h2", "robot-name");
  private readonly type = element("span", "robot-type");
  private readonly state = element("span", "program-state");
  private readonly saveLcd = element("button", "save-lcd", "Save LCD");
  private program: ProgramState | null = null;
  private robotName = "";

  constructor(
    robot: RobotInfo,
    send: (command: BrowserCommand) => void,
    catalog: ProgramCatalog,
    select: (robot: number) => void,
  ) {
    this.element.dataset.robot = String(robot.id);
    this.lcd = new LcdView(
      (key) => send({ type: "key", robot: robot.id, key }),
      (x, y) => send({ type: "touch", robot: robot.id, x, y }),
    );
    this.io = new RobotIoView((command) => send({ ...command, robot: robot.id } as BrowserCommand));
    const header = element("header", "robot-header");
    const title = element("div", "robot-title");
    title.append(this.name, this.type);
    this.saveLcd.type = "button";
    this.saveLcd.title = "Download the LCD as a PNG image";
    this.saveLcd.addEventListener("click", () => {
      const png = this.lcd.pngDataUrl();
      if (png) download(png, `${this.robotName}-${robot.id}-lcd.png`);
    });
    header.append(title, this.state, this.saveLcd);
    // A click on the header (not its buttons) opens this panel and folds the others.
    header.addEventListener("click", (event) => {
      if (!(event.target as HTMLElement).closest("button")) select(robot.id);
    });
    header.tabIndex = 0;
    header.title = "Open this robot's panel";
    header.addEventListener("keydown", (event) => {
      if ((event.key === "Enter" || event.key === " ") && event.target === header) {
        event.preventDefault();
        select(robot.id);
      }
    });
    this.programs = new ProgramControls(robot.id, catalog);
    const screens = element("div", "robot-screens");
    screens.append(this.lcd.element, this.camera.element);
    this.element.append(header, this.programs.element, screens, this.console.element, this.io.element);
    this.describeRobot(robot);
    this.showProgram(null);
  }

  /** Keys, touches, the remote, serial and I/O, and the program controls: only while connected live. */
  setEnabled(enabled: boolean): void {
    this.lcd.setEnabled(enabled);
    this.programs.setEnabled(enabled);
    this.io.setEnabled(enabled);
  }

  /** Open (everything shows) or folded to its header, as one line of a long list. */
  setExpanded(expanded: boolean): void {
    this.element.classList.toggle("expanded", expanded);
    this.element.setAttribute("aria-expanded", String(expanded));
  }

  get expanded(): boolean {
    return this.element.classList.contains("expanded");
  }

  describeRobot(robot: RobotInfo): void {
    this.name.textContent = robot.name;
    this.robotName = robot.name;
    this.type.textContent = `#${robot.id} ${robot.type}`;
    this.element.setAttribute("aria-label", `robot ${robot.name}`);
  }

  showProgram(program: ProgramState | null): void {
    this.program = program && { event: program.event, name: program.name, exit_code: program.exit_code };
    const { text, kind } = describe(program);
    this.state.textContent = text;
    this.state.dataset.kind = kind;
    this.programs.setRunning(program?.event === "started");
  }

  /** Back to how the panel starts (the timeline jumped back): the frame then brings what was there. */
  clear(): void {
    this.lcd.clear();
    this.camera.clear();
    this.console.clear();
    this.showProgram(null);
  }

  appendConsole(message: ConsoleMessage): void {
    this.console.append(message.stream, message.text);
  }

  programState(): ProgramState | null {
    return this.program && { ...this.program };
  }
}
