// three.js plumbing shared by the scenes: renderer, camera (z up, as the physics), orbit
// controls, axes, arrows, cones, and conversions from the core's layouts (row-major 3×3,
// scalar-first quaternions).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

export interface View {
  renderer: THREE.WebGLRenderer;
  scene: THREE.Scene;
  camera: THREE.PerspectiveCamera;
  controls: OrbitControls;
  resize(): void;
}

export function createView(host: HTMLElement): View {
  // preserveDrawingBuffer: the tests read the pixels back (the cost is negligible here).
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  host.appendChild(renderer.domElement);
  renderer.domElement.setAttribute("role", "img");
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x101418);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.05, 200);
  camera.up.set(0, 0, 1);
  camera.position.set(5.5, 4.2, 3.4);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = true;
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(4, 3, 6);
  scene.add(sun);
  const resize = () => {
    const w = Math.max(1, host.clientWidth);
    const h = Math.max(1, host.clientHeight);
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  };
  new ResizeObserver(resize).observe(host);
  resize();
  return { renderer, scene, camera, controls, resize };
}

/** A THREE.Matrix4 from a row-major 3×3 rotation (9 numbers). */
export function matrix4(r: ArrayLike<number>): THREE.Matrix4 {
  return new THREE.Matrix4().set(r[0], r[1], r[2], 0, r[3], r[4], r[5], 0, r[6], r[7], r[8], 0, 0, 0, 0, 1);
}

/** A THREE.Quaternion from a scalar-first quaternion [w, x, y, z]. */
export function quaternion(q: ArrayLike<number>): THREE.Quaternion {
  return new THREE.Quaternion(q[1], q[2], q[3], q[0]);
}

export function vec(v: ArrayLike<number>): THREE.Vector3 {
  return new THREE.Vector3(v[0], v[1], v[2]);
}

export const AXIS_COLORS = [0xe5484d, 0x46a758, 0x3e7bfa];

/** Thin fixed axes (x red, y green, z blue) of length `len`. */
export function fixedAxes(len: number, opacity = 0.45): THREE.Group {
  const g = new THREE.Group();
  for (let k = 0; k < 3; k++) {
    const dir = new THREE.Vector3().setComponent(k, 1);
    const geom = new THREE.BufferGeometry().setFromPoints([dir.clone().multiplyScalar(-len), dir.clone().multiplyScalar(len)]);
    const mat = new THREE.LineBasicMaterial({ color: AXIS_COLORS[k], transparent: true, opacity });
    g.add(new THREE.Line(geom, mat));
  }
  return g;
}

/** Solid arrows of the three body axes. */
export function bodyAxes(len: number): THREE.Group {
  const g = new THREE.Group();
  for (let k = 0; k < 3; k++) {
    const dir = new THREE.Vector3().setComponent(k, 1);
    g.add(new THREE.ArrowHelper(dir, new THREE.Vector3(), len, AXIS_COLORS[k], 0.18 * len, 0.08 * len));
  }
  return g;
}

/** An arrow from the origin; `set(v)` points it along v with its length. */
export class Arrow {
  readonly obj: THREE.ArrowHelper;
  constructor(color: number, private scale = 1) {
    this.obj = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, color, 0.15, 0.07);
  }
  set(v: THREE.Vector3, origin?: THREE.Vector3): void {
    const len = v.length() * this.scale;
    this.obj.visible = len > 1e-9;
    if (!this.obj.visible) return;
    this.obj.setDirection(v.clone().normalize());
    const head = Math.min(0.25, 0.3 * len);
    this.obj.setLength(len, head, 0.45 * head);
    if (origin) this.obj.position.copy(origin);
  }
}

/** A translucent cone with its apex at the origin opening along +z, of half-angle `half`
 * (rad, in (0, π)) and slant length `slant`. A half-angle above π/2 opens along −z. */
export function cone(half: number, slant: number, color: number, opacity = 0.28): THREE.Mesh {
  const flip = half > Math.PI / 2;
  const a = flip ? Math.PI - half : half;
  const height = Math.max(1e-3, slant * Math.cos(a));
  const geom = new THREE.ConeGeometry(Math.max(1e-3, slant * Math.sin(a)), height, 64, 1, true);
  geom.rotateX(-Math.PI / 2);
  geom.translate(0, 0, height / 2);
  if (flip) geom.rotateX(Math.PI);
  const mat = new THREE.MeshStandardMaterial({ color, transparent: true, opacity, side: THREE.DoubleSide, depthWrite: false });
  return new THREE.Mesh(geom, mat);
}

/** A line drawn through the points stored in `pos` (3 numbers each; the caller rewrites them and
 * sets the draw range), initially empty, never frustum-culled (its bounds change each frame). */
export function bufferLine(pos: Float32Array, color: number, opacity = 1): THREE.Line {
  const geom = new THREE.BufferGeometry();
  geom.setAttribute("position", new THREE.BufferAttribute(pos, 3));
  geom.setDrawRange(0, 0);
  const line = new THREE.Line(geom, new THREE.LineBasicMaterial({ color, transparent: opacity < 1, opacity }));
  line.frustumCulled = false;
  return line;
}

/** A polyline of at most `capacity` points; `push` appends, dropping the oldest. */
export class Trail {
  readonly obj: THREE.Line;
  private readonly pos: Float32Array;
  private n = 0;
  constructor(private capacity: number, color: number) {
    this.pos = new Float32Array(3 * capacity);
    this.obj = bufferLine(this.pos, color);
  }
  clear(): void {
    this.n = 0;
    this.obj.geometry.setDrawRange(0, 0);
  }
  push(p: THREE.Vector3): void {
    if (this.n === this.capacity) {
      this.pos.copyWithin(0, 3);
      this.n--;
    }
    this.pos.set([p.x, p.y, p.z], 3 * this.n);
    this.n++;
    const attr = this.obj.geometry.getAttribute("position") as THREE.BufferAttribute;
    attr.needsUpdate = true;
    this.obj.geometry.setDrawRange(0, this.n);
  }
}

export function disposeTree(root: THREE.Object3D): void {
  root.traverse((o) => {
    const m = o as THREE.Mesh;
    m.geometry?.dispose();
    const mat = m.material as THREE.Material | THREE.Material[] | undefined;
    if (Array.isArray(mat)) mat.forEach((x) => x.dispose());
    else mat?.dispose();
  });
  root.removeFromParent();
}
