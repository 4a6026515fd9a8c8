// Inertia (the unit's 2.58–2.66) and the theorems of Euler and Chasles: a solid (one of the core's
// nine standard solids, or an STL file), its inertia tensor, principal moments and axes, kind of
// top and ellipsoid of inertia; then a displaced copy, the rotation axis of the displacement
// (Euler) and its screw axis (Chasles), and the body carried from the first pose to the second by
// the screw motion — every pose from the core (Screw.displacementAt). One picture at a time:
// the body with its principal axes and ellipsoid (no displacement), or the displacement (Euler
// or Chasles) without the ellipsoid; the controls shown are those that apply.
import * as THREE from "three";
import { eulerToMatrix, RigidBody, rotationAxis, screwAxis, type Screw } from "../core";
import { angles, belowPrecision, DEG, fmt, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { axisLabels, disposeTree, fixedAxes, frameOf, matrix4, vec } from "../view";
import { mergeVertices, parseStl } from "../stl";

/** The shapes of the choice; each is the core constructor named in MEANING (RigidBody.cuboid,
 * .solidSphere, .sphericalShell, .solidCylinder, .solidCone, .ellipsoid, .thinRod, .thinDisk,
 * .thinRing; .fromMesh for an STL file). */
export const SHAPES = ["cuboid", "sphere", "shell", "cylinder", "cone", "ellipsoid", "rod", "disk", "ring", "STL file"];
/** None: the body at rest with its principal axes and ellipsoid of inertia; Euler: the rotation
 * R about the CM (t = 0); Chasles: the general displacement (R, t). */
export const MOTIONS = ["none", "Euler", "Chasles"];
const STL = "STL file";
/** The shapes whose constructor takes b, and c (MEANING). */
const USES_B = ["cuboid", "cylinder", "cone", "ellipsoid"];
const USES_C = ["cuboid", "ellipsoid"];
const A = angles("°");
const UNITS: Record<string, number> = { m: 1, cm: 0.01, mm: 0.001 };

/** What the sliders a, b, c mean for each shape (the core constructor's arguments). */
const MEANING: Record<string, string> = {
  cuboid: "RigidBody.cuboid: a, b, c = sides along x, y, z",
  sphere: "RigidBody.solidSphere: a = radius (b, c unused)",
  shell: "RigidBody.sphericalShell (thin): a = radius (b, c unused)",
  cylinder: "RigidBody.solidCylinder: a = radius, b = height along z (c unused)",
  cone: "RigidBody.solidCone: a = base radius, b = height (apex at the origin, axis +z; c unused)",
  ellipsoid: "RigidBody.ellipsoid: a, b, c = semi-axes along x, y, z",
  rod: "RigidBody.thinRod: a = length along z (b, c unused)",
  disk: "RigidBody.thinDisk: a = radius, in the xy plane (b, c unused)",
  ring: "RigidBody.thinRing: a = radius, in the xy plane (b, c unused)",
  "STL file": "RigidBody.fromMesh: m, a, b, c unused; the density ρ and the file's unit apply",
};

/** The screw motion's clock (s): rest at the first pose, move at a constant rate, rest at the
 * second. The fraction s of the motion at scene time t (presentation only). */
const REST0 = 0.5, MOVE = 4, PERIOD = 6;
export function screwFraction(t: number): number {
  const tau = Math.max(0, t) % PERIOD;
  return Math.min(1, Math.max(0, (tau - REST0) / MOVE));
}

/** Principal-axis colours, I1 (smallest) to I3. */
const PRINCIPAL_COLORS = [0xf2b84b, 0xc77dff, 0x2ec4b6];

/** The solid's geometry in the core's body axes (presentation of the same dimensions). */
function solidGeometry(shape: string, a: number, b: number, c: number, mesh: { vertices: Float64Array; faces: Float64Array } | null): THREE.BufferGeometry {
  switch (shape) {
    case "sphere":
    case "shell":
      return new THREE.SphereGeometry(a, 48, 24);
    case "cylinder":
      return new THREE.CylinderGeometry(a, a, b, 48).rotateX(Math.PI / 2);
    case "cone":
      // three's cone has its apex at +y/2; the core's at the origin, base at z = h.
      return new THREE.ConeGeometry(a, b, 48).rotateX(-Math.PI / 2).translate(0, 0, b / 2);
    case "ellipsoid":
      return new THREE.SphereGeometry(1, 48, 24).scale(a, b, c);
    case "rod":
      return new THREE.CylinderGeometry(0.025, 0.025, a, 12).rotateX(Math.PI / 2);
    case "disk":
      return new THREE.CircleGeometry(a, 72);
    case "ring":
      return new THREE.TorusGeometry(a, 0.025, 10, 96);
    case "STL file": {
      const g = new THREE.BufferGeometry();
      g.setAttribute("position", new THREE.BufferAttribute(Float32Array.from(mesh!.vertices), 3));
      g.setIndex(Array.from(mesh!.faces));
      g.computeVertexNormals();
      return g;
    }
    default:
      return new THREE.BoxGeometry(a, b, c);
  }
}

/** The row-major rotation and the translation of a 12-number pose as a THREE.Matrix4. */
function poseMatrix(r: ArrayLike<number>, t: ArrayLike<number>): THREE.Matrix4 {
  return matrix4(r).setPosition(t[0], t[1], t[2]);
}

/** A 3×3 matrix's rows; an entry below the precision at the matrix's largest entry is 0. */
const rows = (m: ArrayLike<number>, d = 4) => {
  const scale = Math.max(...Array.from(m, Math.abs));
  return [0, 1, 2].map((i) => fmtVec(Array.from(m).slice(3 * i, 3 * i + 3), d, scale)).join(" ");
};

export const inertiaScene: SceneDef = {
  id: "inertia",
  title: "Inertia",
  short: "Inertia",
  rateUnit: "°",
  pinned: (p) =>
    p.motion === "Chasles" ? ["screwAngle", "screwSlide", "screwPitch", "s"] : p.motion === "Euler" ? ["eulerAngle", "eulerAxis", "s"] : ["mass", "principalMoments", "kind"],
  describe: "a solid with its principal axes and ellipsoid of inertia, or, for a displacement, the solid carried from a grey ghost to an orange ghost along its screw axis (yellow); the x, y and z axes are labelled",
  blurb:
    "A solid's inertia tensor about its centre of mass (2.58–2.62), principal moments and axes (2.65–2.66; arrows gold I₁ ≤ violet I₂ ≤ teal I₃), " +
    "kind of top, triangle margins I₂+I₃−I₁, I₃+I₁−I₂, I₁+I₂−I₃ (zero for a lamina) and ellipsoid of inertia x·I·x = 1 (blue wire, semi-axes ∝ 1/√I_k, scaled to the body). " +
    "Choose a displacement to see it: the body (CM at the origin, grey ghost) is displaced by x ↦ R x + t, R = R_z(φ) R_x(θ) R_z(ψ), to the orange ghost. " +
    "Euler: a rotation about the CM is a turn about one axis through it. Chasles: any displacement is a screw — a turn about one line (yellow) and a slide along it; " +
    "the body moves along that screw, its CM on the helix.",
  params: [
    { kind: "choice", key: "shape", label: "Shape", options: SHAPES, value: "cuboid" },
    { kind: "number", key: "mass", label: "mass m", unit: "kg", min: 0.1, max: 10, step: 0.1, value: 2, when: (p) => p.shape !== STL },
    { kind: "number", key: "a", label: "a", unit: "m", min: 0.1, max: 2, step: 0.05, value: 1.2, when: (p) => p.shape !== STL },
    { kind: "number", key: "b", label: "b", unit: "m", min: 0.1, max: 2, step: 0.05, value: 0.8, when: (p) => USES_B.includes(String(p.shape)) },
    { kind: "number", key: "c", label: "c", unit: "m", min: 0.1, max: 2, step: 0.05, value: 0.4, when: (p) => USES_C.includes(String(p.shape)) },
    { kind: "number", key: "density", label: "density ρ", unit: "kg/m³", min: 10, max: 20000, step: 10, value: 1000, when: (p) => p.shape === STL },
    { kind: "choice", key: "unit", label: "file's unit", options: Object.keys(UNITS), value: "m", when: (p) => p.shape === STL },
    { kind: "choice", key: "motion", label: "Displacement", options: MOTIONS, value: MOTIONS[0] },
    { kind: "number", key: "phi", label: "φ", unit: "°", min: -180, max: 180, step: 1, value: 60, when: (p) => p.motion !== "none" },
    { kind: "number", key: "theta", label: "θ", unit: "°", min: -180, max: 180, step: 1, value: 30, when: (p) => p.motion !== "none" },
    { kind: "number", key: "psi", label: "ψ", unit: "°", min: -180, max: 180, step: 1, value: 30, when: (p) => p.motion !== "none" },
    { kind: "number", key: "tx", label: "t_x", unit: "m", min: -3, max: 3, step: 0.05, value: 2, when: (p) => p.motion === "Chasles" },
    { kind: "number", key: "ty", label: "t_y", unit: "m", min: -3, max: 3, step: 0.05, value: 0, when: (p) => p.motion === "Chasles" },
    { kind: "number", key: "tz", label: "t_z", unit: "m", min: -3, max: 3, step: 0.05, value: 0.8, when: (p) => p.motion === "Chasles" },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    root.add(fixedAxes(3.2, 0.3));
    axisLabels(ctx.labels, 3.2, ["x", "y", "z"]);
    ctx.camera.position.set(2.2, -5.2, 2.6);

    // Materials: the moving body, the two ghosts (first and second pose).
    const solidMat = new THREE.MeshStandardMaterial({ color: 0xc9d1d9, roughness: 0.55, side: THREE.DoubleSide, flatShading: false });
    const startMat = new THREE.MeshStandardMaterial({ color: 0x8b98a5, transparent: true, opacity: 0.14, depthWrite: false, side: THREE.DoubleSide });
    const targetMat = new THREE.MeshStandardMaterial({ color: 0xf08c3c, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide });
    const makeHolder = (mat: THREE.Material) => {
      const pose = new THREE.Group();
      pose.matrixAutoUpdate = false;
      const offset = new THREE.Group(); // body axes → CM at the pose's origin
      const mesh = new THREE.Mesh(new THREE.BufferGeometry(), mat);
      offset.add(mesh);
      pose.add(offset);
      root.add(pose);
      return { pose, offset, mesh };
    };
    const moving = makeHolder(solidMat);
    const start = makeHolder(startMat);
    const target = makeHolder(targetMat);

    // Ellipsoid of inertia and principal axes, carried by the moving body (about its CM).
    const principal = new THREE.Group();
    principal.matrixAutoUpdate = false;
    moving.pose.add(principal);
    const ellipsoid = new THREE.Mesh(
      new THREE.SphereGeometry(1, 24, 12),
      new THREE.MeshBasicMaterial({ color: 0x7fb4ff, wireframe: true, transparent: true, opacity: 0.3, depthWrite: false }),
    );
    ellipsoid.matrixAutoUpdate = false;
    principal.add(ellipsoid);
    const arrows = PRINCIPAL_COLORS.map((color, k) => {
      const dir = new THREE.Vector3().setComponent(k, 1);
      const a = new THREE.ArrowHelper(dir, new THREE.Vector3(), 1, color, 0.16, 0.08);
      principal.add(a);
      return a;
    });
    const arrowNames = arrows.map((a, k) => ctx.labels.add(["I₁", "I₂", "I₃"][k], new THREE.Vector3(0, 1.1, 0), { obj: a, color: `#${PRINCIPAL_COLORS[k].toString(16)}`, className: "label3d axis" }));

    // The screw axis (a long line with an arrow for its direction) and the CM's path.
    // Lines drawn over the solids (depth test off) so that they read through the bodies.
    const axisLine = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineDashedMaterial({ color: 0xffe066, dashSize: 0.15, gapSize: 0.08, depthTest: false, transparent: true }));
    axisLine.renderOrder = 2;
    root.add(axisLine);
    const axisArrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, 0xffe066, 0.2, 0.1);
    root.add(axisArrow);
    const HELIX = 97;
    const helixPos = new Float32Array(3 * HELIX);
    const helixGeom = new THREE.BufferGeometry();
    helixGeom.setAttribute("position", new THREE.BufferAttribute(helixPos, 3));
    const helix = new THREE.Line(helixGeom, new THREE.LineBasicMaterial({ color: 0xffa65c, depthTest: false, transparent: true }));
    helix.frustumCulled = false;
    helix.renderOrder = 2;
    // The CM of the moving body (a dot on the helix).
    const cmDot = new THREE.Mesh(new THREE.SphereGeometry(0.045, 16, 8), new THREE.MeshBasicMaterial({ color: 0xffa65c, depthTest: false, transparent: true }));
    cmDot.renderOrder = 3;
    moving.pose.add(cmDot);
    root.add(helix);

    // Panel: the meaning of a, b, c; the STL file input; a legend.
    const meaning = document.createElement("p");
    meaning.className = "blurb";
    const fileLabel = document.createElement("label");
    fileLabel.className = "stl-only";
    fileLabel.textContent = "STL file (binary or ASCII, closed mesh): ";
    const file = document.createElement("input");
    Object.assign(file, { type: "file", accept: ".stl,model/stl,application/sla", name: "stl" });
    fileLabel.append(file);
    const fileStatus = document.createElement("p");
    fileStatus.className = "blurb stl-only";
    fileStatus.dataset.key = "stlStatus";
    fileStatus.textContent = "No file loaded.";
    const legend = document.createElement("p");
    legend.className = "blurb";
    const legendInertia =
      '<span style="color:#f2b84b">■ I₁</span> · <span style="color:#c77dff">■ I₂</span> · <span style="color:#2ec4b6">■ I₃</span> principal axes · ' +
      '<span style="color:#7fb4ff">wire</span> ellipsoid of inertia';
    const legendMotion =
      'grey ghost: the first pose · <span style="color:#f08c3c">orange ghost</span>: the second · <span style="color:#ffe066">- -</span> screw axis · ' +
      '<span style="color:#ffa65c">—</span> CM path';
    ctx.panel.append(meaning, fileLabel, fileStatus, legend);

    let stl: { name: string; vertices: Float64Array; faces: Float64Array; triangles: number } | null = null;
    let stlError: Error | null = null;
    file.addEventListener("change", async () => {
      const f = file.files?.[0];
      if (!f) return;
      try {
        const soup = parseStl(await f.arrayBuffer());
        const merged = mergeVertices(soup);
        stl = { name: f.name, ...merged, triangles: soup.length / 9 };
        stlError = null;
        fileStatus.textContent = `${f.name}: ${stl.triangles} triangles, ${merged.vertices.length / 3} distinct vertices.`;
      } catch (e) {
        stl = null;
        stlError = e as Error;
        fileStatus.textContent = `${f.name}: ${stlError.message}`;
      }
      // Select "STL file" through the shell's own control, which reconfigures the scene.
      const sel = document.querySelector<HTMLSelectElement>('#controls select[name="shape"]');
      if (sel) {
        sel.value = "STL file";
        sel.dispatchEvent(new Event("change"));
      }
    });

    let p: Params = {};
    let body: RigidBody | null = null;
    let centred: RigidBody | null = null;
    let screw: Screw | null = null;
    let fixed: Readout[] = [];
    let out: Readout[] = [];
    let R: Float64Array = new Float64Array(9);
    let T: number[] = [0, 0, 0];
    let moments: number[] = [];
    let displaced = false;
    let inertiaRadius = 1;

    const release = () => {
      screw?.free();
      centred?.free();
      body?.free();
      screw = null;
      centred = null;
      body = null;
    };

    const build = (shape: string, m: number, a: number, b: number, c: number): RigidBody => {
      switch (shape) {
        case "sphere": return RigidBody.solidSphere(m, a);
        case "shell": return RigidBody.sphericalShell(m, a);
        case "cylinder": return RigidBody.solidCylinder(m, a, b);
        case "cone": return RigidBody.solidCone(m, a, b);
        case "ellipsoid": return RigidBody.ellipsoid(m, [a, b, c]);
        case "rod": return RigidBody.thinRod(m, a);
        case "disk": return RigidBody.thinDisk(m, a);
        case "ring": return RigidBody.thinRing(m, a);
        case "STL file": {
          if (stlError) throw stlError;
          if (!stl) {
            const e = new Error("file: choose an STL file with the file input below the parameters");
            e.name = "PoinsotError";
            throw e;
          }
          const scale = UNITS[String(p.unit)] ?? 1;
          // The core merges corners that differ in the last bits (CAD exports), as Python's
          // merge_vertices=True does.
          return RigidBody.fromMesh(stl.vertices.map((x) => x * scale), stl.faces, Number(p.density), true);
        }
        default: return RigidBody.cuboid(m, [a, b, c]);
      }
    };

    return {
      configure(params) {
        p = params;
        const shape = String(p.shape);
        const [m, a, b, c] = [Number(p.mass), Number(p.a), Number(p.b), Number(p.c)];
        meaning.textContent = `${shape}: ${MEANING[shape] ?? ""}`;
        for (const el of [fileLabel, fileStatus]) el.hidden = shape !== STL;
        displaced = p.motion !== "none";
        legend.innerHTML = displaced ? legendMotion : legendInertia;
        // Build everything first; swap only when all of it succeeded.
        const nextBody = build(shape, m, a, b, c);
        let nextCentred: RigidBody, nextScrew: Screw, rot: Float64Array, kind: string;
        const com = Array.from(nextBody.centerOfMass);
        try {
          kind = nextBody.kind();
          nextCentred = nextBody.translated(com.map((x) => -x));
          rot = eulerToMatrix([Number(p.phi) * DEG, Number(p.theta) * DEG, Number(p.psi) * DEG], "zxz", true);
          T = p.motion === "Chasles" ? [Number(p.tx), Number(p.ty), Number(p.tz)] : [0, 0, 0];
          nextScrew = screwAxis(rot, T);
        } catch (e) {
          nextBody.free();
          throw e;
        }
        release();
        body = nextBody;
        centred = nextCentred;
        screw = nextScrew;
        R = rot;

        // Geometry: the solid in body axes, offset so that its CM sits at each pose's origin.
        const unit = shape === "STL file" ? UNITS[String(p.unit)] ?? 1 : 1;
        const geom = solidGeometry(shape, a, b, c, stl && { vertices: stl.vertices.map((x) => x * unit), faces: stl.faces });
        const old = moving.mesh.geometry;
        for (const h of [moving, start, target]) {
          h.mesh.geometry = geom;
          h.offset.position.set(-com[0], -com[1], -com[2]);
        }
        old.dispose();
        solidMat.flatShading = shape === "STL file" || shape === "cuboid";
        solidMat.needsUpdate = true;
        geom.computeBoundingSphere();
        const size = Math.max(0.3, geom.boundingSphere!.radius);

        // Principal axes and the ellipsoid of inertia: semi-axes ∝ 1/√I_k, the smallest drawn at
        // 0.6× the body's size, capped at 2.2× (a rotor's zero moment, an infinite semi-axis).
        moments = Array.from(body.principalMoments);
        const axes = body.principalAxes;
        const top = Math.max(...moments);
        const semi = moments.map((I) => (I > 1e-12 * top ? 1 / Math.sqrt(I) : Infinity));
        const finite = semi.filter(Number.isFinite);
        const k = (0.6 * size) / Math.min(...finite);
        const r = semi.map((x) => (Number.isFinite(x) ? Math.min(x * k, 2.2 * size) : 2.2 * size));
        principal.matrix.copy(matrix4(axes));
        ellipsoid.matrix.makeScale(r[0], r[1], r[2]);
        inertiaRadius = 1.05 * Math.max(size, ...r.map((x) => Math.max(x, 0.5 * size) + 0.5));
        arrows.forEach((arr, i) => {
          const len = Math.max(r[i], 0.5 * size) + 0.35;
          arr.setLength(len, 0.16, 0.08);
          ctx.labels.move(arrowNames[i], new THREE.Vector3(0, len + 0.12, 0));
        });

        // The screw axis and the CM's helix (the CM starts at the origin, so its position at
        // fraction s is the translation t(s) of the pose).
        const dir = vec(screw.axis);
        const pt = vec(screw.point);
        const L = 7;
        axisLine.geometry.setFromPoints([pt.clone().addScaledVector(dir, -L), pt.clone().addScaledVector(dir, L)]);
        axisLine.computeLineDistances();
        axisArrow.position.copy(pt);
        axisArrow.setDirection(dir);
        axisArrow.setLength(1.2, 0.22, 0.1);
        for (let i = 0; i < HELIX; i++) {
          const d = screw.displacementAt(i / (HELIX - 1));
          helixPos.set([d[9], d[10], d[11]], 3 * i);
        }
        helixGeom.getAttribute("position").needsUpdate = true;
        // One picture at a time: the body and its ellipsoid, or the displacement.
        start.pose.visible = target.pose.visible = displaced;
        axisLine.visible = axisArrow.visible = helix.visible = cmDot.visible = displaced;
        principal.visible = !displaced;
        start.pose.matrix.identity();
        target.pose.matrix.copy(poseMatrix(R, T));
        for (const h of [start, target]) h.pose.matrixWorldNeedsUpdate = true;

        const margins = Array.from(body.triangleMargins);
        const inertia = Array.from(body.inertia);
        const [ax, ay, az, angle] = rotationAxis(R);
        // Live check: the screw recomposed at s = 1 is the displacement (R, t).
        const whole = screw.displacementAt(1);
        let residual = 0;
        for (let i = 0; i < 9; i++) residual = Math.max(residual, Math.abs(whole[i] - R[i]));
        for (let i = 0; i < 3; i++) residual = Math.max(residual, Math.abs(whole[9 + i] - T[i]));
        const lamina = belowPrecision(margins[2], top);
        const tScale = Math.max(1, ...T.map(Math.abs));
        fixed = [
          { key: "mass", label: "mass (kg)", value: body.mass, text: fmt(body.mass, 6) },
          { key: "com", label: "CM, body axes (m)", value: com, text: fmtVec(com) },
          { key: "inertia", label: "I about CM (kg·m²)", value: inertia, text: rows(inertia) },
          { key: "principalMoments", label: "I₁ ≤ I₂ ≤ I₃ (kg·m²)", value: moments, text: fmtVec(moments, 4, top) },
          { key: "principalAxes", label: "principal axes (columns)", value: Array.from(axes), text: rows(axes) },
          { key: "kind", label: "kind", value: kind, text: kind },
          { key: "triangleMargins", label: "triangle margins (kg·m²)", value: margins, text: fmtVec(margins, 4, top) + (lamina ? " — a lamina" : ""), warn: lamina },
        ];
        if (displaced) {
          fixed.push(
            { key: "R", label: "R (rows)", value: Array.from(R), text: rows(R) },
            { key: "translation", label: "t (m)", value: T, text: fmtVec(T) },
            { key: "eulerAxis", label: "Euler axis of R", value: [ax, ay, az], text: fmtVec([ax, ay, az], 5, 1) },
            { key: "eulerAngle", label: `Euler angle (${A.name})`, unitScale: A.angleScale, value: angle, text: A.angle(angle, 6) },
            { key: "screwAxis", label: "screw axis", value: Array.from(screw.axis), text: fmtVec(screw.axis, 5, 1) },
            { key: "screwPoint", label: "screw point (m)", value: Array.from(screw.point), text: fmtVec(screw.point, 5, tScale) },
            { key: "screwAngle", label: `screw angle (${A.name})`, unitScale: A.angleScale, value: screw.angle, text: A.angle(screw.angle, 6) },
            { key: "screwSlide", label: "slide (m)", value: screw.slide, text: fmt(screw.slide, 6, tScale) },
            { key: "screwPitch", label: `pitch (m/${A.name})`, unitScale: DEG, value: screw.pitch, text: fmt(screw.pitch * DEG, 6, tScale * DEG) },
            { check: true, key: "residual", label: "check |D(1) − (R, t)|∞", value: residual, text: fmt(residual, 3, tScale), warn: residual > 1e-12 * tScale },
          );
        }
      },
      step(t) {
        if (!screw || !centred || !body) return;
        if (!displaced) {
          moving.pose.matrix.identity();
          moving.pose.matrixWorldNeedsUpdate = true;
          out = fixed;
          return;
        }
        const s = screwFraction(t);
        const d = screw.displacementAt(s);
        const Rs = d.subarray(0, 9);
        const ts = d.subarray(9, 12);
        moving.pose.matrix.copy(poseMatrix(Rs, ts));
        moving.pose.matrixWorldNeedsUpdate = true;
        // The moved body's mass properties in space axes: the CM is at t(s), the tensor is
        // R(s) I R(s)ᵀ; its principal moments are those of the body (shown with their drift).
        const rotatedBody = centred.rotated(Rs);
        const moved = rotatedBody.translated(ts);
        rotatedBody.free();
        const movedCom = Array.from(moved.centerOfMass);
        const movedInertia = Array.from(moved.inertia);
        const movedMoments = Array.from(moved.principalMoments);
        moved.free();
        const scale = Math.max(...moments);
        const drift = Math.max(...movedMoments.map((x, i) => Math.abs(x - moments[i]))) / scale;
        const tScale = Math.max(1, ...T.map(Math.abs));
        out = [
          ...fixed,
          { key: "s", label: "s (screw fraction)", value: s, text: fmt(s, 4) },
          { key: "pose", label: "pose R(s) rows, t(s) (m)", value: Array.from(d), text: rows(Rs, 3) + " " + fmtVec(ts, 4, tScale) },
          { key: "movedCom", label: "CM at s (m)", value: movedCom, text: fmtVec(movedCom, 5, tScale) },
          { key: "movedInertia", label: "R(s) I R(s)ᵀ (kg·m²)", value: movedInertia, text: rows(movedInertia) },
          { check: true, key: "momentDrift", label: "moments of R(s) I R(s)ᵀ: drift", value: drift, text: fmt(drift, 3, 1), warn: drift > 1e-12 },
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        // The displacement's two poses and the helix; or the body about its CM (at the origin)
        // with its principal axes.
        return displaced ? frameOf([start.mesh, target.mesh, helix], 0.2) : { center: new THREE.Vector3(), radius: inertiaRadius };
      },
      main() {
        return displaced ? [start.mesh, target.mesh, moving.mesh] : [moving.mesh];
      },
      dispose() {
        release();
        disposeTree(root);
      },
    };
  },
};
