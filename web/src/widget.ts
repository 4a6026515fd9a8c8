// The notebook widget (anywidget's module format, AFM): one of the lab's scenes in a notebook cell,
// on the same WebAssembly core as the lab (bundled into this module as bytes: no server path).
// `render({ model, el })` builds a small shell in `el` — the 3-D view with the scene's HUD and its
// pinned readouts, the scene's sliders, Play/Pause and a view reset — for the scene
// `model.get("scene")` with the parameters `model.get("params")`. The parameters sync both ways:
// a slider sets `params` on the model (Python's `w.params`), a change of `params` from Python
// reconfigures the scene and moves the sliders. Python (poinsot.widgets) checks what it sends.
import "./widget.css";
import init, { version } from "./core";
import wasmBase64 from "./wasm/poinsot_wasm_bg.wasm?base64";
import { aimCamera, createView, fitDistance, freeRect, Labels } from "./view";
import { fmtStep, type Params, type Readout, type Rect, type SceneDef, type SceneInstance } from "./scene";
import { SCENES } from "./scenes";

/** The part of anywidget's model that the widget uses. */
export interface WidgetModel {
  get(key: string): unknown;
  set(key: string, value: unknown): void;
  save_changes(): void;
  on(event: string, cb: () => void): void;
  off(event: string, cb: () => void): void;
}

/** What the tests see of a rendered widget: `el.__poinsot` (the element given to render). */
export interface WidgetHandle {
  scene: string;
  version: string;
  params: Params;
  t: number;
  frames: number;
  playing: boolean;
  error: string | null;
  readouts(): Record<string, Readout["value"]>;
}

/** A pinned readout longer than this (characters) is a sentence: it spans the box (as the lab). */
const LONG_TEXT = 34;

let coreReady: Promise<unknown> | null = null;
/** Instantiates the core once per page, from the bytes bundled in this module. */
function loadCore(): Promise<unknown> {
  if (!coreReady) {
    const bytes = Uint8Array.from(atob(wasmBase64), (c) => c.charCodeAt(0));
    coreReady = init({ module_or_path: bytes });
  }
  return coreReady;
}

/** The scene's parameters from `given` (the model's): its defaults where a key is missing, a number
 * clamped to its slider's range, a choice not among the options replaced by the default. */
export function sceneParams(def: SceneDef, given: unknown): Params {
  const g = (given && typeof given === "object" ? given : {}) as Record<string, unknown>;
  const p: Params = {};
  for (const spec of def.params) {
    const v = g[spec.key];
    if (spec.kind === "number") {
      const x = typeof v === "number" ? v : NaN;
      p[spec.key] = Number.isFinite(x) ? Math.min(spec.max, Math.max(spec.min, x)) : spec.value;
    } else p[spec.key] = typeof v === "string" && spec.options.includes(v) ? v : spec.value;
  }
  return p;
}

function el<K extends keyof HTMLElementTagNameMap>(tag: K, cls = "", parent?: HTMLElement): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  parent?.append(e);
  return e;
}

