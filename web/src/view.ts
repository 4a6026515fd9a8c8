// three.js plumbing shared by the scenes: renderer, camera (z up, as the physics), orbit
// controls, axes, arrows, cones, conversions from the core's layouts (row-major 3×3,
// scalar-first quaternions); the framing of the camera around the HUD (titles, insets, pinned
// readouts); labels that follow points of the 3-D view (axis names, a compass, scale bars).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { Rect } from "./scene";

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
  // A keyboard-operable widget (main.ts: arrow keys orbit, + and − zoom, 0 resets the view); the
  // shell sets its aria-label per scene.
  renderer.domElement.tabIndex = 0;
  renderer.domElement.setAttribute("role", "application");
  renderer.domElement.setAttribute("aria-roledescription", "3-D view");
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
  // The camera's aspect and view offset are the shell's (`aimCamera`), set after every resize.
  const resize = () => {
    const w = Math.max(1, host.clientWidth);
    const h = Math.max(1, host.clientHeight);
    renderer.setSize(w, h, false);
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

// --- framing -------------------------------------------------------------------------------

/** Whether two rectangles overlap (by more than a hair). */
export function overlaps(a: Rect, b: Rect, hair = 0.5): boolean {
  return a.x + a.w - hair > b.x && b.x + b.w - hair > a.x && a.y + a.h - hair > b.y && b.y + b.h - hair > a.y;
}

/** The rectangle of `viewport` free of every rectangle of `huds` (with a gap of `gap` pixels)
 * whose inscribed circle is largest (within 3 %, then whose area is): the place for the main
 * object. The candidates' edges are the viewport's and the HUD rectangles' edges. */
export function freeRect(viewport: Rect, huds: Rect[], gap = 6): Rect {
  const hs = huds.filter((r) => r.w > 0 && r.h > 0 && overlaps(r, viewport, 0)).map((r) => ({ x: r.x - gap, y: r.y - gap, w: r.w + 2 * gap, h: r.h + 2 * gap }));
  if (hs.length === 0) return viewport;
  const x0 = viewport.x, x1 = viewport.x + viewport.w, y0 = viewport.y, y1 = viewport.y + viewport.h;
  const clampX = (x: number) => Math.min(x1, Math.max(x0, x));
  const clampY = (y: number) => Math.min(y1, Math.max(y0, y));
  const lefts = [x0, ...hs.map((r) => clampX(r.x + r.w))];
  const rights = [x1, ...hs.map((r) => clampX(r.x))];
  const tops = [y0, ...hs.map((r) => clampY(r.y + r.h))];
  const bottoms = [y1, ...hs.map((r) => clampY(r.y))];
  let best: Rect = { x: x0, y: y0, w: 0, h: 0 };
  let score = [-1, -1];
  for (const l of lefts) for (const r of rights) {
    if (r - l <= 0) continue;
    for (const t of tops) for (const b of bottoms) {
      if (b - t <= 0) continue;
      const c = { x: l, y: t, w: r - l, h: b - t };
      if (hs.some((h) => overlaps(h, c, 0))) continue;
      // The largest inscribed circle; within 3 % of it, the larger area (a wider band rather
      // than a column a few pixels taller, so that the view stays centred).
      const s = [Math.min(c.w, c.h), c.w * c.h];
      if (s[0] > score[0] * 1.03 || (s[0] >= score[0] * 0.97 && s[1] > score[1])) {
        best = c;
        score = s;
      }
    }
  }
  return best;
}

/** Sets `camera`'s aspect and view offset so that, rendered into `viewport` (stage pixels), its
 * projection centre (the orbit target) falls at the middle of `free`. */
export function aimCamera(camera: THREE.PerspectiveCamera, viewport: Rect, free: Rect): void {
  const cx = free.x + free.w / 2 - viewport.x;
  const cy = free.y + free.h / 2 - viewport.y;
  const fullW = 2 * Math.max(cx, viewport.w - cx, 1);
  const fullH = 2 * Math.max(cy, viewport.h - cy, 1);
  camera.aspect = fullW / fullH;
  camera.setViewOffset(fullW, fullH, fullW / 2 - cx, fullH / 2 - cy, Math.max(1, viewport.w), Math.max(1, viewport.h));
  camera.updateProjectionMatrix();
}

/** The distance from the target at which a sphere of `radius` about it fits in `free` (with a
 * margin) once the camera is aimed by `aimCamera` for `viewport`. */
export function fitDistance(camera: THREE.PerspectiveCamera, radius: number, viewport: Rect, free: Rect, margin = 0.9): number {
  const cy = free.y + free.h / 2 - viewport.y;
  const fullH = 2 * Math.max(cy, viewport.h - cy, 1);
  const focal = fullH / 2 / Math.tan((camera.fov * Math.PI) / 360);
  const half = Math.max(8, 0.5 * Math.min(free.w, free.h) * margin);
  return radius * Math.sqrt(1 + (focal / half) ** 2);
}

const vertex = new THREE.Vector3();
/** The screen box (stage pixels) of `objects` (every vertex of their visible meshes and lines,
 * projected) seen through `camera` rendered into `viewport`, or null when nothing is visible. */
export function projectBox(objects: THREE.Object3D[], camera: THREE.Camera, viewport: Rect): Rect | null {
  camera.updateMatrixWorld();
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  const visit = (o: THREE.Object3D) => {
    if (!o.visible) return;
    const g = (o as THREE.Mesh).geometry as THREE.BufferGeometry | undefined;
    const pos = g?.getAttribute?.("position") as THREE.BufferAttribute | undefined;
    if (pos) {
      o.updateWorldMatrix(true, false);
      const range = g!.drawRange;
      const from = Math.max(0, range.start), to = Math.min(pos.count, range.start + range.count);
      for (let i = from; i < to; i++) {
        vertex.fromBufferAttribute(pos, i).applyMatrix4(o.matrixWorld).project(camera);
        const x = viewport.x + ((vertex.x + 1) / 2) * viewport.w;
        const y = viewport.y + ((1 - vertex.y) / 2) * viewport.h;
        x0 = Math.min(x0, x);
        x1 = Math.max(x1, x);
        y0 = Math.min(y0, y);
        y1 = Math.max(y1, y);
      }
    }
    for (const c of o.children) visit(c);
  };
  for (const o of objects) visit(o);
  return Number.isFinite(x0) ? { x: x0, y: y0, w: x1 - x0, h: y1 - y0 } : null;
}

/** A world point's position on the screen (stage pixels) through `camera` rendered into `viewport`. */
export function projectPoint(p: THREE.Vector3, camera: THREE.Camera, viewport: Rect): { x: number; y: number } {
  camera.updateMatrixWorld();
  const q = p.clone().project(camera);
  return { x: viewport.x + ((q.x + 1) / 2) * viewport.w, y: viewport.y + ((1 - q.y) / 2) * viewport.h };
}

/** The bounding sphere of the world bounding box of `objects` (their frame). */
export function frameOf(objects: THREE.Object3D[], pad = 0): { center: THREE.Vector3; radius: number } {
  const box = new THREE.Box3();
  for (const o of objects) {
    o.updateWorldMatrix(true, true);
    box.expandByObject(o, true);
  }
  if (box.isEmpty()) return { center: new THREE.Vector3(), radius: 1 };
  const sphere = box.getBoundingSphere(new THREE.Sphere());
  return { center: sphere.center, radius: sphere.radius + pad };
}

// --- labels that follow the 3-D view --------------------------------------------------------

/** DOM labels over the canvas at points of the scene (axis names, compass letters, scale-bar
 * captions): crisp text that a screen reader and a test can read. Each label follows a world
 * point, or a point of an object (its local `at`); labels on a layer show only in viewports
 * whose camera sees that layer. */
export class Labels {
  private readonly items: { el: HTMLElement; obj: THREE.Object3D | null; at: THREE.Vector3; layer: number }[] = [];
  private readonly p = new THREE.Vector3();
  constructor(private readonly host: HTMLElement) {}

  /** A label with `text` at `at` (world, or local to `obj`), in `className` (default "label3d"). */
  add(text: string, at: THREE.Vector3, opts: { obj?: THREE.Object3D; color?: string; className?: string; layer?: number } = {}): HTMLElement {
    const el = document.createElement("span");
    el.className = opts.className ?? "label3d";
    el.textContent = text;
    if (opts.color) el.style.color = opts.color;
    this.host.append(el);
    this.items.push({ el, obj: opts.obj ?? null, at: at.clone(), layer: opts.layer ?? 0 });
    return el;
  }

  /** Moves the label `el` to `at` (world, or local to its object). */
  move(el: HTMLElement, at: THREE.Vector3): void {
    const item = this.items.find((i) => i.el === el);
    if (item) item.at.copy(at);
  }

  /** Places every label for `camera` rendering into `viewport` (stage pixels). */
  update(camera: THREE.Camera, viewport: Rect): void {
    for (const item of this.items) {
      const el = item.el;
      const seen = (item.obj ? isShown(item.obj) : true) && camera.layers.test(layerOf(item.layer));
      if (!seen) {
        el.style.visibility = "hidden";
        continue;
      }
      this.p.copy(item.at);
      if (item.obj) this.p.applyMatrix4(item.obj.matrixWorld);
      this.p.project(camera);
      const inside = this.p.z > -1 && this.p.z < 1 && Math.abs(this.p.x) <= 1.02 && Math.abs(this.p.y) <= 1.02;
      el.style.visibility = inside ? "visible" : "hidden";
      const x = viewport.x + ((this.p.x + 1) / 2) * viewport.w;
      const y = viewport.y + ((1 - this.p.y) / 2) * viewport.h;
      el.style.transform = `translate(${x.toFixed(1)}px, ${y.toFixed(1)}px) translate(-50%, -50%)`;
    }
  }

  /** Sets the text of a label. */
  setText(el: HTMLElement, text: string): void {
    if (el.textContent !== text) el.textContent = text;
  }

  dispose(): void {
    for (const item of this.items) item.el.remove();
    this.items.length = 0;
  }
}

/** Whether an object and all its ancestors are visible. */
function isShown(o: THREE.Object3D | null): boolean {
  for (; o; o = o.parent) if (!o.visible) return false;
  return true;
}

function layerOf(layer: number): THREE.Layers {
  const l = new THREE.Layers();
  l.set(layer);
  return l;
}

/** Names at the positive ends of the axes of a `fixedAxes(len)` (scene units): x, y, z, or east,
 * north, up. `skip` leaves an axis unnamed (an axis that is not drawn). */
export function axisLabels(labels: Labels, len: number, names: [string, string, string], skip: number[] = [], opts: { obj?: THREE.Object3D; layer?: number } = {}): HTMLElement[] {
  const colours = ["#ff7a7e", "#7ad38a", "#7fa6ff"];
  return names.flatMap((name, k) =>
    skip.includes(k) ? [] : [labels.add(name, new THREE.Vector3().setComponent(k, len * 1.06), { ...opts, color: colours[k], className: "label3d axis" })],
  );
}

/** A compass on the ground (the plane z = `z`): a ring of `radius` with ticks every 30°, a north
 * arrow, and the letters N, E, S, W outside it (DOM labels). East is +x, north +y. */
export function compass(labels: Labels, radius: number, z = 0.003): THREE.Group {
  const g = new THREE.Group();
  const mat = new THREE.LineBasicMaterial({ color: 0x9aa4b1, transparent: true, opacity: 0.8 });
  const ring: THREE.Vector3[] = [];
  for (let i = 0; i <= 128; i++) {
    const a = (2 * Math.PI * i) / 128;
    ring.push(new THREE.Vector3(radius * Math.cos(a), radius * Math.sin(a), z));
  }
  g.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(ring), mat));
  const ticks: THREE.Vector3[] = [];
  for (let i = 0; i < 12; i++) {
    const a = (2 * Math.PI * i) / 12;
    const r0 = radius * (i % 3 === 0 ? 0.9 : 0.95);
    ticks.push(new THREE.Vector3(r0 * Math.cos(a), r0 * Math.sin(a), z), new THREE.Vector3(radius * Math.cos(a), radius * Math.sin(a), z));
  }
  g.add(new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(ticks), mat));
  // The north arrow: a flat triangle on the ring's north side.
  const tri = new THREE.Shape();
  tri.moveTo(0, radius * 1.0);
  tri.lineTo(-radius * 0.06, radius * 0.84);
  tri.lineTo(radius * 0.06, radius * 0.84);
  tri.closePath();
  const arrow = new THREE.Mesh(new THREE.ShapeGeometry(tri), new THREE.MeshBasicMaterial({ color: 0xe5484d, side: THREE.DoubleSide }));
  arrow.position.z = z + 0.001;
  g.add(arrow);
  // The letters, east and north in the colours of the x and y axes (the scene's east and north
  // axes end at the ring: these letters name them).
  const out = radius * 1.12;
  for (const [name, a, color] of [["N", 90, "#7ad38a"], ["E", 0, "#ff7a7e"], ["S", 270, ""], ["W", 180, ""]] as const) {
    labels.add(name, new THREE.Vector3(out * Math.cos((a * Math.PI) / 180), out * Math.sin((a * Math.PI) / 180), z), { className: "label3d compass", color: color || undefined });
  }
  return g;
}

