// The heavy symmetric top (the unit's 2.102–2.121): a top spinning on a pivot under gravity,
// its attitude from the core's exact Euler angles (z-x-z: φ precession, θ nutation, ψ spin); the
// tip of its axis traces waves, loops or cusps on a sphere between the turning circles θ₁, θ₂;
// the inset plots the effective potential V(θ) (2.110) against the reduced energy E' (2.109).
// Every number comes from the core: the motion (Jacobi elliptic functions), the constants, V(θ),
// the steady-precession roots used by the presets, and the energy recomputed from the state at t.
import * as THREE from "three";
import { eulerToMatrix, HeavyTop } from "../core";
import { angles, DEG, fmt, type Params, type Readout, type SceneDef } from "../scene";
import { axisLabels, bufferLine, disposeTree, fixedAxes, matrix4 } from "../view";
import { choiceOptions, legacyParams, PRECESSION_FACTORS, sceneParams } from "./params";

export const PRESETS = choiceOptions("heavytop", "preset");

/** The radius of the sphere the axis' tip moves on (the top's length from pivot to stem tip). */
const R_TIP = 2;
/** Samples of the dim path drawn ahead of time, and of V(θ) in the inset. */
const PATH_SAMPLES = 3000;
const V_SAMPLES = 240;
/** The bright trail keeps this many points at most. */
const TRAIL_CAPACITY = 4000;
/** The trail's finest time step (s): at most 8 new points per 60 Hz frame of motion, however
 * fast the top nutates (a 1500 rpm tabletop top nods tens of times a second). */
const MIN_TRAIL_DT = 1 / 480;
/** Angles in degrees (the lab's one angle unit), rates in rad/s as the spin slider (rpm beside). */
const A = angles("rad");
/** Below this stage width (CSS px) the V(θ) inset starts folded, so that it does not cover the top. */
const NARROW_STAGE = 600;

/** The initial state a preset starts from: θ₀ (rad, from the tilt slider's degrees: the one
 * conversion to the core's radians), θ̇₀, φ̇₀ (rad/s), given the spin ω₃ (the
 * steady-precession root comes from the core). Choosing initial conditions is not physics:
 * each preset is a fraction of the core's slow steady-precession rate at θ₀. */
function initialState(p: Params): { theta0: number; thetaDot0: number; phiDot0: number } {
  const I1 = Number(p.I1), I3 = Number(p.I3), mgl = Number(p.mgl), w3 = Number(p.w3);
  const theta0 = Number(p.tilt) * DEG;
  const preset = String(p.preset);
  if (preset === "sleeping") return { theta0: 0, thetaDot0: 0, phiDot0: 0 };
  if (preset === "custom") return { theta0, thetaDot0: Number(p.thetaDot0), phiDot0: Number(p.phiDot0) };
  if (preset === "cusps") return { theta0, thetaDot0: 0, phiDot0: 0 };
  // Loops: released against the precession; waves: with half of it; steady: exactly at it.
  const s = HeavyTop.steadyPrecession(I1, I3, mgl, theta0, w3);
  const slow = s.slow;
  s.free();
  const factor = PRECESSION_FACTORS[preset];
  return { theta0, thetaDot0: 0, phiDot0: factor * slow };
}

/** The precession period 2π/|⟨φ̇⟩| from the core, in words: "one turn every 1.08 s", or "—" with
 * the reason where the axis does not turn on average (the core's Infinity). */
export function precessionPeriodReadout(period: number, meanRate: number): Readout {
  const label = "precession period 2π/|⟨φ̇⟩| (s)";
  if (Number.isFinite(period)) return { key: "precessionPeriod", label, value: period, text: `one turn every ${fmt(period, 3)} s` };
  const why = meanRate === 0 ? "the axis does not turn on average: ⟨φ̇⟩ = 0" : "too slow a turn to time";
  return { key: "precessionPeriod", label, value: String(period), text: `— (${why})` };
}