async function render({ model, el: host }: { model: WidgetModel; el: HTMLElement }): Promise<() => void> {
  const id = String(model.get("scene"));
  const def = SCENES.find((d) => d.id === id);
  if (!def) throw new Error(`poinsot widget: no scene "${id}" (the scenes: ${SCENES.map((d) => d.id).join(", ")})`);
  await loadCore();

  const root = el("div", "poinsot-widget", host);
  root.dataset.scene = def.id;
  const stage = el("div", "stage", root);
  const viewHost = el("div", "view", stage);
  const overlay = el("div", "overlay", stage);
  const pinnedDl = el("dl", "pinned hud", stage);
  const alertBox = el("div", "alert", stage);
  alertBox.setAttribute("role", "alert");
  alertBox.hidden = true;
  const side = el("div", "side", root);
  el("h3", "", side).textContent = def.title;
  const transport = el("div", "transport", side);
  const play = el("button", "play", transport);
  play.type = "button";
  const resetView = el("button", "reset-view", transport);
  resetView.type = "button";
  resetView.textContent = "Reset view";
  const form = el("form", "controls", side);
  form.addEventListener("submit", (ev) => ev.preventDefault());
  const panel = el("div", "scene-extra", side);

  const view = createView(viewHost);
  const canvas = view.renderer.domElement;
  canvas.setAttribute("aria-label", `${def.title}: ${def.describe}. Drag to turn the view.`);
  let params = sceneParams(def, model.get("params"));
  const handle: WidgetHandle = {
    scene: def.id, version: version(), params, t: 0, frames: 0, playing: true, error: null,
    readouts: () => Object.fromEntries(current.readouts().map((r) => [r.key, r.value])),
  };
  (host as unknown as { __poinsot: WidgetHandle }).__poinsot = handle;

  const labels = new Labels(overlay);
  let hudRects: Rect[] = [];
  const canvasSize = () => ({ w: Math.max(1, stage.clientWidth), h: Math.max(1, stage.clientHeight) });
  const viewports = (): Rect[] => {
    const { w, h } = canvasSize();
    return current.viewports?.(w, h) ?? [{ x: 0, y: 0, w, h }];
  };
  const freeOf = (vp: Rect): Rect => freeRect(vp, hudRects);
  const current: SceneInstance = def.create({
    scene: view.scene, camera: view.camera, target: view.controls.target, panel, overlay, labels,
    freeRect: freeOf,
    aim: (camera, vp) => aimCamera(camera, vp, freeOf(vp)),
  });
  const home = view.camera.position.clone().sub(view.controls.target).normalize();

  function measureHuds(): void {
    const s = stage.getBoundingClientRect();
    hudRects = [];
    for (const h of stage.querySelectorAll<HTMLElement>(".hud")) {
      if (h.hidden || h.offsetParent === null) continue;
      const r = h.getBoundingClientRect();
      if (r.width > 0 && r.height > 0) hudRects.push({ x: r.left - s.left, y: r.top - s.top, w: r.width, h: r.height });
    }
  }
  /** The camera on the scene's home direction at the distance that fits its frame (as the lab). */
  function fit(): void {
    measureHuds();
    const { w, h } = canvasSize();
    const whole = { x: 0, y: 0, w, h };
    aimCamera(view.camera, whole, freeOf(whole));
    const framed = current.frame();
    let d = 0;
    for (const vp of viewports()) d = Math.max(d, fitDistance(view.camera, framed.radius, vp, freeOf(vp)));
    view.controls.target.copy(framed.center);
    view.camera.position.copy(framed.center).addScaledVector(home, d);
    view.camera.near = Math.max(0.01, d / 200);
    view.camera.far = Math.max(50, 20 * (d + framed.radius));
    view.camera.updateProjectionMatrix();
    view.controls.update();
  }

  // --- readouts pinned on the canvas ------------------------------------------------------
  function renderReadouts(): void {
    const list = current.readouts();
    const keys = typeof def!.pinned === "function" ? def!.pinned(params) : def!.pinned;
    const want = [...keys.map((k) => list.find((r) => r.key === k)).filter((r): r is Readout => !!r), ...list.filter((r) => r.pin && !keys.includes(r.key))];
    const sig = want.map((r) => r.key).join(" ");
    if (pinnedDl.dataset.keys !== sig) {
      pinnedDl.replaceChildren();
      for (const r of want) {
        const row = el("div", keys.includes(r.key) ? (r.text.length > LONG_TEXT ? "item long" : "item") : "note", pinnedDl);
        el("dt", "", row).textContent = r.label;
        el("dd", "", row).dataset.key = r.key;
      }
      pinnedDl.dataset.keys = sig;
    }
    for (const r of want) {
      const dd = pinnedDl.querySelector<HTMLElement>(`dd[data-key="${r.key}"]`)!;
      if (dd.textContent !== r.text) dd.textContent = r.text;
      dd.dataset.value = JSON.stringify(r.value);
      dd.classList.toggle("warn", !!r.warn);
      dd.title = r.detail ?? "";
    }
  }
  function showError(e: unknown): void {
    const err = e as { name?: string; message?: string };
    handle.error = `${err.name ?? "Error"}: ${err.message ?? String(e)}`;
    alertBox.textContent = handle.error;
    alertBox.hidden = false;
    for (const dd of pinnedDl.querySelectorAll("dd")) dd.textContent = "—";
  }
  function stepOnce(): void {
    try {
      current.step(handle.t);
      renderReadouts();
    } catch (e) {
      showError(e);
    }
  }
  function configure(): void {
    handle.params = params;
    try {
      current.configure(params);
      handle.error = null;
      alertBox.hidden = true;
      stepOnce();
    } catch (e) {
      showError(e);
    }
  }

  // --- sliders: each one sets `params` on the model --------------------------------------
  const inputs = new Map<string, { row: HTMLElement; input: HTMLInputElement | HTMLSelectElement; out?: HTMLOutputElement }>();
  for (const spec of def.params) {
    const row = el("label", "", form);
    row.dataset.key = spec.key;
    el("span", "", row).textContent = spec.kind === "number" && spec.unit ? `${spec.label} (${spec.unit})` : spec.label;
    if (spec.kind === "number") {
      const input = el("input", "", row);
      Object.assign(input, { type: "range", min: String(spec.min), max: String(spec.max), step: String(spec.step), name: spec.key });
      input.dataset.key = spec.key;
      const out = el("output", "", row);
      input.addEventListener("input", () => {
        out.textContent = fmtStep(Number(input.value), spec.step);
        setParam(spec.key, Number(input.value));
      });
      inputs.set(spec.key, { row, input, out });
    } else {
      row.classList.add("choice");
      const select = el("select", "", row);
      select.name = spec.key;
      select.dataset.key = spec.key;
      for (const o of spec.options) select.add(new Option(o, o));
      select.addEventListener("change", () => setParam(spec.key, select.value));
      inputs.set(spec.key, { row, input: select });
    }
  }
  /** The controls show `params` (and only those that apply to them). */
  function showParams(): void {
    for (const spec of def!.params) {
      const c = inputs.get(spec.key)!;
      c.input.value = String(params[spec.key]);
      if (c.out && spec.kind === "number") c.out.textContent = fmtStep(Number(params[spec.key]), spec.step);
      c.row.hidden = spec.when ? !spec.when(params) : false;
    }
  }
  function setParam(key: string, value: number | string): void {
    params = { ...params, [key]: value };
    showParams();
    configure();
    model.set("params", { ...params });
    model.save_changes();
  }
  /** `params` changed on the model (from Python): reconfigure, move the sliders. */
  const onModel = () => {
    const next = sceneParams(def, model.get("params"));
    if (JSON.stringify(next) === JSON.stringify(params)) return;
    params = next;
    showParams();
    configure();
    fit();
  };
  model.on("change:params", onModel);

  function setPlaying(on: boolean): void {
    handle.playing = on;
    play.textContent = on ? "Pause" : "Play";
    play.setAttribute("aria-pressed", String(!on));
  }
  play.addEventListener("click", () => setPlaying(!handle.playing));
  resetView.addEventListener("click", () => fit());
  setPlaying(!(window.matchMedia?.("(prefers-reduced-motion: reduce)").matches ?? false));

  showParams();
  configure();
  fit();
  const sizes = new ResizeObserver(() => fit());
  sizes.observe(stage);

  let last = performance.now();
  let frame = 0;
  let alive = true;
  const loop = (now: number) => {
    if (!alive) return;
    const dt = Math.min(0.1, Math.max(0, (now - last) / 1000));
    last = now;
    if (handle.playing && handle.error === null) {
      handle.t += dt;
      stepOnce();
    }
    view.controls.update();
    if (current.render) current.render(view.renderer, view.scene, view.camera);
    else view.renderer.render(view.scene, view.camera);
    if (!current.viewports) labels.update(view.camera, { x: 0, y: 0, ...canvasSize() });
    handle.frames++;
    frame = requestAnimationFrame(loop);
  };
  frame = requestAnimationFrame(loop);

  // anywidget calls this when the view is removed (the cell re-runs or is cleared).
  return () => {
    alive = false;
    cancelAnimationFrame(frame);
    model.off("change:params", onModel);
    sizes.disconnect();
    current.dispose();
    labels.dispose();
    view.controls.dispose();
    view.renderer.dispose();
    root.remove();
  };
}

export default { render };
