// Rotating frames (the unit's 2.20–2.28): a particle seen side by side from the fixed frame
// (left: the turntable turns) and from the frame carried by the turntable (right: the table is at
// rest). The particle is free, or tied to the axis by a spring; the core integrates it in the
// rotating frame with every fictitious force, maps it back to the fixed frame, and splits its
// acceleration into the relative, Coriolis, centripetal and Euler terms. Every number comes from
// the core; the scene only draws. The loop restarts when the particle reaches the table's rim
// (read from the core's path), so that it never leaves the table.
import * as THREE from "three";
import { MovingFrame, SpringParticle, sampleTimes, simulateParticle } from "../core";
import { DEG, fmt, fmtVec, type Params, type Readout, type Rect, type SceneDef } from "../scene";
import { Arrow, axisLabels, bufferLine, disposeTree, fixedAxes, Labels, matrix4, projectBox, vec } from "../view";
import { legacyParams, sceneParams } from "./params";

/** Drawn radius of the turntable (m). */
const TABLE = 1;
/** The particle's mass (kg): energies are per kilogram. */
const MASS = 1;
/** Display scales: arrow length (m) per m/s² of acceleration and per m/s of velocity. */
const ACC_SCALE = 0.3;
const VEL_SCALE = 0.5;
/** Samples of the precomputed paths drawn as trails. */
const TRAIL_SAMPLES = 600;
/** The animation loops after this time (s), or at the last sample of the particle's path (the
 * core's samples over LOOP_MAX) before it first leaves the table. */
const LOOP_MAX = 8;
/** Below this half-view width (CSS px) the view titles take their short form. */
const SHORT_TITLES = 330;

/** Colours of the arrows (and of the legend). */
const COLOURS = {
  relative: 0xffffff,
  coriolis: 0xf2994a,
  centrifugal: 0x56c2e6,
  euler: 0xc77dff,
  force: 0x5bd66b,
  velocity: 0xf2d24b,
  fixedPath: 0xf2d24b,
  rotatingPath: 0xff7b9c,
};

/** Layers: 0 both views, 1 the fixed view only, 2 the rotating view only. */
const FIXED_ONLY = 1;
const ROTATING_ONLY = 2;

function onLayer(obj: THREE.Object3D, layer: number): THREE.Object3D {
  obj.traverse((o) => o.layers.set(layer));
  return obj;
}

const hex = (c: number) => `#${c.toString(16).padStart(6, "0")}`;
const norm = (v: ArrayLike<number>) => Math.hypot(v[0], v[1], v[2]);

/** A polyline over precomputed points, drawn up to a count. */
class Path {
  readonly obj: THREE.Line;
  private readonly pos: Float32Array;
  constructor(capacity: number, color: number) {
    this.pos = new Float32Array(3 * capacity);
    this.obj = bufferLine(this.pos, color);
  }
  set(i: number, p: ArrayLike<number>): void {
    this.pos.set([p[0], p[1], p[2]], 3 * i);
  }
  commit(): void {
    (this.obj.geometry.getAttribute("position") as THREE.BufferAttribute).needsUpdate = true;
  }
  show(n: number): void {
    this.obj.geometry.setDrawRange(0, n);
  }
}