/** A latitude circle θ = const on the sphere of radius R_TIP. */
function latitude(color: number, dashed: boolean): THREE.LineLoop {
  const pts: THREE.Vector3[] = [];
  for (let i = 0; i < 128; i++) {
    const a = (2 * Math.PI * i) / 128;
    pts.push(new THREE.Vector3(Math.cos(a), Math.sin(a), 0));
  }
  const geom = new THREE.BufferGeometry().setFromPoints(pts);
  const mat = dashed
    ? new THREE.LineDashedMaterial({ color, dashSize: 0.05, gapSize: 0.04, transparent: true, opacity: 0.9 })
    : new THREE.LineBasicMaterial({ color, transparent: true, opacity: 0.35 });
  const loop = new THREE.LineLoop(geom, mat);
  if (dashed) loop.computeLineDistances();
  return loop;
}

/** Places a unit latitude circle at polar angle θ on the sphere of radius R_TIP. */
function placeLatitude(loop: THREE.LineLoop, theta: number): void {
  const r = R_TIP * Math.sin(theta);
  loop.visible = r > 1e-4;
  loop.scale.set(Math.max(r, 1e-6), Math.max(r, 1e-6), 1);
  loop.position.set(0, 0, R_TIP * Math.cos(theta));
}

/** The top: a body of revolution (lathe) with its point on the pivot, a stem along body z, and a
 * coloured stripe (vertex colours of one sector) so that the spin is visible. */
function topMesh(): THREE.Group {
  const profile = [
    [0, 0], [0.05, 0.12], [0.3, 0.5], [0.58, 0.9], [0.64, 1.0], [0.6, 1.1], [0.38, 1.24], [0.09, 1.32],
    [0.05, 1.33], [0.05, 1.95], [0.0, R_TIP],
  ].map(([r, h]) => new THREE.Vector2(r, h));
  const geom = new THREE.LatheGeometry(profile, 72);
  geom.rotateX(Math.PI / 2); // lathe axis (y) → body z
  const pos = geom.getAttribute("position");
  const colors = new Float32Array(pos.count * 3);
  const base = new THREE.Color(0xc9d1d9), stripe = new THREE.Color(0xf2b84b), stem = new THREE.Color(0x8b949e);
  for (let i = 0; i < pos.count; i++) {
    const x = pos.getX(i), y = pos.getY(i), z = pos.getZ(i);
    const a = Math.atan2(y, x);
    const c = z > 1.34 ? stem : a > 0 && a < 0.55 ? stripe : base;
    colors.set([c.r, c.g, c.b], 3 * i);
  }
  geom.setAttribute("color", new THREE.BufferAttribute(colors, 3));
  geom.computeVertexNormals();
  const mesh = new THREE.Mesh(geom, new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.45, metalness: 0.1, side: THREE.DoubleSide }));
  const g = new THREE.Group();
  g.add(mesh);
  return g;
}

/** The inset plot of V(θ): samples, the energy line and the turning points, all from the core. */
class PotentialPlot {
  readonly canvas: HTMLCanvasElement;
  private readonly g: CanvasRenderingContext2D;
  private thetas: number[] = [];
  private values: number[] = [];
  private x0 = 0;
  private x1 = 1;
  private y0 = 0;
  private y1 = 1;
  private ePrime = 0;
  private turning: number[] = [];
  /** The cached layer (curve, lines, labels) and whether it must be redrawn. */
  private readonly layer = document.createElement("canvas");
  private layerDirty = true;
  private readonly W = 300;
  private readonly H = 170;
  private readonly pad = { l: 44, r: 10, t: 22, b: 28 };

  /** The inset (a HUD element: the camera keeps the top clear of it) with its fold button. */
  readonly box: HTMLElement;
  readonly toggle: HTMLButtonElement;

