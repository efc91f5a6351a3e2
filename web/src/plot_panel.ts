// Plots of recorded or live signals (pose, odometry, speeds, encoders, battery, PSD readings) against
// simulation time, drawn with uPlot; a line marks the timeline's time. Signals come from the server
// (`signals`, `series`); pick them from the list or by clicking a robot or a PSD beam in the 3D view.

import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import { element } from "./dom";
import type { BrowserCommand, Series, SignalInfo } from "./protocol";

const COLORS = ["#1e63c8", "#e53935", "#2e9e44", "#f39c12", "#8e44ad", "#16a085", "#d35400", "#2c3e50"];
/** While following a live run the plotted series are fetched again this often (ms). */
const LIVE_REFRESH_MS = 1000;
const CURSOR_COLOR = "#c0392b";

export class PlotPanel {
  private readonly list = element("div", "plot-signals");
  private readonly chartBox = element("div", "plot-chart");
  private readonly hint = element("p", "plot-hint", "Pick signals below, or click a robot or a PSD beam in the 3D view.");
  /** why a click in the 3D view added nothing */
  private readonly notice = element("span", "plot-notice");
  private signals: SignalInfo[] = [];
  private readonly selected = new Set<string>();
  private plot: uPlot | null = null;
  private plotted: Series[] = [];
  private time = 0;
  private refresh: number | null = null;
  private requested = false;

  constructor(
    private readonly root: HTMLElement,
    private readonly send: (command: BrowserCommand) => boolean,
  ) {
    const header = element("header", "plot-header");
    const clear = element("button", "plot-clear", "Clear");
    clear.type = "button";
    clear.addEventListener("click", () => {
      this.selected.clear();
      this.showList();
      this.fetch();
    });
    header.append(element("h2", "plot-title", "Plots"), clear, this.notice);
    this.chartBox.append(this.hint);
    root.append(header, this.chartBox, this.list);
    new ResizeObserver(() => this.resize()).observe(this.chartBox);
  }

  get visible(): boolean {
    return !this.root.hidden;
  }

  /** Opens or closes the panel; opening asks for the signals there are. */
  toggle(open = !this.visible): void {
    this.root.hidden = !open;
    if (open && !this.requested) this.requested = this.send({ type: "signals" });
    if (open) this.resize();
  }

  /** Keeps fetching the series while a live run goes on (false: a recording, nothing changes). */
  setLive(live: boolean): void {
    if (live && this.refresh === null) {
      this.refresh = window.setInterval(() => this.visible && this.selected.size && this.fetch(), LIVE_REFRESH_MS);
    } else if (!live && this.refresh !== null) {
      window.clearInterval(this.refresh);
      this.refresh = null;
    }
  }

  /** A new scene or connection: the signals may have changed. */
  reset(): void {
    this.requested = false;
    if (this.visible) this.requested = this.send({ type: "signals" });
  }

  showSignals(signals: SignalInfo[]): void {
    this.signals = signals;
    for (const id of [...this.selected]) if (!signals.some((s) => s.id === id)) this.selected.delete(id);
    this.showList();
    this.fetch();
  }

  /** Adds signals (by id) to the plot and opens the panel; ids the source lacks are dropped once its list is in. */
  select(ids: string[]): void {
    this.notice.textContent = "";
    for (const id of ids) if (this.signals.length === 0 || this.signals.some((s) => s.id === id)) this.selected.add(id);
    this.toggle(true);
    this.showList();
    this.fetch();
  }

  /** A robot was clicked: plot its x and y (and its PSDs when it has any). */
  pickRobot(robot: number): void {
    const names = ["x", "y", "psd.1"];
    this.select(names.map((n) => `robot/${robot}/${n}`));
  }

  /** A PSD beam was clicked: plot that PSD's readings, which there are only if the program read it. */
  pickPsd(robot: number, psd: number): void {
    const id = `robot/${robot}/psd.${psd}`;
    this.select([id]);
    if (this.signals.length > 0 && !this.selected.has(id)) {
      this.notice.textContent = `Robot ${robot}'s PSD ${psd} has no readings: its program has not read it.`;
    }
  }

