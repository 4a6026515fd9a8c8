#!/usr/bin/env bash
# Install what the browser lab needs to build and test, if missing (idempotent, fast when all is
# there): the rust wasm32 target, wasm-bindgen-cli of exactly the Cargo.lock version of the
# wasm-bindgen crate (~4 min to build the first time), Debian's chromium (driven headless by
# playwright-core; needs apt-get and root) and the node packages of web/package-lock.json.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  rustup target add wasm32-unknown-unknown
fi
want="$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)"
if [[ "$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }')" != "$want" ]]; then
  cargo install --force wasm-bindgen-cli --version "$want"
fi
if ! command -v chromium >/dev/null 2>&1; then
  if [[ $(id -u) -eq 0 ]] && command -v apt-get >/dev/null 2>&1; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium
  else
    echo "web/setup.sh: the browser tests need Debian's chromium: sudo apt-get install chromium" >&2
    exit 1
  fi
fi
if ! node -e 'const [a, b] = process.versions.node.split(".").map(Number); process.exit(a > 22 || (a === 22 && b >= 12) || (a === 20 && b >= 19) ? 0 : 1)' 2>/dev/null; then
  echo "web/setup.sh: the browser lab needs node >= 20.19 (vite); found $(node --version 2>/dev/null || echo none)" >&2
  exit 1
fi
if [[ ! -d web/node_modules ]] || [[ web/package-lock.json -nt web/node_modules ]]; then
  (cd web && npm ci --no-audit --no-fund)
fi