  constructor(host: HTMLElement, open: boolean) {
    this.box = document.createElement("div");
    this.box.className = "inset hud heavytop-inset";
    this.toggle = document.createElement("button");
    this.toggle.type = "button";
    this.toggle.addEventListener("click", () => this.setOpen(this.canvas.hidden));
    this.canvas = document.createElement("canvas");
    this.canvas.className = "heavytop-potential";
    const dpr = Math.min(2, window.devicePixelRatio || 1);
    this.canvas.width = this.W * dpr;
    this.canvas.height = this.H * dpr;
    this.layer.width = this.canvas.width;
    this.layer.height = this.canvas.height;
    Object.assign(this.canvas.style, { width: `${this.W}px`, height: `${this.H}px` });
    this.canvas.setAttribute("role", "img");
    this.canvas.setAttribute("aria-label", "effective potential V(θ) with the energy line E′ and the turning points");
    this.box.append(this.toggle, this.canvas);
    host.append(this.box);
    this.g = this.canvas.getContext("2d") as CanvasRenderingContext2D;
    this.g.scale(dpr, dpr);
    this.setOpen(open);
  }

  /** Shows or folds the plot (the button stays). */
  setOpen(open: boolean): void {
    this.canvas.hidden = !open;
    this.toggle.textContent = open ? "V(θ) ▾ hide" : "V(θ) ▸ show";
    this.toggle.setAttribute("aria-expanded", String(open));
  }

  /** New samples: θ grid (rad), V(θ) from the core, E', turning points. */
  set(thetas: number[], values: number[], ePrime: number, turning: number[]): void {
    this.thetas = thetas;
    this.values = values;
    this.ePrime = ePrime;
    this.turning = turning;
    this.x0 = thetas[0];
    this.x1 = thetas[thetas.length - 1];
    const finite = values.filter((v) => Number.isFinite(v));
    const vmin = Math.min(...finite);
    // The lower edge sets the scale, unless the minimum is at that edge (an upright top).
    const edges = [values[0], values[values.length - 1]].map((v) => (Number.isFinite(v) ? v : Math.max(...finite)));
    let vedge = Math.min(...edges);
    if (vedge - vmin <= 1e-6 * (1 + Math.abs(vmin))) vedge = Math.max(...edges);
    const span = Math.max(ePrime - vmin, 0.3 * (vedge - vmin), 1e-9 * (1 + Math.abs(vmin)));
    this.y0 = vmin - 0.12 * span;
    this.y1 = Math.max(ePrime, vmin) + 0.9 * span;
    this.layerDirty = true;
  }

  private px(theta: number): number {
    return this.pad.l + ((theta - this.x0) / (this.x1 - this.x0)) * (this.W - this.pad.l - this.pad.r);
  }
  private py(v: number): number {
    const y = this.pad.t + ((this.y1 - v) / (this.y1 - this.y0)) * (this.H - this.pad.t - this.pad.b);
    return Math.max(-10, Math.min(this.H + 10, y));
  }

  /** Draws the plot with the dot at the current θ and V(θ): the curve, the lines and the labels
   * (which change only with the parameters) from a cached layer, then the state. */
  draw(theta: number, vNow: number): void {
    const g = this.g, W = this.W, H = this.H, P = this.pad;
    if (this.layerDirty) {
      this.layerDirty = false;
      g.clearRect(0, 0, W, H);
      this.drawLayer();
      const cg = this.layer.getContext("2d") as CanvasRenderingContext2D;
      cg.clearRect(0, 0, this.layer.width, this.layer.height);
      cg.drawImage(this.canvas, 0, 0);
    }
    g.save();
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.clearRect(0, 0, this.canvas.width, this.canvas.height);
    g.drawImage(this.layer, 0, 0);
    g.restore();
    g.save();
    g.beginPath();
    g.rect(P.l, P.t, W - P.l - P.r, H - P.t - P.b);
    g.clip();
    // The state: θ(t) on V, with the kinetic part ½I₁θ̇² = E' − V up to the energy line.
    if (Number.isFinite(vNow)) {
      g.strokeStyle = "rgba(255,255,255,0.5)";
      g.lineWidth = 1;
      g.beginPath();
      g.moveTo(this.px(theta), this.py(vNow));
      g.lineTo(this.px(theta), this.py(this.ePrime));
      g.stroke();
      g.fillStyle = "#ffffff";
      g.beginPath();
      g.arc(this.px(theta), this.py(vNow), 4, 0, 2 * Math.PI);
      g.fill();
    }
    g.restore();
  }

