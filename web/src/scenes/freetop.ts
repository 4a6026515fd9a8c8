// The free symmetric top (the unit's 2.77–2.97): the body cone, fixed in the body around its
// symmetry axis, rolls on the space cone, fixed in space around L; their line of contact is ω.
// Prolate (I₃ < I₁): the body cone rolls on the outside; oblate (I₃ > I₁): it surrounds the
// space cone. Every number comes from the core's exact solution.
import * as THREE from "three";
import { FreeSymmetricTop, RigidBody } from "../core";
import { angles, fmt, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { Arrow, axisLabels, bodyAxes, cone, disposeTree, fixedAxes, quaternion, Trail, vec } from "../view";

const SLANT = 2.4;
const A = angles("rad");

export const freeTopScene: SceneDef = {
  id: "freetop",
  title: "Free top",
  short: "Free top",
  rateUnit: "rad",
  pinned: ["shape", "precessionRate", "bodyConeAngle", "spaceConeAngle"],
  describe: "a torque-free symmetric top with its body cone (orange) rolling on the space cone (blue) around the fixed angular momentum L; ω (white) lies along their line of contact; the fixed axes x, y, z and the body axes 1, 2, 3 are labelled",
  blurb:
    "A torque-free symmetric top: ω precesses about the symmetry axis at Ω = (I₁ − I₃) ω₃ / I₁ in the body (2.83). " +
    "The body cone (orange, carried by the body) rolls on the space cone (blue, around the fixed L); they touch along ω (white).",
  params: [
    { kind: "number", key: "I1", label: "I₁ = I₂", unit: "kg·m²", min: 0.2, max: 4, step: 0.05, value: 1 },
    { kind: "number", key: "I3", label: "I₃", unit: "kg·m²", min: 0.2, max: 4, step: 0.05, value: 0.4 },
    { kind: "number", key: "w1", label: "ω₁(0)", unit: "rad/s", min: 0, max: 3, step: 0.05, value: 0.6 },
    { kind: "number", key: "w3", label: "ω₃(0)", unit: "rad/s", min: -3, max: 3, step: 0.05, value: 2 },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    root.add(fixedAxes(3));
    axisLabels(ctx.labels, 3, ["x", "y", "z"]);

    const body = new THREE.Group();
    root.add(body);
    body.add(bodyAxes(1.2));
    axisLabels(ctx.labels, 1.2, ["1", "2", "3"], [], { obj: body });
    let solid: THREE.Mesh | null = null;
    let bodyCone: THREE.Mesh | null = null;
    let spaceCone: THREE.Mesh | null = null;
    const spaceConeHolder = new THREE.Group();
    root.add(spaceConeHolder);
    const omegaArrow = new Arrow(0xffffff, 1);
    const lArrow = new Arrow(0x7cc4ff, 1);
    root.add(omegaArrow.obj, lArrow.obj);
    const omegaLabel = ctx.labels.add("ω", new THREE.Vector3(), { className: "label3d axis" });
    const lLabel = ctx.labels.add("L", new THREE.Vector3(), { className: "label3d axis", color: "#7cc4ff" });
    const trail = new Trail(600, 0xf2b84b);
    root.add(trail.obj);

    let top: FreeSymmetricTop | null = null;
    let rigid: RigidBody | null = null;
    let p: Params = {};
    let lHat = new THREE.Vector3(0, 0, 1);
    let out: Readout[] = [];

    const free = () => {
      top?.free();
      rigid?.free();
      top = null;
      rigid = null;
    };

    return {
      configure(params) {
        p = params;
        const I1 = Number(p.I1), I3 = Number(p.I3);
        const omega0 = [Number(p.w1), 0, Number(p.w3)];
        const next = new FreeSymmetricTop(I1, I3, omega0);
        let nextRigid: RigidBody;
        try {
          nextRigid = RigidBody.fromInertia(1, [I1, 0, 0, 0, I1, 0, 0, 0, I3], [0, 0, 0]);
        } catch (e) {
          next.free();
          throw e;
        }
        free();
        top = next;
        rigid = nextRigid;

        // Shapes follow the moments: a rod for a prolate top, a disk for an oblate one.
        if (solid) disposeTree(solid);
        const oblate = I3 > I1;
        const geom = oblate ? new THREE.CylinderGeometry(1.1, 1.1, 0.22, 64) : new THREE.CylinderGeometry(0.3, 0.3, 1.9, 48);
        geom.rotateX(Math.PI / 2); // cylinder axis (y) → body z, the symmetry axis
        solid = new THREE.Mesh(geom, new THREE.MeshStandardMaterial({ color: 0xc9d1d9, roughness: 0.5, transparent: true, opacity: 0.85 }));
        body.add(solid);

        if (bodyCone) disposeTree(bodyCone);
        if (spaceCone) disposeTree(spaceCone);
        bodyCone = cone(Math.max(1e-3, top.bodyConeAngle), SLANT, 0xf2b84b);
        body.add(bodyCone);
        spaceCone = cone(Math.max(1e-3, top.spaceConeAngle), SLANT, 0x3e7bfa);
        spaceConeHolder.add(spaceCone);
        const L = vec(top.angularMomentum);
        lHat = L.lengthSq() > 0 ? L.clone().normalize() : new THREE.Vector3(0, 0, 1);
        spaceConeHolder.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), lHat);
        lArrow.set(lHat.clone().multiplyScalar(SLANT * 1.15));
        ctx.labels.move(lLabel, lHat.clone().multiplyScalar(SLANT * 1.22));
        trail.clear();
      },
      step(t) {
        if (!top || !rigid) return;
        const w = top.omega(t);
        const q = top.attitude(t);
        const att = quaternion(q);
        body.quaternion.copy(att);
        const wSpace = vec(w).applyQuaternion(att);
        const wDir = wSpace.lengthSq() > 0 ? wSpace.clone().normalize() : wSpace;
        omegaArrow.set(wDir.clone().multiplyScalar(SLANT));
        ctx.labels.move(omegaLabel, wDir.clone().multiplyScalar(SLANT * 1.08));
        trail.push(wDir.clone().multiplyScalar(SLANT));

        const T = rigid.kineticEnergy(w);
        const Lbody = rigid.angularMomentum(w);
        const Lmag = vec(Lbody).length();
        const T0 = top.energy;
        const L0 = vec(top.angularMomentum).length();
        out = [
          { key: "t", label: "t (s)", value: t, text: fmt(t, 5) },
          { key: "shape", label: "shape", value: top.shape, text: top.shape },
          { key: "omega", label: "ω body (rad/s)", value: Array.from(w), text: fmtVec(w) },
          { key: "attitude", label: "attitude [w,x,y,z]", value: Array.from(q), text: fmtVec(q, 4, 1) },
          { key: "precessionRate", label: "Ω (rad/s, 2.83)", value: top.precessionRate, text: fmt(top.precessionRate) },
          { key: "amplitude", label: "A (rad/s)", value: top.amplitude, text: fmt(top.amplitude) },
          { key: "bodyConeAngle", label: `body cone (${A.name})`, unitScale: A.angleScale, value: top.bodyConeAngle, text: A.angle(top.bodyConeAngle) },
          { key: "spaceConeAngle", label: `space cone (${A.name})`, unitScale: A.angleScale, value: top.spaceConeAngle, text: A.angle(top.spaceConeAngle) },
          { key: "energy", label: "T (J), conserved", value: T0, text: fmt(T0, 8) },
          { check: true, key: "energyNow", label: "T(t) from ω(t) (J)", value: T, text: `${fmt(T, 8)} (rel. drift ${fmt(T0 > 0 ? (T - T0) / T0 : 0, 2, 1)})` },
          { key: "angularMomentum", label: "|L| (kg·m²/s)", value: L0, text: fmt(L0, 8) },
          { check: true, key: "angularMomentumNow", label: "|L(t)| from ω(t) (kg·m²/s)", value: Lmag, text: `${fmt(Lmag, 8)} (rel. drift ${fmt(L0 > 0 ? (Lmag - L0) / L0 : 0, 2, 1)})` },
        ];
      },
      readouts() {
        return out;
      },
      frame() {
        // The cones' slant and the L arrow, about the fixed point.
        return { center: new THREE.Vector3(), radius: SLANT * 1.2 };
      },
      main() {
        return [body, spaceConeHolder];
      },
      dispose() {
        free();
        disposeTree(root);
      },
    };
  },
};
