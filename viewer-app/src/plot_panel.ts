// Plots of recorded or live signals (pose, odometry, speeds, encoders, battery, PSD readings) against
// simulation time, drawn with uPlot; a line marks the timeline's time. Signals come from the server
// (`signals`, `series`); pick them from the list or by clicking a robot or a PSD beam in the 3D view.
// The legend sits above the chart (never clipped); hovering reads out the time and every signal's
// value there; a click moves the timeline to that time; the plot exports as PNG and CSV. Readings a
// program took now and then (PSDs) and other sparse signals are drawn as steps: a value holds until
// the next one, rather than a slope that was never measured.

import uPlot from "uplot";
import "uplot/dist/uPlot.min.css";
import { element } from "./dom";
import type { BrowserCommand, Series, SignalInfo } from "./protocol";
import { download, timedName } from "./snapshot_files";

const COLORS = ["#1e63c8", "#e53935", "#2e9e44", "#f39c12", "#8e44ad", "#16a085", "#d35400", "#2c3e50"];
/** While following a live run the plotted series are fetched again this often (ms). */
const LIVE_REFRESH_MS = 1000;
const CURSOR_COLOR = "#c0392b";
/** A series whose samples are further apart than this (s, median) is drawn as steps. */
const SPARSE_INTERVAL = 0.1;
/** A press and release this close (CSS px) is a click (it moves the timeline), not a zoom drag. */
const CLICK_SLOP = 4;

/** The value a series has at time t: its last sample at or before t (null before its first). */
function valueAt(series: Series, t: number): number | null {
  const { times, values } = series;
  let low = 0;
  let high = times.length - 1;
  if (high < 0 || times[0] > t) return null;
  while (low < high) {
    const middle = (low + high + 1) >> 1;
    if (times[middle] <= t) low = middle;
    else high = middle - 1;
  }
  return values[low];
}

function median(numbers: number[]): number {
  if (numbers.length === 0) return 0;
  const sorted = [...numbers].sort((a, b) => a - b);
  return sorted[sorted.length >> 1];
}

function formatValue(value: number): string {
  const size = Math.abs(value);
  return size >= 1000 || size === 0 ? value.toFixed(0) : size >= 10 ? value.toFixed(1) : value.toFixed(3);
}

export class PlotPanel {
  private readonly list = element("div", "plot-signals");
  private readonly chartBox = element("div", "plot-chart");
  private readonly legend = element("div", "plot-legend");
  private readonly readout = element("div", "plot-readout");
  private readonly hint = element("p", "plot-hint", "Pick signals on the right, or click a robot or a PSD beam in the 3D view.");
  /** why a click in the 3D view added nothing */
  private readonly notice = element("span", "plot-notice");
  private readonly pngButton = element("button", "plot-png", "PNG");
  private readonly csvButton = element("button", "plot-csv", "CSV");
  private signals: SignalInfo[] = [];
  private readonly selected = new Set<string>();
  private plot: uPlot | null = null;
  private plotted: Series[] = [];
  private time = 0;
  private refresh: number | null = null;
  private requested = false;
  private readonly seekListeners: ((time: number) => void)[] = [];
  private pressedAt: { x: number; y: number } | null = null;
  /** what the chart draws (signals and how), to know when new data can go into the same chart */
  private shape = "";

  constructor(
    private readonly root: HTMLElement,
    private readonly send: (command: BrowserCommand) => boolean,
  ) {
    const header = element("header", "plot-header");
    const clear = element("button", "plot-clear", "Clear");
    clear.type = this.pngButton.type = this.csvButton.type = "button";
    clear.title = "Remove every signal from the plot";
    this.pngButton.title = "Download the plot as a PNG image";
    this.csvButton.title = "Download the plotted values as CSV (time, then one column per signal)";
    clear.addEventListener("click", () => {
      this.selected.clear();
      this.showList();
      this.fetch();
    });
    this.pngButton.addEventListener("click", () => {
      const png = this.png();
      if (png) download(png, timedName("plot", this.time, "png"));
    });
    this.csvButton.addEventListener("click", () => {
      download(new Blob([this.csv()], { type: "text/csv" }), timedName("plot", this.time, "csv"));
    });
    header.append(element("h2", "plot-title", "Plots"), clear, this.pngButton, this.csvButton, this.notice);
    const main = element("div", "plot-main");
    this.readout.setAttribute("aria-live", "off");
    main.append(this.legend, this.chartBox, this.readout);
    this.chartBox.append(this.hint);
    root.append(header, main, this.list);
    new ResizeObserver(() => this.resize()).observe(this.chartBox);
    this.showButtons();
  }