  /** The parts of the plot that change only with the parameters. */
  private drawLayer(): void {
    const g = this.g, W = this.W, H = this.H, P = this.pad;
    g.font = "11px system-ui, sans-serif";
    g.fillStyle = "#9aa4b1";
    g.fillText("V(θ) (J, 2.110) · E′ (J, 2.109)", P.l, 14);
    // Frame and θ ticks (degrees).
    g.strokeStyle = "#3a4654";
    g.lineWidth = 1;
    g.strokeRect(P.l, P.t, W - P.l - P.r, H - P.t - P.b);
    g.fillText(A.angle(this.x0, 3), P.l - 4, H - 10);
    const right = A.angle(this.x1, 3);
    g.fillText(right, W - P.r - g.measureText(right).width, H - 10);
    const axis = `θ (${A.name})`;
    g.fillText(axis, (P.l + W - P.r - g.measureText(axis).width) / 2, H - 10);
    g.save();
    g.beginPath();
    g.rect(P.l, P.t, W - P.l - P.r, H - P.t - P.b);
    g.clip();
    // Turning points θ₁, θ₂.
    g.strokeStyle = "rgba(242, 184, 75, 0.55)";
    g.setLineDash([3, 3]);
    for (const th of this.turning) {
      g.beginPath();
      g.moveTo(this.px(th), P.t);
      g.lineTo(this.px(th), H - P.b);
      g.stroke();
    }
    // Energy line E'.
    g.strokeStyle = "#f2b84b";
    g.setLineDash([6, 4]);
    g.beginPath();
    g.moveTo(P.l, this.py(this.ePrime));
    g.lineTo(W - P.r, this.py(this.ePrime));
    g.stroke();
    g.setLineDash([]);
    // V(θ).
    g.strokeStyle = "#7cc4ff";
    g.lineWidth = 2;
    g.beginPath();
    let pen = false;
    this.thetas.forEach((th, i) => {
      const v = this.values[i];
      if (!Number.isFinite(v)) { pen = false; return; }
      if (pen) g.lineTo(this.px(th), this.py(v));
      else g.moveTo(this.px(th), this.py(v));
      pen = true;
    });
    g.stroke();
    g.restore();
    // Value ticks (J) at the edges of the vertical range.
    g.fillStyle = "#9aa4b1";
    g.fillText(fmt(this.y1, 3), 2, P.t + 9);
    g.fillText(fmt(this.y0, 3), 2, H - P.b);
  }
}

/** The bright trail of the axis' tip over the last stretch of time: points on a fixed time grid
 * (multiples of `dt`, from the core in batches; only new grid points are computed each frame) plus
 * the point at t, so that a seek shows the same trail as playing up to t. The points lie in order
 * in a buffer twice the trail's length, drawn from the trail's first point: a frame writes (and
 * uploads) only its new points, and the trail slides back to the buffer's start once per
 * trail's length of points — no per-frame copy of the whole trail. */
class TipTrail {
  readonly obj: THREE.Line;
  private readonly pos = new Float32Array(3 * (2 * TRAIL_CAPACITY + 1));
  /** Grid points start..end are in the buffer, point k at slot k − offset. */
  private start = 0;
  private end = -1;
  private offset = 0;
  private span = 1;
  private dt = 0.01;

  constructor(color: number) {
    this.obj = bufferLine(this.pos, color);
  }

