// The viewer: routes the simulator's messages to the 3D view, toolbar, timeline, plots and robot panels.

import { AudioPlayer } from "./audio_player";
import { ViewerConnection, type ConnectionState } from "./connection";
import { SnapshotBuffer } from "./interpolation";
import { Overlays } from "./overlays";
import { HelpOverlay } from "./help";
import { PanelList } from "./panel_list";
import { PlotPanel } from "./plot_panel";
import {
  parseServerMessage,
  type BrowserCommand,
  type FrameMessage,
  type SceneMessage,
  type ServerMessage,
  type StatusMessage,
} from "./protocol";
import type { PickTarget } from "./interaction";
import type { RobotPanel } from "./robot_panel";
import { SceneWarnings } from "./scene_warnings";
import { SettingsPanel } from "./settings_panel";
import { RecordingUpload } from "./recording_upload";
import { download, timedName } from "./snapshot_files";
import { TimelineBar, type TimelineState } from "./timeline_bar";
import { Toolbar } from "./toolbar";
import { VideoExport } from "./video_export";
import { WorldView } from "./world_view";
import type { ViewMode } from "./camera_modes";

export interface ViewerElements {
  toolbar: HTMLElement;
  timeline: HTMLElement;
  world: HTMLElement;
  plots: HTMLElement;
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
  readonly timeline: TimelineBar;
  readonly plots: PlotPanel;
  readonly video: VideoExport;
  readonly upload: RecordingUpload;
  readonly settings: SettingsPanel;
  private readonly toolbar: Toolbar;
  private readonly videoButton: HTMLButtonElement;
  /** Called with every command the page sends (the scene editor turns drags into edits). */
  readonly commandWatchers: ((command: BrowserCommand) => void)[] = [];
  /** Called with what a click in the 3D view picked (the scene editor selects it). */
  readonly pickWatchers: ((target: PickTarget) => void)[] = [];
  /** Called with every new scene. */
  readonly sceneWatchers: ((scene: SceneMessage) => void)[] = [];
  /** Called once, when the simulator has said whether this is a live run or a replay. */
  private readonly modeWatchers: ((mode: "live" | "replay") => void)[] = [];
  private mode: "live" | "replay" | null = null;
  /** Called with the connection's state: what needs the simulator is off while it is away. */
  readonly connectionWatchers: ((connected: boolean) => void)[] = [];
  /** Recording the 3D view of the live run (until Stop video), not a played timeline. */
  private liveVideo = false;
  private lastScene: SceneMessage | null = null;
  private lastStatus: StatusMessage | null = null;
  private ignored = 0;
  private replay = false;
  private frames = 0;
  private pathsWanted = false;

