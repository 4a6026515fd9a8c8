// The rotating Earth: a body dropped from a tower at latitude λ lands east of the plumb line
// (the unit's 2.42, first order in ω) — here beside the exact drop integrated in the rotating
// frame by the core (Coriolis and centrifugal terms), with the Foucault rate at the same latitude.
// Horizontal distances are exaggerated (the factor is a control) so that centimetres show.
import * as THREE from "three";
import { Earth, type Fall } from "../core";
import { DEG, fmt, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { disposeTree, Trail } from "../view";

/** The tower's drawn height (scene units). */
const TOWER = 3;

export const dropScene: SceneDef = {
  id: "drop",
  title: "Falling body",
  blurb:
    "A body dropped from rest lands east of the plumb line: x ≈ ⅓ ω cos λ √(8h³/g) (2.42). " +
    "The ball follows the exact path (the core integrates it in the rotating frame); the yellow mark is 2.42, the white one the exact landing point. " +
    "Horizontal distances are multiplied by the exaggeration factor.",
  params: [
    { kind: "number", key: "height", label: "height h", unit: "m", min: 10, max: 500, step: 5, value: 100 },
    { kind: "number", key: "latitude", label: "latitude λ", unit: "°", min: -89, max: 89, step: 1, value: 45 },
    { kind: "choice", key: "rate", label: "Earth's rate", options: ["sidereal", "solar day"], value: "sidereal" },
    { kind: "choice", key: "exaggeration", label: "exaggeration ×", options: ["1", "10", "100", "1000", "10000"], value: "1000" },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    const grid = new THREE.GridHelper(6, 12, 0x3a4654, 0x242c35);
    grid.rotateX(Math.PI / 2); // the ground is the EN plane (z up)
    root.add(grid);
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
    const mark = (color: number) => {
      const m = new THREE.Mesh(new THREE.RingGeometry(0.06, 0.1, 32), new THREE.MeshBasicMaterial({ color, side: THREE.DoubleSide }));
      m.position.z = 0.005;
      root.add(m);
      return m;
    };
    const exactMark = mark(0xffffff);
    const firstOrderMark = mark(0xf2b84b);
    const path = new Trail(400, 0xe5484d);
    root.add(path.obj);
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
        exactMark.position.set(fall.east * s.h, fall.north * s.h, 0.005);
        firstOrderMark.position.set(firstOrder * s.h, 0, 0.004);
        path.clear();
        lastTau = -1;
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
          { key: "east", label: "east, exact (m)", value: fall.east, text: fmt(fall.east, 8) },
          { key: "north", label: "north, exact (m)", value: fall.north, text: fmt(fall.north, 6) },
          { key: "eastFirstOrder", label: "east, 2.42 (m)", value: firstOrder, text: fmt(firstOrder, 8) },
          { key: "ratio", label: "exact / 2.42", value: ratio, text: fmt(ratio, 10) },
          { key: "foucaultRate", label: "Foucault rate (rad/s)", value: foucault, text: `${fmt(foucault, 6)} (${fmt(Math.abs(foucault) / DEG * 3600, 4)}°/h)` },
        ];
      },
      readouts() {
        return out;
      },
      dispose() {
        release();
        disposeTree(root);
      },
    };
  },
};
