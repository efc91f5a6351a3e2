// The robot panels, kept in step with the robots of the current scene. As many panels are open as
// there are columns for them beside the 3D view (one below 1830 px; a wide screen shows two or
// three robots side by side); the others are folded to one line each.

import { ProgramCatalog } from "./program_controls";
import type { BrowserCommand, RobotInfo } from "./protocol";
import { RobotPanel } from "./robot_panel";

/** An open panel's width (CSS px): the 480 px LCD, its bezel, the panel's padding and border. */
export const PANEL_WIDTH = 510;
const PANEL_GAP = 10;
/** The 3D view keeps at least this much of the window's width before panels take another column. */
const MIN_WORLD_WIDTH = 800;
const MAX_COLUMNS = 3;

export class PanelList {
  private readonly panels = new Map<number, RobotPanel>();
  private enabled = false;
  private selectedRobot: number | null = null;
  /** the open panels, the most recently opened last */
  private open: number[] = [];
  private columnCount = 1;
  readonly catalog = new ProgramCatalog();
  /** Whether the program list is asked for (a live run; a replay has none): set once the mode is known. */
  catalogWanted = false;
  private readonly selectListeners = new Set<(robot: number) => void>();

  constructor(
    private readonly container: HTMLElement,
    private readonly send: (command: BrowserCommand) => void,
  ) {
    window.addEventListener("resize", () => this.layOut());
    this.layOut();
  }

  /** The robot whose panel was opened last (its label stands out, the camera follows it). */
  get selected(): number | null {
    return this.selectedRobot;
  }

  /** How many panels are open side by side. */
  get columns(): number {
    return this.columnCount;
  }

  onSelect(listener: (robot: number) => void): void {
    this.selectListeners.add(listener);
  }

  /** Opens the robot's panel (folding the one opened longest ago when all columns are taken) and
   * scrolls it into view. */
  select(robot: number): void {
    const panel = this.panels.get(robot);
    if (!panel) return;
    this.selectedRobot = robot;
    this.open = [...this.open.filter((id) => id !== robot), robot].slice(-this.columnCount);
    this.showOpen();
    panel.element.scrollIntoView({ block: "nearest" });
    for (const listener of this.selectListeners) listener(robot);
  }

  /**
   * A robot that stays (same id) keeps its panel, so its LCD and console survive a reset; robots
   * that left lose theirs. `newScene`: another scene replaced the running one, every panel starts
   * afresh (no status, console, images or program choice of the old scene's robot with that id).
   */
  showRobots(robots: RobotInfo[], newScene = false): void {
    const ids = new Set(robots.map((r) => r.id));
    if (newScene) this.catalog.forgetRobots();
    for (const [id, panel] of this.panels) {
      if (!ids.has(id) || newScene) {
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
        panel.setEnabled(this.enabled);
        this.panels.set(robot.id, panel);
      }
      this.container.append(panel.element); // in scene order
    }
    this.open = this.open.filter((id) => ids.has(id));
    const keep = this.selectedRobot !== null && ids.has(this.selectedRobot);
    this.layOut();
    if (robots.length) this.select(keep ? this.selectedRobot! : robots[0].id);
    else this.selectedRobot = null;
    if (this.catalogWanted) void this.catalog.refresh();
  }

  /** The panel for a robot, or null when the scene has no such robot. */
  find(robot: number): RobotPanel | null {
    return this.panels.get(robot) ?? null;
  }

  ids(): number[] {
    return [...this.panels.keys()];
  }

  /** Keys, touches, remote and program controls only work while connected to a live run. */
  setEnabled(enabled: boolean): void {
    this.enabled = enabled;
    for (const panel of this.panels.values()) panel.setEnabled(enabled);
  }

  /** Columns for the window's width: each takes an open panel; as many open as fit (and robots). */
  private layOut(): void {
    const room = Math.floor((window.innerWidth - MIN_WORLD_WIDTH + PANEL_GAP) / (PANEL_WIDTH + PANEL_GAP));
    const columns = Math.max(1, Math.min(MAX_COLUMNS, room, this.panels.size || 1));
    this.columnCount = columns;
    this.container.style.setProperty("--panel-columns", String(columns));
    this.container.classList.toggle("multi", columns > 1);
    // More columns than open panels: open the next ones in scene order; fewer: fold the oldest.
    for (const id of this.panels.keys()) {
      if (this.open.length >= columns) break;
      if (!this.open.includes(id)) this.open.unshift(id);
    }
    if (this.selectedRobot !== null && this.open.includes(this.selectedRobot)) {
      this.open = [...this.open.filter((id) => id !== this.selectedRobot), this.selectedRobot];
    }
    this.open = this.open.slice(-columns);
    this.showOpen();
  }

  private showOpen(): void {
    for (const [id, panel] of this.panels) {
      panel.setExpanded(this.open.includes(id));
      panel.element.classList.toggle("selected", id === this.selectedRobot);
    }
  }
}
