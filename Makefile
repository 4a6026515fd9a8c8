# poinsot — the two commands that matter:
#   make demo   set up (virtual environment, build, install with all extras) and run `poinsot tour`
#   make test   the same set-up, then every test: cargo test, clippy, pytest, the examples, the
#               browser lab (needs the web tooling that .ci/run installs)
#   make lab    build the browser lab (WebAssembly core + page) and serve it: `poinsot lab`
#   make wheel  build the abi3 wheel, the browser lab inside, into dist/ (installs without Rust)
#   make sdist  build the source distribution into dist/ (installs with pip and Rust anywhere)
SHELL := /bin/bash
PYTHON ?= python3
VENV ?= .venv
PY := $(VENV)/bin/python
export PYO3_PYTHON := $(abspath $(PY))
export MPLBACKEND := Agg

.PHONY: docs lab-shots errata-page docs-setup test-docs setup demo test test-rust lint doc publish-check test-python examples bench stubtest clean lab lab-build test-web web-setup fuzz fuzz-python fuzz-web wheel test-wheel sdist test-sdist wheel-aarch64 msrv

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip

# Build the Rust core + bindings (maturin, release) and install poinsot editable with all extras.
setup: $(PY)
	@if [[ -z "$(POINSOT_SET_UP)" ]]; then set -x; $(PY) -m pip install -q -e '.[all,test,docs,notebook,parallel]'; fi

demo: setup
	$(VENV)/bin/poinsot tour

# Every test, in an order that keeps both cores busy where one step uses only one: pytest runs
# beside the web tooling's install (wasm-bindgen-cli takes minutes to build) and the MSRV check,
# and the documentation (Sphinx runs the gallery and the notebooks one by one) beside the source
# distribution's build and test. The browser lab's tests run on their own (test-web: the files
# that time frames alone, the others two at a time). The examples are run by the documentation
# build (sphinx-gallery executes every file of examples/ and stops the build on an error:
# docs/conf.py), so `make examples` is not repeated here.
test: setup test-rust lint python-beside-tooling test-web docs-beside-sdist test-wheel

# Two makes side by side, the second at a lower priority (nice), so that the first keeps a core
# for itself (its tests time how fast a call answers Ctrl-C); the second's log is printed after
# both end, and the step fails if either does. POINSOT_SET_UP and POINSOT_LAB_BUILT say what is
# done already (the set-up; the lab, which two makes must not build at once).
BESIDE = mkdir -p target; \
	nice -n 10 $(MAKE) --no-print-directory POINSOT_SET_UP=1 POINSOT_LAB_BUILT=$(3) $(2) > target/beside.log 2>&1 & pid=$$!; \
	$(MAKE) --no-print-directory POINSOT_SET_UP=1 POINSOT_LAB_BUILT=$(3) $(1); rc1=$$?; \
	wait $$pid; rc2=$$?; echo "== make $(2) (ran beside make $(1)), exit $$rc2:"; cat target/beside.log; \
	exit $$(( rc1 != 0 || rc2 != 0 ))

.PHONY: python-beside-tooling docs-beside-sdist
python-beside-tooling: setup
	@$(call BESIDE,test-python,web-setup msrv,)

docs-beside-sdist: setup lab-build
	@$(call BESIDE,test-docs,test-sdist,1)

# The Rust tests build with Cargo.toml's test-release profile (release without LTO: minutes less).
test-rust:
	cargo test -p poinsot --profile test-release
	cargo test -p poinsot-wasm --profile test-release

lint: $(PY)
	cargo fmt --all --check
	cargo clippy --workspace --all-targets --release -- -D warnings
	$(PY) -m mypy.stubtest poinsot._core --allowlist python/stubtest-allowlist.txt
	RUSTDOCFLAGS="-D warnings" cargo doc -p poinsot --no-deps
	$(PY) -m ruff check python examples docs/conf.py docs/_ext
	$(PY) -m ruff format --check python examples docs/conf.py docs/_ext
	$(PY) -m mypy python/poinsot

# The workspace builds with the oldest Rust it declares (Cargo.toml's rust-version: nalgebra 0.35
# and its `wide` need 1.89), checked with that toolchain (installed by rustup when missing).
MSRV := $(shell sed -n 's/^rust-version = "\(.*\)"/\1/p' Cargo.toml)
msrv:
	rustup toolchain install $(MSRV) --profile minimal >/dev/null
	CARGO_TARGET_DIR=target/msrv cargo +$(MSRV) check --workspace --all-targets --quiet