  /** A new motion: grid step `dt` (s), `window` (s) of trail. */
  reset(dt: number, window: number): void {
    this.dt = dt;
    this.span = Math.max(1, Math.min(TRAIL_CAPACITY - 1, Math.ceil(window / dt)));
    this.start = 0;
    this.end = -1;
    this.offset = 0;
  }

  update(top: HeavyTop, t: number, tip: THREE.Vector3): void {
    const attr = this.obj.geometry.getAttribute("position") as THREE.BufferAttribute;
    const kEnd = Math.floor(t / this.dt + 1e-9);
    const kStart = Math.max(0, kEnd - this.span + 1);
    let from = kStart;
    // The points already in the buffer are kept when the new trail continues them.
    if (kStart >= this.start && kStart <= this.end + 1 && kEnd >= this.end) from = this.end + 1;
    else this.offset = kStart;
    // Room for the new points and the tip: slide the kept ones back to the start.
    let moved = false;
    if (kEnd + 1 - this.offset >= 2 * TRAIL_CAPACITY) {
      const keep = Math.max(kStart, this.offset);
      if (from > keep) this.pos.copyWithin(0, 3 * (keep - this.offset), 3 * (from - this.offset));
      this.offset = keep;
      moved = true;
    }
    if (kEnd >= from) {
      const times = new Float64Array(kEnd - from + 1);
      for (let k = from; k <= kEnd; k++) times[k - from] = k * this.dt;
      const axis = top.symmetryAxis(times);
      const at = 3 * (from - this.offset);
      for (let i = 0; i < axis.length; i++) this.pos[at + i] = R_TIP * axis[i];
    }
    this.start = kStart;
    this.end = kEnd;
    const tipSlot = 3 * (kEnd + 1 - this.offset);
    this.pos[tipSlot] = tip.x;
    this.pos[tipSlot + 1] = tip.y;
    this.pos[tipSlot + 2] = tip.z;
    // Upload the new points and the tip only (all of them after a slide).
    attr.clearUpdateRanges();
    if (!moved) {
      const first = 3 * (Math.min(from, kEnd + 1) - this.offset);
      attr.addUpdateRange(first, tipSlot + 3 - first);
    }
    attr.needsUpdate = true;
    this.obj.geometry.setDrawRange(kStart - this.offset, kEnd - kStart + 2);
  }
}

