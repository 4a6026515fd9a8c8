// Euler angles (the unit's 2.98–2.99): sliders for the three angles of any of the 24
// conventions, the three rotation discs of a gimbal, the line of nodes, and gimbal lock made
// visible (discs 1 and 3 coincide; the rates of 2.99 become undefined and the core says so).
import * as THREE from "three";
import { bodyAngularVelocity, eulerRates, eulerToMatrix, matrixToEuler, rotationAxis } from "../core";
import { angles, DEG, fmtVec, type Params, type Readout, type SceneDef } from "../scene";
import { AXIS_COLORS, axisLabels, bodyAxes, disposeTree, fixedAxes, matrix4 } from "../view";

export const SEQUENCES = ["zxz", "zyz", "xyx", "xzx", "yxy", "yzy", "xyz", "xzy", "yxz", "yzx", "zxy", "zyx"];
const AXIS_INDEX: Record<string, number> = { x: 0, y: 1, z: 2 };
const A = angles("°");

/** Column k of a row-major 3×3 matrix. */
function column(m: ArrayLike<number>, k: number): THREE.Vector3 {
  return new THREE.Vector3(m[k], m[3 + k], m[6 + k]);
}

export const eulerScene: SceneDef = {
  id: "euler",
  title: "Euler angles",
  short: "Euler",
  rateUnit: "°",
  pinned: ["angles", "angle", "axis", "gimbalLock"],
  describe: "a plate with a fin turned by three Euler angles, the three rotation discs of a gimbal and the dashed line of nodes; the fixed axes x, y, z and the body axes 1, 2, 3 are labelled",
  blurb:
    "R = R_a(α) R_b(β) R_c(γ) (intrinsic; extrinsic reverses the product). The unit's φ, θ, ψ are intrinsic zxz. " +
    "Each disc is the plane of one rotation; the dashed line is the line of nodes (the axis of the middle rotation). " +
    "Set the middle angle to 0° (or ±90° for Tait–Bryan) to see gimbal lock: discs 1 and 3 coincide.",
  params: [
    { kind: "choice", key: "seq", label: "Sequence", options: SEQUENCES, value: "zxz" },
    { kind: "choice", key: "convention", label: "Convention", options: ["intrinsic", "extrinsic"], value: "intrinsic" },
    { kind: "number", key: "phi", label: "1st angle φ", unit: "°", min: -180, max: 180, step: 1, value: 30 },
    { kind: "number", key: "theta", label: "2nd angle θ", unit: "°", min: -180, max: 180, step: 1, value: 40 },
    { kind: "number", key: "psi", label: "3rd angle ψ", unit: "°", min: -180, max: 180, step: 1, value: 20 },
    { kind: "number", key: "phiDot", label: "rate φ̇", unit: "°/s", min: -90, max: 90, step: 1, value: 20 },
    { kind: "number", key: "thetaDot", label: "rate θ̇", unit: "°/s", min: -90, max: 90, step: 1, value: 0 },
    { kind: "number", key: "psiDot", label: "rate ψ̇", unit: "°/s", min: -90, max: 90, step: 1, value: 45 },
  ],
  create(ctx) {
    const root = new THREE.Group();
    ctx.scene.add(root);
    root.add(fixedAxes(2.6));
    axisLabels(ctx.labels, 2.6, ["x", "y", "z"]);

    // The body: a flat plate with a fin, so that every orientation reads at a glance.
    const body = new THREE.Group();
    body.matrixAutoUpdate = false;
    const plate = new THREE.Mesh(new THREE.BoxGeometry(1.6, 0.9, 0.18), new THREE.MeshStandardMaterial({ color: 0xc9d1d9, roughness: 0.6 }));
    const fin = new THREE.Mesh(new THREE.BoxGeometry(0.5, 0.06, 0.5), new THREE.MeshStandardMaterial({ color: 0xf2b84b }));
    fin.position.set(-0.5, 0, 0.32);
    body.add(plate, fin, bodyAxes(1.7));
    root.add(body);
    axisLabels(ctx.labels, 1.7, ["1", "2", "3"], [], { obj: body });

    // The three rotation discs (radii 2.2, 1.95, 1.7), coloured as the axis they turn about.
    const discs = [2.2, 1.95, 1.7].map((r) => {
      const m = new THREE.Mesh(new THREE.TorusGeometry(r, 0.025, 8, 96), new THREE.MeshStandardMaterial({ color: 0xffffff }));
      const fill = new THREE.Mesh(
        new THREE.CircleGeometry(r, 96),
        new THREE.MeshBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.07, side: THREE.DoubleSide, depthWrite: false }),
      );
      m.add(fill);
      root.add(m);
      return m;
    });
    const nodesGeom = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(-2.5, 0, 0), new THREE.Vector3(2.5, 0, 0)]);
    const nodes = new THREE.Line(nodesGeom, new THREE.LineDashedMaterial({ color: 0xf2b84b, dashSize: 0.12, gapSize: 0.08 }));
    nodes.computeLineDistances();
    root.add(nodes);

    let p: Params = {};
    let state: { angles: number[]; rates: number[]; R: Float64Array; readouts: Readout[] } | null = null;
    const zHat = new THREE.Vector3(0, 0, 1);
    const xHat = new THREE.Vector3(1, 0, 0);

    return {
      configure(params) {
        p = params;
        const seq = String(p.seq);
        const intrinsic = p.convention === "intrinsic";
        // Validate now, so that a bad parameter is reported before the first frame.
        eulerToMatrix([Number(p.phi) * DEG, Number(p.theta) * DEG, Number(p.psi) * DEG], seq, intrinsic);
        // Colour the discs as the axis each one turns about (in the order applied intrinsically).
        const seqI = intrinsic ? seq : [...seq].reverse().join("");
        discs.forEach((d, i) => (d.material as THREE.MeshStandardMaterial).color.setHex(AXIS_COLORS[AXIS_INDEX[seqI[i]]]));
      },
      step(t) {
        const seq = String(p.seq);
        const intrinsic = p.convention === "intrinsic";
        const deg = [Number(p.phi) + Number(p.phiDot) * t, Number(p.theta) + Number(p.thetaDot) * t, Number(p.psi) + Number(p.psiDot) * t];
        const angles = deg.map((a) => a * DEG);
        const rates = [Number(p.phiDot) * DEG, Number(p.thetaDot) * DEG, Number(p.psiDot) * DEG];
        const R = eulerToMatrix(angles, seq, intrinsic);
        body.matrix.copy(matrix4(R));
        body.matrixWorldNeedsUpdate = true;

        // The gimbal: the same rotation as an intrinsic product, applied one factor at a time.
        const seqI = intrinsic ? seq : [...seq].reverse().join("");
        const aI = intrinsic ? angles : [...angles].reverse();
        const M1 = eulerToMatrix([aI[0], 0, 0], seqI, true);
        const M2 = eulerToMatrix([aI[0], aI[1], 0], seqI, true);
        const normals = [new THREE.Vector3().setComponent(AXIS_INDEX[seqI[0]], 1), column(M1, AXIS_INDEX[seqI[1]]), column(M2, AXIS_INDEX[seqI[2]])];
        normals.forEach((n, i) => discs[i].quaternion.setFromUnitVectors(zHat, n.clone().normalize()));
        nodes.quaternion.setFromUnitVectors(xHat, normals[1].clone().normalize());

        const [ax, ay, az, angle] = rotationAxis(R);
        const back = matrixToEuler(R, seq, intrinsic);
        const recovered = Array.from(back.angles);
        const lock = back.gimbalLock;
        back.free();
        const omega = bodyAngularVelocity(angles, rates, seq, intrinsic);
        let ratesText: string;
        let ratesDetail: string | undefined;
        let ratesValue: number[] | string;
        try {
          ratesValue = Array.from(eulerRates(angles, omega, seq, intrinsic));
          ratesText = A.rates(ratesValue, 4);
        } catch (e) {
          // The core's error, in full in the value and the tooltip; in a few words on the page.
          const err = e as Error;
          ratesValue = `${err.name}: ${err.message}`;
          ratesText = `none at gimbal lock (${err.name})`;
          ratesDetail = ratesValue;
        }
        const sep = normals[0].angleTo(normals[2]);
        state = {
          angles, rates, R,
          readouts: [
            { key: "angles", label: `angles (${A.name})`, unitScale: A.angleScale, value: angles, text: A.vec(angles, 5, 1) },
            { key: "R", label: "R (rows)", value: Array.from(R), text: [0, 1, 2].map((i) => fmtVec(R.subarray(3 * i, 3 * i + 3), 4, 1)).join(" ") },
            { key: "axis", label: "rotation axis", value: [ax, ay, az], text: fmtVec([ax, ay, az], 4, 1) },
            { key: "angle", label: `rotation angle (${A.name})`, unitScale: A.angleScale, value: angle, text: A.angle(angle, 6) },
            { key: "recovered", label: `angles from R (${A.name})`, unitScale: A.angleScale, value: recovered, text: A.vec(recovered, 5, 1) },
            { key: "gimbalLock", label: "gimbal lock", value: lock, text: lock ? "yes: only a sum/difference of the outer angles is defined" : "no", warn: lock },
            { key: "discSeparation", label: `disc 1 ∠ disc 3 (${A.name})`, unitScale: A.angleScale, value: sep, text: A.angle(sep, 4), warn: lock },
            { key: "omegaBody", label: `ω body (${A.perSecond}, 2.99)`, unitScale: A.rateScale, value: Array.from(omega), text: A.rates(omega, 5) },
            { key: "ratesFromOmega", label: `rates from ω (${A.perSecond})`, unitScale: A.rateScale, value: ratesValue, text: ratesText, detail: ratesDetail, warn: typeof ratesValue === "string" },
          ],
        };
      },
      readouts() {
        return state?.readouts ?? [];
      },
      frame() {
        // The outer disc's sphere holds every disc and the body, whatever the angles.
        return { center: new THREE.Vector3(), radius: 2.3 };
      },
      main() {
        return [body, ...discs];
      },
      dispose() {
        disposeTree(root);
      },
    };
  },
};