export const framesScene: SceneDef = {
  id: "frames",
  title: "Rotating frames",
  short: "Frames",
  rateUnit: "rad",
  pinned: ["tau", "speedFixed", "speedRotating", "omegaNow"],
  describe: "a turntable and a particle seen side by side from the fixed frame (left, the table turns) and from the table's own frame (right, the table at rest), with its path and the arrows of its acceleration and of the forces per mass; the fixed axes x′, y′ and the table's axes x, y are labelled",
  blurb:
    "A particle seen from the fixed frame (left, the turntable turns) and from the turntable's own frame (right, the table at rest). " +
    "The core integrates it in the rotating frame, m a_rel = F − 2m ω×v − m ω×(ω×r) − m ω̇×r (2.26–2.28), and maps it back (2.20–2.21): " +
    "a free particle (k = 0) runs straight on the left and curves on the right. Arrows on the right: the relative acceleration and the forces per mass that make it. " +
    "Primed axes (x′, y′) are fixed, unprimed ones (x, y) turn with the table; the loop restarts when the particle reaches the rim.",
  params: sceneParams("frames"),
  legacyParams: legacyParams("frames"),
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    root.add(fixedAxes(1.6, 0.6));
    // The two views' labels: the fixed axes (primed, the unit's convention) and the table's.
    const rightLabels = new Labels(ctx.overlay);
    let boxes: Rect[] = [];

    // The turntable: a disk with spokes and its own x (red) and y (green) axes; carries the
    // rotating view's path and arrows.
    const table = new THREE.Group();
    root.add(table);
    const disk = new THREE.Mesh(
      new THREE.CylinderGeometry(TABLE, TABLE, 0.04, 96).rotateX(Math.PI / 2).translate(0, 0, -0.07),
      new THREE.MeshStandardMaterial({ color: 0x3a4452, roughness: 0.8 }),
    );
    table.add(disk);
    const spokes: THREE.Vector3[] = [];
    for (let k = 0; k < 12; k++) {
      const a = (k * Math.PI) / 6;
      spokes.push(new THREE.Vector3(0.12 * Math.cos(a), 0.12 * Math.sin(a), -0.045), new THREE.Vector3(TABLE * Math.cos(a), TABLE * Math.sin(a), -0.045));
    }
    table.add(new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(spokes), new THREE.LineBasicMaterial({ color: 0x6b7785 })));
    const rim = new THREE.Mesh(new THREE.RingGeometry(TABLE * 0.97, TABLE, 96), new THREE.MeshBasicMaterial({ color: 0x8a96a6, side: THREE.DoubleSide }));
    rim.position.z = -0.044;
    table.add(rim);
    for (const [k, c] of [[0, 0xe5484d], [1, 0x46a758]] as const) {
      const dir = new THREE.Vector3().setComponent(k, 1);
      table.add(new THREE.ArrowHelper(dir, new THREE.Vector3(0, 0, -0.04), TABLE * 1.15, c, 0.1, 0.05));
    }
    for (const l of [ctx.labels, rightLabels]) {
      axisLabels(l, 1.6, ["x′", "y′", "z′"]);
      axisLabels(l, TABLE * 1.15, ["x", "y", "z"], [2], { obj: table });
    }

    const ball = new THREE.Mesh(new THREE.SphereGeometry(0.045, 24, 16), new THREE.MeshStandardMaterial({ color: 0xe5484d }));
    root.add(ball);
    const anchor = new THREE.Mesh(new THREE.SphereGeometry(0.03, 16, 12), new THREE.MeshStandardMaterial({ color: COLOURS.force }));
    root.add(anchor);
    const spring = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3(1, 0, 0)]), new THREE.LineDashedMaterial({ color: COLOURS.force, dashSize: 0.04, gapSize: 0.03 }));
    root.add(spring);

    const fixedPath = new Path(TRAIL_SAMPLES, COLOURS.fixedPath);
    root.add(onLayer(fixedPath.obj, FIXED_ONLY));
    const rotatingPath = new Path(TRAIL_SAMPLES, COLOURS.rotatingPath);
    table.add(onLayer(rotatingPath.obj, ROTATING_ONLY));

    // Left: the fixed-frame velocity and acceleration (fixed components, world coordinates).
    const fixedVel = new Arrow(COLOURS.velocity, VEL_SCALE);
    const fixedAcc = new Arrow(COLOURS.force, ACC_SCALE);
    root.add(onLayer(fixedVel.obj, FIXED_ONLY), onLayer(fixedAcc.obj, FIXED_ONLY));
    // Right: the relative velocity and acceleration and the forces per mass, in moving
    // components, carried by the table.
    const relVel = new Arrow(COLOURS.velocity, VEL_SCALE);
    const relAcc = new Arrow(COLOURS.relative, ACC_SCALE);
    const coriolis = new Arrow(COLOURS.coriolis, ACC_SCALE);
    const centrifugal = new Arrow(COLOURS.centrifugal, ACC_SCALE);
    const euler = new Arrow(COLOURS.euler, ACC_SCALE);
    const force = new Arrow(COLOURS.force, ACC_SCALE);
    for (const a of [relVel, relAcc, coriolis, centrifugal, euler, force]) table.add(onLayer(a.obj, ROTATING_ONLY));

    // The rotating view's camera: the orbit camera carried along by the table.
    const rotCam = new THREE.PerspectiveCamera();
    ctx.camera.position.set(1.75, -3.1, 2.85);
    ctx.target.set(0, 0, -0.1);

    // Labels over the two halves, and the legend under the controls.
    // The two views' titles (HUD: each stays within its half), short on a narrow screen.
    const TITLES = [
      ["Fixed (inertial) frame — the table turns", "Fixed frame"],
      ["Rotating frame — carried by the table", "Rotating frame"],
    ];
    const titles = TITLES.map(([long]) => {
      const d = document.createElement("div");
      d.className = "hud-title hud frames-title";
      d.textContent = long;
      ctx.overlay.append(d);
      return d;
    });
    const divider = document.createElement("div");
    Object.assign(divider.style, { position: "absolute", top: "0", bottom: "0", left: "50%", width: "1px", background: "#3a4654" });
    ctx.overlay.append(divider);

    const legend = document.createElement("div");
    legend.setAttribute("role", "list");
    legend.setAttribute("aria-label", "Legend");
    Object.assign(legend.style, { fontSize: "0.82rem", lineHeight: "1.5" });
    const entry = (c: number, text: string, line = false) => {
      const row = document.createElement("div");
      row.setAttribute("role", "listitem");
      const sw = document.createElement("span");
      Object.assign(sw.style, { display: "inline-block", width: "1.4em", height: line ? "2px" : "0.7em", background: hex(c), marginRight: "0.5em", verticalAlign: "middle" });
      row.append(sw, document.createTextNode(text));
      legend.append(row);
    };
    const title = document.createElement("div");
    title.textContent = `Arrows (1 m/s² ↦ ${ACC_SCALE} m, 1 m/s ↦ ${VEL_SCALE} m); right: a_rel = F/m + Coriolis + centrifugal + Euler (2.26–2.27)`;
    Object.assign(title.style, { color: "#9aa4b1", marginBottom: "0.2rem" });
    legend.append(title);
    entry(COLOURS.relative, "relative acceleration a_rel = (d²r/dt²)_rot");
    entry(COLOURS.coriolis, "Coriolis −2 ω × v_rel");
    entry(COLOURS.centrifugal, "centrifugal −ω × (ω × r)");
    entry(COLOURS.euler, "Euler −ω̇ × r");
    entry(COLOURS.force, "true force per mass F/m = −(k/m) r (left: the fixed-frame acceleration)");
    entry(COLOURS.velocity, "velocity (left ṙ′, right v_rel)");
    entry(COLOURS.fixedPath, "path seen from the fixed frame (left)", true);
    entry(COLOURS.rotatingPath, "path seen from the table (right)", true);
    ctx.panel.append(legend);

    let p: Params = {};
    let frame0: MovingFrame | null = null;
    let particle: SpringParticle | null = null;
    let r0: Float64Array = new Float64Array(3);
    let v0rel: Float64Array = new Float64Array(3);
    let loop = LOOP_MAX;
    /** The path over one loop: sample times and states [r, v_rel] (6 numbers each), rotating frame. */
    let times: Float64Array = new Float64Array(0);
    let states: Float64Array = new Float64Array(0);
    let energy0 = 0;
    let jacobi0 = 0;
    let out: Readout[] = [];

    const release = () => {
      frame0?.free();
      particle?.free();
      frame0 = null;
      particle = null;
    };

    /** The fixed-frame position and velocity of the relative state (r, v) at time t. */
    const toFixed = (f: MovingFrame, r: ArrayLike<number>, v: ArrayLike<number>) => {
      const m = f.toFixed(Float64Array.from(r), Float64Array.from(v), new Float64Array(3));
      const res = { position: m.position, velocity: m.velocity };
      m.free();
      return res;
    };

    return {
      configure(params) {
        p = params;
        const w = Number(p.omega), wd = Number(p.omegaDot), k = Number(p.stiffness);
        const zero = new Float64Array(3);
        const nextFrame = new MovingFrame(zero, zero, zero, Float64Array.of(0, 0, w), Float64Array.of(0, 0, wd));
        let nextParticle: SpringParticle;
        try {
          nextParticle = new SpringParticle(MASS, k);
        } catch (e) {
          nextFrame.free();
          throw e;
        }
        release();
        frame0 = nextFrame;
        particle = nextParticle;

        // At t = 0 the frames coincide; the launch velocity is given in one of them (polar input).
        r0 = Float64Array.of(Number(p.r0), 0, 0);
        const dir = Number(p.launchAngle) * DEG; // the slider's degrees → the core's radians
        const launch = Float64Array.of(Number(p.speed) * Math.cos(dir), Number(p.speed) * Math.sin(dir), 0);
        let v0fixed: Float64Array;
        if (p.launch === "rotating frame") {
          v0rel = launch;
          v0fixed = toFixed(frame0, r0, v0rel).velocity;
        } else {
          v0fixed = launch;
          const m = frame0.toMoving(r0, launch, particle.acceleration(r0));
          v0rel = m.velocity;
          m.free();
        }
        energy0 = particle.energy(r0, v0fixed);
        jacobi0 = particle.jacobiIntegral(frame0, r0, v0rel);

        // The path over LOOP_MAX; the loop ends where it first leaves the table (|r| is the same
        // in both frames, which share the axis), and the path is sampled again over the loop.
        loop = LOOP_MAX;
        times = sampleTimes(0, loop, TRAIL_SAMPLES);
        states = simulateParticle(frame0, r0, v0rel, loop, times, MASS, k);
        for (let i = 1; i < TRAIL_SAMPLES; i++) {
          if (norm(states.subarray(6 * i, 6 * i + 3)) > TABLE) {
            // Leaving at once (from the rim, outwards): the first sample interval.
            loop = times[Math.max(1, i - 1)];
            times = sampleTimes(0, loop, TRAIL_SAMPLES);
            states = simulateParticle(frame0, r0, v0rel, loop, times, MASS, k);
            break;
          }
        }
        for (let i = 0; i < TRAIL_SAMPLES; i++) {
          const r = states.subarray(6 * i, 6 * i + 3), v = states.subarray(6 * i + 3, 6 * i + 6);
          rotatingPath.set(i, r);
          const f = frame0.at(times[i]);
          fixedPath.set(i, toFixed(f, r, v).position);
          f.free();
        }
        fixedPath.commit();
        rotatingPath.commit();
        spring.visible = anchor.visible = k > 0;
      },
      step(t) {
        if (!frame0 || !particle) return;
        const k = Number(p.stiffness);
        const tau = Math.max(0, t) % loop;
        let i = Math.min(TRAIL_SAMPLES - 1, Math.floor((tau / loop) * (TRAIL_SAMPLES - 1)));
        while (i > 0 && times[i] > tau) i--;
        fixedPath.show(i + 1);
        rotatingPath.show(i + 1);

        // The state at tau: integrated by the core in the rotating frame from the last sample of
        // the path before tau (deterministic: a seek gives the same numbers as playing).
        const fi = frame0.at(times[i]);
        const dt = tau - times[i];
        let y: Float64Array;
        try {
          y = simulateParticle(fi, states.subarray(6 * i, 6 * i + 3), states.subarray(6 * i + 3, 6 * i + 6), dt, Float64Array.of(dt), MASS, k);
        } finally {
          fi.free();
        }
        const r = y.subarray(0, 3), v = y.subarray(3, 6);
        const f = frame0.at(tau);
        const att = f.attitude;
        const omegaNow = f.angularVelocity;
        const fixed = toFixed(f, r, v);
        const aTrue = particle.acceleration(fixed.position);
        // The rotating observer's split (2.26–2.27), then the fixed observer's (2.21).
        const rel = f.toMoving(fixed.position, fixed.velocity, aTrue);
        const aRel = rel.acceleration;
        const fx = f.toFixed(r, v, aRel);
        const terms = { relative: fx.relative, coriolis: fx.coriolis, centripetal: fx.centripetal, euler: fx.euler, sum: fx.acceleration };
        const fict = { coriolis: rel.coriolis, centrifugal: rel.centrifugal, euler: rel.euler, inertial: rel.inertial };
        fx.free();
        rel.free();
        const energy = particle.energy(fixed.position, fixed.velocity);
        const jacobi = particle.jacobiIntegral(f, r, v);
        f.free();

        // Draw.
        table.setRotationFromMatrix(matrix4(att));
        const at = vec(fixed.position);
        ball.position.copy(at);
        spring.geometry.setFromPoints([new THREE.Vector3(), at]);
        spring.computeLineDistances();
        fixedVel.set(vec(fixed.velocity), at);
        fixedAcc.set(vec(aTrue), at);
        const atRel = vec(r);
        relVel.set(vec(v), atRel);
        relAcc.set(vec(aRel), atRel);
        coriolis.set(vec(fict.coriolis), atRel);
        centrifugal.set(vec(fict.centrifugal), atRel);
        euler.set(vec(fict.euler), atRel);
        force.set(vec(fict.inertial), atRel);

        const residual = Math.hypot(terms.sum[0] - aTrue[0], terms.sum[1] - aTrue[1], terms.sum[2] - aTrue[2]);
        // The scale of the terms summed: the largest of them.
        const aScale = Math.max(...[terms.relative, terms.coriolis, terms.centripetal, terms.euler, aTrue].map(norm));
        const uniform = Number(p.omegaDot) === 0;
        const eDrift = energy - energy0, jDrift = jacobi - jacobi0;
        const vecOut = (key: string, label: string, x: ArrayLike<number>, digits = 4): Readout => ({ key, label, value: Array.from(x), text: fmtVec(x, digits) });
        out = [
          { key: "tau", label: "t in the loop (s)", value: tau, text: fmt(tau, 4) },
          { key: "loop", label: "loop (s), to the rim or 8 s", value: loop, text: fmt(loop, 4) },
          { key: "omegaNow", label: "ω(t) of the table (rad/s)", value: omegaNow[2], text: fmt(omegaNow[2], 6) },
          vecOut("positionFixed", "r′ fixed frame (m)", fixed.position),
          vecOut("positionRotating", "r rotating frame (m)", r),
          vecOut("velocityFixed", "ṙ′ fixed frame (m/s)", fixed.velocity),
          vecOut("velocityRotating", "v_rel rotating frame (m/s)", v),
          { key: "speedFixed", label: "speed seen fixed (m/s)", value: norm(fixed.velocity), text: fmt(norm(fixed.velocity), 8) },
          { key: "speedRotating", label: "speed seen rotating (m/s)", value: norm(v), text: fmt(norm(v), 8) },
          vecOut("relative", "a_rel (2.21, fixed comp.)", terms.relative),
          vecOut("coriolis", "Coriolis 2ω×v_rel", terms.coriolis),
          vecOut("centripetal", "centripetal ω×(ω×r)", terms.centripetal),
          vecOut("euler", "Euler ω̇×r", terms.euler),
          vecOut("sum", "sum of the four (m/s²)", terms.sum),
          vecOut("accelerationFixed", "r̈′ = F/m (m/s²)", aTrue),
          { check: true, key: "residual", label: "|sum − F/m| (m/s²)", value: residual, text: fmt(residual, 3, aScale), warn: residual > 1e-12 },
          { key: "energy", label: "E = ½mṙ′² + ½kr′² (J)", value: energy, text: `${fmt(energy, 9)} (drift ${fmt(eDrift, 2, Math.max(Math.abs(energy), Math.abs(energy0)))})` },
          {
            key: "jacobi",
            label: "Jacobi ½mv² + ½kr² − ½m|ω×r|² (J)",
            value: jacobi,
            text: `${fmt(jacobi, 9)} (${uniform ? "conserved, drift" : "not conserved: ω̇ ≠ 0, change"} ${fmt(jDrift, 2, Math.max(Math.abs(jacobi), Math.abs(jacobi0), Math.abs(energy)))})`,
          },
        ];
      },
      readouts() {
        return out;
      },
      viewports(w, h) {
        const half = Math.floor(w / 2);
        return [{ x: 0, y: 0, w: half, h }, { x: half, y: 0, w: w - half, h }];
      },
      render(renderer, scene, camera) {
        const size = renderer.getSize(new THREE.Vector2());
        const w = size.x, h = size.y;
        const [left, right] = this.viewports!(w, h);
        // Titles: the long form where a half has room for it.
        const short = left.w < SHORT_TITLES ? 1 : 0;
        titles.forEach((d, i) => {
          if (d.textContent !== TITLES[i][short]) d.textContent = TITLES[i][short];
        });
        titles[1].style.left = `${right.x + 8}px`;
        titles[0].style.left = "8px";
        for (const d of titles) d.style.maxWidth = `${left.w - 16}px`;
        divider.style.left = `${right.x}px`;
        renderer.setScissorTest(true);
        // Left: the fixed frame, through the orbit camera.
        ctx.aim(camera, left);
        camera.layers.set(0);
        camera.layers.enable(FIXED_ONLY);
        renderer.setViewport(left.x, 0, left.w, h);
        renderer.setScissor(left.x, 0, left.w, h);
        renderer.render(scene, camera);
        // Right: the same camera carried by the table (turned with it about the axis).
        rotCam.fov = camera.fov;
        rotCam.near = camera.near;
        rotCam.far = camera.far;
        ctx.aim(rotCam, right);
        rotCam.position.copy(camera.position).applyQuaternion(table.quaternion);
        rotCam.quaternion.copy(table.quaternion).multiply(camera.quaternion);
        rotCam.layers.set(0);
        rotCam.layers.enable(ROTATING_ONLY);
        renderer.setViewport(right.x, 0, right.w, h);
        renderer.setScissor(right.x, 0, right.w, h);
        renderer.render(scene, rotCam);
        renderer.setScissorTest(false);
        renderer.setViewport(0, 0, w, h);
        rotCam.updateMatrixWorld();
        ctx.labels.update(camera, left);
        rightLabels.update(rotCam, right);
        boxes = [projectBox([disk], camera, left), projectBox([disk], rotCam, right)].filter((r): r is Rect => r !== null);
      },
      frame() {
        return { center: new THREE.Vector3(0, 0, -0.05), radius: TABLE * 1.12 };
      },
      main() {
        return [disk];
      },
      mainBoxes() {
        return boxes;
      },
      dispose() {
        release();
        disposeTree(root);
        rightLabels.dispose();
        ctx.camera.layers.set(0);
      },
    };
  },
};
