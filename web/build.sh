#!/usr/bin/env bash
# Build the browser lab: the core compiled to WebAssembly (poinsot-wasm), its JavaScript glue
# (wasm-bindgen --target web, into src/wasm, git-ignored) and the page (vite, into
# python/poinsot/lab, git-ignored, shipped in the wheel through maturin's python-source), then the
# notebook widgets' front end (vite.widget.config.ts: one ES module with the core inlined, into
# python/poinsot/widgets/static, git-ignored, in the wheel), then the lab as one self-contained
# file (vite.export.config.ts: script, styles and core inside the HTML, opens from file://), copied
# to python/poinsot/lab/poinsot-lab.html (in the wheel with the page; `poinsot lab --export`).
#   bash web/build.sh          everything
#   bash web/build.sh wasm     the WebAssembly module and its glue only
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
cd "$root"

want="$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)"
have="$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)"
if [[ "$have" != "$want" ]]; then
  echo "web/build.sh: wasm-bindgen $want is needed (Cargo.lock), found '${have:-none}':" >&2
  echo "  cargo install wasm-bindgen-cli --version $want" >&2
  exit 1
fi

cargo build --target wasm32-unknown-unknown --release -p poinsot-wasm
# --experimental-reset-state-function: the page's guard (src/protect.js) replaces an instance that
# trapped (which must never happen) by a fresh one through the generated __wbg_reset_state.
wasm-bindgen --target web --experimental-reset-state-function --out-dir web/src/wasm \
  target/wasm32-unknown-unknown/release/poinsot_wasm.wasm

if [[ "${1:-all}" == "wasm" ]]; then exit 0; fi
cd "$here"
if [[ ! -d node_modules ]]; then npm ci --no-audit --no-fund; fi
# The real pole's path for the scene "The Earth as a top" (a decimated copy of the package's
# attributed IERS extract, into src/generated, git-ignored).
node tools/pole_path.mjs
npx tsc --noEmit
npx vite build
npx vite build -c vite.widget.config.ts
npx vite build -c vite.export.config.ts
# A file to e-mail or put on Moodle: refused above 4 MB (it is about 2.2 MB).
size="$(wc -c < "$root/target/lab-export/index.html" | tr -d " ")"
if (( size > 4000000 )); then
  echo "web/build.sh: the one-file lab is $size bytes, over the 4 MB it must stay under" >&2
  exit 1
fi
cp "$root/target/lab-export/index.html" "$root/python/poinsot/lab/poinsot-lab.html"
