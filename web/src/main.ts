// The lab's shell: loads the core (WebAssembly), builds the scene tabs, the parameter controls
// and the readouts (all of them in the panel, the scene's three or four that matter pinned on the
// canvas), frames the camera around the HUD (titles, insets, pinned readouts), runs the
// animation loop with the physics in it, and keeps the URL (the "share" link) in step with the
// parameters. Camera keys: arrows orbit a focused view, + and − zoom, 0 resets the view.
import "./style.css";
import * as THREE from "three";
import init, { coreStatus, version, type CoreStatus } from "./core";
import { aimCamera, createView, fitDistance, freeRect, Labels, projectBox } from "./view";
import { type NumberParam, type Params, type Readout, type Rect, type SceneDef, type SceneInstance } from "./scene";
import { SCENES } from "./scenes";
import { ariaValueText, fromInput, inputRange, resolve, toInput, valueText } from "./sliders";
import { Recorder } from "./record";

/** What the tests (and a curious user, from the console) can see: window.__lab. */
interface LabHandle {
  ready: boolean;
  version: string;
  /** The ids of every scene, in the order of the tabs. */
  scenes: string[];
  scene: string;
  params: Params;
  t: number;
  playing: boolean;
  frames: number;
  /** Physics time per frame (ms): the median over the last `PHYSICS_WINDOW` frames (a frame the
   * machine's other work delays does not move it; a slowdown of every frame does). */
  physicsMs: number;
  error: string | null;
  /** A slider move the core refused (no valid value on its way): the sentence shown; the last
   * valid state stays on screen. Null when the last move was taken. */
  refused: string | null;
  /** The sentence of the last slider move resolved by another slider following or the moved one
   * stopping (null when taken as it was). */
  note: string | null;
  /** Whether a refused slider move is resolved (other slider follows, or the moved one stops);
   * false sends every move to the core as it is (the negative control of tests/sliders.test.mjs). */
  couple: boolean;
  /** Whether the page honours prefers-reduced-motion (it starts paused). */
  reducedMotion: boolean;
  /** The core's guard: restarts of the WebAssembly instance after an internal error. */
  core(): CoreStatus;
  readouts(): Record<string, Readout["value"]>;
  seek(t: number): void;
  /** The layout of the view (stage pixels, page coordinates): the HUD elements (by id or
   * class), the free rectangles of the viewports, and the screen boxes of the main object. */
  layout(): { stage: Rect; huds: { id: string; rect: Rect }[]; free: Rect[]; main: Rect[] };
  /** The camera: position, target (scene units). */
  camera(): { position: number[]; target: number[] };
  /** The scene's named points on the screen (page pixels), e.g. a mark's centre. */
  probes(): Record<string, { x: number; y: number }>;
  /** The record of the readouts over time: its CSV, and the series of one column (record.ts). */
  record(): { csv: string; series(key: string): { t: number[]; v: number[]; scale: number } };
}

const PHYSICS_WINDOW = 120;
/** The keys that open the scenes, in tab order: the digits 1–9 (0 fits the view; - and = zoom
 * it); a tab past the ninth has no key, and says none. */
const SCENE_KEYS = ["1", "2", "3", "4", "5", "6", "7", "8", "9"];
/** A pinned readout longer than this (characters) is a sentence: it wraps across the box. */
const LONG_TEXT = 34;
/** Keyboard orbit: one arrow press turns the view by this much (rad); + and − zoom by ZOOM. */
const ORBIT_STEP = (10 * Math.PI) / 180;
const ZOOM = 1.15;
/** The camera is refitted on a parameter change when the framed sphere moves or grows by more
 * than this fraction of its radius (or when the user has not moved the camera). */
const REFRAME = 0.25;
const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

