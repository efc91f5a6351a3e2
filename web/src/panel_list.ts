// The robot panels, kept in step with the robots of the current scene.

import type { BrowserCommand, RobotInfo } from "./protocol";
import { RobotPanel } from "./robot_panel";

export class PanelList {
  private readonly panels = new Map<number, RobotPanel>();
  private enabled = false;

  constructor(
    private readonly container: HTMLElement,
    private readonly send: (command: BrowserCommand) => void,
  ) {}

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
        panel = new RobotPanel(robot, this.send);
        panel.lcd.setEnabled(this.enabled);
        this.panels.set(robot.id, panel);
      }
      this.container.append(panel.element); // in scene order
    }
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
    for (const panel of this.panels.values()) panel.lcd.setEnabled(enabled);
  }
}
