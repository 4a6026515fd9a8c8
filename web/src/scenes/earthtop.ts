// The Earth as a top (issue 25): the unit's symmetric top with I₁ = I₂ < I₃ is the Earth, an
// oblate body spinning once a sidereal day, whose equatorial bulge the Sun and the Moon pull
// towards the ecliptic. The torque, averaged over their orbits, turns the spin axis about the
// ecliptic pole (the precession of the equinoxes, one turn in about 25,700 years: the torque
// theory of 2.98–2.121 applied to the Earth); the 18.6-year regression of the Moon's node makes
// the axis nod (the principal nutation); left alone, the axis would wobble about the figure axis
// with Euler's period (2.83), which the elastic Earth lengthens into the Chandler wobble seen in
// the real pole's path (the inset: the IERS EOP 20 C04 series bundled with the lab).
//
// Every rate, period and amplitude comes from the core's `RigidEarth`; the animation moves the
// axis by them: longitude ψ(t) = |ψ̇| t + Δψ₀ sin Ω(t), obliquity ε(t) = ε + Δε₀ cos Ω(t), the
// node Ω(t) = −2π t / T_node (the core's period of the Moon's node), t counted from the start
// (not a date). The drawing exaggerates, and says so on the view: the bulge, the nod, the time.
import * as THREE from "three";
import { Earth, fitWobble, RigidEarth } from "../core";
import { angles, DEG, fmt, type Params, type Readout, type SceneDef } from "../scene";
import { Arrow, bufferLine, cone, disposeTree } from "../view";
import pole from "../generated/pole_path.json";

const A = angles("°");
/** A Julian year (s): the clock's unit. */
const YEAR = 365.25 * 86400;
/** One second of arc (rad). */
const ARCSEC = Math.PI / 648000;
/** The readouts' unit for the slow rates: seconds of arc per Julian year, from rad/s. */
const ARCSEC_PER_YEAR = YEAR / ARCSEC;
/** The drawn Earth's equatorial radius, its axis's half-length, the cone's slant (scene units). */
const RADIUS = 1;
const AXIS = 1.75;
/** Where the Sun and the Moon are drawn (scene units from the Earth's centre), on the ecliptic. */
const SUN_AT = 2.9;
const MOON_AT = 2.3;
/** The drawn bulge: the figure's flattening is drawn BULGE × H (at most MAX_FLATTENING). */
const BULGE = 100;
const MAX_FLATTENING = 0.45;
/** Samples of the axis's recent path (its tail), and how many node periods it spans. */
const TAIL = 3200;
const TAIL_NODES = 450;
/** The elastic Earth's Love numbers for the Chandler period (the core's documented example). */
const K2 = 0.3;
const KS = 0.938;
/** Below this stage width (CSS px) the pole-path inset starts folded. */
const NARROW_STAGE = 620;

/** The real pole's path (the bundled decimated IERS series): MJD (days), x and y (″). */
interface PolePath {
  source: string[];
  stride: number;
  rows: number;
  mjd: number[];
  x: number[];
  y: number[];
}
const POLE = pole as PolePath;

/** The calendar year of a modified Julian date (to a day; for the inset's labels). */
const yearOf = (mjd: number) => new Date((mjd - 40587) * 86400000).getUTCFullYear();

/** The inset: the real pole's path (x, y) from the IERS series, with its source. */
class PolePlot {
  readonly box: HTMLElement;
  readonly canvas: HTMLCanvasElement;
  readonly toggle: HTMLButtonElement;
  readonly credit: HTMLElement;
  private readonly W = 250;
  private readonly H = 250;

