// Flow into a low (the unit's Fig. 2.7): parcels of air start at rest on a ring around a
// low-pressure centre, the pressure gradient pulls them in, the Coriolis force turns them to the
// right in the north (to the left in the south), friction lets them spiral in. The core
// integrates them; the page draws the map, the tracks and the winds, and reads the sense of the
// circulation out of the simulation. One second of the page is one hour of the simulation. The
// map is drawn to scale (a scale bar says which), with a compass; the page says when the inertial
// circle is too large for the map.
import * as THREE from "three";
import { Earth, type LowFlow } from "../core";
import { angles, DEG, fmt, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { Arrow, axisLabels, compass, disposeTree, fixedAxes, roundDown125, roundText, ScaleBar } from "../view";

/** Radius of the ring the parcels start on (m) and its drawn radius (scene units). */
export const LOW_RADIUS = 5e5;
const RING = 2.2;
/** The run: two days sampled every 6 minutes; one page second is an hour. */
export const LOW_DURATION = 2 * 86400;
export const LOW_SAMPLES = 481;
export const LOW_PARCELS = 8;
export const SECONDS_PER_PAGE_SECOND = 3600;
/** The inertial parcel's speed (m/s) and its run when there is no inertial period (the equator). */
export const INERTIAL_SPEED = 10;
export const INERTIAL_EQUATOR_RUN = 86400;
const A = angles("°");
const COLORS = [0xe5484d, 0xf2b84b, 0x46a758, 0x3ec7c7, 0x3e7bfa, 0x8e6cf0, 0xe56cc4, 0xc9d1d9];

export const lowScene: SceneDef = {
  id: "low",
  title: "Flow into a low",
  short: "Low",
  rateUnit: "°",
  pinned: ["tau", "sense", "circulation", "inertialPeriod"],
  describe: "a round map around a low-pressure centre with isobars, eight parcels of air with their tracks and winds, and the dashed circle of an inertial oscillation; east, north and up are labelled, a compass and a scale bar lie on the map",
  blurb:
    "Air at rest on a ring 500 km from a low-pressure centre is pulled in by the pressure gradient, turned by the Coriolis force (to the right in the north, to the left in the south, not at all at the equator) and slowed by friction. " +
    "The core integrates the parcels; the sense of the circulation is measured from the run: counterclockwise round a northern low, clockwise round a southern one. " +
    "Circulation: the parcels' mean x v_y − y v_x over the run; energy, friction's work and their budget: means over the parcels. " +
    "Rings are isobars, arrows the winds; the dashed circle is an inertial oscillation (a parcel set moving at 10 m/s with no pressure gradient: it circles in 2π/|f|). One second is one hour; the run lasts two days.",
  params: [
    { kind: "number", key: "latitude", label: "latitude λ", unit: "°", min: -90, max: 90, step: 1, value: 40 },
    { kind: "number", key: "pull", label: "pressure pull at the ring", unit: "mm/s²", min: 0.2, max: 3, step: 0.1, value: 1 },
    { kind: "number", key: "friction", label: "friction γ", unit: "10⁻⁵/s", min: 0, max: 10, step: 0.5, value: 3 },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    const map = new THREE.Mesh(new THREE.CircleGeometry(RING * 1.25, 96), new THREE.MeshStandardMaterial({ color: 0x1d2a33, roughness: 1 }));
    root.add(map);
    // Isobars of the paraboloidal low: equal pressure steps at radii ∝ √n.
    for (let n = 1; n <= 6; n++) {
      const r = RING * 1.2 * Math.sqrt(n / 6);
      const ring = new THREE.Mesh(new THREE.RingGeometry(r - 0.006, r + 0.006, 128), new THREE.MeshBasicMaterial({ color: 0x4b6478 }));
      ring.position.z = 0.002;
      root.add(ring);
    }
    const centre = new THREE.Mesh(new THREE.RingGeometry(0.07, 0.12, 48), new THREE.MeshBasicMaterial({ color: 0xe5484d, side: THREE.DoubleSide }));
    centre.position.z = 0.004;
    root.add(centre);
    const axes = fixedAxes(RING * 1.25, 0.5);
    axes.position.z = 0.003;
    root.add(axes);
    // East and north end at the compass ring (its E and N name them); up is labelled.
    axisLabels(ctx.labels, RING * 1.25, ["east", "north", "up"], [0, 1]);
    root.add(compass(ctx.labels, RING * 1.32, 0.001));
    // The map is to scale: a round distance about a unit long.
    const scale = RING / LOW_RADIUS;
    const bar = new ScaleBar(ctx.labels, new THREE.Vector3(-0.45, -2.45, 0.02), new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 0.06, 0));
    const km = roundDown125(1.0 / scale / 1000);
    bar.set(km * 1000 * scale, `${roundText(km)} km`);
    root.add(bar.obj);

    const parcels = COLORS.slice(0, LOW_PARCELS).map((color) => {
      const dot = new THREE.Mesh(new THREE.SphereGeometry(0.06, 20, 12), new THREE.MeshStandardMaterial({ color }));
      const track = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color, transparent: true, opacity: 0.8 }));
      track.frustumCulled = false;
      const wind = new Arrow(color, 1);
      root.add(dot, track, wind.obj);
      return { dot, track, wind };
    });
    // The inertial circle: a parcel set moving at 10 m/s with no pressure gradient, for scale.
    const inertial = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineDashedMaterial({ color: 0x9aa4b1, dashSize: 0.05, gapSize: 0.04 }));
    inertial.frustumCulled = false;
    root.add(inertial);
    // From the south-south-east, above: up stands apart from north on the screen.
    ctx.camera.position.set(2.2, -6, 6.5);
    ctx.target.set(0, 0, 0);

    let p: Params = {};
    let earth: Earth | null = null;
    let flow: LowFlow | null = null;
    let times: Float64Array = new Float64Array();
    let e0: number[] = [];
    let period = Infinity;
    let f = 0;
    let turning = 0;
    let windScale = 1;
    let circScale = 0;
    let out: Readout[] = [];
    let offMap: Readout | null = null;

    const release = () => {
      flow?.free();
      earth?.free();
      flow = null;
      earth = null;
    };

    return {
      configure(params) {
        p = params;
        const lat = Number(p.latitude) * DEG;
        const pull = Number(p.pull) * 1e-3;
        const gamma = Number(p.friction) * 1e-5;
        const nextEarth = new Earth(Earth.siderealRate(), Earth.meanRadius(), Earth.standardGravity());
        let nextFlow: LowFlow;
        let track: Float64Array;
        try {
          nextFlow = nextEarth.flowIntoLow(lat, LOW_RADIUS, LOW_PARCELS, pull, gamma, LOW_DURATION, LOW_SAMPLES);
          period = nextEarth.inertialPeriod(lat);
          f = nextEarth.coriolisParameter(lat);
          // Python's default run of inertial_oscillation: two inertial periods (a day at the equator).
          const run = Number.isFinite(period) ? 2 * period : INERTIAL_EQUATOR_RUN;
          const osc = nextEarth.inertialOscillation(lat, [INERTIAL_SPEED, 0], run, 401);
          turning = osc.turningRate;
          track = osc.track();
          osc.free();
        } catch (e) {
          nextEarth.free();
          throw e;
        }
        release();
        earth = nextEarth;
        flow = nextFlow;
        times = flow.times();
        const start = flow.at(0);
        e0 = parcels.map((_, i) => start[6 * i + 4]);
        parcels.forEach((pc, i) => {
          const tr = flow!.track(i);
          const pts = new Float32Array((tr.length / 2) * 3);
          for (let k = 0; k < tr.length / 2; k++) {
            pts[3 * k] = tr[2 * k] * scale;
            pts[3 * k + 1] = tr[2 * k + 1] * scale;
            pts[3 * k + 2] = 0.01;
          }
          pc.track.geometry.dispose();
          pc.track.geometry = new THREE.BufferGeometry();
          pc.track.geometry.setAttribute("position", new THREE.BufferAttribute(pts, 3));
          pc.track.geometry.setDrawRange(0, 1);
        });
        // The inertial circle drawn from the first parcel's start, eastward.
        const pts: THREE.Vector3[] = [];
        for (let k = 0; k < track.length / 2; k++) pts.push(new THREE.Vector3(RING + track[2 * k] * scale, track[2 * k + 1] * scale, 0.012));
        inertial.geometry.dispose();
        inertial.geometry = new THREE.BufferGeometry().setFromPoints(pts);
        inertial.computeLineDistances();
        // The drawn circle's reach from the centre: beyond the map it is hidden, and the page says so.
        const reach = Math.max(...pts.map((q) => Math.hypot(q.x, q.y)));
        inertial.visible = reach <= RING * 1.25;
        const across = Math.max(...pts.map((q) => Math.hypot(q.x - pts[0].x, q.y - pts[0].y))) / scale / 1000;
        offMap = inertial.visible
          ? null
          : {
              key: "inertialOffMap", label: "inertial circle", value: across, warn: true, pin: true,
              text: Number.isFinite(period) ? `${fmt(across, 3)} km across: larger than the map, not drawn` : "no inertial circle at the equator (a straight line off the map), not drawn",
            };
        // Winds drawn so that the speed the pull alone would give (√(pull · R)) is half the ring.
        windScale = (0.5 * RING) / Math.sqrt(pull * LOW_RADIUS);
        // The scale of x v_y − y v_x: the ring's radius times that speed (a circulation within
        // a few ε of it is round-off: 0 at the equator).
        circScale = LOW_RADIUS * Math.sqrt(pull * LOW_RADIUS);
      },
      step(t) {
        if (!flow) return;
        const T = flow.duration;
        const tau = (Math.max(0, t) * SECONDS_PER_PAGE_SECOND) % T;
        const now = flow.at(tau);
        let k = 0;
        while (k + 1 < times.length && times[k + 1] <= tau) k++;
        let worst = 0;
        let energy = 0;
        parcels.forEach((pc, i) => {
          const [x, y, vx, vy, en, lost] = now.subarray(6 * i, 6 * i + 6);
          pc.dot.position.set(x * scale, y * scale, 0.03);
          pc.wind.set(new THREE.Vector3(vx, vy, 0).multiplyScalar(windScale), new THREE.Vector3(x * scale, y * scale, 0.03));
          pc.track.geometry.setDrawRange(0, k + 1);
          energy += en / parcels.length;
          worst = Math.max(worst, Math.abs(en + lost - e0[i]) / e0[i]);
        });
        const dissipated = Array.from({ length: parcels.length }, (_, i) => now[6 * i + 5]);
        const lostMean = dissipated.reduce((a, b) => a + b, 0) / parcels.length;
        const circ = flow.circulation;
        const sense = flow.sense;
        const first = Array.from(now.subarray(0, 4));
        out = [
          { key: "tau", label: "t in the run (h)", value: tau, text: fmt(tau / 3600, 5) },
          { key: "parcel", label: "parcel 1: x, y (km), v (m/s)", value: first, text: fmtVec([first[0] / 1e3, first[1] / 1e3, first[2], first[3]], 4) },
          { key: "circulation", label: "circulation (m²/s)", value: circ, text: fmt(circ, 8, circScale) },
          { key: "sense", label: "sense (from the run)", value: sense, text: sense === "none" ? "none (no turning)" : `${sense} (seen from above)` },
          { key: "coriolis", label: "f = 2Ω sin λ (1/s)", value: f, text: fmt(f, 6) },
          { key: "inertialPeriod", label: "inertial period (h)", value: period, text: Number.isFinite(period) ? fmt(period / 3600, 6) : "∞ (no inertial circle)" },
          { key: "inertialTurning", label: `inertial turning (${A.perHour})`, unitScale: A.perHourScale, value: turning, text: A.perHourRate(turning, 6) },
          { key: "energy", label: "energy ½v²+½kr² (J/kg)", value: energy, text: fmt(energy, 8) },
          { key: "dissipated", label: "friction's work (J/kg)", value: lostMean, text: fmt(lostMean, 8) },
          { check: true, key: "budgetDrift", label: "budget |E+W−E₀|/E₀", value: worst, text: fmt(worst, 3, 1), warn: worst > 1e-8 },
          ...(offMap ? [offMap] : []),
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        // The map (radius 1.25 ring) and the compass round it.
        return { center: new THREE.Vector3(), radius: RING * 1.32 };
      },
      main() {
        return [map];
      },
      dispose() {
        release();
        disposeTree(root);
      },
    };
  },
};