  constructor(elements: ViewerElements) {
    const send = (command: BrowserCommand) => {
      for (const watch of this.commandWatchers) watch(command);
      return this.connection.send(command);
    };
    this.toolbar = new Toolbar(elements.toolbar, send);
    this.panels = new PanelList(elements.panels, send);
    this.warnings = new SceneWarnings(elements.toolbar);
    this.world = new WorldView(
      elements.world,
      send,
      (target) => {
        for (const watch of this.pickWatchers) watch(target);
        // A click on a robot opens its panel; with the plots open, it plots the robot too.
        if (target.kind === "robot") this.panels.select(target.id);
        if (target.kind === "robot" && this.plots.visible) this.plots.pickRobot(target.id);
        if (target.kind === "psd") this.plots.pickPsd(target.robot, target.id);
      },
      () => this.overlays.drawnRays(),
    );
    this.help = new HelpOverlay(elements.world);
    const viewMode = elements.toolbar.querySelector<HTMLSelectElement>("#view-mode");
    viewMode?.addEventListener("change", () => this.world.setViewMode(viewMode.value as ViewMode, this.panels.selected));
    this.panels.onSelect((robot) => {
      this.world.highlightRobot(robot);
      this.world.followRobot(robot);
    });
    this.settings = new SettingsPanel(elements.world, elements.toolbar.querySelector("#settings-toggle")!);
    this.world.addOverlay(this.overlays.group);
    this.timeline = new TimelineBar(elements.timeline, send);
    this.timeline.onChange((state) => this.followTimeline(state));
    this.plots = new PlotPanel(elements.plots, send);
    this.video = new VideoExport((video) =>
      download(video, timedName(this.replay ? "replay" : "video", this.timeline.current.time, "webm")),
    );
    this.videoButton = elements.timeline.querySelector<HTMLButtonElement>("#tl-video")!;
    this.videoButton.hidden = !VideoExport.supported();
    this.videoButton.addEventListener("click", () => this.toggleVideo());
    this.upload = new RecordingUpload(elements.timeline);
    elements.toolbar.querySelector("#plots-toggle")?.addEventListener("click", () => this.plots.toggle());
    elements.toolbar.querySelector("#reset-view")?.addEventListener("click", () => {
      if (viewMode && viewMode.value === "follow") viewMode.value = "free";
      this.world.resetView();
    });
    this.plots.onSeek((time) => this.timeline.seek(time));
    elements.toolbar.querySelector("#shot-3d")?.addEventListener("click", () => {
      const png = this.world.screenshot();
      if (png) download(png, timedName("3d", this.timeline.current.time, "png"));
    });
    this.connection = new ViewerConnection({
      onMessage: (frame) => this.receive(frame),
      onState: (state) => this.showConnection(state),
    });
  }