  /** What the note beside the title says now (for tests). */
  noticeText(): string {
    return this.notice.textContent ?? "";
  }

  showSeries(series: Series[]): void {
    this.plotted = series.filter((s) => this.selected.has(s.id));
    this.draw();
  }

  /** The timeline's time: where the cursor line stands. */
  setTime(time: number): void {
    this.time = time;
    this.plot?.redraw(false, false);
  }

  /** What is plotted: ids and how many points each has (for tests). */
  plottedSeries(): { id: string; points: number }[] {
    return this.plotted.map((s) => ({ id: s.id, points: s.times.length }));
  }

  private fetch(): void {
    if (this.signals.length === 0) return; // showSignals fetches once the list is in
    if (this.selected.size === 0) {
      this.showSeries([]);
      return;
    }
    this.send({ type: "series", ids: [...this.selected] });
  }

  private showList(): void {
    this.list.replaceChildren();
    const byRobot = new Map<number, SignalInfo[]>();
    for (const signal of this.signals) byRobot.set(signal.robot, [...(byRobot.get(signal.robot) ?? []), signal]);
    for (const [robot, signals] of byRobot) {
      const group = element("fieldset", "plot-group");
      group.append(element("legend", "", `robot ${robot}`));
      for (const signal of signals) {
        const label = element("label", "plot-signal");
        const box = element("input");
        box.type = "checkbox";
        box.checked = this.selected.has(signal.id);
        box.dataset.signal = signal.id;
        box.addEventListener("change", () => {
          if (box.checked) this.selected.add(signal.id);
          else this.selected.delete(signal.id);
          this.hint.hidden = this.selected.size > 0;
          this.fetch();
        });
        label.append(box, `${signal.name} (${signal.unit})`);
        group.append(label);
      }
      this.list.append(group);
    }
    this.hint.hidden = this.selected.size > 0;
  }

  private draw(): void {
    this.plot?.destroy();
    this.plot = null;
    if (this.plotted.length === 0 || this.root.hidden) return;
    // uPlot wants one time axis: the union of the series' times, with gaps where one has no sample.
    const times = [...new Set(this.plotted.flatMap((s) => s.times))].sort((a, b) => a - b);
    const index = new Map(times.map((t, i) => [t, i]));
    const columns = this.plotted.map((s) => {
      const column: (number | null)[] = new Array(times.length).fill(null);
      s.times.forEach((t, i) => (column[index.get(t)!] = s.values[i]));
      return column;
    });
    const info = (id: string) => this.signals.find((s) => s.id === id);
    const units = [...new Set(this.plotted.map((s) => info(s.id)?.unit ?? ""))];
    const options: uPlot.Options = {
      width: Math.max(200, this.chartBox.clientWidth),
      height: Math.max(120, this.chartBox.clientHeight),
      scales: { x: { time: false } },
      axes: [
        { label: "t (s)" },
        ...units.map((unit, i) => ({ scale: unit, label: unit, side: i % 2 ? 1 : 3, grid: { show: i === 0 } })),
      ],
      series: [
        { label: "t (s)" },
        ...this.plotted.map((s, i) => ({
          label: info(s.id)?.label ?? s.id,
          scale: info(s.id)?.unit ?? "",
          stroke: COLORS[i % COLORS.length],
          spanGaps: true,
          points: { show: false },
        })),
      ],
      hooks: { draw: [(u: uPlot) => this.drawCursor(u)] },
    };
    this.plot = new uPlot(options, [times, ...columns] as uPlot.AlignedData, this.chartBox);
  }

  private drawCursor(u: uPlot): void {
    const x = u.valToPos(this.time, "x", true);
    if (!Number.isFinite(x)) return;
    const { top, height } = u.bbox;
    const context = u.ctx;
    context.save();
    context.strokeStyle = CURSOR_COLOR;
    context.lineWidth = 2;
    context.beginPath();
    context.moveTo(x, top);
    context.lineTo(x, top + height);
    context.stroke();
    context.restore();
  }

  private resize(): void {
    if (!this.plot || this.root.hidden) return;
    this.plot.setSize({ width: Math.max(200, this.chartBox.clientWidth), height: Math.max(120, this.chartBox.clientHeight) });
  }
}