# The core crate's API documentation (target/doc/poinsot), warnings as errors (also in `lint`).
doc:
	RUSTDOCFLAGS="-D warnings" cargo doc -p poinsot --no-deps

# The core crate as crates.io would receive it: packaged, then built from the package alone.
publish-check:
	cargo publish -p poinsot --dry-run --allow-dirty

# The wheel test (python/tests/test_wheel.py) needs the built wheel: `make test-wheel` runs it.
test-python: setup
	$(PY) -m pytest -q -m "not wheel and not sdist" python/tests

examples: setup
	@set -e; for f in examples/*.py; do echo "== $$f"; $(PY) $$f; done

bench: setup
	$(PY) -m pip install -q mujoco  # a peer, for bench/free_body_vs_mujoco.py only
	cargo bench -p poinsot
	$(PY) bench/run_all.py

# The browser lab (web/): the core compiled to WebAssembly, the page built by vite into
# python/poinsot/lab (git-ignored, shipped in the wheel). Needs the rust wasm32 target,
# wasm-bindgen-cli of the Cargo.lock version and node/npm (.ci/run installs them).
web-setup:
	bash web/setup.sh

# The documentation site (Sphinx, docs/conf.py) into docs/_build/html: the topic pages, the
# gallery (examples/ executed), the API and CLI references, the notebooks, the lab. Offline:
# MathJax (docs/node_modules) and the built lab are inside. Warnings are errors.
# docs/errata.md from poinsot.derive.errata() (kept in git; test_derive_pages.py holds it equal).
errata-page:
	$(PY) docs/_ext/derive_pages.py

docs-setup:
	cd docs && npm ci --no-audit --no-fund

docs: lab-shots docs-setup
	$(PY) -m sphinx -W --keep-going -b html docs docs/_build/html

# The static site for any web host: the documentation with the lab inside (lab/index.html, and
# lab/poinsot-lab.html, the lab as one file to download), relative addresses only, nothing loaded
# from the network, no 127.0.0.1 (docs/_ext/check_site.py reads every page), and .nojekyll so
# that GitHub Pages serves the _static/ folders as they are. SITE_DIR is the folder the release
# workflow (.github/workflows/release.yml) publishes to GitHub Pages: upload exactly this folder.
SITE_DIR := docs/_build/html
.PHONY: site
site: docs
	touch $(SITE_DIR)/.nojekyll
	$(PY) docs/_ext/check_site.py $(SITE_DIR)

# The built site (make site, checked) in Debian's chromium (docs/tests/*.mjs): home, math, gallery, API,
# lab, search; on a phone (narrow.test.mjs: wide tables, the equation index), the downloads.
test-docs: site
	cd docs && node --test --test-concurrency=1 tests/

lab-build: setup web-setup
	@if [[ -z "$(POINSOT_LAB_BUILT)" ]]; then set -x; bash web/build.sh; fi

# One screenshot of each scene of the built lab (web/shots/shots.test.mjs, Debian's chromium) into
# docs/_generated/lab/ (git-ignored), for the pages that show the lab (docs/_ext/pictures.py).
lab-shots: lab-build
	cd web && PYTHON=$(abspath $(PY)) node --test shots/shots.test.mjs

lab: lab-build
	$(VENV)/bin/poinsot lab

# The abi3 wheel (CPython >= 3.9, one per platform) with the built browser lab inside
# (python/poinsot/lab, git-ignored, named in pyproject's [tool.maturin] include), into dist/.
# A user without Rust installs it with `pip install dist/poinsot-*.whl`.
wheel: lab-build
	$(PY) -m pip install -q 'maturin>=1.16,<2'
	rm -f dist/poinsot-*.whl
	$(VENV)/bin/maturin build --release --out dist

# Installs that wheel into a fresh virtual environment with no Rust on PATH, runs `poinsot tour`
# and fetches the lab's page and WebAssembly from `poinsot lab` (python/tests/test_wheel.py).
test-wheel: wheel
	POINSOT_WHEEL="$$(ls dist/poinsot-*.whl)" $(PY) -m pytest -q -m wheel python/tests/test_wheel.py

# The source distribution (maturin sdist) into dist/: the Rust workspace without the wasm crate,
# Cargo.lock, the Python package, README and licences, and the built browser lab and notebook
# widgets (python/poinsot/lab and widgets/static, git-ignored, named in pyproject's include with
# format "sdist"), so that `poinsot lab` works from an sdist install. Installing it builds the core
# with maturin and cargo: it needs Rust >= 1.89 and a C linker, never node or wasm-bindgen.
sdist: lab-build
	$(PY) -m pip install -q 'maturin>=1.16,<2'
	rm -f dist/poinsot-*.tar.gz
	$(VENV)/bin/maturin sdist --out dist

# Installs that sdist into a fresh virtual environment with plain `pip install` (build isolation:
# maturin from the index or pip's cache), checks its file list, that no web tool was called, and
# that `poinsot fall` and the API answer as this checkout does (python/tests/test_sdist.py). The
# cargo target dir (target/sdist) starts empty each run: the sdist's files carry the archive's
# mtimes, so cargo would take an earlier checkout's build as fresh and install a stale core.
test-sdist: sdist
	rm -rf target/sdist
	CARGO_TARGET_DIR=$(abspath target/sdist) POINSOT_SDIST="$$(ls dist/poinsot-*.tar.gz)" \
		$(PY) -m pytest -q -m sdist python/tests/test_sdist.py

# The Linux aarch64 wheel (manylinux_2_17, glibc >= 2.17), cross-built on x86-64 with zig as the
# linker (maturin --zig; the ziglang package and rustup's aarch64-unknown-linux-gnu target are
# installed when missing), the browser lab inside, into dist/aarch64/ (apart from the host's
# wheel that test-wheel installs), then inspected as auditwheel reads a wheel (tags, ELF machine,
# glibc versions, linked libraries: python/tests/test_wheel_aarch64.py); this machine cannot run
# it. Not in `make test`: a first release build for another CPU costs about 200 s of CPU (17 min
# of wall time on two busy cores); the release workflow builds and tests it on every tag.
wheel-aarch64: lab-build
	$(PY) -m pip install -q 'maturin>=1.16,<2' ziglang
	rustup target add aarch64-unknown-linux-gnu
	rm -f dist/aarch64/poinsot-*.whl
	PATH="$(abspath $(VENV))/bin:$$PATH" $(VENV)/bin/maturin build --release \
		--target aarch64-unknown-linux-gnu --zig --out dist/aarch64
	POINSOT_WHEEL_AARCH64="$$(ls dist/aarch64/poinsot-*.whl)" $(PY) -m pytest -q -m wheel \
		python/tests/test_wheel_aarch64.py

# Browser tests (playwright-core + Debian chromium): scenes, controls, URL, parity with Python.
# The files that time frames run alone; the others two at a time (each file starts its own
# server and browser), which halves their wall time on two cores.
WEB_TIMED := tests/cost.test.mjs tests/lab.test.mjs
WEB_UNTIMED := $(patsubst web/%,%,$(filter-out $(addprefix web/,$(WEB_TIMED)),$(sort $(wildcard web/tests/*.test.mjs))))
test-web: lab-build
	$(PY) web/tests/make_golden.py web/tests/golden.json
	cd web && PYTHON=$(abspath $(PY)) node --test --test-concurrency=1 $(WEB_TIMED)
	cd web && PYTHON=$(abspath $(PY)) node --test --test-concurrency=2 $(WEB_UNTIMED)

# Long fuzzing of the whole public surface (issue 10, item 18): `make test` runs bounded,
# fixed-seed campaigns (python/tests/test_fuzz.py, web/tests/wasm_fuzz.test.mjs); these run long
# ones. FUZZ_EXAMPLES sets the number of random Python calls (hypothesis, random seed).
FUZZ_EXAMPLES ?= 20000
fuzz: fuzz-python fuzz-web

fuzz-python: setup
	POINSOT_FUZZ_EXAMPLES=$(FUZZ_EXAMPLES) $(PY) -m pytest -q -s python/tests/test_fuzz.py

# Long fuzzing of the WebAssembly core (issue 10, item 18): every export with adversarial values,
# in node, a random seed (printed; FUZZ_SEED=<seed> repeats a run), FUZZ_CALLS calls (about 2 ms
# each). `make test-web` runs a bounded, fixed-seed run (web/tests/wasm_fuzz.test.mjs).
FUZZ_CALLS ?= 100000
fuzz-web: web-setup
	bash web/build.sh wasm
	node web/tests/wasm_fuzz.mjs --calls $(FUZZ_CALLS) $(if $(FUZZ_SEED),--seed $(FUZZ_SEED))

clean:
	cargo clean
	rm -rf $(VENV) .pytest_cache .hypothesis dist
