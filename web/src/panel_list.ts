// The robot panels, kept in step with the robots of the current scene.

import { ProgramCatalog } from "./program_controls";
import type { BrowserCommand, RobotInfo } from "./protocol";
import { RobotPanel } from "./robot_panel";

export class PanelList {
  private readonly panels = new Map<number, RobotPanel>();
  private enabled = false;
  private selectedRobot: number | null = null;
  readonly catalog = new ProgramCatalog();
  private readonly selectListeners = new Set<(robot: number) => void>();

  constructor(
    private readonly container: HTMLElement,
    private readonly send: (command: BrowserCommand) => void,
  ) {}

  /** The robot whose panel is open (one at a time; the others show one line each). */
  get selected(): number | null {
    return this.selectedRobot;
  }

  onSelect(listener: (robot: number) => void): void {
    this.selectListeners.add(listener);
  }

  /** Opens the robot's panel, folds the others and scrolls it into view. */
  select(robot: number): void {
    const panel = this.panels.get(robot);
    if (!panel) return;
    this.selectedRobot = robot;
    for (const [id, other] of this.panels) other.setExpanded(id === robot);
    panel.element.scrollIntoView({ block: "nearest" });
    for (const listener of this.selectListeners) listener(robot);
  }

  /**
   * A robot that stays (same id) keeps its panel, so its LCD and console survive a reset;
   * robots that left lose theirs.
   */
  showRobots(robots: RobotInfo[]): void {
    const ids = new Set(robots.map((r) => r.id));
    for (const [id, panel] of this.panels) {
      if (!ids.has(id)) {
        panel.element.remove();
        this.panels.delete(id);
      }
    }
    for (const robot of robots) {
      let panel = this.panels.get(robot.id);
      if (panel) {
        panel.describeRobot(robot);
      } else {
        panel = new RobotPanel(robot, this.send, this.catalog, (id) => this.select(id));
        panel.lcd.setEnabled(this.enabled);
        panel.programs.setEnabled(this.enabled);
        this.panels.set(robot.id, panel);
      }
      this.container.append(panel.element); // in scene order
    }
    const keep = this.selectedRobot !== null && ids.has(this.selectedRobot);
    if (robots.length) this.select(keep ? this.selectedRobot! : robots[0].id);
    else this.selectedRobot = null;
    void this.catalog.refresh();
  }

  /** The panel for a robot, or null when the scene has no such robot. */
  find(robot: number): RobotPanel | null {
    return this.panels.get(robot) ?? null;
  }

  ids(): number[] {
    return [...this.panels.keys()];
  }

  /** Keys only work while connected; disabling them shows that a press would go nowhere. */
  setEnabled(enabled: boolean): void {
    this.enabled = enabled;
    for (const panel of this.panels.values()) {
      panel.lcd.setEnabled(enabled);
      panel.programs.setEnabled(enabled);
    }
  }
}
