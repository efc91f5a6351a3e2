// The timeline: play, pause, step and scrub through a recording, or back over the live run's recent
// history (the server keeps it); the state at the chosen time arrives as a `frame`. Live, Step ›
// runs the simulation itself on by one physics step (Shift: 10 ms) and pauses it.

import type { BrowserCommand, FrameMessage, StatusMessage, TimelineMessage } from "./protocol";

/** live: following the simulation; review: looking back over its history; replay: a recording. */
export type TimelineMode = "live" | "review" | "replay";

export interface TimelineState {
  mode: TimelineMode;
  time: number;
  start: number;
  end: number;
  playing: boolean;
  speed: number;
}

function find<T extends HTMLElement>(root: HTMLElement, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`EyeSim viewer: the page has no ${selector}`);
  return found;
}

/** The step buttons move by this (s); with Shift by STEP_LONG. */
const STEP = 0.05;
const STEP_LONG = 1;
/** Live, Step › with Shift runs the simulation on by this (s); without, one physics step. */
const LIVE_STEP_LONG = 0.01;
const SLIDER_STEPS = 10000;

export class TimelineBar {
  private readonly root: HTMLElement;
  private readonly play: HTMLButtonElement;
  private readonly back: HTMLButtonElement;
  private readonly forward: HTMLButtonElement;
  private readonly speedSelect: HTMLSelectElement;
  private readonly slider: HTMLInputElement;
  private readonly label: HTMLElement;
  private readonly live: HTMLButtonElement;
  private readonly title: HTMLElement;
  private state: TimelineState = { mode: "live", time: 0, start: 0, end: 0, playing: false, speed: 1 };
  /** a seek is on its way: the next one waits for its frame, so a slow link is not flooded */
  private awaiting = false;
  private wanted: number | null = null;
  private dragging = false;
  private readonly listeners: ((state: TimelineState) => void)[] = [];

  constructor(
    root: HTMLElement,
    private readonly send: (command: BrowserCommand) => boolean,
  ) {
    this.root = root;
    this.play = find(root, "#tl-play");
    this.back = find(root, "#tl-back");
    this.forward = find(root, "#tl-forward");
    this.speedSelect = find(root, "#tl-speed");
    this.slider = find(root, "#tl-scrub");
    this.label = find(root, "#tl-time");
    this.live = find(root, "#tl-live");
    this.title = find(root, "#tl-title");
    this.slider.max = String(SLIDER_STEPS);

    this.play.addEventListener("click", () => this.togglePlay());
    this.back.addEventListener("click", (event) => this.step(event.shiftKey ? -STEP_LONG : -STEP));
    this.forward.addEventListener("click", (event) => this.stepForward(event.shiftKey));
    this.speedSelect.addEventListener("change", () => (this.state.speed = Number(this.speedSelect.value) || 1));
    this.slider.addEventListener("input", () => {
      this.dragging = true;
      this.state.playing = false;
      this.seek(this.sliderTime());
    });
    this.slider.addEventListener("change", () => (this.dragging = false));
    this.live.addEventListener("click", () => this.goLive());
    this.show();
  }

  get current(): TimelineState {
    return { ...this.state };
  }

  /** Called with the new state whenever the shown time or mode changes. */
  onChange(listener: (state: TimelineState) => void): void {
    this.listeners.push(listener);
  }

  /** The server says what the timeline covers (on connect). */
  showTimeline(message: TimelineMessage): void {
    if (message.mode === "replay") {
      this.state = { ...this.state, mode: "replay", start: message.start ?? 0, end: message.end ?? 0, time: message.start ?? 0 };
      this.title.textContent = message.name ? `replay of ${message.name}` : "replay";
    } else {
      this.state = { ...this.state, mode: "live", playing: false };
      this.title.textContent = "live";
    }
    this.awaiting = false;
    this.wanted = null;
    this.show();
  }