  start(): void {
    this.connection.connect();
    let last = performance.now();
    const frame = (now: number) => {
      this.timeline.tick(now - last);
      last = now;
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

  /** `listener(mode)` once the simulator has said whether it is a live run or a replay (at once if known). */
  onMode(listener: (mode: "live" | "replay") => void): void {
    if (this.mode) listener(this.mode);
    else this.modeWatchers.push(listener);
  }

  get status(): StatusMessage | null {
    return this.lastStatus;
  }

  /** Messages dropped as malformed or of an unknown type. */
  get ignoredMessages(): number {
    return this.ignored;
  }

  /** Timeline frames shown so far. */
  get framesShown(): number {
    return this.frames;
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

  /** The running scene now has this file name (saved under a new one). */
  showSceneName(name: string): void {
    this.toolbar.showSceneName(name);
  }

  /** Looking at a recording or the past, rather than following a live run. */
  private get reviewing(): boolean {
    return this.timeline.current.mode !== "live";
  }

  private handle(message: ServerMessage): void {
    switch (message.type) {
      case "scene":
        this.lastScene = message;
        this.snapshots.clear();
        this.panels.showRobots(message.robots, message.new_scene);
        this.world.showScene(message);
        this.toolbar.showSceneName(message.name);
        this.showLabels();
        this.overlays.reset(message.settings);
        this.warnings.show(message.warnings);
        this.plots.reset();
        if (this.reviewing) this.requestPaths();
        for (const watch of this.sceneWatchers) watch(message);
        break;
      case "snapshot":
        this.snapshots.push(message, performance.now());
        if (this.overlays.update(message.robots, message.rays, message.time, !this.reviewing)) this.world.requestRender();
        for (const robot of message.robots) {
          if (robot.battery !== undefined) this.panels.find(robot.id)?.io.showBattery(robot.battery);
        }
        break;
      case "status":
        this.lastStatus = message;
        this.toolbar.showStatus(message);
        this.timeline.showStatus(message);
        break;
      case "timeline":
        this.timeline.showTimeline(message);
        this.replay = message.mode === "replay";
        this.knowMode(message.mode);
        this.upload.setAvailable(this.replay);
        this.toolbar.setReplay(this.replay, message.name);
        this.panels.setEnabled(!this.replay && this.connection.state === "open");
        this.plots.setLive(message.mode === "live");
        break;
      case "frame":
        this.showFrame(message);
        break;
      case "signals":
        this.plots.showSignals(message.signals);
        break;
      case "series":
        this.plots.showSeries(message.series);
        break;
      case "paths":
        this.overlays.loadPaths(message.robots);
        this.overlays.cutAt(this.reviewing ? this.timeline.current.time : Infinity);
        this.world.requestRender();
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
        this.showLabels();
        break;
      case "error":
        console.warn(`EyeSim viewer: the simulator rejected a command: ${message.message}`);
        break;
    }
  }

  /** Live or replay, known from the first `timeline` message: only then is the program list asked for
   * (a replay has none, and asking would be answered 404). */
  private knowMode(mode: "live" | "replay"): void {
    if (this.mode === mode) return;
    this.mode = mode;
    this.panels.catalogWanted = mode === "live";
    if (mode === "live") void this.panels.catalog.refresh();
    for (const watch of this.modeWatchers.splice(0)) watch(mode);
  }

  /** Each robot's label in the 3D view: its id and the program it runs (ran), else its name. */
  private showLabels(): void {
    for (const robot of this.lastScene?.robots ?? []) {
      const program = this.panels.find(robot.id)?.programState()?.name;
      this.world.setRobotLabel(robot.id, `${robot.id} · ${program ?? robot.name}`);
    }
  }

  /** The state at a time of the timeline: panels afresh where asked, then the messages as usual. */
  private showFrame(frame: FrameMessage): void {
    for (const robot of frame.clear) this.panels.find(robot)?.clear();
    for (const message of frame.messages) {
      if (message.type === "snapshot") this.snapshots.clear(); // show this moment now, not blended
      this.handle(message);
    }
    if (frame.clear.length) this.showLabels();
    this.frames++;
    this.timeline.frameArrived(frame);
    this.overlays.cutAt(this.reviewing ? this.timeline.current.time : Infinity);
    this.world.requestRender();
  }

  private followTimeline(state: TimelineState): void {
    const reviewing = state.mode !== "live";
    this.world.setReadOnly(state.mode === "replay" || state.mode === "review");
    this.plots.setTime(state.time);
    if (reviewing && !this.pathsWanted) this.requestPaths();
    if (!reviewing) this.pathsWanted = false;
    if (this.video.recording && !this.liveVideo && !state.playing) {
      this.video.stop();
      this.videoButton.textContent = "Record video";
    }
  }

  private requestPaths(): void {
    if (this.lastScene?.settings.trace) this.pathsWanted = this.connection.send({ type: "paths" });
  }

  /** Records the 3D view: live, as the simulation runs, until clicked again; else while the
   * timeline plays (from the start when at the end), until its end or a click. */
  private toggleVideo(): void {
    if (this.video.recording) {
      if (this.liveVideo) {
        this.liveVideo = false;
        this.video.stop();
        this.videoButton.textContent = "Record video";
      } else {
        this.timeline.setPlaying(false);
      }
      return;
    }
    const canvas = this.world.canvas;
    const state = this.timeline.current;
    if (!canvas) return;
    if (state.mode === "live") {
      if (this.video.start(canvas)) {
        this.liveVideo = true;
        this.videoButton.textContent = "Stop video";
      }
      return;
    }
    if (state.time >= state.end) this.timeline.seek(state.start);
    if (this.video.start(canvas)) {
      this.videoButton.textContent = "Stop video";
      this.timeline.setPlaying(true);
    }
  }

  private panelOf(robot: number): RobotPanel | null {
    const panel = this.panels.find(robot);
    if (!panel) console.warn(`EyeSim viewer: a message for robot ${robot}, which is not in the scene`);
    return panel;
  }

  private showConnection(state: ConnectionState): void {
    this.toolbar.showConnection(state);
    this.timeline.setEnabled(state === "open");
    this.panels.setEnabled(state === "open" && !this.replay);
    this.settings.setEnabled(state === "open");
    this.plots.setEnabled(state === "open");
    for (const watch of this.connectionWatchers) watch(state === "open");
  }
}