  constructor(host: HTMLElement, open: boolean) {
    this.box = document.createElement("div");
    this.box.className = "inset hud earthtop-inset";
    this.toggle = document.createElement("button");
    this.toggle.type = "button";
    this.toggle.addEventListener("click", () => this.setOpen(this.canvas.hidden));
    this.canvas = document.createElement("canvas");
    this.canvas.className = "earthtop-pole";
    const dpr = Math.min(2, window.devicePixelRatio || 1);
    this.canvas.width = this.W * dpr;
    this.canvas.height = this.H * dpr;
    Object.assign(this.canvas.style, { width: `${this.W}px`, height: `${this.H}px` });
    this.canvas.setAttribute("role", "img");
    const [y0, y1] = [yearOf(POLE.mjd[0]), yearOf(POLE.mjd[POLE.mjd.length - 1])];
    this.canvas.setAttribute("aria-label", `the real path of the Earth's rotation pole, x against y in seconds of arc, ${y0} to ${y1}: the Chandler and annual wobbles, a spiral a few metres wide`);
    this.credit = document.createElement("div");
    this.credit.className = "earthtop-credit";
    this.credit.textContent = `Data: IERS EOP 20 C04, IERS Earth Orientation Centre, Paris Observatory (every ${5 * POLE.stride}th day)`;
    Object.assign(this.credit.style, { fontSize: ".68rem", color: "#9aa4b1", padding: "0 .45rem .25rem", maxWidth: `${this.W - 10}px` });
    this.box.append(this.toggle, this.canvas, this.credit);
    Object.assign(this.box.style, { position: "relative", left: "0", top: "0", alignSelf: "flex-start" });
    host.append(this.box);
    this.draw();
    this.setOpen(open);
  }

  setOpen(open: boolean): void {
    this.canvas.hidden = !open;
    this.credit.hidden = !open;
    this.toggle.textContent = open ? "the real pole ▾ hide" : "the real pole ▸ show";
    this.toggle.setAttribute("aria-expanded", String(open));
  }

  /** The path, drawn once: x to the right, y up (″), older points dimmer, the last one a dot. */
  private draw(): void {
    const g = this.canvas.getContext("2d") as CanvasRenderingContext2D;
    const dpr = this.canvas.width / this.W;
    g.scale(dpr, dpr);
    const W = this.W, H = this.H, P = { l: 38, r: 8, t: 20, b: 30 };
    const xs = POLE.x, ys = POLE.y, n = xs.length;
    const cx = (Math.min(...xs) + Math.max(...xs)) / 2, cy = (Math.min(...ys) + Math.max(...ys)) / 2;
    const half = 0.55 * Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
    const px = (x: number) => P.l + ((x - (cx - half)) / (2 * half)) * (W - P.l - P.r);
    const py = (y: number) => P.t + (((cy + half) - y) / (2 * half)) * (H - P.t - P.b);
    g.font = "11px system-ui, sans-serif";
    g.fillStyle = "#9aa4b1";
    g.fillText(`the real pole, ${yearOf(POLE.mjd[0])}–${yearOf(POLE.mjd[n - 1])}`, P.l, 13);
    g.strokeStyle = "#3a4654";
    g.lineWidth = 1;
    g.strokeRect(P.l, P.t, W - P.l - P.r, H - P.t - P.b);
    const lo = fmt(cx - half, 2), hi = fmt(cx + half, 2);
    g.fillText(lo, P.l, H - 16);
    g.fillText(hi, W - P.r - g.measureText(hi).width, H - 16);
    const xl = "x (″, to Greenwich)";
    g.fillText(xl, (P.l + W - P.r - g.measureText(xl).width) / 2, H - 4);
    g.save();
    g.translate(11, (P.t + H - P.b) / 2);
    g.rotate(-Math.PI / 2);
    const yl = "y (″, to 90° W)";
    g.fillText(yl, -g.measureText(yl).width / 2, 0);
    g.restore();
    g.fillText(fmt(cy + half, 2), 14, P.t + 10);
    g.fillText(fmt(cy - half, 2), 14, H - P.b);
    // Older points dimmer: the spiral's turns, with the amplitude's swell and fall.
    for (let i = 1; i < n; i++) {
      const a = 0.15 + 0.85 * (i / n);
      g.strokeStyle = `rgba(124, 196, 255, ${a.toFixed(3)})`;
      g.beginPath();
      g.moveTo(px(xs[i - 1]), py(ys[i - 1]));
      g.lineTo(px(xs[i]), py(ys[i]));
      g.stroke();
    }
    g.fillStyle = "#f2b84b";
    g.beginPath();
    g.arc(px(xs[n - 1]), py(ys[n - 1]), 3.5, 0, 2 * Math.PI);
    g.fill();
    g.fillText(String(yearOf(POLE.mjd[n - 1])), px(xs[n - 1]) + 6, py(ys[n - 1]) + 4);
  }
}

