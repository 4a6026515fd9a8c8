// The rotating Earth: a body dropped from a tower at latitude λ lands east of the plumb line
// (the unit's 2.42, first order in ω) — here beside the exact drop integrated in the rotating
// frame by the core (Coriolis and centrifugal terms), with the Foucault rate at the same latitude.
// Horizontal distances are exaggerated (the factor is a control, written on the view with a
// scale bar) so that centimetres show; the page says when the landing point runs off the drawing.
import * as THREE from "three";
import { Earth, type Fall } from "../core";
import { angles, DEG, fmt, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { axisLabels, compass, disposeTree, fixedAxes, frameOf, projectPoint, roundDown125, roundText, ScaleBar, Trail } from "../view";

/** The tower's drawn height (scene units). */
const TOWER = 3;
/** Half the side of the ground drawn (scene units): a landing point beyond it is off the drawing. */
const GROUND = 3;
/** Below this drawn distance (scene units) the landing point is not told apart from the foot of
 * the plumb line (the marks' radius). */
const VISIBLE = 0.12;
const A = angles("°");

export const dropScene: SceneDef = {
  id: "drop",
  title: "Falling body",
  short: "Fall",
  rateUnit: "°",
  pinned: ["east", "eastFirstOrder", "ratio", "foucaultRate"],
  describe: "a tower on the ground of the rotating Earth, a ball dropped from its top, and where it lands east of the plumb line (exact, white ring; the unit's 2.42, yellow dot); east, north and up are labelled and a compass lies on the ground",
  blurb:
    "A body dropped from rest lands east of the plumb line: x ≈ ⅓ ω cos λ √(8h³/g) (2.42). " +
    "The ball follows the exact path (the core integrates it in the rotating frame); the yellow dot is 2.42, the white ring the exact landing point. " +
    "Horizontal distances are multiplied by the exaggeration factor, written on the view beside a scale bar.",
  params: [
    { kind: "number", key: "height", label: "height h", unit: "m", min: 10, max: 500, step: 5, value: 100 },
    { kind: "number", key: "latitude", label: "latitude λ", unit: "°", min: -89, max: 89, step: 1, value: 45 },
    { kind: "choice", key: "rate", label: "Earth's rate", options: ["sidereal", "solar day"], value: "sidereal" },
    { kind: "choice", key: "exaggeration", label: "exaggeration ×", options: ["1", "10", "100", "1000", "10000"], value: "1000" },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    const grid = new THREE.GridHelper(2 * GROUND, 12, 0x3a4654, 0x242c35);
    grid.rotateX(Math.PI / 2); // the ground is the EN plane (z up)
    root.add(grid);
    const axes = fixedAxes(GROUND * 0.9, 0.7);
    axes.position.z = 0.002;
    root.add(axes);
    // East and north end at the compass ring (its E and N name them); up is labelled.
    axisLabels(ctx.labels, GROUND * 0.9, ["east", "north", "up"], [0, 1]);
    root.add(compass(ctx.labels, GROUND * 0.9));
    const tower = new THREE.Mesh(new THREE.BoxGeometry(0.25, 0.25, 1), new THREE.MeshStandardMaterial({ color: 0x6b7785 }));
    tower.position.set(-0.2, 0, 0);
    root.add(tower);
    const ball = new THREE.Mesh(new THREE.SphereGeometry(0.08, 24, 16), new THREE.MeshStandardMaterial({ color: 0xe5484d }));
    root.add(ball);
    const plumb = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, 0), new THREE.Vector3(0, 0, TOWER)]),
      new THREE.LineDashedMaterial({ color: 0x9aa4b1, dashSize: 0.08, gapSize: 0.06 }),
    );
    plumb.computeLineDistances();
    root.add(plumb);
    // The exact landing point: a white ring; 2.42: a yellow dot inside it, drawn on top, so that
    // both show where they coincide (they differ by parts in 10⁵ at the default height).
    const exactMark = new THREE.Mesh(new THREE.RingGeometry(0.075, 0.115, 40), new THREE.MeshBasicMaterial({ color: 0xffffff, side: THREE.DoubleSide }));
    exactMark.position.z = 0.004;
    const firstOrderMark = new THREE.Mesh(
      new THREE.CircleGeometry(0.055, 32),
      new THREE.MeshBasicMaterial({ color: 0xf2b84b, side: THREE.DoubleSide, depthTest: false, transparent: true }),
    );
    firstOrderMark.renderOrder = 3;
    firstOrderMark.position.z = 0.006;
    root.add(exactMark, firstOrderMark);
    const exactLabel = ctx.labels.add("exact", new THREE.Vector3(0.3, -0.35, 0), { obj: exactMark, className: "label3d mark" });
    const firstLabel = ctx.labels.add("2.42", new THREE.Vector3(0.3, 0.35, 0), { obj: firstOrderMark, className: "label3d mark", color: "#f2b84b" });
    void exactLabel;
    void firstLabel;
    const heightLabel = ctx.labels.add("", new THREE.Vector3(-0.2, 0, TOWER + 0.25), { className: "label3d scale" });
    const path = new Trail(400, 0xe5484d);
    root.add(path.obj);
    // The horizontal scale bar, along east on the ground south of the landing point.
    const bar = new ScaleBar(ctx.labels, new THREE.Vector3(0, -0.9, 0.01), new THREE.Vector3(1, 0, 0), new THREE.Vector3(0, 0.06, 0));
    root.add(bar.obj);
    // The exaggeration, written on the view itself.
    const note = document.createElement("div");
    note.className = "hud-note hud";
    note.style.left = "0.5rem";
    note.style.top = "0.5rem";
    ctx.overlay.append(note);
    // East (x) is the direction to look across: put the camera south-west, above.
    ctx.camera.position.set(-2.5, -8, 4);
    ctx.target.set(0, 0, TOWER / 2);

    let p: Params = {};
    let earth: Earth | null = null;
    let fall: Fall | null = null;
    let firstOrder = 0;
    let foucault = 0;
    let out: Readout[] = [];
    let lastTau = -1;
    let drawing: Readout | null = null;

    const release = () => {
      fall?.free();
      earth?.free();
      fall = null;
      earth = null;
    };
    const scales = () => {
      const v = TOWER / Number(p.height);
      return { v, h: v * Number(p.exaggeration) };
    };

    return {
      configure(params) {
        p = params;
        const rate = p.rate === "solar day" ? Earth.solarDayRate() : Earth.siderealRate();
        const nextEarth = new Earth(rate, Earth.meanRadius(), Earth.standardGravity());
        let nextFall: Fall;
        try {
          nextFall = nextEarth.drop(Number(p.height), Number(p.latitude) * DEG);
          firstOrder = nextEarth.eastwardDeflection(Number(p.height), Number(p.latitude) * DEG);
          foucault = nextEarth.foucaultRate(Number(p.latitude) * DEG);
        } catch (e) {
          nextEarth.free();
          throw e;
        }
        release();
        earth = nextEarth;
        fall = nextFall;
        const s = scales();
        tower.scale.z = TOWER;
        tower.position.z = TOWER / 2;
        exactMark.position.set(fall.east * s.h, fall.north * s.h, 0.004);
        firstOrderMark.position.set(firstOrder * s.h, 0, 0.006);
        path.clear();
        lastTau = -1;
        ctx.labels.setText(heightLabel, `h = ${fmt(Number(p.height), 3)} m`);
        // The scale bar: a round length drawn about one unit long; the exaggeration on the view.
        const x = Number(p.exaggeration);
        const metres = roundDown125(1.2 / s.h);
        const caption = metres >= 1 ? `${roundText(metres)} m` : metres >= 0.01 ? `${roundText(metres * 100)} cm` : `${roundText(metres * 1000)} mm`;
        bar.set(metres * s.h, `${caption}${x === 1 ? "" : ` (drawn ×${roundText(x)})`}`);
        note.textContent = x === 1 ? "Distances to scale" : `Horizontal distances ×${roundText(x)}`;
        // Say when the drawing cannot show the landing point.
        const reach = Math.max(Math.hypot(fall.east, fall.north), Math.abs(firstOrder)) * s.h;
        const onDrawing = reach <= GROUND * 0.95;
        exactMark.visible = firstOrderMark.visible = onDrawing;
        drawing = !onDrawing
          ? { key: "drawing", label: "off the drawing", value: reach, text: `the landing point is drawn ${fmt(reach / GROUND, 3)}× beyond the ground: lower the exaggeration`, warn: true, pin: true }
          : reach < VISIBLE
            ? { key: "drawing", label: "too small to see", value: reach, text: `the landing point is drawn within the marks of the plumb line: raise the exaggeration`, warn: true, pin: true }
            : null;
      },
      step(t) {
        if (!fall) return;
        const T = fall.time;
        // Fall, rest a quarter of the flight on the ground, fall again.
        const tau = Math.min(T, Math.max(0, t) % (1.25 * T));
        if (tau < lastTau) path.clear();
        lastTau = tau;
        const x = fall.state(tau);
        const s = scales();
        const pos = new THREE.Vector3(x[0] * s.h, x[1] * s.h, x[2] * s.v);
        ball.position.copy(pos);
        path.push(pos);
        const ratio = fall.east / firstOrder;
        out = [
          { key: "tau", label: "t in the fall (s)", value: tau, text: fmt(tau, 5) },
          { key: "state", label: "(x, y, z) (m)", value: Array.from(x.subarray(0, 3)), text: fmtVec(x.subarray(0, 3)) },
          { key: "time", label: "time of flight (s)", value: T, text: fmt(T, 8) },
          { key: "east", label: "east, exact (m)", value: fall.east, text: fmt(fall.east, 6) },
          { key: "north", label: "north, exact (m)", value: fall.north, text: fmt(fall.north, 6) },
          { key: "eastFirstOrder", label: "east, 2.42 (m)", value: firstOrder, text: fmt(firstOrder, 6) },
          { key: "ratio", label: "exact / 2.42", value: ratio, text: fmt(ratio, 10) },
          { key: "foucaultRate", label: `Foucault rate −Ω sin λ (${A.perHour})`, unitScale: A.perHourScale, value: foucault, text: A.perHourRate(foucault) },
          ...(drawing ? [drawing] : []),
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        const shown = [tower, exactMark, firstOrderMark].filter((o) => o.visible);
        return frameOf(shown, 0.15);
      },
      main() {
        return [tower, exactMark, firstOrderMark];
      },
      probes(camera, viewport) {
        return {
          firstOrderMark: projectPoint(firstOrderMark.getWorldPosition(new THREE.Vector3()), camera, viewport),
          exactMark: projectPoint(exactMark.getWorldPosition(new THREE.Vector3()), camera, viewport),
        };
      },
      dispose() {
        release();
        disposeTree(root);
      },
    };
  },
};
