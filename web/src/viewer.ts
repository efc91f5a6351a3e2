// The viewer: routes the simulator's messages to the 3D view, toolbar and robot panels.

import { AudioPlayer } from "./audio_player";
import { ViewerConnection, type ConnectionState } from "./connection";
import { SnapshotBuffer } from "./interpolation";
import { Overlays } from "./overlays";
import { HelpOverlay } from "./help";
import { PanelList } from "./panel_list";
import {
  parseServerMessage,
  type BrowserCommand,
  type SceneMessage,
  type ServerMessage,
  type StatusMessage,
} from "./protocol";
import type { RobotPanel } from "./robot_panel";
import { SceneWarnings } from "./scene_warnings";
import { Toolbar } from "./toolbar";
import { WorldView } from "./world_view";

export interface ViewerElements {
  toolbar: HTMLElement;
  world: HTMLElement;
  panels: HTMLElement;
}

export class Viewer {
  readonly connection: ViewerConnection;
  readonly world: WorldView;
  readonly panels: PanelList;
  readonly snapshots = new SnapshotBuffer();
  readonly overlays = new Overlays();
  readonly audio = new AudioPlayer();
  readonly warnings: SceneWarnings;
  readonly help: HelpOverlay;
  private readonly toolbar: Toolbar;
  private lastScene: SceneMessage | null = null;
  private lastStatus: StatusMessage | null = null;
  private ignored = 0;

  constructor(elements: ViewerElements) {
    const send = (command: BrowserCommand) => this.connection.send(command);
    this.toolbar = new Toolbar(elements.toolbar, send);
    this.panels = new PanelList(elements.panels, send);
    this.warnings = new SceneWarnings(elements.toolbar);
    this.world = new WorldView(elements.world, send);
    this.help = new HelpOverlay(elements.world);
    this.world.addOverlay(this.overlays.group);
    this.connection = new ViewerConnection({
      onMessage: (frame) => this.receive(frame),
      onState: (state) => this.showConnection(state),
    });
  }

  start(): void {
    this.connection.connect();
    const frame = () => {
      const poses = this.snapshots.posesAt(performance.now());
      if (poses) this.world.applyPoses(poses);
      this.world.render();
      requestAnimationFrame(frame);
    };
    requestAnimationFrame(frame);
  }

  get scene(): SceneMessage | null {
    return this.lastScene;
  }

  get status(): StatusMessage | null {
    return this.lastStatus;
  }

  /** Messages dropped as malformed or of an unknown type. */
  get ignoredMessages(): number {
    return this.ignored;
  }

  private receive(frame: unknown): void {
    const message = parseServerMessage(frame);
    if (!message) {
      this.ignored++;
      return;
    }
    try {
      this.handle(message);
    } catch (error) {
      // A bug in one handler must not stop the messages after it.
      console.error(`EyeSim viewer: failed to handle a ${message.type} message`, error, message);
    }
  }

  private handle(message: ServerMessage): void {
    switch (message.type) {
      case "scene":
        this.lastScene = message;
        this.snapshots.clear();
        this.panels.showRobots(message.robots);
        this.world.showScene(message);
        this.overlays.reset(message.settings);
        this.warnings.show(message.warnings);
        break;
      case "snapshot":
        this.snapshots.push(message, performance.now());
        if (this.overlays.update(message.robots, message.rays)) this.world.requestRender();
        for (const robot of message.robots) {
          if (robot.battery !== undefined) this.panels.find(robot.id)?.io.showBattery(robot.battery);
        }
        break;
      case "status":
        this.lastStatus = message;
        this.toolbar.showStatus(message);
        break;
      case "lcd":
        this.panelOf(message.robot)?.lcd.showImage(message.png);
        break;
      case "menu":
        this.panelOf(message.robot)?.lcd.showMenu(message);
        break;
      case "audio":
        this.audio.play(message);
        break;
      case "serial":
        this.panelOf(message.robot)?.io.appendSerial(message);
        break;
      case "camera":
        this.panelOf(message.robot)?.camera.show(message);
        break;
      case "io":
        this.panelOf(message.robot)?.io.showIo(message);
        break;
      case "console":
        this.panelOf(message.robot)?.appendConsole(message);
        break;
      case "program":
        this.panelOf(message.robot)?.showProgram(message);
        break;
      case "error":
        console.warn(`EyeSim viewer: the simulator rejected a command: ${message.message}`);
        break;
    }
  }

  private panelOf(robot: number): RobotPanel | null {
    const panel = this.panels.find(robot);
    if (!panel) console.warn(`EyeSim viewer: a message for robot ${robot}, which is not in the scene`);
    return panel;
  }

  private showConnection(state: ConnectionState): void {
    this.toolbar.showConnection(state);
    this.panels.setEnabled(state === "open");
  }
}
