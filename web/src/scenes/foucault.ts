// The Foucault pendulum (the unit's 2.30 and 2.33 applied to a spherical pendulum): the core
// integrates the bob in the rotating local frame (Coriolis and centrifugal terms, the string's
// tension) and fits the turn of the swing plane through the turning points; the page draws the
// bob, the wire, the trace on the floor (the rosette) and the swing plane, and reads the fitted
// rate beside −Ω sin λ. The Earth turns once a sidereal day, so the plane needs a day/|sin λ| to
// turn round; a planet spinning faster (the exaggeration factor) makes the turn visible. Where
// the unit's −Ω sin λ stops describing the run (a spin not small against √(g/L), a wide swing),
// the core says so and the page pins its sentence on the view.
import * as THREE from "three";
import { Earth, FoucaultRun as FoucaultRunClass, type FoucaultRun } from "../core";
import { angles, DEG, fmt, fmtDiff, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { axisLabels, compass, disposeTree, fixedAxes, roundDown125, roundText, ScaleBar } from "../view";

/** Height of the point of suspension above the floor (scene units). */
const TOP = 3.4;
/** Drawn length of the wire (scene units); the bob hangs TOP − WIRE above the floor. */
const WIRE = 3.0;
/** Drawn half-width of the swing (scene units): horizontal distances are scaled to it. */
const SWING = 1.5;
/** The run: 120 s sampled every 0.05 s (the trace is drawn through the samples). */
export const FOUCAULT_DURATION = 120;
export const FOUCAULT_SAMPLES = 2401;
const A = angles("°");

/** The regimes of the core's measurement in a few words (the core's sentence, with its figures,
 * is the readout's tooltip). */
const REGIMES: Record<string, string> = {
  precessing: "precessing: the plane turns steadily",
  still: "still: the plane does not turn measurably",
  too_short: "too short: too few swings, or too little turn, to measure a rate",
  unsteady: "unsteady: the plane rocks instead of turning",
  wide_swing: "wide swing: its own precession competes with the Foucault rate",
  not_a_swing: "not a swing: the spin is so fast that the bob runs round a loop",
  no_rest: "no rest: the spin flings the bob off any rest position",
};

/** Whether −Ω sin λ describes the run, in words, from the core's check: its verdict, its
 * departures against its tolerance, Ω/√(g/L) and A/L. */
function unitRateText(run: FoucaultRun): string {
  const tol = FoucaultRunClass.unitRateTolerance();
  const pct = (x: number | undefined) => (x === undefined ? "—" : `${fmt(100 * x, 2, 100)} %`);
  const spin = `Ω/√(g/L) = ${fmt(run.spinRatio, 2)}`;
  const amp = `A/L = ${fmt(run.amplitudeRatio, 2)}`;
  const sd = run.spinDeparture, ad = run.amplitudeDeparture;
  const steady = run.regime === "precessing" || run.regime === "still";
  if (run.unitRateHolds) {
    return ad === undefined
      ? `yes: the plane does not turn measurably, and the small-swing rate is within ${pct(sd)} of −Ω sin λ (${spin})`
      : `yes: the small-swing rate is within ${pct(sd)} of −Ω sin λ (${spin}), the measured rate within ${pct(ad)} of it (${amp})`;
  }
  if (!steady) return `no: the plane does not turn steadily (${REGIMES[run.regime] ?? run.regime}; ${spin}, ${amp})`;
  const why: string[] = [];
  if (sd === undefined || sd > tol) why.push(`Ω is not ≪ √(g/L) (${spin}): the small-swing rate departs from −Ω sin λ by ${pct(sd)}`);
  if (ad !== undefined && ad > tol) why.push(`the swing is wide (${amp}): the measured rate departs from the small-swing rate by ${pct(ad)}`);
  return `no: ${why.join("; and ")}`;
}

export const foucaultScene: SceneDef = {
  id: "foucault",
  title: "Foucault pendulum",
  short: "Foucault",
  rateUnit: "°",
  pinned: ["tau", "precessionRate", "expectedRate", "sense"],
  describe: "a pendulum hanging from a beam over a round floor, its trace on the floor and its swing plane (white); east, north and up are labelled and a compass lies around the floor",
  blurb:
    "The swing plane turns at −Ω sin λ: clockwise seen from above in the north, counterclockwise in the south, not at all at the equator. " +
    "The core integrates the bob in the rotating frame; white: the swing plane at the last turning point, yellow: the bob's trace on the floor (the rosette); it was released towards the north. " +
    "The real Earth needs a day/|sin λ| for a turn, so the spin factor puts the pendulum on a planet spinning that much faster — a physical parameter of the simulated planet, not a faster film. " +
    "−Ω sin λ holds while Ω ≪ √(g/L) and the amplitude ≪ L: push the spin, length or amplitude up to watch the fitted rate part from it; the view says when it no longer applies (the core measures both departures) — " +
    "and where the plane no longer turns steadily (near the equator of a fast planet, a spin not small against √(g/L), a swing too wide) the core's regime says so and gives no rate. " +
    "J = ½v² + gz − ½|Ω×r|², the energy in the rotating frame, is conserved (Coriolis and the wire do no work): its drift checks the integration. " +
    "Horizontal distances are drawn enlarged; red is east, green north.",
  params: [
    { kind: "number", key: "latitude", label: "latitude λ", unit: "°", min: -90, max: 90, step: 1, value: 49 },
    { kind: "number", key: "length", label: "length L", unit: "m", min: 1, max: 100, step: 1, value: 10 },
    { kind: "number", key: "amplitude", label: "amplitude", unit: "m", min: 0.1, max: 5, step: 0.1, value: 1 },
    { kind: "choice", key: "spin", label: "planet's spin × Earth's", options: ["1", "10", "100", "1000"], value: "1000" },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    const floor = new THREE.Mesh(
      new THREE.CircleGeometry(2.1, 96),
      new THREE.MeshStandardMaterial({ color: 0x2a3139, roughness: 0.9, side: THREE.DoubleSide }),
    );
    root.add(floor);
    const rings = new THREE.PolarGridHelper(2.1, 12, 4, 96, 0x3a4654, 0x3a4654);
    rings.rotateX(Math.PI / 2);
    rings.position.z = 0.002;
    root.add(rings);
    const axes = fixedAxes(2.2, 0.8);
    axes.position.z = 0.004;
    root.add(axes);
    // East and north end at the compass ring (its E and N name them); up is labelled.
    axisLabels(ctx.labels, 2.2, ["east", "north", "up"], [0, 1]);
    root.add(compass(ctx.labels, 2.3, 0.002));
    // The horizontal scale bar on the floor, south of the swing, and the enlargement on the view.
    const bar = new THREE.Group();
    root.add(bar);
    const scaleBar = new ScaleBar(ctx.labels, new THREE.Vector3(-0.5, -1.8, 0.01), new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 0.06, 0));
    bar.add(scaleBar.obj);
    const note = document.createElement("div");
    note.className = "hud-note hud";
    Object.assign(note.style, { left: "0.5rem", top: "0.5rem" });
    ctx.overlay.append(note);
    // The support: a beam across the top.
    const beam = new THREE.Mesh(new THREE.BoxGeometry(1.2, 0.12, 0.12), new THREE.MeshStandardMaterial({ color: 0x6b7785 }));
    beam.position.set(0, 0, TOP + 0.06);
    root.add(beam);
    const wireGeom = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, TOP), new THREE.Vector3(0, 0, TOP - WIRE)]);
    const wire = new THREE.Line(wireGeom, new THREE.LineBasicMaterial({ color: 0xc9d1d9 }));
    root.add(wire);
    const bob = new THREE.Mesh(new THREE.SphereGeometry(0.13, 32, 20), new THREE.MeshStandardMaterial({ color: 0xe5484d, metalness: 0.3, roughness: 0.4 }));
    root.add(bob);
    const shadow = new THREE.Mesh(new THREE.CircleGeometry(0.06, 24), new THREE.MeshBasicMaterial({ color: 0x000000, transparent: true, opacity: 0.5 }));
    root.add(shadow);
    // The trace over the floor through every sample, drawn up to the current one.
    const trace = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xf2b84b }));
    trace.frustumCulled = false;
    root.add(trace);
    const planeLine = (color: number, opacity: number) => {
      const l = new THREE.Line(
        new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(-2.1, 0, 0), new THREE.Vector3(2.1, 0, 0)]),
        new THREE.LineBasicMaterial({ color, transparent: true, opacity }),
      );
      l.position.z = 0.008;
      root.add(l);
      return l;
    };
    const nowPlane = planeLine(0xffffff, 1);
    ctx.camera.position.set(3.2, -6.2, 5.2);
    ctx.target.set(0, 0, 1.2);

    let p: Params = {};
    let earth: Earth | null = null;
    let run: FoucaultRun | null = null;
    let times: Float64Array = new Float64Array();
    let turnTimes: Float64Array = new Float64Array();
    let turnAngles: Float64Array = new Float64Array();
    let period = 0;
    let j0 = 0;
    let scaleH = 1;
    let out: Readout[] = [];

    const release = () => {
      run?.free();
      earth?.free();
      run = null;
      earth = null;
    };
    const L0 = () => Number(p.length);
    /** Scene position of an ENU position (m, origin at the suspension). */
    const place = (x: number, y: number, z: number, L: number) =>
      new THREE.Vector3(x * scaleH, y * scaleH, TOP + (z / L) * WIRE);

    return {
      configure(params) {
        p = params;
        const rate = Earth.siderealRate() * Number(p.spin);
        const nextEarth = new Earth(rate, Earth.meanRadius(), Earth.standardGravity());
        let nextRun: FoucaultRun;
        try {
          nextRun = nextEarth.foucault(Number(p.latitude) * DEG, Number(p.length), Number(p.amplitude), 0, FOUCAULT_DURATION, FOUCAULT_SAMPLES);
        } catch (e) {
          nextEarth.free();
          throw e;
        }
        release();
        earth = nextEarth;
        run = nextRun;
        times = run.times();
        turnTimes = run.turnTimes();
        turnAngles = run.turnAngles();
        // Two turning points per swing: the period is twice their mean spacing.
        const n = turnTimes.length;
        period = n > 1 ? (2 * (turnTimes[n - 1] - turnTimes[0])) / (n - 1) : 0;
        j0 = run.jacobiIntegral(0);
        scaleH = SWING / Number(p.amplitude);
        const pos = run.positions();
        const pts = new Float32Array(times.length * 3);
        for (let i = 0; i < times.length; i++) {
          pts[3 * i] = pos[3 * i] * scaleH;
          pts[3 * i + 1] = pos[3 * i + 1] * scaleH;
          pts[3 * i + 2] = 0.006;
        }
        trace.geometry.dispose();
        trace.geometry = new THREE.BufferGeometry();
        trace.geometry.setAttribute("position", new THREE.BufferAttribute(pts, 3));
        trace.geometry.setDrawRange(0, 1);
        // Horizontal distances are scaled by scaleH, vertical ones by WIRE / L.
        const stretch = scaleH / (WIRE / L0());
        const metres = roundDown125(1.0 / scaleH);
        scaleBar.set(metres * scaleH, `${roundText(metres)} m${Math.abs(stretch - 1) < 1e-9 ? "" : ` (drawn ×${roundText(stretch)})`}`);
        note.textContent = Math.abs(stretch - 1) < 1e-9 ? "Distances to scale" : `Horizontal distances ×${roundText(stretch)} against vertical`;
      },
      step(t) {
        if (!run) return;
        const T = run.duration;
        const tau = Math.max(0, t) % T;
        const s = run.state(tau);
        const L = Number(p.length);
        const b = place(s[0], s[1], s[2], L);
        bob.position.copy(b);
        shadow.position.set(b.x, b.y, 0.007);
        const w = wireGeom.getAttribute("position") as THREE.BufferAttribute;
        w.setXYZ(1, b.x, b.y, b.z);
        w.needsUpdate = true;
        // The trace through the samples up to tau.
        let k = 0;
        while (k + 1 < times.length && times[k + 1] <= tau) k++;
        trace.geometry.setDrawRange(0, k + 1);
        // The swing plane at the last turning point before tau (the start before the first).
        let m = -1;
        while (m + 1 < turnTimes.length && turnTimes[m + 1] <= tau) m++;
        nowPlane.visible = m >= 0;
        if (m >= 0) nowPlane.rotation.z = turnAngles[m];
        const j = earth!.jacobiIntegral(Number(p.latitude) * DEG, s);
        // The core's measurement: a rate only where the plane turns steadily (the regime).
        const fitted = run.precessionRate;
        const theory = run.theoryRate;
        const expected = run.expectedRate;
        const regime = run.regime;
        const rateText = (r: number | undefined) => (r === undefined ? "—" : A.rate(r, 6));
        const sense = run.sense;
        const holds = run.unitRateHolds;
        const unitRate = unitRateText(run);
        out = [
          { key: "tau", label: "t in the run (s)", value: tau, text: fmt(tau, 5) },
          { key: "position", label: "bob (x, y, z) (m)", value: Array.from(s.subarray(0, 3)), text: fmtVec(s.subarray(0, 3)) },
          { key: "expectedRate", label: `−Ω sin λ (${A.perSecond})`, unitScale: A.rateScale, value: expected, text: A.rate(expected, 6), warn: !holds },
          { key: "regime", label: "regime", value: regime, text: REGIMES[regime] ?? regime, detail: run.regimeNote, warn: regime !== "precessing" && regime !== "still" },
          { key: "precessionRate", label: `fitted rate (${A.perSecond})`, unitScale: A.rateScale, value: fitted ?? "undefined", text: rateText(fitted) },
          { key: "theoryRate", label: `small-swing theory (${A.perSecond})`, unitScale: A.rateScale, value: theory ?? "undefined", text: rateText(theory) },
          {
            key: "unitRate", label: "does −Ω sin λ apply?", value: holds,
            text: unitRate, detail: run.unitRateNote, warn: !holds, pin: !holds,
          },
          { key: "turningPoints", label: "turning points fitted", value: turnTimes.length, text: String(turnTimes.length) },
          { key: "sense", label: "plane turns", value: sense, text: sense === "none" ? "not at all" : sense === "undefined" ? "— (no steady turn: see the regime)" : `${sense} (seen from above)`, warn: sense === "undefined" },
          { key: "period", label: "swing period (s)", value: period, text: fmt(period, 7) },
          { key: "jacobi", label: "Jacobi J (J/kg)", value: j, text: fmt(j, 12) },
          { check: true, key: "jacobiDrift", label: "J(t) − J(0) (J/kg)", value: j - j0, text: fmtDiff(j, j0), warn: Math.abs(j - j0) > 1e-6 * Math.abs(j0) },
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        // The floor (radius 2.1) and the beam above it.
        return { center: new THREE.Vector3(0, 0, TOP / 2), radius: Math.hypot(2.15, TOP / 2 + 0.1) };
      },
      main() {
        return [floor, beam, bob];
      },
      dispose() {
        release();
        disposeTree(root);
      },
    };
  },
};