export const heavyTopScene: SceneDef = {
  id: "heavytop",
  title: "Heavy top",
  short: "Heavy top",
  rateUnit: "rad",
  pinned: ["motionClass", "turningPoints", "nutationPeriod", "precessionPeriod"],
  // The core's names of the sliders' arguments (HeavyTop.fromSpin, steadyPrecession).
  argumentKeys: { omega3: "w3", theta: "tilt", theta0: "tilt", phi_dot: "phiDot0", theta_dot: "thetaDot0" },
  legacyParams: legacyParams("heavytop"),
  describe: "a spinning top on a pivot under gravity, the tip of its axis moving on a translucent sphere between two dashed turning circles, with its trail; an inset plots the effective potential V(θ); the axes x, y, z are labelled",
  blurb:
    "A symmetric top on a pivot under gravity, exactly (θ by Jacobi's sn, φ and ψ by elliptic integrals; 2.102–2.121). " +
    "The tip of its axis moves on the sphere between the turning circles θ₁, θ₂ (dashed), where E′ = V(θ) (inset): " +
    "loops when φ̇ changes sign, waves when it does not, cusps when released at rest in θ and φ. " +
    "Presets start at θ₀ with θ̇₀ = 0 and φ̇₀ a fraction of the slow steady precession (loops −½, cusps 0, waves ½, steady 1); " +
    "“sleeping” stands the top upright (θ₀ = 0); “custom” uses the φ̇₀, θ̇₀ sliders.",
  params: sceneParams("heavytop", {
    tilt: (p) => p.preset !== "sleeping",
    phiDot0: (p) => p.preset === "custom",
    thetaDot0: (p) => p.preset === "custom",
  }),
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    root.add(fixedAxes(2.8, 0.3));
    axisLabels(ctx.labels, 2.8, ["x", "y", "z"]);

    // The sphere of the tip, its equator, and the turning circles θ₁, θ₂.
    const sphere = new THREE.Mesh(
      new THREE.SphereGeometry(R_TIP, 64, 32),
      new THREE.MeshStandardMaterial({ color: 0x3e7bfa, transparent: true, opacity: 0.1, depthWrite: false, side: THREE.DoubleSide }),
    );
    root.add(sphere);
    const equator = latitude(0x9aa4b1, false);
    placeLatitude(equator, Math.PI / 2);
    const circle1 = latitude(0xf2b84b, true);
    const circle2 = latitude(0xf2b84b, true);
    root.add(equator, circle1, circle2);

    // The pivot on its post.
    // A slim post under the pivot (a hanging top, θ > 90°, swings past it) on a small foot.
    const post = new THREE.Mesh(
      new THREE.CylinderGeometry(0.035, 0.05, 1.4, 16).rotateX(Math.PI / 2).translate(0, 0, -0.7),
      new THREE.MeshStandardMaterial({ color: 0x6b7685, roughness: 0.7 }),
    );
    const foot = new THREE.Mesh(
      new THREE.CylinderGeometry(0.3, 0.34, 0.06, 32).rotateX(Math.PI / 2).translate(0, 0, -1.43),
      new THREE.MeshStandardMaterial({ color: 0x4a5563, roughness: 0.8 }),
    );
    const pivot = new THREE.Mesh(new THREE.SphereGeometry(0.06, 16, 12), new THREE.MeshStandardMaterial({ color: 0xe6e9ee }));
    root.add(post, foot, pivot);

    const body = new THREE.Group();
    body.matrixAutoUpdate = false;
    body.add(topMesh());
    root.add(body);
    const tipDot = new THREE.Mesh(new THREE.SphereGeometry(0.045, 16, 12), new THREE.MeshBasicMaterial({ color: 0xffffff }));
    root.add(tipDot);

    // The path over the first stretch of time (dim, drawn at once) and the trail up to t (bright).
    const pathPos = new Float32Array(3 * PATH_SAMPLES);
    const pathGeom = new THREE.BufferGeometry();
    pathGeom.setAttribute("position", new THREE.BufferAttribute(pathPos, 3));
    const path = new THREE.Line(pathGeom, new THREE.LineBasicMaterial({ color: 0x7cc4ff, transparent: true, opacity: 0.35 }));
    path.frustumCulled = false;
    root.add(path);
    const trail = new TipTrail(0xf2b84b);
    root.add(trail.obj);

    const plot = new PotentialPlot(ctx.overlay, ctx.overlay.clientWidth >= NARROW_STAGE);
    plot.toggle.addEventListener("click", () => { drawn.dirty = true; });

    let top: HeavyTop | null = null;
    let p: Params = {};
    let fixed: Readout[] = [];
    let out: Readout[] = [];
    const tip = new THREE.Vector3();
    // The state the inset shows (drawn in render, outside the physics step).
    let drawn = { theta: NaN, vNow: NaN, dirty: false };

    const free = () => {
      top?.free();
      top = null;
    };

    return {
      configure(params) {
        p = params;
        const I1 = Number(p.I1), I3 = Number(p.I3), mgl = Number(p.mgl), w3 = Number(p.w3);
        const s0 = initialState(p);
        const next = HeavyTop.fromSpin(I1, I3, mgl, 0, s0.theta0, 0, s0.phiDot0, s0.thetaDot0, w3);
        free();
        top = next;

        const [th1, th2] = top.turningPoints;
        placeLatitude(circle1, th1);
        placeLatitude(circle2, th2);
        circle2.visible &&= th2 - th1 > 1e-9;

        // Time scales of the drawing: the nutation period and one turn of mean precession.
        const period = top.nutationPeriod;
        const rate = Math.abs(top.meanPrecessionRate);
        const turn = rate > 0 ? (2 * Math.PI) / rate : Infinity;
        const nut = Number.isFinite(period) && period > 0 ? period : 1;
        const window = Math.min(60, Math.max(6 * nut, Math.min(0.95 * turn, 30)));
        const dt = Math.max(nut / 60, window / (TRAIL_CAPACITY - 2), MIN_TRAIL_DT);
        trail.reset(dt, window);
        const times = new Float64Array(PATH_SAMPLES);
        for (let i = 0; i < PATH_SAMPLES; i++) times[i] = (window * i) / (PATH_SAMPLES - 1);
        const axis = top.symmetryAxis(times);
        for (let i = 0; i < 3 * PATH_SAMPLES; i++) pathPos[i] = R_TIP * axis[i];
        (pathGeom.getAttribute("position") as THREE.BufferAttribute).needsUpdate = true;

        // V(θ) around the band [θ₁, θ₂].
        const half = Math.max(0.35, 1.5 * (th2 - th1));
        const lo = Math.max(1e-3, Math.min(th1, th2) - half);
        const hi = Math.min(Math.PI - 1e-3, th2 + half);
        const grid: number[] = [];
        for (let i = 0; i < V_SAMPLES; i++) grid.push(lo + ((hi - lo) * i) / (V_SAMPLES - 1));
        plot.set(grid, Array.from(top.effectivePotential(grid)), top.reducedEnergy, [th1, th2]);

        const minSpin = HeavyTop.minSpin(I1, I3, mgl, s0.theta0);
        const sleepAt = HeavyTop.sleepingThreshold(I1, I3, mgl);
        const stable = top.isSleepingStable;
        let steady: number[] = [];
        let steadyText = `none: |ω₃| < ${A.rate(minSpin, 4)} (2.119)`;
        if (Math.abs(w3) >= minSpin) {
          const s = HeavyTop.steadyPrecession(I1, I3, mgl, s0.theta0, w3);
          steady = [s.slow, s.fast];
          steadyText = `slow ${A.rate(s.slow, 6)}, fast ${A.rate(s.fast, 6)}`;
          s.free();
        }
        const init = Array.from(top.initialState);
        fixed = [
          { key: "motionClass", label: "motion", value: top.motionClass, text: top.motionClass },
          { key: "initialRates", label: `φ̇₀, θ̇₀, ψ̇₀ (${A.perSecond})`, unitScale: A.rateScale, value: init.slice(3), text: A.rates(init.slice(3)) },
          { key: "omega3", label: `ω₃ (${A.perSecond}, 2.99)`, unitScale: A.rateScale, value: top.omega3, text: A.rate(top.omega3, 6) },
          { key: "turningPoints", label: `θ₁, θ₂ (${A.name})`, unitScale: A.angleScale, value: [th1, th2], text: `${A.angle(th1, 5)}, ${A.angle(th2, 5)}` },
          { key: "nutationPeriod", label: "nutation period (s)", value: top.nutationPeriod, text: fmt(top.nutationPeriod) },
          { key: "meanPrecessionRate", label: `⟨φ̇⟩ (${A.perSecond})`, unitScale: A.rateScale, value: top.meanPrecessionRate, text: A.rate(top.meanPrecessionRate) },
          precessionPeriodReadout(top.precessionPeriod, top.meanPrecessionRate),
          { key: "steadyRates", label: `steady φ̇ at θ₀ (${A.perSecond}, 2.116)`, unitScale: A.rateScale, value: steady, text: steadyText },
          { key: "minSpin", label: `min spin at θ₀ (${A.perSecond}, 2.119)`, unitScale: A.rateScale, value: minSpin, text: A.rate(minSpin) },
          { key: "sleepingThreshold", label: `sleeping threshold (${A.perSecond})`, unitScale: A.rateScale, value: sleepAt, text: A.rate(sleepAt) },
          {
            key: "sleepsStably", label: "upright top sleeps", value: stable,
            text: stable ? "stably (ω₃² > 4mglI₁/I₃²)" : "no: it would fall (ω₃² ≤ 4mglI₁/I₃²)", warn: !stable,
          },
        ];
      },
      step(t) {
        if (!top) return;
        const s = top.state(t);
        const [phi, theta, psi, phiDot, thetaDot, psiDot] = s;
        const R = eulerToMatrix([phi, theta, psi], "zxz", true);
        body.matrix.copy(matrix4(R));
        body.matrixWorldNeedsUpdate = true;
        tip.set(R[2], R[5], R[8]).multiplyScalar(R_TIP);
        tipDot.position.copy(tip);
        trail.update(top, t, tip);

        const I1 = Number(p.I1), I3 = Number(p.I3), mgl = Number(p.mgl);
        const [pPhiNow, pPsiNow, eNow] = HeavyTop.constantsOfState(I1, I3, mgl, theta, thetaDot, phiDot, psiDot);
        const vNow = top.effectivePotential([theta])[0];
        drawn = { theta, vNow, dirty: true };
        const E = top.energy, pPhi = top.pPhi, pPsi = top.pPsi;
        const rel = (a: number, b: number) => fmt(b !== 0 ? (a - b) / Math.abs(b) : a - b, 2, 1);
        out = [
          { key: "t", label: "t (s)", value: t, text: fmt(t, 5) },
          { key: "angles", label: `φ, θ, ψ (${A.name})`, unitScale: A.angleScale, value: [phi, theta, psi], text: A.vec([phi, theta, psi], 5, 1) },
          { key: "rates", label: `φ̇, θ̇, ψ̇ (${A.perSecond})`, unitScale: A.rateScale, value: [phiDot, thetaDot, psiDot], text: A.rates([phiDot, thetaDot, psiDot]) },
          ...fixed,
          { key: "energy", label: "E (J, 2.105), conserved", value: E, text: fmt(E, 10) },
          { check: true, key: "energyNow", label: "E(t) from the state", value: eNow, text: `${fmt(eNow, 10)} (rel. drift ${rel(eNow, E)})` },
          { key: "pPhi", label: "p_φ (2.104)", value: pPhi, text: fmt(pPhi, 10) },
          { check: true, key: "pPhiNow", label: "p_φ(t) from the state", value: pPhiNow, text: `${fmt(pPhiNow, 10)} (rel. drift ${rel(pPhiNow, pPhi)})` },
          { key: "pPsi", label: "p_ψ = I₃ω₃ (2.103)", value: pPsi, text: fmt(pPsi, 10) },
          { check: true, key: "pPsiNow", label: "p_ψ(t) from the state", value: pPsiNow, text: `${fmt(pPsiNow, 10)} (rel. drift ${rel(pPsiNow, pPsi)})` },
          { key: "reducedEnergy", label: "E′ (J, 2.109)", value: top.reducedEnergy, text: fmt(top.reducedEnergy, 10) },
          { key: "potentialNow", label: "V(θ(t)) (J, 2.110)", value: vNow, text: fmt(vNow, 10) },
        ];
      },
      readouts() {
        return out;
      },
      render(renderer, scene, camera) {
        if (drawn.dirty) plot.draw(drawn.theta, drawn.vNow);
        drawn.dirty = false;
        renderer.render(scene, camera);
      },
      frame() {
        // The sphere of the tip holds the top at every time, and the post with its foot.
        return { center: new THREE.Vector3(), radius: R_TIP * 1.04 };
      },
      main() {
        return [sphere];
      },
      dispose() {
        free();
        disposeTree(root);
        plot.box.remove();
      },
    };
  },
};
