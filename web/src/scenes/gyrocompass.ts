// Gyrocompass (issue 26): a top on the turning Earth. A pendulous gyrocompass on a ship at a
// latitude: a rotor whose spin axis is held near the horizontal by a pendulous case; whenever the
// Earth's rotation tilts the axis, gravity torques it, and it spirals onto the meridian. Started
// off north it swings about the meridian once a Schuler period, 2π √(R/g) = 84.4 min (the rotor's
// momentum chosen for it: the core's `Gyrocompass.schulerTuned`), the swing shrinking with the
// damping. On a moving ship it settles on the horizontal part of the local frame's whole rotation
// (the Earth's plus the ship's over the curved Earth): off north by the steaming error, exact and
// in the manufacturers' small-angle form. The second view is Foucault's free gyroscope (1852):
// a rotor on its centre of mass keeps its axis fixed in space, so that, seen from the ground, a
// horizontal axis drifts clockwise (in the north) at Ω sin λ.
//
// Every number comes from the core: the period, the errors, and the motion, which is the core's
// full simulation of the compass as a rigid gyrostat carried by the ship's frame
// (`Gyrocompass.simulate`) and of the free rotor carried by the place (`freeGyroscope`, the
// exact flow); the scene samples their runs (linear between samples) at the clock's time.
import * as THREE from "three";
import { Earth, fixedAxisHeadingRate, freeGyroscope, Gyrocompass, type CompassRun } from "../core";
import { angles, DEG, fmt, type Params, type Readout, type SceneDef } from "../scene";
import { Arrow, bufferLine, compass, disposeTree } from "../view";

const A = angles("°");
/** A knot (m/s). */
const KNOT = 1852 / 3600;
/** The sensitive element's moments about its pivot (kg·m², spin, horizontal, up): ten times the
 * core's default, so that its fast nutation (H/I ≈ 4 rad/s) costs the browser ten times fewer
 * steps; the settling does not depend on them (the core's docs). */
export const LAB_INERTIA = [5, 10, 10];
/** The compass's run: this many undamped periods, sampled this many times. */
const PERIODS = 5;
const SAMPLES = 1201;
/** How many runs the scene keeps to show again without the core (about 30 kB each). */
const RUNS_KEPT = 32;
/** Foucault's gyroscope: one sidereal day, sampled every 2 minutes; its spin (rad/s). */
const GYRO_SAMPLES = 719;
const GYRO_SPIN = 100;
/** The drawn tilt: × TILT_DRAWN (a tilt of a degree would not show). */
const TILT_DRAWN = 10;
/** Drawn sizes (scene units): the compass card, the spin axis. */
const CARD = 1.3;
const AXIS = 1.05;
const TRAIL = 1200;
export const GYRO_VIEWS = ["compass", "Foucault's gyroscope"];

/** Linear interpolation of `ys` sampled at the evenly spaced `ts` at time `t` (clamped). */
function sample(ts: ArrayLike<number>, ys: ArrayLike<number>, t: number): number {
  const n = ts.length;
  const dt = (ts[n - 1] - ts[0]) / (n - 1);
  const x = Math.min(n - 1, Math.max(0, (t - ts[0]) / dt));
  const i = Math.min(n - 2, Math.floor(x));
  const f = x - i;
  return ys[i] + f * (ys[i + 1] - ys[i]);
}

/** The end of the spin axis drawn at `heading` (clockwise from north) and `tilt` (up), rad. */
function axisDir(heading: number, tilt: number): THREE.Vector3 {
  const c = Math.cos(tilt);
  return new THREE.Vector3(c * Math.sin(heading), c * Math.cos(heading), Math.sin(tilt));
}

/** Hours and minutes of `s` seconds, "3 h 07 min". */
function clockText(s: number): string {
  const m = Math.floor(s / 60);
  return `${Math.floor(m / 60)} h ${String(m % 60).padStart(2, "0")} min`;
}