/** A scale bar: a segment with end ticks from `from` along `dir` (scene units), its length set
 * with `set(length, caption)`, and a caption under its middle. */
export class ScaleBar {
  readonly obj = new THREE.Group();
  private readonly line: THREE.LineSegments;
  readonly label: HTMLElement;
  constructor(private readonly labels: Labels, private readonly from: THREE.Vector3, private readonly dir: THREE.Vector3, private readonly tick: THREE.Vector3, color = 0xe6e9ee) {
    this.line = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color }));
    this.line.frustumCulled = false;
    this.obj.add(this.line);
    this.label = labels.add("", from.clone(), { className: "label3d scale" });
  }
  /** A bar `length` scene units long, captioned `caption`. */
  set(length: number, caption: string): void {
    const a = this.from.clone(), b = this.from.clone().addScaledVector(this.dir, length);
    const t = this.tick;
    this.line.geometry.dispose();
    this.line.geometry = new THREE.BufferGeometry().setFromPoints([a, b, a.clone().add(t), a.clone().sub(t), b.clone().add(t), b.clone().sub(t)]);
    this.labels.move(this.label, a.clone().lerp(b, 0.5).addScaledVector(t, -3.5));
    this.labels.setText(this.label, caption);
  }
}

/** A round number (a scale bar's length, a factor) as text: at most 3 significant digits, no
 * trailing zeros. */
export function roundText(x: number): string {
  return String(Number(x.toPrecision(3)));
}

/** The largest of 1, 2, 5 × 10ⁿ not above x (x > 0): a round length for a scale bar. */
export function roundDown125(x: number): number {
  const p = 10 ** Math.floor(Math.log10(x));
  const m = x / p;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}
