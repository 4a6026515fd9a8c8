// The lab's shell: loads the core (WebAssembly), builds the scene tabs, the parameter controls
// and the readouts, runs the animation loop with the physics in it, and keeps the URL (the
// "share" link) in step with the parameters.
import "./style.css";
import init, { coreStatus, version, type CoreStatus } from "./core";
import { createView } from "./view";
import { fmt, type Params, type Readout, type SceneDef, type SceneInstance } from "./scene";
import { SCENES } from "./scenes";

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
  /** Mean physics time per frame (ms) over the last `PHYSICS_WINDOW` frames. */
  physicsMs: number;
  error: string | null;
  /** The core's guard: restarts of the WebAssembly instance after an internal error. */
  core(): CoreStatus;
  readouts(): Record<string, Readout["value"]>;
  seek(t: number): void;
}

const PHYSICS_WINDOW = 120;
const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

async function main(): Promise<void> {
  await init();
  const view = createView($("view"));
  const lab: LabHandle = {
    ready: false, version: version(), scenes: SCENES.map((d) => d.id), scene: "", params: {}, t: 0, playing: true, frames: 0,
    physicsMs: 0, error: null, core: coreStatus,
    readouts: () => Object.fromEntries(current.readouts().map((r) => [r.key, r.value])),
    seek: (t: number) => { lab.t = t; stepOnce(); },
  };
  (window as unknown as { __lab: LabHandle }).__lab = lab;

  let def: SceneDef = SCENES[0];
  let current: SceneInstance;
  let speed = 1;
  const costs: number[] = [];

  const alertBox = $("alert");
  function showError(e: unknown): void {
    const err = e as { name?: string; message?: string };
    lab.error = `${err.name ?? "Error"}: ${err.message ?? String(e)}`;
    alertBox.textContent = lab.error;
    alertBox.hidden = false;
    // No stale numbers beside an error: the readouts wait for valid parameters.
    for (const dd of cells.values()) {
      dd.textContent = "—";
      dd.dataset.value = "null";
    }
  }
  function clearError(): void {
    lab.error = null;
    alertBox.hidden = true;
  }

  // --- URL <-> state --------------------------------------------------------------------
  function paramsFromUrl(d: SceneDef, q: URLSearchParams): Params {
    const p: Params = {};
    for (const spec of d.params) {
      const raw = q.get(spec.key);
      if (spec.kind === "number") {
        const x = raw === null ? NaN : Number(raw);
        p[spec.key] = Number.isFinite(x) ? Math.min(spec.max, Math.max(spec.min, x)) : spec.value;
      } else {
        p[spec.key] = raw !== null && spec.options.includes(raw) ? raw : spec.value;
      }
    }
    return p;
  }
  function writeUrl(): void {
    const q = new URLSearchParams({ scene: def.id });
    for (const spec of def.params) q.set(spec.key, String(lab.params[spec.key]));
    if (speed !== 1) q.set("speed", String(speed));
    if (!lab.playing) {
      q.set("paused", "1");
      q.set("t", String(lab.t));
    }
    history.replaceState(null, "", `${location.pathname}?${q}`);
  }

  // --- controls ---------------------------------------------------------------------------
  const form = $<HTMLFormElement>("controls");
  form.addEventListener("submit", (ev) => ev.preventDefault());
  function buildControls(): void {
    form.replaceChildren();
    for (const spec of def.params) {
      const label = document.createElement("label");
      const name = document.createElement("span");
      name.textContent = spec.kind === "number" && spec.unit ? `${spec.label} (${spec.unit})` : spec.label;
      label.append(name);
      if (spec.kind === "number") {
        const input = document.createElement("input");
        Object.assign(input, { type: "range", min: String(spec.min), max: String(spec.max), step: String(spec.step), name: spec.key });
        input.value = String(lab.params[spec.key]);
        input.dataset.key = spec.key;
        const out = document.createElement("output");
        out.textContent = fmt(Number(input.value), 4);
        input.addEventListener("input", () => {
          out.textContent = fmt(Number(input.value), 4);
          setParam(spec.key, Number(input.value));
        });
        label.append(input, out);
      } else {
        const select = document.createElement("select");
        select.name = spec.key;
        select.dataset.key = spec.key;
        for (const o of spec.options) select.add(new Option(o, o));
        select.value = String(lab.params[spec.key]);
        select.addEventListener("change", () => setParam(spec.key, select.value));
        label.append(select, document.createElement("span"));
      }
      form.append(label);
    }
  }
  function setParam(key: string, value: number | string): void {
    lab.params = { ...lab.params, [key]: value };
    configure();
    writeUrl();
  }

  // --- readouts ---------------------------------------------------------------------------
  const dl = $("readouts");
  const cells = new Map<string, HTMLElement>();
  function renderReadouts(): void {
    for (const r of current.readouts()) {
      let dd = cells.get(r.key);
      if (!dd) {
        const dt = document.createElement("dt");
        dt.textContent = r.label;
        dd = document.createElement("dd");
        dd.dataset.key = r.key;
        dl.append(dt, dd);
        cells.set(r.key, dd);
      }
      if (dd.textContent !== r.text) dd.textContent = r.text;
      dd.dataset.value = JSON.stringify(r.value);
      dd.classList.toggle("warn", !!r.warn);
    }
  }

  // --- scenes -------------------------------------------------------------------------------
  const nav = $("scenes");
  const panel = $("scene-extra");
  const overlay = $("overlay");
  SCENES.forEach((d, i) => {
    const b = document.createElement("button");
    b.type = "button";
    b.textContent = d.title;
    b.dataset.scene = d.id;
    b.setAttribute("aria-keyshortcuts", String(i + 1));
    b.addEventListener("click", () => openScene(d, new URLSearchParams()));
    nav.append(b);
  });

  function configure(): void {
    try {
      current.configure(lab.params);
      clearError();
      stepOnce();
    } catch (e) {
      showError(e);
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
    lab.physicsMs = costs.reduce((a, b) => a + b, 0) / costs.length;
    renderReadouts();
  }

  function openScene(d: SceneDef, q: URLSearchParams): void {
    current?.dispose();
    def = d;
    lab.scene = d.id;
    lab.params = paramsFromUrl(d, q);
    const t = Number(q.get("t"));
    lab.t = Number.isFinite(t) && t >= 0 ? t : 0;
    setPlaying(q.get("paused") !== "1");
    costs.length = 0;
    cells.clear();
    dl.replaceChildren();
    $("scene-title").textContent = d.title;
    $("scene-blurb").textContent = d.blurb;
    for (const b of nav.querySelectorAll("button")) {
      if ((b as HTMLElement).dataset.scene === d.id) b.setAttribute("aria-current", "page");
      else b.removeAttribute("aria-current");
    }
    view.camera.position.set(5.5, 4.2, 3.4);
    view.controls.target.set(0, 0, 0);
    panel.replaceChildren();
    overlay.replaceChildren();
    current = d.create({ scene: view.scene, camera: view.camera, target: view.controls.target, panel, overlay });
    buildControls();
    configure();
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
  const shareBox = $<HTMLInputElement>("share-url");
  const share = () => {
    writeUrl();
    shareBox.value = location.href;
    shareBox.hidden = false;
    shareBox.select();
    navigator.clipboard?.writeText(location.href).catch(() => undefined);
  };
  $("share").addEventListener("click", share);

  document.addEventListener("keydown", (ev) => {
    const tag = (ev.target as HTMLElement).tagName;
    if (ev.ctrlKey || ev.metaKey || ev.altKey || tag === "INPUT" || tag === "SELECT" || tag === "TEXTAREA") return;
    if (ev.key === " " && tag !== "BUTTON") { ev.preventDefault(); setPlaying(!lab.playing); writeUrl(); }
    else if (ev.key === "r" || ev.key === "R") reset();
    else if (ev.key === "s" || ev.key === "S") share();
    else if (/^[1-9]$/.test(ev.key) && SCENES[Number(ev.key) - 1]) openScene(SCENES[Number(ev.key) - 1], new URLSearchParams());
  });

  // --- start --------------------------------------------------------------------------------
  const q = new URLSearchParams(location.search);
  const s = Number(q.get("speed"));
  if ([0.25, 0.5, 1, 2, 4].includes(s)) { speed = s; speedSel.value = String(s); }
  openScene(SCENES.find((d) => d.id === q.get("scene")) ?? SCENES[0], q);

  let last = performance.now();
  const loop = (now: number) => {
    // rAF's timestamp is the frame's start, which can precede `last` (taken with performance.now()).
    const dt = Math.min(0.1, Math.max(0, (now - last) / 1000));
    last = now;
    if (lab.playing && lab.error === null) {
      lab.t += dt * speed;
      stepOnce();
    }
    view.controls.update();
    if (current.render) current.render(view.renderer, view.scene, view.camera);
    else view.renderer.render(view.scene, view.camera);
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