export const earthTopScene: SceneDef = {
  id: "earthtop",
  title: "The Earth as a top",
  short: "Earth top",
  rateUnit: "°",
  pinned: ["precessionPeriod", "eulerPeriod", "chandlerPeriod", "chandlerObserved"],
  describe:
    "the Earth drawn as a flattened spinning top, its spin axis (white) sweeping a cone (yellow) about the ecliptic pole with a wavy tail where it nods; " +
    "the Sun and the Moon on the ecliptic pull on the equatorial bulge (arrows), and their torques (arrows at the tip of the axis) turn the axis; an inset plots the real pole's path from the IERS data",
  blurb:
    "The Earth is a symmetric top: flattened, spinning once a day. The Sun and the Moon pull on its equatorial bulge, trying to stand its equator up into the ecliptic; " +
    "like a spinning top under gravity, the axis turns aside instead, round a cone about the ecliptic pole: the precession of the equinoxes (2.98–2.121, with the Sun's and the Moon's torques averaged over their orbits). " +
    "The Moon's orbit turns every 18.6 years and makes the axis nod (the nutation). The free Earth would wobble with Euler's period (2.83); the elastic Earth wobbles more slowly, as the real pole's path shows (inset). " +
    "Time runs fast, and the bulge and the nod are drawn larger than they are: the view says by how much.",
  params: [
    { kind: "number", key: "flattening", label: "dynamical flattening H = (C − A)/C", unit: "", min: 0.0005, max: 0.05, step: 0.0001, scale: "log", value: 0.003273795 },
    { kind: "number", key: "obliquity", label: "obliquity ε", unit: "°", min: 1, max: 89, step: 0.01, value: 23.44 },
    { kind: "number", key: "yearsPerSecond", label: "time runs at", unit: "years per second", min: 1, max: 10000, step: 1, scale: "log", value: 1000 },
    { kind: "choice", key: "nod", label: "nutation drawn ×", options: ["1", "300", "1000", "3000"], value: "1000" },
  ],
  argumentKeys: { dynamical_flattening: "flattening" },
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);

    // The ecliptic (the plane of the Sun's path, z = 0) and its pole.
    const ringPts: THREE.Vector3[] = [];
    for (let k = 0; k <= 128; k++) ringPts.push(new THREE.Vector3(Math.cos((k / 128) * 2 * Math.PI), Math.sin((k / 128) * 2 * Math.PI), 0).multiplyScalar(SUN_AT));
    const ecliptic = new THREE.Line(new THREE.BufferGeometry().setFromPoints(ringPts), new THREE.LineBasicMaterial({ color: 0x6b7785, transparent: true, opacity: 0.7 }));
    root.add(ecliptic);
    const plane = new THREE.Mesh(new THREE.CircleGeometry(SUN_AT, 96), new THREE.MeshBasicMaterial({ color: 0x2a3440, transparent: true, opacity: 0.25, side: THREE.DoubleSide, depthWrite: false }));
    root.add(plane);
    const eclipticPole = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, -AXIS * 1.1), new THREE.Vector3(0, 0, AXIS * 1.25)]),
      new THREE.LineDashedMaterial({ color: 0x9aa4b1, dashSize: 0.08, gapSize: 0.06 }),
    );
    eclipticPole.computeLineDistances();
    root.add(eclipticPole);
    ctx.labels.add("ecliptic pole", new THREE.Vector3(0, 0, AXIS * 1.33), { className: "label3d axis" });
    ctx.labels.add("ecliptic", new THREE.Vector3(SUN_AT * 0.71, -SUN_AT * 0.71, 0), { className: "label3d axis", color: "#9aa4b1" });

    // The Earth: a flattened sphere with its equator (the bulge) and a few parallels, carried by
    // `body`, whose z axis is the spin axis.
    const body = new THREE.Group();
    root.add(body);
    const globe = new THREE.Mesh(new THREE.SphereGeometry(RADIUS, 64, 32), new THREE.MeshStandardMaterial({ color: 0x2f6fb0, roughness: 0.7, metalness: 0.05 }));
    globe.geometry.rotateX(Math.PI / 2); // the sphere's poles (y) → z
    const figure = new THREE.Group();
    figure.add(globe);
    for (const lat of [-60, -30, 30, 60]) {
      const r = RADIUS * Math.cos(lat * DEG) * 1.003;
      const circle = new THREE.Mesh(new THREE.TorusGeometry(r, 0.006, 6, 96), new THREE.MeshBasicMaterial({ color: 0x9fc3e6, transparent: true, opacity: 0.6 }));
      circle.position.z = RADIUS * Math.sin(lat * DEG) * 1.003;
      figure.add(circle);
    }
    const bulge = new THREE.Mesh(new THREE.TorusGeometry(RADIUS * 1.005, 0.035, 10, 128), new THREE.MeshStandardMaterial({ color: 0xf28c38, roughness: 0.5 }));
    figure.add(bulge);
    body.add(figure);
    const spin = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, -AXIS), new THREE.Vector3(0, 0, AXIS)]),
      new THREE.LineBasicMaterial({ color: 0xffffff }),
    );
    body.add(spin);
    const spinTip = new THREE.Mesh(new THREE.SphereGeometry(0.045, 16, 12), new THREE.MeshBasicMaterial({ color: 0xffffff }));
    spinTip.position.z = AXIS;
    body.add(spinTip);
    ctx.labels.add("spin axis", new THREE.Vector3(0.0, 0, AXIS + 0.2), { obj: body, className: "label3d axis" });
    ctx.labels.add("bulge", new THREE.Vector3(-RADIUS * 0.8, -RADIUS * 0.8, 0), { obj: body, className: "label3d mark", color: "#f28c38" });

    // The precession cone about the ecliptic pole, and the axis's recent path (its tail).
    const coneHolder = new THREE.Group();
    root.add(coneHolder);
    let precessionCone: THREE.Mesh | null = null;
    const tailPos = new Float32Array(3 * TAIL);
    const tail = bufferLine(tailPos, 0xf2b84b);
    root.add(tail);
    const tailLabel = ctx.labels.add("the axis's path, nodding", new THREE.Vector3(), { className: "label3d mark", color: "#f2b84b" });
    const coneLabel = ctx.labels.add("precession cone", new THREE.Vector3(), { className: "label3d mark", color: "#f2b84b" });

    // The Sun and the Moon, drawn at a solstice (where their pull on the bulge is largest),
    // their pull on the near side of the bulge, and their torques at the tip of the axis.
    const sun = new THREE.Mesh(new THREE.SphereGeometry(0.2, 24, 16), new THREE.MeshBasicMaterial({ color: 0xffd35c }));
    const moon = new THREE.Mesh(new THREE.SphereGeometry(0.11, 20, 14), new THREE.MeshStandardMaterial({ color: 0xc9d1d9 }));
    root.add(sun, moon);
    const sunLabel = ctx.labels.add("Sun", new THREE.Vector3(), { className: "label3d mark", color: "#ffd35c" });
    const moonLabel = ctx.labels.add("Moon", new THREE.Vector3(), { className: "label3d mark", color: "#c9d1d9" });
    const sunPull = new Arrow(0xffd35c);
    const moonPull = new Arrow(0xc9d1d9);
    const sunTorque = new Arrow(0xffd35c);
    const moonTorque = new Arrow(0xc9d1d9);
    root.add(sunPull.obj, moonPull.obj, sunTorque.obj, moonTorque.obj);
    const pullLabel = ctx.labels.add("pull", new THREE.Vector3(), { className: "label3d mark", color: "#ffd35c" });
    const torqueLabel = ctx.labels.add("torque", new THREE.Vector3(), { className: "label3d mark", color: "#ffd35c" });

    // The clock and what is exaggerated, written on the view, above the inset: one column at
    // the top left (the view's buttons hold the top right, the pinned readouts the bottom).
    const column = document.createElement("div");
    Object.assign(column.style, { position: "absolute", left: "0.5rem", top: "0.5rem", display: "flex", flexDirection: "column", gap: "0.35rem" });
    const note = document.createElement("div");
    note.className = "hud-note hud earthtop-note";
    Object.assign(note.style, { position: "relative", whiteSpace: "pre-line", maxWidth: "17rem", fontSize: ".74rem", alignSelf: "flex-start" });
    const clock = document.createElement("div");
    clock.style.fontVariantNumeric = "tabular-nums";
    const exaggeration = document.createElement("div");
    note.append(clock, exaggeration);
    column.append(note);
    ctx.overlay.append(column);
    new PolePlot(column, ctx.overlay.clientWidth >= NARROW_STAGE);
    // The observed Chandler period: the core's fit of the path the inset shows (a trend, the
    // prograde Chandler circle, its period searched over 380–500 days, and the annual circles).
    const fit = fitWobble(POLE.mjd.map((m) => (m - POLE.mjd[0]) * 86400), POLE.x.map((v) => v * ARCSEC), POLE.y.map((v) => v * ARCSEC));
    const observed = fit.chandler;
    const [chandlerObserved, chandlerSigma] = [observed.period, observed.periodSigma];
    observed.free();
    fit.free();

    ctx.camera.position.set(3.4, -6.4, 5.2);
    ctx.target.set(0, 0, 0);

    let p: Params = {};
    let earth: RigidEarth | null = null;
    // The core's numbers for the current parameters.
    let rate = 0;
    let parts = [0, 0];
    let period = 0;
    let nodePeriod = 0;
    let nut = [0, 0];
    let euler = 0;
    let chandler = 0;
    let iau = 0;
    let eps0 = 0;
    let nod = 1;
    let out: Readout[] = [];
    /** The time (years) the tail was last drawn for (NaN: to be drawn). */
    let tailYears = NaN;
    /** The tail's samples, on a fixed grid of times k·gridStep (s) so that a frame asks the core
     * only for the samples it adds: the directions (ecliptic axes, × AXIS) of grid samples
     * gridFirst … gridFirst + gridCount − 1, oldest first; the current direction is drawn after
     * them. */
    let gridStep = 1;
    let gridFirst = 0;
    let gridCount = 0;
    const gridPos = new Float32Array(3 * TAIL);

    /** The core's averaged pole (RigidEarth.averagedPole: the uniform precession and the
     * principal nutation, the node at 0 when t = 0) at the times `t` (s), the nod drawn
     * × `scale`: the spin axis's longitude ψ westward from +y (the IAU sense of ψ_A), its
     * obliquity ε from the ecliptic pole, and the Moon's node Ω. */
    const poleAt = (t: number[], scale = nod) => {
      const pole = earth!.averagedPole(t, 0, scale);
      try {
        return { psi: pole.psi, eps: pole.obliquity, node: pole.moonNode };
      } finally {
        pole.free();
      }
    };
    /** Direction (ecliptic axes, z the ecliptic pole) of the axis at (ψ, ε). */
    const direction = (psi: number, eps: number) =>
      new THREE.Vector3(Math.sin(eps) * Math.sin(psi), Math.sin(eps) * Math.cos(psi), Math.cos(eps));
    /** The grid samples first … last (inclusive) of the tail, keeping those already drawn. */
    const gridTo = (first: number, last: number) => {
      const keep0 = Math.max(first, gridFirst);
      const keep1 = Math.min(last, gridFirst + gridCount - 1);
      const kept = first >= gridFirst ? Math.max(0, keep1 - keep0 + 1) : 0;
      if (kept > 0) gridPos.copyWithin(0, 3 * (keep0 - gridFirst), 3 * (keep1 - gridFirst + 1));
      const from = kept > 0 ? keep1 + 1 : first;
      const times: number[] = [];
      for (let i = from; i <= last; i++) times.push(i * gridStep);
      if (times.length > 0) {
        const { psi, eps } = poleAt(times);
        for (let j = 0; j < times.length; j++) {
          const k = 3 * (from - first + j);
          const se = AXIS * Math.sin(eps[j]);
          gridPos[k] = se * Math.sin(psi[j]);
          gridPos[k + 1] = se * Math.cos(psi[j]);
          gridPos[k + 2] = AXIS * Math.cos(eps[j]);
        }
      }
      gridFirst = first;
      gridCount = Math.max(0, last - first + 1);
    };

    return {
      configure(params) {
        p = params;
        const next = new RigidEarth(Number(p.flattening), Earth.siderealRate(), Number(p.obliquity) * DEG);
        try {
          rate = next.precessionRate;
          parts = Array.from(next.precessionParts);
          period = next.precessionPeriod;
          nodePeriod = next.moonNodePeriod;
          nut = Array.from(next.nutationAmplitudes);
          euler = next.eulerPeriod;
          chandler = next.chandlerPeriod(K2, KS);
          iau = -RigidEarth.iau2006PrecessionRate();
        } catch (e) {
          next.free();
          throw e;
        }
        earth?.free();
        earth = next;
        eps0 = Number(p.obliquity) * DEG;
        nod = Number(p.nod);
        const f = Math.min(MAX_FLATTENING, BULGE * Number(p.flattening));
        figure.scale.set(1, 1, 1 - f);
        if (precessionCone) disposeTree(precessionCone);
        precessionCone = cone(eps0, AXIS, 0xf2b84b, 0.16);
        coneHolder.add(precessionCone);
        ctx.labels.move(coneLabel, new THREE.Vector3(-AXIS * Math.sin(eps0) * 1.15, -0.2, AXIS * Math.cos(eps0)));
        tailYears = NaN;
        // The tail spans TAIL_NODES node periods in TAIL − 2 grid steps (plus the current point).
        gridStep = (TAIL_NODES * nodePeriod) / (TAIL - 2);
        gridCount = 0;
        const drawn = f / Number(p.flattening);
        // A phone's view is small: the same facts, in fewer words.
        exaggeration.textContent = ctx.overlay.clientWidth >= NARROW_STAGE
          ? `Bulge drawn ×${Math.round(drawn)} (the real Earth: 1/298 flatter at the poles); ` +
            (nod === 1 ? "the nod to scale (too small to see); " : `the 18.6-year nod drawn ×${nod}; `) +
            "the Sun and the Moon drawn at a solstice, where they pull hardest"
          : `Drawn: bulge ×${Math.round(drawn)}, ` + (nod === 1 ? "nod to scale" : `18.6-year nod ×${nod}`) + "; Sun, Moon at a solstice";
      },
      step(t) {
        if (!earth) return;
        const years = Math.max(0, t) * Number(p.yearsPerSecond);
        const seconds = years * YEAR;
        const { psi: psiNow, eps: epsNow } = poleAt([seconds]);
        const now = { eps: epsNow[0], dir: direction(psiNow[0], epsNow[0]) };
        body.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), now.dir);
        // The tail: the last TAIL_NODES node periods (or less, from the start), sampled finely
        // enough to show each nod: the grid samples in that span, then the current point.
        const span = Math.min(years, (TAIL_NODES * nodePeriod) / YEAR);
        let drawnPoints = 0;
        if (years !== tailYears) {
          tailYears = years;
          const last = Math.floor(seconds / gridStep);
          gridTo(Math.max(0, last - (TAIL - 2)), last);
          tailPos.set(gridPos.subarray(0, 3 * gridCount));
          tailPos.set(now.dir.clone().multiplyScalar(AXIS).toArray(), 3 * gridCount);
        }
        drawnPoints = span > 0 ? gridCount + 1 : 0;
        (tail.geometry.getAttribute("position") as THREE.BufferAttribute).needsUpdate = true;
        tail.geometry.setDrawRange(0, drawnPoints);
        const mid = 3 * Math.floor(drawnPoints / 3);
        ctx.labels.move(tailLabel, new THREE.Vector3(tailPos[mid], tailPos[mid + 1], tailPos[mid + 2]).multiplyScalar(1.12));
        tailLabel.hidden = span <= 0;
        // The solstice direction: the axis's lean, projected on the ecliptic.
        const lean = new THREE.Vector3(now.dir.x, now.dir.y, 0).normalize();
        const sunAt = lean.clone().multiplyScalar(SUN_AT);
        const moonAt = lean.clone().multiplyScalar(-MOON_AT);
        sun.position.copy(sunAt);
        moon.position.copy(moonAt);
        ctx.labels.move(sunLabel, sunAt.clone().add(new THREE.Vector3(0, 0, 0.38)));
        ctx.labels.move(moonLabel, moonAt.clone().add(new THREE.Vector3(0, 0, 0.28)));
        // The near side of the bulge to each body (on the drawn, flattened equator).
        const eq = lean.clone().multiplyScalar(Math.cos(now.eps)).add(new THREE.Vector3(0, 0, -Math.sin(now.eps))).multiplyScalar(RADIUS);
        const sunPullLen = 0.55, moonPullLen = 0.55 * Math.min(3, Math.abs(parts[1] / parts[0]));
        sunPull.set(sunAt.clone().sub(eq).normalize().multiplyScalar(sunPullLen), eq);
        const eqFar = eq.clone().negate();
        moonPull.set(moonAt.clone().sub(eqFar).normalize().multiplyScalar(Math.min(0.9, moonPullLen)), eqFar);
        ctx.labels.move(pullLabel, eq.clone().add(sunAt.clone().sub(eq).normalize().multiplyScalar(sunPullLen + 0.15)));
        // The torques (of the orbit-averaged pull): along the motion of the axis's tip, which
        // turns at the signed rate about the ecliptic pole, ŝ′ = ψ̇ k̂ × ŝ (westward: ψ̇ < 0);
        // each as long as its part of ψ̇.
        const dir = new THREE.Vector3(0, 0, 1).cross(now.dir).normalize().multiplyScalar(Math.sign(rate));
        const tip = now.dir.clone().multiplyScalar(AXIS);
        const scale = 1.3 / Math.abs(parts[0] + parts[1]);
        const nSun = dir.clone().multiplyScalar(Math.abs(parts[0]) * scale);
        const nMoon = dir.clone().multiplyScalar(Math.abs(parts[1]) * scale);
        sunTorque.set(nSun, tip);
        moonTorque.set(nMoon, tip.clone().add(nSun));
        ctx.labels.move(torqueLabel, tip.clone().add(nSun).add(nMoon).add(dir.clone().multiplyScalar(0.3)).add(new THREE.Vector3(0, 0, 0.1)));
        clock.textContent = `${Math.floor(years)} years from the start (1 s = ${Number(p.yearsPerSecond)} years)`;

        const pole = poleAt([seconds], 1);
        const real = { psi: pole.psi[0], eps: pole.eps[0], node: pole.node[0] };
        const lon = (((real.psi / DEG) % 360) + 360) % 360;
        const nodeDeg = (((real.node / DEG) % 360) + 360) % 360;
        out = [
          { key: "years", label: "time (years from the start)", value: years, text: fmt(years, 6) },
          { key: "precessionPeriod", label: "precession", value: period, text: `one turn every ${fmt(period / YEAR, 5)} years` },
          { key: "precessionRate", label: "precession rate (″ per year; − westward)", unitScale: ARCSEC_PER_YEAR, value: rate, text: fmt(rate * ARCSEC_PER_YEAR, 5) },
          { key: "precessionParts", label: "by the Sun, by the Moon (″ per year)", unitScale: ARCSEC_PER_YEAR, value: parts, text: `${fmt(parts[0] * ARCSEC_PER_YEAR, 4)}, ${fmt(parts[1] * ARCSEC_PER_YEAR, 4)}` },
          { key: "iau2006", label: "measured: IAU 2006 luni-solar (″ per year)", unitScale: ARCSEC_PER_YEAR, value: iau, text: fmt(iau * ARCSEC_PER_YEAR, 5) },
          { key: "nutation", label: "nutation Δψ₀, Δε₀ (″, 18.6 years)", unitScale: 1 / ARCSEC, value: nut, text: `${fmt(nut[0] / ARCSEC, 4)}, ${fmt(nut[1] / ARCSEC, 4)}` },
          { key: "eulerPeriod", label: "Euler period (rigid Earth, 2.83)", value: euler, text: `${fmt(euler / (2 * Math.PI / Earth.siderealRate()), 3)} sidereal days` },
          { key: "chandlerPeriod", label: `Chandler (elastic: k₂ ${fmt(K2, 2)}, kₛ ${fmt(KS, 3)})`, value: chandler, text: `${fmt(chandler / 86400, 3)} d` },
          { key: "chandlerObserved", label: "Chandler (observed)", value: chandlerObserved, detail: `the core's fit of the pole path in the inset (IERS EOP 20 C04): 1-σ ${fmt(chandlerSigma / 86400, 2)} d`, text: `${fmt(chandlerObserved / 86400, 3)} d` },
          { key: "poleLongitude", label: `axis longitude ψ (${A.name}, westward)`, unitScale: A.angleScale, value: lon * DEG, text: A.angle(lon * DEG, 5) },
          { key: "obliquityNow", label: `obliquity ε(t) (${A.name})`, unitScale: A.angleScale, value: real.eps, text: A.angle(real.eps, 7) },
          { key: "node", label: `Moon's node Ω (${A.name})`, unitScale: A.angleScale, value: nodeDeg * DEG, text: A.angle(nodeDeg * DEG, 4) },
          { check: true, key: "precessionVsIau", label: "precession rate / IAU 2006 − 1", value: rate / iau - 1, text: fmt(rate / iau - 1, 3) },
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        return { center: new THREE.Vector3(0, 0, 0.1), radius: SUN_AT + 0.3 };
      },
      main() {
        return [body, coneHolder, sun, moon];
      },
      dispose() {
        earth?.free();
        earth = null;
        disposeTree(root);
      },
    };
  },
};