  /** A live run's status: the history's range grows; while live, the cursor follows the present. */
  showStatus(status: StatusMessage): void {
    if (this.state.mode === "replay") return;
    this.state.end = status.time;
    this.state.start = status.history_start ?? this.state.start;
    if (this.state.mode === "live") this.state.time = status.time;
    this.show();
  }

  /** A frame arrived: the next seek may go. */
  frameArrived(frame: FrameMessage): void {
    this.awaiting = false;
    if (frame.start !== undefined && this.state.mode === "replay") this.state.start = frame.start;
    if (frame.end !== undefined && this.state.mode === "replay") this.state.end = frame.end;
    if (this.wanted !== null) {
      const next = this.wanted;
      this.wanted = null;
      this.request(next);
    }
  }

  /** Shows `time` (seconds): asks the server for the frame; a live viewer starts looking back. */
  seek(time: number): void {
    const clamped = Math.min(this.state.end, Math.max(this.state.start, time));
    if (this.state.mode === "live") this.state.mode = "review";
    this.state.time = clamped;
    this.request(clamped);
    this.show();
  }

  /** Advances playback by `elapsedMs` of wall time (called every animation frame). */
  tick(elapsedMs: number): void {
    if (!this.state.playing || this.dragging) return;
    const next = this.state.time + (elapsedMs / 1000) * this.state.speed;
    if (next >= this.state.end) {
      if (this.state.mode === "review") {
        this.goLive();
        return;
      }
      this.state.playing = false;
      this.seek(this.state.end);
      return;
    }
    this.seek(next);
  }

  setPlaying(playing: boolean): void {
    if (this.state.mode === "live") return;
    if (playing && this.state.time >= this.state.end) this.seek(this.state.start);
    this.state.playing = playing;
    this.show();
  }

  setEnabled(enabled: boolean): void {
    for (const control of [this.play, this.back, this.forward, this.speedSelect, this.slider, this.live]) {
      control.disabled = !enabled;
    }
  }

  private togglePlay(): void {
    if (this.state.mode === "live") {
      this.seek(this.state.end);
      return;
    }
    this.setPlaying(!this.state.playing);
  }

  /** Live: one physics step of the simulation (Shift: 10 ms), which then pauses; else 0.05 s (1 s) on. */
  private stepForward(long: boolean): void {
    if (this.state.mode !== "live") {
      this.step(long ? STEP_LONG : STEP);
      return;
    }
    this.send(long ? { type: "step", seconds: LIVE_STEP_LONG } : { type: "step" });
  }

  private step(seconds: number): void {
    this.state.playing = false;
    this.seek(this.state.time + seconds);
  }

  private goLive(): void {
    if (this.state.mode === "replay") return;
    this.state.mode = "live";
    this.state.playing = false;
    this.wanted = null;
    this.send({ type: "live" });
    this.show();
  }

  private request(time: number): void {
    if (this.awaiting) {
      this.wanted = time;
      return;
    }
    this.awaiting = this.send({ type: "seek", time });
  }

  private sliderTime(): number {
    const span = this.state.end - this.state.start;
    return this.state.start + (Number(this.slider.value) / SLIDER_STEPS) * span;
  }

  private show(): void {
    const { mode, time, start, end, playing } = this.state;
    this.root.dataset.mode = mode;
    this.play.textContent = mode === "live" ? "Look back" : playing ? "Pause" : "Play";
    this.live.hidden = mode === "replay";
    this.live.classList.toggle("active", mode === "live");
    this.forward.title = mode === "live"
      ? "Run the simulation one physics step on, then pause it (Shift: 10 ms)"
      : "Step forward 0.05 s (Shift: 1 s)";
    this.back.title = mode === "live" ? "Look back 0.05 s (Shift: 1 s)" : "Step back 0.05 s (Shift: 1 s)";
    const span = end - start;
    if (!this.dragging) this.slider.value = String(span > 0 ? Math.round(((time - start) / span) * SLIDER_STEPS) : 0);
    this.label.textContent = `${time.toFixed(2)} s / ${end.toFixed(2)} s`;
    for (const listener of this.listeners) listener(this.current);
  }
}