export const gyrocompassScene: SceneDef = {
  id: "gyrocompass",
  title: "Gyrocompass",
  short: "Gyrocompass",
  rateUnit: "°",
  pinned: (p) => (p.view === GYRO_VIEWS[1] ? ["gyroHeading", "driftRate", "unitDriftRate"] : ["heading", "period", "speedError", "settleError"]),
  describe:
    "a compass card on a ship's deck with north marked; the gyrocompass's spin axis (an arrow, its north-seeking end) starts off north and spirals onto the meridian, its path traced; " +
    "the ship's heading drawn on the deck; in the second view, Foucault's free gyroscope, whose axis drifts against the compass card",
  blurb:
    "A gyrocompass is a heavy top carried by the turning Earth: a fast rotor in a case that hangs below its pivot. As the Earth turns, the horizon tilts under the rotor's axis; gravity then pulls on the case, and the rotor's answer is to turn its axis towards the meridian (2.98–2.121 in a frame turning at Ω(0, cos λ, sin λ), 2.29). " +
    "Started off north it swings about north and settles there, once every 84.4 minutes when its rotor is sized for Schuler's period 2π√(R/g), which makes it blind to the ship's accelerations. " +
    "On a moving ship it settles on the rotation of the ship's own frame, off north by the steaming error. Foucault's free gyroscope (second view) keeps its axis fixed among the stars: against the ground it drifts at Ω sin λ.",
  params: [
    { kind: "choice", key: "view", label: "view", options: GYRO_VIEWS, value: GYRO_VIEWS[0] },
    { kind: "number", key: "latitude", label: "latitude λ", unit: "°", min: -82, max: 82, step: 0.5, value: 50 },
    { kind: "number", key: "heading0", label: "started off north by", unit: "°", min: -90, max: 90, step: 1, value: 30 },
    { kind: "number", key: "speed", label: "ship's speed", unit: "kn", min: 0, max: 50, step: 0.5, value: 0, when: (p) => p.view !== GYRO_VIEWS[1] },
    { kind: "number", key: "course", label: "ship's course", unit: "°", min: 0, max: 359, step: 1, value: 0, when: (p) => p.view !== GYRO_VIEWS[1] },
    { kind: "number", key: "damping", label: "damping ratio ζ", unit: "", min: 0, max: 0.9, step: 0.01, value: 0.3, when: (p) => p.view !== GYRO_VIEWS[1] },
    { kind: "number", key: "minutesPerSecond", label: "time runs at", unit: "min per second", min: 1, max: 240, step: 1, scale: "log", value: 20 },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);

    // The deck: a disc with the compass card (N, E, S, W; east +x, north +y).
    const deck = new THREE.Mesh(new THREE.CircleGeometry(CARD * 1.05, 96), new THREE.MeshStandardMaterial({ color: 0x3a3228, roughness: 0.9, side: THREE.DoubleSide }));
    root.add(deck);
    root.add(compass(ctx.labels, CARD, 0.004));
    // True north (the meridian) and where the compass will settle.
    const meridian = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, -CARD, 0.006), new THREE.Vector3(0, CARD, 0.006)]),
      new THREE.LineDashedMaterial({ color: 0x7ad38a, dashSize: 0.06, gapSize: 0.04 }),
    );
    meridian.computeLineDistances();
    root.add(meridian);
    const settleLine = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, 0.008), new THREE.Vector3(0, CARD * 0.95, 0.008)]),
      new THREE.LineBasicMaterial({ color: 0xf2b84b }),
    );
    root.add(settleLine);
    const settleLabel = ctx.labels.add("settles here", new THREE.Vector3(), { className: "label3d mark", color: "#f2b84b" });
    // The ship: a hull outline pointing along its course.
    const hull = new THREE.Shape();
    hull.moveTo(0, 0.5);
    hull.quadraticCurveTo(0.16, 0.15, 0.13, -0.4);
    hull.lineTo(-0.13, -0.4);
    hull.quadraticCurveTo(-0.16, 0.15, 0, 0.5);
    const ship = new THREE.Mesh(new THREE.ShapeGeometry(hull), new THREE.MeshBasicMaterial({ color: 0x9fc3e6, transparent: true, opacity: 0.35, side: THREE.DoubleSide }));
    ship.position.set(-CARD * 0.55, -CARD * 0.55, 0.01);
    root.add(ship);
    const shipLabel = ctx.labels.add("ship", new THREE.Vector3(-CARD * 0.55, -CARD * 0.55 - 0.55, 0.01), { className: "label3d mark", color: "#9fc3e6" });

    // The sensitive element: a post, the rotor (a disc) and its spin axis, carried by `element`
    // whose x axis is the spin axis's north-seeking end.
    const post = new THREE.Mesh(new THREE.CylinderGeometry(0.02, 0.02, 0.35, 12), new THREE.MeshStandardMaterial({ color: 0x9aa4b1 }));
    post.rotation.x = Math.PI / 2;
    post.position.z = 0.175;
    root.add(post);
    const element = new THREE.Group();
    element.position.z = 0.35;
    root.add(element);
    const rotor = new THREE.Mesh(new THREE.CylinderGeometry(0.28, 0.28, 0.08, 40), new THREE.MeshStandardMaterial({ color: 0xc9a25c, metalness: 0.4, roughness: 0.4 }));
    rotor.rotation.z = Math.PI / 2; // the cylinder's axis (y) → x
    element.add(rotor);
    const spinAxis = new Arrow(0xffffff);
    spinAxis.set(new THREE.Vector3(AXIS, 0, 0), new THREE.Vector3(-0.3, 0, 0));
    element.add(spinAxis.obj);
    const tailEnd = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(-0.3, 0, 0), new THREE.Vector3(-0.6, 0, 0)]),
      new THREE.LineBasicMaterial({ color: 0x9aa4b1 }),
    );
    element.add(tailEnd);
    const axisLabel = ctx.labels.add("spin axis", new THREE.Vector3(AXIS - 0.2, 0, 0.14), { obj: element, className: "label3d axis" });
    // The sphere the axis's end moves on (its upper half, translucent).
    const dome = new THREE.Mesh(
      new THREE.SphereGeometry(AXIS - 0.25, 48, 24, 0, 2 * Math.PI, 0, Math.PI / 2),
      new THREE.MeshStandardMaterial({ color: 0x3e7bfa, transparent: true, opacity: 0.12, depthWrite: false, side: THREE.DoubleSide }),
    );
    dome.rotation.x = Math.PI / 2; // the sphere's pole (y) → z
    dome.position.z = 0.35;
    root.add(dome);
    // The path of the axis's end, and the celestial pole (Foucault's view).
    const trailPos = new Float32Array(3 * TRAIL);
    const trail = bufferLine(trailPos, 0xf2b84b);
    root.add(trail);
    const poleLine = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineDashedMaterial({ color: 0x7cc4ff, dashSize: 0.06, gapSize: 0.04 }));
    root.add(poleLine);
    const poleLabel = ctx.labels.add("celestial pole", new THREE.Vector3(), { className: "label3d mark", color: "#7cc4ff" });

    // The clock and what is exaggerated, on the view.
    const note = document.createElement("div");
    note.className = "hud-note hud gyrocompass-note";
    Object.assign(note.style, { position: "absolute", left: "0.5rem", top: "0.5rem", whiteSpace: "pre-line", maxWidth: "17rem", fontSize: ".74rem" });
    const clock = document.createElement("div");
    clock.style.fontVariantNumeric = "tabular-nums";
    const said = document.createElement("div");
    note.append(clock, said);
    ctx.overlay.append(note);

    // The side panel: the axis's heading against its tilt (the spiral onto north).
    const fig = document.createElement("figure");
    fig.className = "gyrocompass-plot";
    const canvas = document.createElement("canvas");
    canvas.width = 640;
    canvas.height = 360;
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", "the spin axis's tilt against its heading: a spiral onto north");
    canvas.style.width = "100%";
    const caption = document.createElement("figcaption");
    caption.style.fontSize = "0.8em";
    fig.append(canvas, caption);
    fig.style.margin = "0.5em 0";
    ctx.panel.append(fig);

    ctx.camera.position.set(1.6, -3.4, 2.6);
    ctx.target.set(0, 0, 0.25);

    let p: Params = {};
    let gyro = false;
    let c: Gyrocompass | null = null;
    let run: { t: ArrayLike<number>; heading: ArrayLike<number>; tilt: ArrayLike<number> } = { t: [0, 1], heading: [0, 0], tilt: [0, 0] };
    let quats: ArrayLike<number> = [];
    /** The last RUNS_KEPT runs by their inputs, the most recent last (a run takes the core a
     * few hundred ms in the browser; the samples are copies, kept in JavaScript). */
    const runs = new Map<string, { run?: typeof run; quats?: ArrayLike<number> }>();
    const remember = (key: string, value: { run?: typeof run; quats?: ArrayLike<number> }) => {
      runs.delete(key);
      runs.set(key, value);
      if (runs.size > RUNS_KEPT) runs.delete(runs.keys().next().value as string);
    };
    let period = 0;
    let speedError = 0;
    let smallAngle = 0;
    let settleError = 0;
    let settleTilt = 0;
    let groundSpeed = 0;
    let duration = 1;
    let lat = 0;
    let out: Readout[] = [];
    let tNow = 0;

    /** The ground-seen spin axis of Foucault's gyroscope at time `t` (s): the core's attitude,
     * the nearest samples blended (its x axis). */
    const gyroAxis = (t: number): THREE.Vector3 => {
      const n = quats.length / 4;
      const x = Math.min(n - 1, Math.max(0, (t / duration) * (n - 1)));
      const i = Math.min(n - 2, Math.floor(x));
      const q0 = new THREE.Quaternion(quats[4 * i + 1], quats[4 * i + 2], quats[4 * i + 3], quats[4 * i]);
      const q1 = new THREE.Quaternion(quats[4 * i + 5], quats[4 * i + 6], quats[4 * i + 7], quats[4 * i + 4]);
      return new THREE.Vector3(1, 0, 0).applyQuaternion(q0.slerp(q1, x - i));
    };
    const headingOf = (v: THREE.Vector3) => Math.atan2(v.x, v.y);
    const tiltOf = (v: THREE.Vector3) => Math.atan2(v.z, Math.hypot(v.x, v.y));

    /** Where the motion is at time t: heading and tilt (rad). */
    const at = (t: number) => {
      if (gyro) {
        const v = gyroAxis(t);
        return { heading: headingOf(v), tilt: tiltOf(v) };
      }
      return { heading: sample(run.t, run.heading, t), tilt: sample(run.t, run.tilt, t) };
    };

    /** The run's heading and tilt (°) at its samples, for the plot (set by `configure`). */
    let pts: { h: number; v: number; t: number }[] = [];

    function drawPlot(): void {
      const g = canvas.getContext("2d");
      if (!g) return;
      const W = canvas.width, H = canvas.height, k = 2;
      const pad = { l: 52 * k, r: 10 * k, t: 8 * k, b: 30 * k };
      g.setTransform(1, 0, 0, 1, 0, 0);
      g.fillStyle = "#101418";
      g.fillRect(0, 0, W, H);
      const x0 = pad.l, x1 = W - pad.r, y0 = pad.t, y1 = H - pad.b;
      const hs = pts.map((q) => q.h), vs = pts.map((q) => q.v);
      const hMax = Math.max(1e-6, ...hs.map(Math.abs)) * 1.1;
      const vMin = Math.min(...vs), vMax = Math.max(...vs);
      const vPad = Math.max(1e-6, 0.1 * (vMax - vMin));
      const px = (h: number) => x0 + ((h + hMax) / (2 * hMax)) * (x1 - x0);
      const py = (v: number) => y1 - ((v - (vMin - vPad)) / (vMax - vMin + 2 * vPad)) * (y1 - y0);
      g.strokeStyle = "#3a4652";
      g.lineWidth = 1;
      g.strokeRect(x0, y0, x1 - x0, y1 - y0);
      g.beginPath();
      g.moveTo(px(0), y0);
      g.lineTo(px(0), y1);
      g.stroke();
      g.font = `${11 * k}px system-ui, sans-serif`;
      g.fillStyle = "#9aa4ae";
      g.textBaseline = "top";
      g.textAlign = "left";
      g.fillText(fmt(-hMax, 3), x0, y1 + 4);
      g.textAlign = "right";
      g.fillText(fmt(hMax, 3), x1, y1 + 4);
      g.textAlign = "center";
      g.fillText("north", px(0), y1 + 4);
      g.fillText("heading (°, east +)", (x0 + x1) / 2, y1 + 16 * k);
      g.textBaseline = "middle";
      g.textAlign = "right";
      g.fillText(fmt(vMax, 3), x0 - 6, py(vMax));
      g.fillText(fmt(vMin, 3), x0 - 6, py(vMin));
      g.save();
      g.translate(10 * k, (y0 + y1) / 2);
      g.rotate(-Math.PI / 2);
      g.textAlign = "center";
      g.fillText("tilt (°)", 0, 0);
      g.restore();
      // The whole path dim, the part up to now bright, the state a dot.
      for (const [alpha, upTo] of [[0.25, duration], [1, tNow]] as const) {
        g.strokeStyle = `rgba(242, 184, 75, ${alpha})`;
        g.lineWidth = 1.5 * k;
        g.beginPath();
        // A heading that wraps through ±180° starts a new piece of line (no stroke across the plot).
        pts
          .filter((q) => q.t <= upTo)
          .forEach((q, i, all) => (i && Math.abs(q.h - all[i - 1].h) <= 180 ? g.lineTo(px(q.h), py(q.v)) : g.moveTo(px(q.h), py(q.v))));
        g.stroke();
      }
      const now = at(tNow);
      g.fillStyle = "#ffffff";
      g.beginPath();
      g.arc(px(now.heading / DEG), py(now.tilt / DEG), 4 * k, 0, 2 * Math.PI);
      g.fill();
    }

    const release = () => {
      c?.free();
      c = null;
    };

    return {
      configure(params) {
        p = params;
        gyro = p.view === GYRO_VIEWS[1];
        lat = Number(p.latitude) * DEG;
        const heading0 = Number(p.heading0) * DEG;
        const next = Gyrocompass.schulerTuned(lat, Gyrocompass.defaultPendulosity(), Number(p.damping), LAB_INERTIA);
        let r: CompassRun | null = null;
        try {
          const speed = Number(p.speed) * KNOT, course = Number(p.course) * DEG;
          period = next.period;
          speedError = next.speedError(speed, course);
          smallAngle = next.speedErrorSmallAngle(speed, course);
          settleError = next.settleError;
          settleTilt = next.settleTilt;
          groundSpeed = next.groundSpeed;
          // The core's run for these inputs, computed once: moving a slider back to a value
          // seen before (or one the run does not depend on, the clock's speed) reuses it.
          const key = JSON.stringify(gyro ? [lat, heading0] : [lat, heading0, Number(p.damping), speed, course]);
          const seen = runs.get(key);
          if (gyro) {
            duration = (2 * Math.PI) / Earth.siderealRate();
            quats = seen?.quats ?? freeGyroscope(lat, heading0, 0, GYRO_SPIN, duration, GYRO_SAMPLES);
            remember(key, { quats });
          } else {
            duration = PERIODS * period;
            if (seen?.run) {
              run = seen.run;
            } else {
              r = next.simulate(duration, heading0, settleTilt, speed, course, SAMPLES);
              run = { t: r.times, heading: r.heading, tilt: r.tilt };
            }
            remember(key, { run });
          }
        } catch (e) {
          next.free();
          throw e;
        } finally {
          r?.free();
        }
        release();
        c = next;
        const settled = -settleError - speedError;
        settleLine.geometry.setFromPoints([new THREE.Vector3(0, 0, 0.008), axisDir(settled, 0).multiplyScalar(CARD * 0.95).setZ(0.008)]);
        ctx.labels.move(settleLabel, axisDir(settled, 0).multiplyScalar(CARD * 0.7).setZ(0.02).add(new THREE.Vector3(0.18, 0, 0)));
        settleLine.visible = !gyro;
        settleLabel.hidden = gyro;
        ship.rotation.z = -Number(p.course) * DEG;
        ship.visible = !gyro && Number(p.speed) > 0;
        shipLabel.hidden = !ship.visible;
        // The celestial pole: north, up at the latitude (below the horizon in the south).
        const pole = new THREE.Vector3(0, Math.cos(lat), Math.sin(lat)).multiplyScalar(AXIS * 1.2);
        poleLine.geometry.setFromPoints([new THREE.Vector3(0, 0, 0.35), pole.clone().add(new THREE.Vector3(0, 0, 0.35))]);
        poleLine.computeLineDistances();
        poleLine.visible = gyro;
        ctx.labels.move(poleLabel, pole.clone().multiplyScalar(1.1).add(new THREE.Vector3(0, 0, 0.35)));
        poleLabel.hidden = !gyro;
        rotor.scale.set(gyro ? 0.8 : 1, 1, gyro ? 0.8 : 1);
        said.textContent = gyro
          ? "Foucault's gyroscope: a free rotor on its centre of mass, its axis fixed among the stars; the card turns with the Earth under it"
          : `Tilt drawn ×${TILT_DRAWN}; the rotor sized for Schuler's period (H = ${fmt(next.angularMomentum, 3)} kg·m²/s at P = ${fmt(Gyrocompass.defaultPendulosity(), 3)} N·m)`;
        caption.textContent = gyro
          ? "The free gyroscope's axis seen from the ground over a sidereal day: heading against tilt."
          : "The spin axis's tilt against its heading: it swings about north and spirals in (dim: the run ahead).";
        const n = gyro ? quats.length / 4 : run.t.length;
        pts = [];
        for (let i = 0; i < n; i++) {
          const t = (i / (n - 1)) * duration;
          const a = at(t);
          pts.push({ h: a.heading / DEG, v: a.tilt / DEG, t });
        }
        for (let k = 0; k < TRAIL; k++) {
          const t = (k / (TRAIL - 1)) * duration;
          const a = at(t);
          const v = axisDir(a.heading, gyro ? a.tilt : TILT_DRAWN * a.tilt).multiplyScalar(AXIS + 0.05 - 0.3);
          trailPos.set([v.x, v.y, v.z + 0.35], 3 * k);
        }
        (trail.geometry.getAttribute("position") as THREE.BufferAttribute).needsUpdate = true;
      },
      step(t) {
        if (!c) return;
        const seconds = Math.min(duration, Math.max(0, t) * Number(p.minutesPerSecond) * 60);
        tNow = seconds;
        const now = at(seconds);
        const drawnTilt = gyro ? now.tilt : TILT_DRAWN * now.tilt;
        element.quaternion.setFromUnitVectors(new THREE.Vector3(1, 0, 0), axisDir(now.heading, drawnTilt));
        trail.geometry.setDrawRange(0, Math.max(0, Math.round((seconds / duration) * (TRAIL - 1)) + 1));
        clock.textContent = `${clockText(seconds)} from the start (1 s = ${Number(p.minutesPerSecond)} min)` + (seconds >= duration ? ", the run's end" : "");
        axisLabel.hidden = false;
        drawPlot();
        if (gyro) {
          // The heading's rate from the core (fixedAxisHeadingRate: Ω (sin λ − cos λ tan θ cos α)
          // of the axis, fixed among the stars, at the heading and tilt the core's run gives). The
          // unit's Ω sin λ is the drift of a HORIZONTAL axis: the rate at the start, while the
          // axis lies flat; later the axis rises off the horizontal and its heading turns at
          // another rate.
          const start = at(0);
          const rate = fixedAxisHeadingRate(lat, now.heading, now.tilt);
          const startRate = fixedAxisHeadingRate(lat, start.heading, start.tilt);
          const unit = Earth.siderealRate() * Math.sin(lat);
          out = [
            { key: "hours", label: "time (h from the start)", unitScale: 1 / 3600, value: seconds, text: fmt(seconds / 3600, 5) },
            { key: "gyroHeading", label: `axis heading (${A.name}, clockwise from north)`, unitScale: A.angleScale, value: now.heading, text: A.angle(now.heading, 5) },
            { key: "gyroTilt", label: `axis tilt (${A.name})`, unitScale: A.angleScale, value: now.tilt, text: A.angle(now.tilt, 5) },
            { key: "driftRate", label: `drift of the horizontal axis at the start (${A.perHour}, clockwise +)`, unitScale: A.perHourScale, value: startRate, text: A.perHourRate(startRate, 4) },
            { key: "headingRate", label: `the axis's heading turning now (${A.perHour}, clockwise +)`, unitScale: A.perHourScale, value: rate, text: A.perHourRate(rate, 4) },
            { key: "unitDriftRate", label: `the unit's Ω sin λ (${A.perHour})`, unitScale: A.perHourScale, value: unit, text: A.perHourRate(unit, 5) },
          ];
        } else {
          out = [
            { key: "hours", label: "time (h from the start)", unitScale: 1 / 3600, value: seconds, text: fmt(seconds / 3600, 5) },
            { key: "heading", label: `heading of the spin axis (${A.name}, east +)`, unitScale: A.angleScale, value: now.heading, text: A.angle(now.heading, 4) },
            { key: "tilt", label: `tilt (${A.name})`, unitScale: A.angleScale, value: now.tilt, text: A.angle(now.tilt, 4) },
            { key: "period", label: "period of the settling swing", value: period, text: `settles in one swing every ${fmt(period / 60, 3)} min` },
            { key: "schulerPeriod", label: "Schuler's period 2π√(R/g)", value: Gyrocompass.schulerPeriod(), text: `${fmt(Gyrocompass.schulerPeriod() / 60, 4)} min` },
            { key: "speedError", label: `steaming error (${A.name}, + high)`, unitScale: A.angleScale, value: speedError, text: A.angle(speedError, 4, Math.PI) },
            { key: "speedErrorSmallAngle", label: `small-angle form V cos C/(ΩR cos λ) (${A.name})`, unitScale: A.angleScale, value: smallAngle, text: A.angle(smallAngle, 4, Math.PI) },
            { key: "settleError", label: `latitude error (${A.name})`, unitScale: A.angleScale, value: settleError, text: A.angle(settleError, 4, Math.PI) },
            { key: "groundSpeed", label: "the ground's speed ΩR cos λ (kn)", unitScale: 1 / KNOT, value: groundSpeed, text: fmt(groundSpeed / KNOT, 4) },
            { check: true, key: "speedErrorForms", label: `exact − small-angle (${A.name})`, unitScale: A.angleScale, value: speedError - smallAngle, text: A.angle(speedError - smallAngle, 3, Math.PI) },
          ];
        }
      },
      readouts() {
        return out;
      },
      frame() {
        return { center: new THREE.Vector3(0, 0, 0.3), radius: CARD * 1.2 };
      },
      main() {
        return [deck, element];
      },
      dispose() {
        release();
        disposeTree(root);
      },
    };
  },
};