async function main(): Promise<void> {
  await init();
  const stage = $("stage");
  const view = createView($("view"));
  const canvas = view.renderer.domElement;
  const reducedMotion = window.matchMedia?.("(prefers-reduced-motion: reduce)").matches ?? false;
  view.controls.enableDamping = !reducedMotion;
  const lab: LabHandle = {
    ready: false, version: version(), scenes: SCENES.map((d) => d.id), scene: "", params: {}, t: 0, playing: true, frames: 0,
    physicsMs: 0, error: null, refused: null, note: null, couple: true, reducedMotion, core: coreStatus,
    readouts: () => Object.fromEntries(current.readouts().map((r) => [r.key, r.value])),
    seek: (t: number) => { lab.t = t; stepOnce(); },
    layout: () => layoutNow(),
    camera: () => ({ position: view.camera.position.toArray(), target: view.controls.target.toArray() }),
    probes: () => {
      const s = stageRect();
      const pts = current.probes?.(view.camera, viewports()[0]) ?? {};
      return Object.fromEntries(Object.entries(pts).map(([k, p]) => [k, { x: p.x + s.x, y: p.y + s.y }]));
    },
    record: () => ({ csv: recorder.csv(), series: (key: string) => recorder.series(key) }),
  };
  (window as unknown as { __lab: LabHandle }).__lab = lab;

  let def: SceneDef = SCENES[0];
  let current: SceneInstance;
  let labels: Labels;
  let speed = 1;
  const costs: number[] = [];

  const alertBox = $("alert");
  /** The parameters of the state on screen, which the core accepted (null before the first). */
  let valid: Params | null = null;
  function showError(e: unknown): void {
    const err = e as { name?: string; message?: string };
    lab.error = `${err.name ?? "Error"}: ${err.message ?? String(e)}`;
    alertBox.textContent = lab.error;
    alertBox.hidden = false;
    // No stale numbers beside an error: the readouts wait for valid parameters.
    for (const dd of [...cells.values(), ...pinnedCells.values()]) {
      dd.textContent = "—";
      dd.dataset.value = "null";
      shown.delete(dd);
    }
  }
  function clearError(): void {
    lab.error = null;
    lab.refused = null;
    alertBox.hidden = true;
  }
  /** A refused slider move: the sentence, the last valid state kept (readouts, view, motion). */
  function showRefusal(sentence: string): void {
    lab.refused = sentence;
    alertBox.textContent = sentence;
    alertBox.hidden = false;
  }
  const sliderNote = document.createElement("p");
  sliderNote.id = "slider-note";
  sliderNote.className = "slider-note";
  sliderNote.setAttribute("role", "status");
  sliderNote.hidden = true;
  function showNote(sentence: string | null): void {
    lab.note = sentence;
    sliderNote.textContent = sentence ?? "";
    sliderNote.hidden = sentence === null;
  }

  // --- URL <-> state --------------------------------------------------------------------
  function paramsFromUrl(d: SceneDef, q: URLSearchParams): Params {
    const p: Params = {};
    // A link of an earlier lab: its angle in radians read into the slider now in degrees.
    const legacy = new Map<string, number>();
    for (const [old, { key, factor }] of Object.entries(d.legacyParams ?? {})) {
      const raw = q.get(old);
      if (raw !== null && q.get(key) === null && raw.trim() !== "") legacy.set(key, Number(raw) * factor);
    }
    for (const spec of d.params) {
      const raw = q.get(spec.key);
      if (spec.kind === "number") {
        const x = raw === null ? (legacy.get(spec.key) ?? NaN) : Number(raw);
        p[spec.key] = Number.isFinite(x) ? Math.min(spec.max, Math.max(spec.min, x)) : spec.value;
      } else {
        p[spec.key] = raw !== null && spec.options.includes(raw) ? raw : spec.value;
      }
    }
    return p;
  }
  /** The state as a query: the scene, its parameters, the speed and (when paused) the time. */
  function stateQuery(): URLSearchParams {
    const q = new URLSearchParams({ scene: def.id });
    for (const spec of def.params) q.set(spec.key, String(lab.params[spec.key]));
    if (speed !== 1) q.set("speed", String(speed));
    if (!lab.playing) {
      q.set("paused", "1");
      q.set("t", String(lab.t));
    }
    return q;
  }
  function writeUrl(): void {
    // A browser may refuse to rewrite the address of a page opened from a file: the share link
    // does not depend on it (shareLink), so the refusal is ignored.
    try {
      history.replaceState(null, "", `${location.pathname}?${stateQuery()}`);
    } catch { /* the address keeps its old query */ }
  }

  // --- controls ---------------------------------------------------------------------------
  const form = $<HTMLFormElement>("controls");
  form.addEventListener("submit", (ev) => ev.preventDefault());
  const controlRows = new Map<string, HTMLElement>();
  function buildControls(): void {
    form.replaceChildren();
    controlRows.clear();
    for (const spec of def.params) {
      const label = document.createElement("label");
      label.dataset.key = spec.key;
      const name = document.createElement("span");
      name.textContent = spec.kind === "number" && spec.unit ? `${spec.label} (${spec.unit})` : spec.label;
      label.append(name);
      if (spec.kind === "number") {
        const input = document.createElement("input");
        Object.assign(input, { type: "range", ...inputRange(spec), name: spec.key });
        input.dataset.key = spec.key;
        if (spec.scale === "log") input.dataset.scale = "log";
        const out = document.createElement("output");
        label.append(input, out);
        showValue(spec, Number(lab.params[spec.key]), label);
        input.addEventListener("input", () => setParam(spec.key, fromInput(spec, input.value)));
      } else {
        label.classList.add("choice");
        const select = document.createElement("select");
        select.name = spec.key;
        select.dataset.key = spec.key;
        for (const o of spec.options) select.add(new Option(o, o));
        select.value = String(lab.params[spec.key]);
        select.addEventListener("change", () => setParam(spec.key, select.value));
        label.append(select);
      }
      form.append(label);
      controlRows.set(spec.key, label);
    }
    form.append(sliderNote);
    showApplicable();
  }
  /** Puts a slider's thumb, output and spoken value at `x`. */
  function showValue(spec: NumberParam, x: number, row = controlRows.get(spec.key)): void {
    const input = row?.querySelector("input");
    const out = row?.querySelector("output");
    if (!input || !out) return;
    input.value = toInput(spec, x);
    out.textContent = valueText(spec, x);
    input.setAttribute("aria-valuetext", ariaValueText(spec, x));
  }
  /** Puts every control at the current parameters (after a move another slider followed). */
  function syncControls(): void {
    for (const spec of def.params) {
      if (spec.kind === "number") showValue(spec, Number(lab.params[spec.key]));
      else {
        const select = controlRows.get(spec.key)?.querySelector("select");
        if (select && select.value !== lab.params[spec.key]) select.value = String(lab.params[spec.key]);
      }
    }
  }
  /** Shows the controls that apply to the current parameters only. */
  function showApplicable(): void {
    for (const spec of def.params) {
      const row = controlRows.get(spec.key);
      if (row) row.hidden = spec.when ? !spec.when(lab.params) : false;
    }
  }
  /** A slider or select moved: the core tries the new parameters; a move it refuses is resolved
   * by another slider following or the moved one stopping (sliders.ts), or refused with a
   * sentence naming the moved slider, the last valid state kept on screen. */
  function setParam(key: string, value: number | string): void {
    // In an error state (a refused link or file) the move starts from the parameters shown.
    if (!lab.couple || valid === null || lab.error !== null) {
      lab.params = { ...lab.params, [key]: value };
      showApplicable();
      syncControls();
      configure(lab.error === null);
      writeUrl();
      return;
    }
    const keyOf = (argument: string) => def.argumentKeys?.[argument] ?? argument;
    const trial = (p: Params): unknown => {
      try {
        current.configure(p);
        current.step(lab.t);
        return null;
      } catch (e) {
        return e;
      }
    };
    const r = resolve(def.params, valid, key, value, trial, keyOf);
    // A choice (a shape, a file, a preset) the core refuses with nothing to follow is taken as
    // chosen, and the core's error shown: the choice is the student's question, not a slip.
    const chosen = r.refused && def.params.find((p) => p.key === key)?.kind === "choice";
    lab.params = chosen ? { ...valid, [key]: value } : r.params;
    showApplicable();
    syncControls();
    showNote(r.refused ? null : r.note);
    configure(!chosen);
    if (r.refused && r.note && !chosen) showRefusal(r.note);
    writeUrl();
  }

  // --- readouts: all of them in the panel, the pinned ones on the canvas ---------------------
  // The checks of the computation (residuals, drifts, conserved quantities recomputed) in their
  // own folded list below the results.
  const dl = $("readouts");
  const checksBox = document.createElement("details");
  checksBox.className = "checks";
  const checksSummary = document.createElement("summary");
  checksSummary.textContent = "Checks of the computation";
  const checksDl = document.createElement("dl");
  checksDl.id = "checks";
  checksDl.className = "readouts";
  checksBox.append(checksSummary, checksDl);
  dl.after(checksBox);
  // The plot of a readout against time and the CSV export, under the scene's own widgets.
  const recorder = new Recorder(document.createElement("div"));
  $("scene-extra").after(recorder.box);
  const cells = new Map<string, HTMLElement>();
  /** What each readout cell shows now (its text, value, warning and detail). */
  const shown = new WeakMap<HTMLElement, { text: string; value: Readout["value"]; warn: boolean; detail: string }>();
  const sameValue = (a: Readout["value"], b: Readout["value"]) =>
    a === b || (Array.isArray(a) && Array.isArray(b) && a.length === b.length && a.every((x, i) => Object.is(x, b[i])));
  const pinnedDl = $("pinned");
  const pinnedCells = new Map<string, HTMLElement>();
  function renderReadouts(): void {
    const list = current.readouts();
    for (const r of list) {
      let dd = cells.get(r.key);
      if (!dd) {
        const dt = document.createElement("dt");
        dt.textContent = r.label;
        dd = document.createElement("dd");
        dd.dataset.key = r.key;
        (r.check ? checksDl : dl).append(dt, dd);
        cells.set(r.key, dd);
      }
      // Only what changed is written: a scene's two dozen readouts cost more in the DOM than
      // its physics (most of them, the constants, change only with the parameters).
      const was = shown.get(dd);
      if (was && was.text === r.text && sameValue(was.value, r.value) && was.warn === !!r.warn && was.detail === (r.detail ?? "")) continue;
      if (dd.textContent !== r.text) dd.textContent = r.text;
      dd.dataset.value = JSON.stringify(r.value);
      dd.classList.toggle("warn", !!r.warn);
      if (dd.title !== (r.detail ?? "")) dd.title = r.detail ?? "";
      shown.set(dd, { text: r.text, value: Array.isArray(r.value) ? r.value.slice() : r.value, warn: !!r.warn, detail: r.detail ?? "" });
    }
    checksBox.hidden = checksDl.childElementCount === 0;
    // The pinned readouts: the scene's keys, in its order, then the warnings it pins now.
    const pinnedKeys = typeof def.pinned === "function" ? def.pinned(lab.params) : def.pinned;
    const want = [...pinnedKeys.map((k) => list.find((r) => r.key === k)).filter((r): r is Readout => !!r), ...list.filter((r) => r.pin && !pinnedKeys.includes(r.key))];
    const keys = want.map((r) => r.key).join(" ");
    if (pinnedDl.dataset.keys !== keys) {
      pinnedDl.replaceChildren();
      pinnedCells.clear();
      for (const r of want) {
        const row = document.createElement("div");
        // A sentence spans the box (its label above it); a number sits beside its label.
        row.className = pinnedKeys.includes(r.key) ? (r.text.length > LONG_TEXT ? "item long" : r.text.length > 18 ? "item wide" : "item") : "note";
        const dt = document.createElement("dt");
        dt.textContent = r.label;
        const dd = document.createElement("dd");
        dd.dataset.key = r.key;
        row.append(dt, dd);
        pinnedDl.append(row);
        pinnedCells.set(r.key, dd);
      }
      pinnedDl.dataset.keys = keys;
    }
    for (const r of want) {
      const dd = pinnedCells.get(r.key)!;
      if (dd.textContent !== r.text) dd.textContent = r.text;
      dd.classList.toggle("warn", !!r.warn);
      if (dd.title !== (r.detail ?? "")) dd.title = r.detail ?? "";
    }
  }

  // --- framing: the camera keeps the main object clear of the HUD ----------------------------
  let hudRects: { id: string; rect: Rect }[] = [];
  let hudsDirty = true;
  let userMoved = false;
  const home = new THREE.Vector3(1, 1, 1);
  let framed = { center: new THREE.Vector3(), radius: 1 };
  const stageRect = (): Rect => {
    const r = stage.getBoundingClientRect();
    return { x: r.left, y: r.top, w: r.width, h: r.height };
  };
  function measureHuds(): void {
    const s = stage.getBoundingClientRect();
    hudRects = [];
    for (const el of stage.querySelectorAll<HTMLElement>(".hud")) {
      if (el.hidden || el.offsetParent === null) continue;
      const r = el.getBoundingClientRect();
      if (r.width === 0 || r.height === 0) continue;
      hudRects.push({ id: el.id || el.className, rect: { x: r.left - s.left, y: r.top - s.top, w: r.width, h: r.height } });
    }
    hudsDirty = false;
  }
  const freeCache = new Map<string, Rect>();
  /** The free part of a viewport. Where the scene has several viewports side by side, the part
   * free in all of them (in each one's own coordinates), so that its views are framed alike. */
  function freeOf(vp: Rect): Rect {
    const key = `${vp.x},${vp.y},${vp.w},${vp.h}`;
    let f = freeCache.get(key);
    if (!f) {
      const huds = hudRects.map((h) => h.rect);
      const all = current?.viewports ? viewports() : [vp];
      const local = all.map((v) => {
        const r = freeRect(v, huds);
        return { x0: r.x - v.x, y0: r.y - v.y, x1: r.x + r.w - v.x, y1: r.y + r.h - v.y };
      });
      const x0 = Math.max(...local.map((r) => r.x0)), y0 = Math.max(...local.map((r) => r.y0));
      const x1 = Math.min(...local.map((r) => r.x1)), y1 = Math.min(...local.map((r) => r.y1));
      f = { x: vp.x + x0, y: vp.y + y0, w: Math.max(1, x1 - x0), h: Math.max(1, y1 - y0) };
      freeCache.set(key, f);
    }
    return f;
  }
  const canvasSize = () => ({ w: Math.max(1, stage.clientWidth), h: Math.max(1, stage.clientHeight) });
  const viewports = (): Rect[] => {
    const { w, h } = canvasSize();
    return current.viewports?.(w, h) ?? [{ x: 0, y: 0, w, h }];
  };
  function aimDefault(): void {
    const { w, h } = canvasSize();
    const vp = { x: 0, y: 0, w, h };
    aimCamera(view.camera, vp, freeOf(vp));
  }
  /** Puts the camera on the scene's home direction at the distance that fits its frame. */
  function fit(): void {
    framed = current.frame();
    let d = 0;
    for (const vp of viewports()) d = Math.max(d, fitDistance(view.camera, framed.radius, vp, freeOf(vp)));
    view.controls.target.copy(framed.center);
    view.camera.position.copy(framed.center).addScaledVector(home, d);
    view.camera.near = Math.max(0.01, d / 200);
    view.camera.far = Math.max(50, 20 * (d + framed.radius));
    view.camera.updateProjectionMatrix();
    const damping = view.controls.enableDamping;
    view.controls.enableDamping = false; // no glide out of a reset
    view.controls.update();
    view.controls.enableDamping = damping;
    userMoved = false;
  }
  /** After a parameter change: refit unless the user has moved the camera and the frame stayed. */
  function maybeRefit(): void {
    const f = current.frame();
    const moved = f.center.distanceTo(framed.center) > REFRAME * framed.radius || Math.abs(f.radius - framed.radius) > REFRAME * framed.radius;
    if (!userMoved || moved) fit();
  }
  view.controls.addEventListener("start", () => { userMoved = true; });
  const relayout = () => { hudsDirty = true; };
  const sizes = new ResizeObserver(relayout);
  sizes.observe(stage);
  sizes.observe(pinnedDl);
  sizes.observe($("view-buttons"));
  const overlay = $("overlay");
  // HUD elements a scene adds to the overlay (titles, insets) are watched too.
  new MutationObserver(() => {
    for (const el of overlay.querySelectorAll<HTMLElement>(".hud")) sizes.observe(el);
    relayout();
  }).observe(overlay, { childList: true, subtree: true, attributes: true, attributeFilter: ["hidden", "class"] });

  function layoutNow(): ReturnType<LabHandle["layout"]> {
    measureHuds();
    freeCache.clear();
    const vps = viewports();
    const main = current.mainBoxes?.() ?? [projectBox(current.main(), view.camera, vps[0])].filter((b): b is Rect => b !== null);
    return { stage: stageRect(), huds: hudRects, free: vps.map(freeOf), main };
  }

  // Keyboard orbit on the focused view; 0 (anywhere) resets it.
  const offset = new THREE.Vector3();
  function orbit(dAzimuth: number, dPolar: number, zoom = 1): void {
    offset.copy(view.camera.position).sub(view.controls.target);
    const r = offset.length() * zoom;
    let azimuth = Math.atan2(offset.y, offset.x) + dAzimuth;
    let polar = Math.acos(Math.min(1, Math.max(-1, offset.z / offset.length()))) + dPolar;
    polar = Math.min(Math.PI - 0.05, Math.max(0.05, polar));
    if (!Number.isFinite(azimuth)) azimuth = 0;
    offset.set(r * Math.sin(polar) * Math.cos(azimuth), r * Math.sin(polar) * Math.sin(azimuth), r * Math.cos(polar));
    view.camera.position.copy(view.controls.target).add(offset);
    view.controls.update();
    userMoved = true;
  }
  canvas.addEventListener("keydown", (ev) => {
    const keys: Record<string, () => void> = {
      ArrowLeft: () => orbit(-ORBIT_STEP, 0),
      ArrowRight: () => orbit(ORBIT_STEP, 0),
      ArrowUp: () => orbit(0, -ORBIT_STEP),
      ArrowDown: () => orbit(0, ORBIT_STEP),
      "+": () => orbit(0, 0, 1 / ZOOM),
      "=": () => orbit(0, 0, 1 / ZOOM),
      "-": () => orbit(0, 0, ZOOM),
      Home: () => fit(),
    };
    const act = keys[ev.key];
    if (act && !ev.ctrlKey && !ev.metaKey && !ev.altKey) {
      ev.preventDefault();
      ev.stopPropagation();
      act();
    }
  });
  $("reset-view").addEventListener("click", () => fit());

  // --- scenes -------------------------------------------------------------------------------
  const nav = $("scenes");
  const panel = $("scene-extra");
  SCENES.forEach((d, i) => {
    const b = document.createElement("button");
    b.type = "button";
    const long = document.createElement("span");
    long.className = "long";
    long.textContent = d.title;
    const short = document.createElement("span");
    short.className = "short";
    short.textContent = d.short;
    short.setAttribute("aria-hidden", "true");
    b.append(long, short);
    b.title = d.title;
    b.dataset.scene = d.id;
    if (SCENE_KEYS[i]) b.setAttribute("aria-keyshortcuts", SCENE_KEYS[i]);
    b.addEventListener("click", () => openScene(d, new URLSearchParams()));
    nav.append(b);
  });

  /** Configures the scene with the current parameters; refused, the last valid state stays on
   * screen with the core's sentence (`keepLast`), or the error replaces the readouts. */
  function configure(keepLast = true): void {
    try {
      current.configure(lab.params);
      clearError();
      valid = { ...lab.params };
      recorder.restart(def.id);
      stepOnce();
      maybeRefit();
    } catch (e) {
      if (valid === null || !keepLast) {
        showError(e);
        return;
      }
      // The last valid state stays on screen (the sliders back at it), the refusal said.
      const moved = Object.keys(lab.params).find((k) => lab.params[k] !== valid![k]);
      const spec = def.params.find((p) => p.key === moved);
      const err = e as { message?: string };
      lab.params = { ...valid };
      current.configure(lab.params);
      syncControls();
      showApplicable();
      stepOnce();
      showRefusal(`${spec ? spec.label : "This setting"} cannot take that value: ${err.message ?? String(e)}`);
    }
  }
  function stepOnce(): void {
    const t0 = performance.now();
    try {
      current.step(lab.t);
    } catch (e) {
      showError(e);
      return;
    }
    costs.push(performance.now() - t0);
    if (costs.length > PHYSICS_WINDOW) costs.shift();
    const sorted = [...costs].sort((a, b) => a - b);
    const mid = sorted.length >> 1;
    lab.physicsMs = sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
    renderReadouts();
    recorder.push(lab.t, current.readouts());
  }

  const about = $<HTMLDetailsElement>("about");
  const narrow = () => window.matchMedia("(max-width: 800px)").matches;
  function openScene(d: SceneDef, q: URLSearchParams): void {
    current?.dispose();
    labels?.dispose();
    valid = null;
    showNote(null);
    def = d;
    lab.scene = d.id;
    lab.params = paramsFromUrl(d, q);
    const t = Number(q.get("t"));
    lab.t = Number.isFinite(t) && t >= 0 ? t : 0;
    // prefers-reduced-motion: nothing moves until the user presses Play.
    setPlaying(!reducedMotion && q.get("paused") !== "1");
    costs.length = 0;
    cells.clear();
    dl.replaceChildren();
    checksDl.replaceChildren();
    pinnedCells.clear();
    pinnedDl.replaceChildren();
    delete pinnedDl.dataset.keys;
    $("scene-title").textContent = d.title;
    $("scene-blurb").textContent = d.blurb;
    about.open = !narrow();
    canvas.setAttribute("aria-label", `${d.title}: ${d.describe}. Drag to turn the view, or focus it and use the arrow keys; + and − zoom; 0 resets the view.`);
    for (const b of nav.querySelectorAll("button")) {
      if ((b as HTMLElement).dataset.scene === d.id) {
        b.setAttribute("aria-current", "page");
        b.scrollIntoView?.({ block: "nearest", inline: "nearest" });
      } else b.removeAttribute("aria-current");
    }
    view.camera.clearViewOffset();
    view.camera.position.set(5.5, 4.2, 3.4);
    view.controls.target.set(0, 0, 0);
    view.camera.layers.set(0);
    panel.replaceChildren();
    overlay.replaceChildren();
    labels = new Labels(overlay);
    current = d.create({
      scene: view.scene, camera: view.camera, target: view.controls.target, panel, overlay, labels,
      freeRect: (vp) => freeOf(vp),
      aim: (camera, vp) => aimCamera(camera, vp, freeOf(vp)),
    });
    home.copy(view.camera.position).sub(view.controls.target).normalize();
    buildControls();
    recorder.reset(d.id, typeof d.pinned === "function" ? d.pinned(lab.params)[0] : d.pinned[0]);
    // The first layout with this scene's HUD, then the frame.
    try {
      current.configure(lab.params);
      clearError();
      valid = { ...lab.params };
      stepOnce();
    } catch (e) {
      showError(e);
    }
    measureHuds();
    freeCache.clear();
    aimDefault();
    fit();
    writeUrl();
  }

  // --- transport ----------------------------------------------------------------------------
  const play = $<HTMLButtonElement>("play");
  function setPlaying(on: boolean): void {
    lab.playing = on;
    play.textContent = on ? "Pause" : "Play";
    play.setAttribute("aria-pressed", String(!on));
  }
  play.addEventListener("click", () => { setPlaying(!lab.playing); writeUrl(); });
  const reset = () => {
    lab.params = paramsFromUrl(def, new URLSearchParams());
    lab.t = 0;
    buildControls();
    configure();
    writeUrl();
  };
  $("reset").addEventListener("click", reset);
  const speedSel = $<HTMLSelectElement>("speed");
  speedSel.addEventListener("change", () => { speed = Number(speedSel.value); writeUrl(); });
  // --- share: a link to this state where the page was opened from ------------------------------
  const shareBox = $<HTMLInputElement>("share-url");
  const shareNote = $("share-note");
  /** The page's own address (the host it was served from, or the file on this computer: never a
   * fixed host) with the state in its query, and where that link works, in words. */
  function shareLink(): { url: string; where: string } {
    const url = `${location.href.split(/[?#]/)[0]}?${stateQuery()}`;
    const host = location.hostname;
    const where = location.protocol === "file:"
      ? "works on this computer (a link to this file; to share the lab, send the file itself)"
      : host === "127.0.0.1" || host === "localhost" || host === "[::1]"
        ? "works on this computer while poinsot lab runs (to hand the lab to others: poinsot lab --export FILE.html)"
        : `works for anyone who can open ${location.host}`;
    return { url, where };
  }
  /** Copies the link; says so, or (clipboard refused, missing or silent for 2 s: a page opened
   * from a file, an old browser) shows the link selected, to copy by hand. */
  const share = () => {
    writeUrl();
    const { url, where } = shareLink();
    shareBox.value = url;
    shareBox.hidden = false;
    shareBox.select();
    shareNote.hidden = false;
    shareNote.className = "share-note";
    shareNote.textContent = "Copying the link…";
    const refused = new Promise<never>((_, reject) => setTimeout(() => reject(new Error("no answer")), 2000));
    const copy = navigator.clipboard?.writeText ? Promise.race([navigator.clipboard.writeText(url), refused]) : refused;
    copy.then(
      () => {
        shareNote.classList.add("ok");
        shareNote.textContent = `Link copied: it ${where}.`;
      },
      () => {
        shareNote.classList.add("manual");
        shareNote.textContent = `Copy this link by hand (Ctrl+C or ⌘C): it ${where}.`;
        shareBox.focus();
        shareBox.select();
      },
    );
  };
  $("share").addEventListener("click", share);

  document.addEventListener("keydown", (ev) => {
    const tag = (ev.target as HTMLElement).tagName;
    if (ev.ctrlKey || ev.metaKey || ev.altKey || tag === "INPUT" || tag === "SELECT" || tag === "TEXTAREA") return;
    if (ev.key === " " && tag !== "BUTTON") { ev.preventDefault(); setPlaying(!lab.playing); writeUrl(); }
    else if (ev.key === "r" || ev.key === "R") reset();
    else if (ev.key === "s" || ev.key === "S") share();
    else if (ev.key === "0") fit();
    else if (SCENE_KEYS.includes(ev.key) && SCENES[SCENE_KEYS.indexOf(ev.key)]) openScene(SCENES[SCENE_KEYS.indexOf(ev.key)], new URLSearchParams());
  });

  // --- start --------------------------------------------------------------------------------
  const q = new URLSearchParams(location.search);
  const s = Number(q.get("speed"));
  if ([0.25, 0.5, 1, 2, 4].includes(s)) { speed = s; speedSel.value = String(s); }
  openScene(SCENES.find((d) => d.id === q.get("scene")) ?? SCENES[0], q);

  let last = performance.now();
  const full = (): Rect => ({ x: 0, y: 0, ...canvasSize() });
  const loop = (now: number) => {
    // rAF's timestamp is the frame's start, which can precede `last` (taken with performance.now()).
    const dt = Math.min(0.1, Math.max(0, (now - last) / 1000));
    last = now;
    if (lab.playing && lab.error === null) {
      lab.t += dt * speed;
      stepOnce();
    }
    if (hudsDirty) {
      measureHuds();
      freeCache.clear();
      aimDefault();
      if (!userMoved) fit();
    }
    view.controls.update();
    if (current.render) current.render(view.renderer, view.scene, view.camera);
    else view.renderer.render(view.scene, view.camera);
    if (!current.viewports) labels.update(view.camera, full());
    lab.frames++;
    requestAnimationFrame(loop);
  };
  requestAnimationFrame(loop);
  lab.ready = true;
}

main().catch((e) => {
  const box = document.getElementById("alert");
  if (box) { box.textContent = `The lab could not start: ${e}`; box.hidden = false; }
  console.error(e);
});