  get visible(): boolean {
    return !this.root.hidden;
  }

  /** `listener(time)` when a click on the chart asks to show that time. */
  onSeek(listener: (time: number) => void): void {
    this.seekListeners.push(listener);
  }

  /** Opens or closes the panel; opening asks for the signals there are. */
  toggle(open = !this.visible): void {
    this.root.hidden = !open;
    if (open && !this.requested) this.requested = this.send({ type: "signals" });
    if (open) this.resize();
  }

  /** The list's boxes ask the simulator for series: off while it is away. */
  setEnabled(enabled: boolean): void {
    for (const box of this.list.querySelectorAll("input")) box.disabled = !enabled;
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

  /** The legend's entries, the hover readout, and the ids of the series drawn as steps (for tests). */
  shown(): { legend: string[]; readout: string; stepped: string[] } {
    const legend = [...this.legend.querySelectorAll(".u-series")]
      .map((entry) => entry.querySelector(".u-label")?.textContent ?? "")
      .filter((label) => label !== "t (s)");
    const stepped = this.plotted.filter((s) => this.stepped(s)).map((s) => s.id);
    const readout = [...this.readout.children].map((part) => part.textContent ?? "").join("   ");
    return { legend, readout, stepped };
  }

  /** Where a time is on the page, in CSS pixels: (x, y of the chart's middle); null with no chart. */
  pagePosition(time: number): { x: number; y: number } | null {
    if (!this.plot) return null;
    const over = this.plot.over.getBoundingClientRect();
    return { x: over.left + this.plot.valToPos(time, "x"), y: over.top + over.height / 2 };
  }

  /** The plotted values as CSV: a time column, then one column per signal (its label and unit),
   * a row for every time any of them has a sample; empty where a signal has none. */
  csv(): string {
    const times = [...new Set(this.plotted.flatMap((s) => s.times))].sort((a, b) => a - b);
    const quote = (text: string) => (/[",\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text);
    const header = ["t (s)", ...this.plotted.map((s) => {
      const info = this.info(s.id);
      return `${info?.label ?? s.id} (${info?.unit ?? ""})`;
    })];
    const indices = this.plotted.map((s) => new Map(s.times.map((t, i) => [t, s.values[i]])));
    const rows = times.map((t) => [String(t), ...indices.map((index) => (index.has(t) ? String(index.get(t)) : ""))]);
    return [header.map(quote), ...rows].map((row) => row.join(",")).join("\n") + "\n";
  }

  /** The chart with its legend as a PNG data URL, or null with nothing plotted. */
  png(): string | null {
    if (!this.plot) return null;
    const chart = this.plot.ctx.canvas;
    const ratio = chart.width / Math.max(1, this.plot.width);
    const legendHeight = Math.round(24 * ratio);
    const canvas = document.createElement("canvas");
    canvas.width = chart.width;
    canvas.height = chart.height + legendHeight;
    const context = canvas.getContext("2d");
    if (!context) return null;
    context.fillStyle = "#ffffff";
    context.fillRect(0, 0, canvas.width, canvas.height);
    context.font = `${Math.round(13 * ratio)}px system-ui, sans-serif`;
    context.textBaseline = "middle";
    let x = 8 * ratio;
    this.plotted.forEach((s, i) => {
      context.fillStyle = COLORS[i % COLORS.length];
      context.fillRect(x, legendHeight / 2 - 2 * ratio, 14 * ratio, 4 * ratio);
      x += 18 * ratio;
      context.fillStyle = "#1f2933";
      const label = `${this.info(s.id)?.label ?? s.id} (${this.info(s.id)?.unit ?? ""})`;
      context.fillText(label, x, legendHeight / 2);
      x += context.measureText(label).width + 16 * ratio;
    });
    context.drawImage(chart, 0, legendHeight);
    return canvas.toDataURL("image/png");
  }

  private info(id: string): SignalInfo | undefined {
    return this.signals.find((s) => s.id === id);
  }

  /** Readings taken now and then (a PSD read by the program) or samples far apart: steps. */
  private stepped(series: Series): boolean {
    if (/\/psd\.\d+$/.test(series.id)) return true;
    const gaps = series.times.slice(1).map((t, i) => t - series.times[i]);
    return median(gaps) > SPARSE_INTERVAL;
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

  private showButtons(): void {
    this.pngButton.disabled = this.csvButton.disabled = this.plotted.length === 0;
  }

  private draw(): void {
    this.showButtons();
    // uPlot wants one time axis: the union of the series' times, with gaps where one has no sample.
    const times = [...new Set(this.plotted.flatMap((s) => s.times))].sort((a, b) => a - b);
    const index = new Map(times.map((t, i) => [t, i]));
    const columns = this.plotted.map((s) => {
      const column: (number | null)[] = new Array(times.length).fill(null);
      s.times.forEach((t, i) => (column[index.get(t)!] = s.values[i]));
      return column;
    });
    const data = [times, ...columns] as uPlot.AlignedData;
    // The same signals drawn the same way (a live run's refresh): new data, the pointer's readout stays.
    const shape = JSON.stringify(this.plotted.map((s) => [s.id, this.stepped(s)]));
    if (this.plot && shape === this.shape && !this.root.hidden) {
      this.plot.setData(data);
      return;
    }
    this.plot?.destroy();
    this.plot = null;
    this.shape = shape;
    this.legend.replaceChildren();
    this.readout.textContent = "";
    if (this.plotted.length === 0 || this.root.hidden) return;
    const units = [...new Set(this.plotted.map((s) => this.info(s.id)?.unit ?? ""))];
    const steps = uPlot.paths.stepped!({ align: 1 });
    const options: uPlot.Options = {
      ...this.size(),
      scales: { x: { time: false } },
      axes: [
        { label: "t (s)" },
        ...units.map((unit, i) => ({ scale: unit, label: unit, side: i % 2 ? 1 : 3, grid: { show: i === 0 } })),
      ],
      series: [
        { label: "t (s)" },
        ...this.plotted.map((s, i) => ({
          label: `${this.info(s.id)?.label ?? s.id} (${this.info(s.id)?.unit ?? ""})`,
          scale: this.info(s.id)?.unit ?? "",
          stroke: COLORS[i % COLORS.length],
          width: 1.5,
          spanGaps: true,
          points: { show: false },
          ...(this.stepped(s) ? { paths: steps } : {}),
        })),
      ],
      // The legend names the signals above the chart; the readout over it says the values at the pointer.
      legend: { show: true, live: false, mount: (_: uPlot, legend: HTMLElement) => this.legend.append(legend) },
      hooks: {
        draw: [(u: uPlot) => this.drawCursor(u)],
        setCursor: [(u: uPlot) => this.showReadout(u)],
      },
    };
    this.plot = new uPlot(options, data, this.chartBox);
    this.plot.over.addEventListener("pointerdown", (event) => (this.pressedAt = { x: event.clientX, y: event.clientY }));
    this.plot.over.addEventListener("pointerup", (event) => this.clicked(event));
    this.plot.over.addEventListener("pointerleave", () => (this.readout.textContent = ""));
    this.plot.over.title = "Click to show this time";
  }

  /** The time and every plotted signal's value under the pointer. */
  private showReadout(u: uPlot): void {
    const left = u.cursor.left;
    if (left === undefined || left < 0) {
      this.readout.textContent = "";
      return;
    }
    const t = u.posToVal(left, "x");
    const parts = this.plotted.map((s) => {
      const value = valueAt(s, t);
      const info = this.info(s.id);
      return `${info?.label ?? s.id} ${value === null ? "–" : formatValue(value)} ${info?.unit ?? ""}`.trim();
    });
    this.readout.replaceChildren(...[`t ${t.toFixed(2)} s`, ...parts].map((text) => element("span", "", text)));
  }

  private clicked(event: PointerEvent): void {
    const pressed = this.pressedAt;
    this.pressedAt = null;
    if (!this.plot || !pressed || Math.hypot(event.clientX - pressed.x, event.clientY - pressed.y) > CLICK_SLOP) return;
    const over = this.plot.over.getBoundingClientRect();
    const time = this.plot.posToVal(event.clientX - over.left, "x");
    if (Number.isFinite(time)) for (const listener of this.seekListeners) listener(time);
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

  private size(): { width: number; height: number } {
    return { width: Math.max(200, this.chartBox.clientWidth), height: Math.max(100, this.chartBox.clientHeight) };
  }

  private resize(): void {
    if (!this.plot || this.root.hidden) return;
    this.plot.setSize(this.size());
  }
}
