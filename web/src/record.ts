// The record of a scene's readouts over time: every numeric readout (each component of a vector
// one column) at each step of the motion, plotted against time (one readout, picked from a list,
// on a small canvas) and exported as CSV (a download). The record restarts when the parameters
// change or the time goes back (a new motion, a seek, a reset). No dependency: a 2-D canvas.
import { fmt, type Readout } from "./scene";

/** Rows kept at most (the oldest dropped): minutes of motion at 60 frames a second. */
const CAPACITY = 20000;
/** The plot is redrawn at most this often (ms) while the motion plays. */
const REDRAW_MS = 120;

interface Column {
  key: string;
  /** The readout's label, with the component's index for a vector ("r′ fixed frame (m) [2]"). */
  label: string;
  /** The factor from the readout's value to the column's (Readout.unitScale). */
  scale: number;
}

/** A readout's numeric columns and their values: a number, or each number of a vector — named
 * by its own name where the label lists one per component ("φ, θ, ψ (°)" → "θ (°)"), else
 * by its place ("r′ fixed frame (m) [2]"). */
function numbers(r: Readout): { key: string; label: string; value: number; scale: number }[] {
  // In the unit the label names (an angle in degrees), as the readout's text.
  const k = r.unitScale ?? 1;
  if (typeof r.value === "number") return [{ key: r.key, label: r.label, value: r.value * k, scale: k }];
  if (!Array.isArray(r.value)) return [];
  const m = /^([^(]*?)\s*(\(.*\))?$/.exec(r.label);
  const names = m ? m[1].split(", ") : [];
  const own = names.length === r.value.length && names.every((n) => n && !n.includes(" "));
  return r.value.map((v, i) => ({ key: `${r.key}[${i}]`, label: own ? `${names[i]}${m![2] ? ` ${m![2]}` : ""}` : `${r.label} [${i + 1}]`, value: v * k, scale: k }));
}

export class Recorder {
  readonly box: HTMLDetailsElement;
  readonly select: HTMLSelectElement;
  readonly canvas: HTMLCanvasElement;
  private readonly g: CanvasRenderingContext2D;
  private readonly download: HTMLButtonElement;
  private columns: Column[] = [];
  private index = new Map<string, number>();
  private times: number[] = [];
  private rows: number[][] = [];
  private scene = "";
  private drawnAt = 0;
  private readonly W = 300;
  private readonly H = 150;

  constructor(host: HTMLElement) {
    this.box = document.createElement("details");
    this.box.id = "record";
    this.box.className = "record";
    const summary = document.createElement("summary");
    summary.textContent = "Plot a readout against time · CSV";
    const row = document.createElement("div");
    row.className = "record-row";
    const label = document.createElement("label");
    label.textContent = "Readout ";
    this.select = document.createElement("select");
    this.select.id = "record-key";
    label.append(this.select);
    this.download = document.createElement("button");
    this.download.type = "button";
    this.download.id = "record-csv";
    this.download.textContent = "Download CSV";
    this.download.title = "Every numeric readout at each recorded time, as a CSV file";
    row.append(label, this.download);
    this.canvas = document.createElement("canvas");
    this.canvas.id = "record-plot";
    const dpr = Math.min(2, window.devicePixelRatio || 1);
    this.canvas.width = this.W * dpr;
    this.canvas.height = this.H * dpr;
    Object.assign(this.canvas.style, { width: "100%", maxWidth: `${this.W}px`, aspectRatio: `${this.W} / ${this.H}` });
    this.canvas.setAttribute("role", "img");
    this.g = this.canvas.getContext("2d") as CanvasRenderingContext2D;
    this.g.scale(dpr, dpr);
    this.box.append(summary, row, this.canvas);
    host.append(this.box);
    this.select.addEventListener("change", () => this.draw());
    this.box.addEventListener("toggle", () => this.draw());
    this.download.addEventListener("click", () => this.save());
  }

  /** A new motion (a scene opened, its parameters changed): the record restarts. */
  restart(scene: string): void {
    this.scene = scene;
    this.times = [];
    this.rows = [];
    this.draw();
  }

  /** The readouts at time t (s). A time before the last recorded one restarts the record. */
  push(t: number, readouts: Readout[]): void {
    const last = this.times.length ? this.times[this.times.length - 1] : -Infinity;
    if (t < last) this.restart(this.scene);
    else if (t === last) this.times.pop(), this.rows.pop();
    const row: number[] = new Array(this.columns.length).fill(NaN);
    let added = false;
    for (const r of readouts) {
      for (const c of numbers(r)) {
        let i = this.index.get(c.key);
        if (i === undefined) {
          i = this.columns.length;
          this.columns.push({ key: c.key, label: c.label, scale: c.scale });
          this.index.set(c.key, i);
          added = true;
        }
        row[i] = c.value;
      }
    }
    if (added) this.fillSelect();
    this.times.push(t);
    this.rows.push(row);
    if (this.times.length > CAPACITY) {
      this.times.shift();
      this.rows.shift();
    }
    const now = performance.now();
    if (now - this.drawnAt > REDRAW_MS) this.draw();
  }

  /** Forgets the columns (a scene opened): the list offers the new scene's readouts. */
  reset(scene: string, preferred?: string): void {
    this.columns = [];
    this.index.clear();
    this.select.replaceChildren();
    this.preferred = preferred;
    this.restart(scene);
  }
  private preferred: string | undefined;

  private fillSelect(): void {
    const keep = this.select.value;
    this.select.replaceChildren(...this.columns.filter((c) => c.key !== "t").map((c) => new Option(c.label, c.key)));
    const want = keep || this.preferred;
    if (want && this.index.has(want)) this.select.value = want;
  }

  /** The recorded series of a column: times (s), values (in the unit its label names) and the
   * factor from the readout's value to them. */
  series(key: string): { t: number[]; v: number[]; scale: number } {
    const i = this.index.get(key);
    if (i === undefined) return { t: [], v: [], scale: 1 };
    const t: number[] = [], v: number[] = [];
    this.rows.forEach((row, k) => {
      if (Number.isFinite(row[i])) {
        t.push(this.times[k]);
        v.push(row[i]);
      }
    });
    return { t, v, scale: this.columns[i].scale };
  }

  /** The record as CSV: a header (t (s), then each column's label) and one row per time, full precision. */
  csv(): string {
    const cols = this.columns.filter((c) => c.key !== "t");
    const quote = (s: string) => `"${s.replaceAll('"', '""')}"`;
    const lines = [["t (s)", ...cols.map((c) => c.label)].map(quote).join(",")];
    this.rows.forEach((row, k) => {
      lines.push([this.times[k], ...cols.map((c) => row[this.index.get(c.key)!])].map((x) => (Number.isFinite(x) ? String(x) : "")).join(","));
    });
    return lines.join("\n") + "\n";
  }

  private save(): void {
    const blob = new Blob([this.csv()], { type: "text/csv" });
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = `poinsot-${this.scene || "lab"}.csv`;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }

  /** Draws the picked readout against time (only while the box is open). */
  draw(): void {
    this.drawnAt = performance.now();
    if (!this.box.open) return;
    const g = this.g, W = this.W, H = this.H;
    const P = { l: 52, r: 8, t: 16, b: 22 };
    const key = this.select.value;
    const label = this.select.selectedOptions[0]?.text ?? "";
    const { t, v } = this.series(key);
    this.canvas.setAttribute("aria-label", `${label} against time t (s), ${t.length} points`);
    this.canvas.dataset.points = String(t.length);
    g.clearRect(0, 0, W, H);
    g.font = "11px system-ui, sans-serif";
    g.fillStyle = "#9aa4b1";
    g.strokeStyle = "#3a4654";
    g.lineWidth = 1;
    g.strokeRect(P.l, P.t, W - P.l - P.r, H - P.t - P.b);
    g.fillText(label.length > 44 ? `${label.slice(0, 43)}…` : label, P.l, 11);
    if (t.length === 0) {
      g.fillText("no record yet: play the motion", P.l + 6, H / 2);
      return;
    }
    const t0 = t[0], t1 = Math.max(t[t.length - 1], t0 + 1e-9);
    let lo = Math.min(...v), hi = Math.max(...v);
    if (hi - lo <= 1e-12 * Math.max(1, Math.abs(hi))) {
      const pad = Math.max(1e-9, Math.abs(hi) * 1e-3);
      lo -= pad;
      hi += pad;
    }
    const px = (x: number) => P.l + ((x - t0) / (t1 - t0)) * (W - P.l - P.r);
    const py = (y: number) => P.t + ((hi - y) / (hi - lo)) * (H - P.t - P.b);
    g.fillText(fmt(hi, 3), 2, P.t + 9);
    g.fillText(fmt(lo, 3), 2, H - P.b);
    g.fillText(`${fmt(t0, 3)} s`, P.l, H - 6);
    const right = `${fmt(t1, 3)} s`;
    g.fillText(right, W - P.r - g.measureText(right).width, H - 6);
    g.strokeStyle = "#7cc4ff";
    g.lineWidth = 1.5;
    g.beginPath();
    // At most one point per half pixel column: a long record draws as fast as a short one.
    const stride = Math.max(1, Math.floor(t.length / (2 * (W - P.l - P.r))));
    for (let k = 0; k < t.length; k += stride) {
      if (k === 0) g.moveTo(px(t[k]), py(v[k]));
      else g.lineTo(px(t[k]), py(v[k]));
    }
    g.lineTo(px(t[t.length - 1]), py(v[v.length - 1]));
    g.stroke();
  }
}
