// Poinsot's construction and the tumbling box: the exact torque-free motion of an asymmetric
// body (Jacobi elliptic functions solving the unit's Euler equations 2.72 with N = 0: T and L
// conserved, 2.75–2.76). The body is a uniform box whose sides give three different moments.
//
// View "Poinsot ellipsoid": the inertia ellipsoid ρ·I·ρ = 1, fixed in the body, rolls without
// slipping on the invariable plane ρ·L̂ = (2T)^½/|L|, touching it at ρ = ω/(2T)^½; the polhode
// (orange, on the ellipsoid) and the herpolhode (white, on the plane). The picture is turned
// so that L points down, onto the plane below the fixed centre.
// View "tumbling box": the box spun about one principal axis with a small perturbation; about
// the intermediate axis it flips every half period (the Dzhanibekov effect); about the others it
// only wobbles. Every number comes from the core.
import * as THREE from "three";
import { axisStability, FreeRigidBody, RigidBody } from "../core";
import { fmt, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { Arrow, AXIS_COLORS, axisLabels, bufferLine, disposeTree, fixedAxes, quaternion, vec } from "../view";
import { BOX_MASS, choiceOptions, sceneParams } from "./params";

export const POINSOT_VIEWS = choiceOptions("poinsot", "view");
export const SPIN_AXES = choiceOptions("poinsot", "axis");
/** Display radius of the ellipsoid's longest semi-axis and of the box's longest half-side. */
const R_ELLIPSOID = 1.6;
const R_BOX = 1.45;
/** Display radius of the invariable plane. */
const PLANE_RADIUS = 2.5;
/** Samples of the closed polhode drawn on the ellipsoid. */
const POLHODE_SAMPLES = 480;
/** At most this many points of the herpolhode and of the ω(t) plot. */
const TRAIL_POINTS = 2400;

/** The body axis (0, 1, 2) with the smallest, intermediate or largest of `moments`. */
function axisByRank(moments: number[], rank: string): number {
  const order = [0, 1, 2].sort((i, j) => moments[i] - moments[j]);
  return order[rank === "smallest" ? 0 : rank === "largest" ? 2 : 1];
}

/** The page's ω(0): `spin` about axis `i`, plus `eps`·spin on each of the other two axes. */
export function initialOmega(i: number, spin: number, eps: number): number[] {
  const w = [eps * spin, eps * spin, eps * spin];
  w[i] = spin;
  return w;
}

/** A curve sampled on the fixed grid t_k = k·dt (so that it is the same whether played or
 * seeked), over a window of at most `capacity` points ending at the current time. The samples
 * come from `sample(times)` (a batch call into the core, 3 numbers per time). */
class GridCurve {
  private k0 = 0;
  private pts: number[] = [];
  constructor(
    private readonly sample: (times: Float64Array) => ArrayLike<number>,
    readonly dt: number,
    readonly capacity: number,
  ) {}
  /** Bring the window to [t − (capacity − 1)·dt, t]; returns the first grid index held. */
  update(t: number): number {
    const kNow = Math.floor(t / this.dt);
    const kLo = Math.max(0, kNow - this.capacity + 1);
    const held = this.pts.length / 3;
    const kHi = this.k0 + held - 1;
    let from: number;
    if (held === 0 || kLo > kHi + 1 || kLo < this.k0 || kNow < kHi) {
      this.pts = [];
      this.k0 = kLo;
      from = kLo;
    } else {
      if (kLo > this.k0) {
        this.pts.splice(0, 3 * (kLo - this.k0));
        this.k0 = kLo;
      }
      from = kHi + 1;
    }
    if (from <= kNow) {
      const times = new Float64Array(kNow - from + 1).map((_, j) => (from + j) * this.dt);
      const s = this.sample(times);
      for (let j = 0; j < s.length; j++) this.pts.push(s[j]);
    }
    return this.k0;
  }
  get points(): number[] {
    return this.pts;
  }
}

/** A line whose points are rewritten each frame (up to `capacity`). */
class Polyline {
  readonly obj: THREE.Line;
  private readonly pos: Float32Array;
  constructor(capacity: number, color: number, opacity = 1) {
    this.pos = new Float32Array(3 * capacity);
    this.obj = bufferLine(this.pos, color, opacity);
  }
  set(points: ArrayLike<number>, scale: number, extra?: THREE.Vector3): void {
    const n = Math.min(points.length, this.pos.length - (extra ? 3 : 0));
    for (let i = 0; i < n; i++) this.pos[i] = points[i] * scale;
    let count = n / 3;
    if (extra) {
      this.pos.set([extra.x, extra.y, extra.z], n);
      count++;
    }
    const attr = this.obj.geometry.getAttribute("position") as THREE.BufferAttribute;
    attr.needsUpdate = true;
    this.obj.geometry.setDrawRange(0, count);
  }
}

/** The regime in words, with the axis ω circles (the core's pole axis). */
function regimeText(regime: string, pole: number | undefined): string {
  const axis = pole === undefined ? "" : ` (${"xyz"[pole]})`;
  if (regime === "about max axis") return `about max axis: ω circles the largest-moment axis${axis}`;
  if (regime === "about min axis") return `about min axis: ω circles the smallest-moment axis${axis}`;
  if (regime === "separatrix") return "separatrix: ω tends to the intermediate axis";
  return regime;
}

/** How near the separatrix the motion is, and why: the Jacobi parameter m of the core's exact
 * solution (m = 1 on the separatrix, 0 for a steady or symmetric motion), shown as 1 − m, with
 * the core's linear stability of the spun axis. */
function separatrixReadout(m: number, regime: string, pole: number | undefined, spun: number, spunStability: string): Readout {
  const gap = fmt(1 - m, 3, 1);
  const side = regime === "about max axis" ? "above" : regime === "about min axis" ? "below" : "";
  const circled = pole === undefined ? "" : "xyz"[pole];
  const axis = "xyz"[spun];
  let text: string;
  if (regime === "separatrix" || gap === "0") text = "1 − m = 0: on the separatrix";
  else if (regime === "steady" || regime === "symmetric") text = `1 − m = ${gap}: ${regime}, no separatrix`;
  else if (spunStability === "unstable")
    text = `1 − m = ${gap}, just ${side} it: a spin about ${axis} is unstable, ε moves ω off the separatrix, so ω circles ${circled} and flips past ±${axis}`;
  else text = `1 − m = ${gap}, ${side} it: a spin about ${axis} is ${spunStability}, ω circles ${circled}`;
  return { key: "separatrix", label: "from the separatrix (m = 1)", value: m, text };
}

export const poinsotScene: SceneDef = {
  id: "poinsot",
  title: "Poinsot & tumbling box",
  short: "Poinsot",
  rateUnit: "rad",
  pinned: ["regime", "separatrix", "spinComponent", "flipInterval"],
  describe: "either the inertia ellipsoid rolling on the invariable plane below it, with the polhode (orange) and the herpolhode (white), or a box tumbling about its centre with the arrows of ω (white) and L (blue); the body axes 1, 2, 3 and the fixed axes x, y, z are labelled",
  blurb:
    "A free asymmetric body (a uniform box, 1 kg), exact solution. Poinsot: the inertia ellipsoid ρ·I·ρ = 1, fixed in the body, " +
    "rolls without slipping on the invariable plane ⊥ L at distance (2T)^½/|L|, touching it at ρ = ω/(2T)^½; orange: the polhode " +
    "(on the body), white: the herpolhode (on the plane). ω(0) = spin along the chosen axis + ε·spin along each other axis. Tumbling box: spun about the intermediate axis it flips every half period " +
    "(Dzhanibekov); about the smallest or largest axis it only wobbles. White arrow ω, blue arrow L.",
  params: sceneParams("poinsot"),
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    ctx.camera.position.set(4.9, 3.7, 1.8);
    ctx.target.set(0, 0, -0.5);

    // --- the Poinsot view: in `poinsotRoot`, turned so that L̂ points along −z ---------------
    const poinsotRoot = new THREE.Group();
    root.add(poinsotRoot);
    const ellBody = new THREE.Group();
    poinsotRoot.add(ellBody);
    const ellipsoid = new THREE.Mesh(
      new THREE.SphereGeometry(1, 64, 40),
      new THREE.MeshStandardMaterial({ color: 0x8fb3d9, roughness: 0.45, transparent: true, opacity: 0.6, depthWrite: false }),
    );
    const ellipsoidWire = new THREE.LineSegments(
      new THREE.WireframeGeometry(new THREE.SphereGeometry(1, 24, 12)),
      new THREE.LineBasicMaterial({ color: 0xc9d1d9, transparent: true, opacity: 0.18 }),
    );
    // The principal axes, each as long as its semi-axis (its tip is a vertex of the ellipsoid).
    const ellAxes = [0, 1, 2].map((k) => {
      const dir = new THREE.Vector3().setComponent(k, 1);
      return new THREE.ArrowHelper(dir, new THREE.Vector3(), 1, AXIS_COLORS[k], 0.12, 0.06);
    });
    const centre = new THREE.Mesh(new THREE.SphereGeometry(0.04, 16, 12), new THREE.MeshBasicMaterial({ color: 0xffffff }));
    ellBody.add(ellipsoid, ellipsoidWire, centre, ...ellAxes);
    const ellAxisNames = ellAxes.map((a, k) => ctx.labels.add("xyz"[k], new THREE.Vector3(0, 1.1, 0), { obj: a, className: "label3d axis", color: ["#ff7a7e", "#7ad38a", "#7fa6ff"][k] }));
    const polhode = new Polyline(POLHODE_SAMPLES + 1, 0xffa94d);
    ellBody.add(polhode.obj);
    const plane = new THREE.Group();
    poinsotRoot.add(plane);
    const planeDisc = new THREE.Mesh(
      new THREE.CircleGeometry(PLANE_RADIUS, 96),
      new THREE.MeshStandardMaterial({ color: 0x2a3440, transparent: true, opacity: 0.75, side: THREE.DoubleSide, depthWrite: false }),
    );
    const planeGrid = new THREE.PolarGridHelper(PLANE_RADIUS, 12, 6, 96, 0x52606d, 0x3a4652);
    planeGrid.rotateX(Math.PI / 2); // the helper lies in xz; the plane's local normal is z
    plane.add(planeDisc, planeGrid);
    const herpolhode = new Polyline(TRAIL_POINTS + 1, 0xffffff);
    poinsotRoot.add(herpolhode.obj);
    const contactDot = new THREE.Mesh(new THREE.SphereGeometry(0.05, 16, 12), new THREE.MeshBasicMaterial({ color: 0xff6b6b }));
    poinsotRoot.add(contactDot);
    const omegaRay = new Arrow(0xffffff);
    const lRay = new Arrow(0x7cc4ff);
    poinsotRoot.add(omegaRay.obj, lRay.obj);

    // --- the tumbling-box view -------------------------------------------------------------
    const boxRoot = new THREE.Group();
    root.add(boxRoot);
    boxRoot.add(fixedAxes(2.6, 0.3));
    axisLabels(ctx.labels, 2.6, ["X", "Y", "Z"], [], { obj: boxRoot });
    const boxBody = new THREE.Group();
    boxRoot.add(boxBody);
    // Faces +x, −x, +y, −y, +z, −z: the + faces in the colour of their axis, so a flip shows.
    const faceColors = [AXIS_COLORS[0], 0x9aa4ae, AXIS_COLORS[1], 0x9aa4ae, AXIS_COLORS[2], 0x9aa4ae];
    const faceMaterials = faceColors.map((c) => new THREE.MeshStandardMaterial({ color: c, roughness: 0.55 }));
    let box: THREE.Mesh | null = null;
    let boxEdges: THREE.LineSegments | null = null;
    // The body axes, each sticking out of the box by 40 % of its half-side.
    const boxAxes = [0, 1, 2].map((k) => {
      const dir = new THREE.Vector3().setComponent(k, 1);
      return new THREE.ArrowHelper(dir, new THREE.Vector3(), 1, AXIS_COLORS[k], 0.15, 0.07);
    });
    boxBody.add(...boxAxes);
    const boxAxisNames = boxAxes.map((a, k) => ctx.labels.add("xyz"[k], new THREE.Vector3(0, 1.1, 0), { obj: a, className: "label3d axis", color: ["#ff7a7e", "#7ad38a", "#7fa6ff"][k] }));
    // The path of the spun axis's tip in space over the last period: a flip is a swing from
    // near +L to near −L and back.
    const tipTrail = new Polyline(TRAIL_POINTS + 1, 0xffffff, 0.8);
    // The sphere that the tip moves on, faint.
    const tipSphere = new THREE.Mesh(
      new THREE.SphereGeometry(1, 48, 32),
      new THREE.MeshStandardMaterial({ color: 0x3e7bfa, transparent: true, opacity: 0.1, depthWrite: false }),
    );
    boxRoot.add(tipTrail.obj, tipSphere);
    const omegaArrow = new Arrow(0xffffff);
    const lArrow = new Arrow(0x7cc4ff);
    boxRoot.add(omegaArrow.obj, lArrow.obj);

    // --- the ω(t) plot in the side panel ----------------------------------------------------
    const fig = document.createElement("figure");
    fig.className = "poinsot-plot";
    const canvas = document.createElement("canvas");
    canvas.width = 640;
    canvas.height = 300;
    canvas.setAttribute("role", "img");
    canvas.setAttribute("aria-label", "ω components in the body against time");
    canvas.style.width = "100%";
    const caption = document.createElement("figcaption");
    caption.textContent = "ω in the body (x red, y green, z blue) over the last seconds; a flip reverses the spun component.";
    caption.style.fontSize = "0.8em";
    fig.append(canvas, caption);
    fig.style.margin = "0.5em 0";
    ctx.panel.append(fig);

    let body: FreeRigidBody | null = null;
    let rigid: RigidBody | null = null;
    let p: Params = {};
    let view = POINSOT_VIEWS[0];
    let moments = [1, 1, 1];
    let spunAxis = 1;
    let stability = { kinds: [] as string[], rates: [] as number[] };
    let lHat = new THREE.Vector3(0, 0, 1);
    let kEll = 1; // display scale of the Poinsot view (ρ → scene units)
    let kOmega = 1; // display scale of ω in the box view
    let contactCurve: GridCurve | null = null;
    let tipCurve: GridCurve | null = null;
    let tipLength = 1;
    let omegaCurve: GridCurve | null = null;
    let omega0Norm = 1;
    let tNow = 0;
    /** The motion's constants, read from the core once per configure. */
    let constants = { d: 0, T0: 0, L0: 0, period: 0, flip: 0, regime: "", m: 0, pole: undefined as number | undefined };
    let out: Readout[] = [];

    const free = () => {
      body?.free();
      rigid?.free();
      body = null;
      rigid = null;
    };

    /** The ω(t) plot, with its axes: ω (rad/s) ticks at ±|ω(0)| and 0, t (s) ticks at the
     * window's ends; canvas pixels are twice the CSS size (crisp text). */
    function drawPlot(): void {
      const g = canvas.getContext("2d");
      if (!g || !omegaCurve) return;
      const W = canvas.width, H = canvas.height, k = 2;
      const pad = { l: 50 * k, r: 8 * k, t: 6 * k, b: 18 * k };
      g.setTransform(1, 0, 0, 1, 0, 0);
      g.fillStyle = "#101418";
      g.fillRect(0, 0, W, H);
      const x0 = pad.l, x1 = W - pad.r, y0 = pad.t, y1 = H - pad.b;
      const span = (omegaCurve.capacity - 1) * omegaCurve.dt;
      // The window: the last `span` seconds, or [0, span] until then.
      const tStart = Math.max(0, tNow - span);
      const w0 = omega0Norm || 1;
      const py = (w: number) => (y0 + y1) / 2 - (w / w0) * 0.45 * (y1 - y0);
      const px = (t: number) => x0 + ((t - tStart) / span) * (x1 - x0);
      // Axes, ticks and their labels.
      g.strokeStyle = "#3a4652";
      g.lineWidth = 1;
      g.strokeRect(x0, y0, x1 - x0, y1 - y0);
      g.font = `${11 * k}px system-ui, sans-serif`;
      g.fillStyle = "#9aa4ae";
      g.textBaseline = "middle";
      g.textAlign = "right";
      const yTicks = [w0, 0, -w0].map((w) => ({ w, text: fmt(w, 3) }));
      for (const { w, text } of yTicks) {
        g.beginPath();
        g.moveTo(x0 - 4, py(w));
        g.lineTo(w === 0 ? x1 : x0, py(w));
        g.stroke();
        g.fillText(text, x0 - 6, py(w));
      }
      g.save();
      g.translate(8 * k, (y0 + y1) / 2);
      g.rotate(-Math.PI / 2);
      g.textAlign = "center";
      g.fillText("ω (rad/s)", 0, 0);
      g.restore();
      g.textBaseline = "top";
      g.textAlign = "left";
      g.fillText(fmt(tStart, 3), x0, y1 + 4);
      g.textAlign = "right";
      g.fillText(fmt(tStart + span, 3), x1, y1 + 4);
      g.textAlign = "center";
      g.fillText("t (s)", (x0 + x1) / 2, y1 + 4);
      canvas.dataset.axes = `t (s): ${fmt(tStart, 3)} to ${fmt(tStart + span, 3)}; ω (rad/s): ${yTicks.map((y) => y.text).join(", ")}`;
      // The curves.
      const pts = omegaCurve.points;
      const n = pts.length / 3;
      if (n < 2) return;
      const k0 = Math.max(0, Math.floor(tNow / omegaCurve.dt) - omegaCurve.capacity + 1);
      g.save();
      g.beginPath();
      g.rect(x0, y0, x1 - x0, y1 - y0);
      g.clip();
      for (let c = 0; c < 3; c++) {
        g.strokeStyle = `#${AXIS_COLORS[c].toString(16).padStart(6, "0")}`;
        g.lineWidth = c === spunAxis ? 2 * k : k;
        g.beginPath();
        for (let j = 0; j < n; j++) {
          const x = px((k0 + j) * omegaCurve.dt);
          const y = py(pts[3 * j + c]);
          if (j === 0) g.moveTo(x, y);
          else g.lineTo(x, y);
        }
        g.stroke();
      }
      g.restore();
    }

    return {
      configure(params) {
        p = params;
        view = String(p.view); // the shell only passes listed options
        const rank = String(p.axis);
        const sides = [Number(p.a), Number(p.b), Number(p.c)];
        const nextRigid = RigidBody.cuboid(BOX_MASS, sides);
        let next: FreeRigidBody;
        let stab;
        try {
          const I = nextRigid.inertia;
          const m = [I[0], I[4], I[8]]; // a cuboid's inertia is diagonal in its own axes
          const axis = axisByRank(m, rank);
          next = new FreeRigidBody(m, initialOmega(axis, Number(p.spin), Number(p.eps)), []);
          try {
            stab = axisStability(m, Number(p.spin));
          } catch (e) {
            next.free();
            throw e;
          }
          moments = m;
          spunAxis = axis;
        } catch (e) {
          nextRigid.free();
          throw e;
        }
        free();
        body = next;
        rigid = nextRigid;
        stability = { kinds: stab.kinds, rates: Array.from(stab.rates) };
        stab.free();

        const poinsot = view === POINSOT_VIEWS[0];
        poinsotRoot.visible = poinsot;
        boxRoot.visible = !poinsot;
        lHat = vec(body.invariablePlaneNormal);
        constants = {
          d: body.invariablePlaneDistance,
          T0: body.energy,
          L0: vec(body.angularMomentum).length(),
          period: body.period,
          flip: body.flipInterval,
          regime: body.regime,
          m: body.parameter,
          pole: body.poleAxis,
        };
        const w0 = vec(body.omega(0));
        omega0Norm = w0.length();

        // Poinsot view: semi-axes 1/√I_i, the longest drawn R_ELLIPSOID long.
        kEll = R_ELLIPSOID * Math.sqrt(Math.min(...moments));
        ellipsoid.scale.set(kEll / Math.sqrt(moments[0]), kEll / Math.sqrt(moments[1]), kEll / Math.sqrt(moments[2]));
        ellipsoidWire.scale.copy(ellipsoid.scale);
        ellAxes.forEach((a, k) => {
          a.setLength(kEll / Math.sqrt(moments[k]), 0.12, 0.06);
          ctx.labels.move(ellAxisNames[k], new THREE.Vector3(0, kEll / Math.sqrt(moments[k]) + 0.15, 0));
        });
        poinsotRoot.quaternion.setFromUnitVectors(lHat, new THREE.Vector3(0, 0, -1));
        const d = body.invariablePlaneDistance * kEll;
        plane.position.copy(lHat.clone().multiplyScalar(d));
        plane.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), lHat);
        lRay.set(lHat.clone().multiplyScalar(d));
        // The polhode, drawn a hair outside the surface so that it is not hidden by it.
        polhode.set(body.contactPolhode(POLHODE_SAMPLES), kEll * 1.004);

        // The grids: fine enough for the fastest turn (|L|/I_min rad/s about L).
        const turnRate = vec(body.angularMomentum).length() / Math.min(...moments);
        const dtContact = Math.min(0.05, (2 * Math.PI) / turnRate / 90);
        const b = body;
        contactCurve = new GridCurve((ts) => b.contactPoints(ts), dtContact, TRAIL_POINTS);
        const span = Number.isFinite(body.period) ? Math.min(60, Math.max(8, 2.2 * body.period)) : 20;
        omegaCurve = new GridCurve((ts) => b.omegas(ts), span / (TRAIL_POINTS / 4 - 1), TRAIL_POINTS / 4);

        // Box view.
        if (box) disposeTree(box);
        if (boxEdges) disposeTree(boxEdges);
        const kBox = (2 * R_BOX) / Math.max(...sides);
        const geom = new THREE.BoxGeometry(sides[0] * kBox, sides[1] * kBox, sides[2] * kBox);
        box = new THREE.Mesh(geom, faceMaterials);
        boxEdges = new THREE.LineSegments(new THREE.EdgesGeometry(geom), new THREE.LineBasicMaterial({ color: 0x101418 }));
        boxBody.add(box, boxEdges);
        kOmega = 2.2 / (omega0Norm || 1);
        const half = sides.map((x) => 0.5 * x * kBox);
        boxAxes.forEach((a, k) => {
          a.setLength(Math.max(1.4 * half[k], 0.35), 0.15, 0.07);
          ctx.labels.move(boxAxisNames[k], new THREE.Vector3(0, Math.max(1.4 * half[k], 0.35) + 0.15, 0));
        });
        tipLength = Math.max(1.4 * half[spunAxis], 0.35);
        tipSphere.scale.setScalar(tipLength);
        const e = new THREE.Vector3().setComponent(spunAxis, tipLength);
        const tipSpan = Number.isFinite(body.period) ? Math.ceil(body.period / dtContact) : TRAIL_POINTS;
        tipCurve = new GridCurve(
          (ts) => {
            const out = new Float64Array(3 * ts.length);
            ts.forEach((t, j) => {
              const tip = e.clone().applyQuaternion(quaternion(b.attitude(t)));
              out.set([tip.x, tip.y, tip.z], 3 * j);
            });
            return out;
          },
          dtContact,
          Math.min(TRAIL_POINTS, Math.max(50, tipSpan)),
        );
        lArrow.set(lHat.clone().multiplyScalar(2.4));
      },
      step(t) {
        if (!body || !rigid) return;
        tNow = t;
        const s = body.state(t);
        const w = s.subarray(0, 3);
        const q = s.subarray(3, 7);
        const att = quaternion(q);
        const rhoBody = body.contactPointBody(t);
        const rho = body.contactPoint(t);
        const { d, T0, L0, period, flip, regime, m, pole } = constants;

        if (view === POINSOT_VIEWS[0]) {
          ellBody.quaternion.copy(att);
          const c = vec(rho).multiplyScalar(kEll);
          contactDot.position.copy(c);
          omegaRay.set(c);
          contactCurve?.update(t);
          if (contactCurve) herpolhode.set(contactCurve.points, kEll, c);
        } else {
          boxBody.quaternion.copy(att);
          omegaArrow.set(vec(w).applyQuaternion(att).multiplyScalar(kOmega));
          if (tipCurve) {
            tipCurve.update(t);
            tipTrail.set(tipCurve.points, 1, new THREE.Vector3().setComponent(spunAxis, tipLength).applyQuaternion(att));
          }
        }
        omegaCurve?.update(t);

        // Conservation, recomputed from ω(t) by the rigid body's own T = ½ ω·I·ω (2.54) and L = I·ω (2.51).
        const T = rigid.kineticEnergy(w);
        const L = vec(rigid.angularMomentum(w)).length();
        // The contact conditions, as relative residuals: ρ·I·ρ = 1 (by the rigid body's T at
        // ω = ρ) and ρ·L̂ = d.
        const onEllipsoid = 2 * rigid.kineticEnergy(rhoBody) - 1;
        const onPlane = (rho[0] * lHat.x + rho[1] * lHat.y + rho[2] * lHat.z) / d - 1;
        out = [
          { key: "t", label: "t (s)", value: t, text: fmt(t, 5) },
          { key: "moments", label: "I (x, y, z) (kg·m²)", value: moments, text: fmtVec(moments) },
          { key: "spunAxis", label: "spun axis", value: spunAxis, text: `${"xyz"[spunAxis]} (${String(p.axis)} moment)` },
          { key: "stability", label: "steady spin about x, y, z", value: stability.kinds.join(", "), text: stability.kinds.join(", ") },
          {
            key: "stabilityRates", label: "  oscillation / growth rate (1/s)", value: stability.rates,
            text: fmtVec(stability.rates, 4),
          },
          { key: "regime", label: "regime", value: regime, text: regimeText(regime, pole), warn: regime === "separatrix" },
          separatrixReadout(m, regime, pole, spunAxis, stability.kinds[spunAxis] ?? ""),
          { key: "period", label: "period of ω (s)", value: Number.isFinite(period) ? period : String(period), text: fmt(period) },
          {
            key: "flipInterval", label: "flip interval (half period, s)", value: Number.isFinite(flip) ? flip : String(flip),
            text: fmt(flip),
          },
          { key: "omega", label: "ω body (rad/s)", value: Array.from(w), text: fmtVec(w) },
          {
            key: "spinComponent", label: `ω on the spun axis ${"xyz"[spunAxis]} (rad/s)`, value: w[spunAxis],
            text: `${fmt(w[spunAxis])}${w[spunAxis] < 0 ? "  (flipped)" : ""}`, warn: w[spunAxis] < 0,
          },
          { key: "attitude", label: "attitude [w,x,y,z]", value: Array.from(q), text: fmtVec(q, 4, 1) },
          { key: "planeDistance", label: "plane distance (2T)^½/|L|", value: d, text: fmt(d) },
          { key: "planeNormal", label: "plane normal L̂", value: Array.from(lHat.toArray()), text: fmtVec(lHat.toArray(), 4, 1) },
          { key: "contactPoint", label: "contact ρ (space)", value: Array.from(rho), text: fmtVec(rho) },
          {
            check: true, key: "contactResidual", label: "contact: ρ·I·ρ − 1, ρ·L̂/d − 1", value: [onEllipsoid, onPlane],
            text: `${fmt(onEllipsoid, 2, 1)}, ${fmt(onPlane, 2, 1)}`, warn: Math.max(Math.abs(onEllipsoid), Math.abs(onPlane)) > 1e-10,
          },
          { key: "energy", label: "T (J), conserved", value: T0, text: fmt(T0, 8) },
          { check: true, key: "energyNow", label: "T(t) from ω(t) (J)", value: T, text: `${fmt(T, 8)} (rel. drift ${fmt((T - T0) / T0, 2, 1)})` },
          { key: "angularMomentum", label: "|L| (kg·m²/s), conserved", value: L0, text: fmt(L0, 8) },
          {
            check: true, key: "angularMomentumNow", label: "|L(t)| from ω(t) (kg·m²/s)", value: L,
            text: `${fmt(L, 8)} (rel. drift ${fmt((L - L0) / L0, 2, 1)})`,
          },
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        if (view !== POINSOT_VIEWS[0]) return { center: new THREE.Vector3(), radius: 2.6 };
        // The ellipsoid about the centre and the plane's disc a distance d below it (L̂ is −z).
        const d = constants.d * kEll;
        return { center: new THREE.Vector3(0, 0, -d / 2), radius: Math.max(Math.hypot(PLANE_RADIUS, d / 2), R_ELLIPSOID + d / 2) };
      },
      main() {
        return view === POINSOT_VIEWS[0] ? [ellipsoid, planeDisc] : box ? [box] : [];
      },
      render(renderer, scene, camera) {
        drawPlot();
        renderer.render(scene, camera);
      },
      dispose() {
        free();
        faceMaterials.forEach((m) => m.dispose());
        disposeTree(root);
      },
    };
  },
};
