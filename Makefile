# VSR Playground: the two commands of the README, and their parts.
#   make run         install what is missing, build the page, serve it at http://127.0.0.1:8080
#   make test        install what is missing (and chromium), then every check and test
#   make site        the page as one folder for any static web server, at any sub-path, offline
#                    after the first visit: target/site (scripts/site.mjs; docs/teaching.md says
#                    how a teacher puts it online; .github/workflows/pages.yml publishes it)
#   make lint        rustfmt and clippy, then the page's types (make typecheck: builds the wasm package first)
#   make test-cluster  the campaign recipes from a bare folder: GNU parallel, and Slurm on a
#                      single-node Slurm started here (scripts/slurm-local.sh; needs root)
#   make test-python the Python package (python/): wheel, install, pytest (docs/python.md)
#   make test-python-install  pip install "./python[examples,gym]" in a fresh venv, then use it
#   make bench-wasm  speed of the wasm build in Node (figures for the README)
#   make web-package the npm-ready web package (wasm core + <vsr-robot>) in target/web-package
#   make test-browsers    opt-in: the page in Firefox and WebKitGTK gives vsr's results, with Chromium's figures beside (tests/browsers/)

SHELL := /bin/bash
export PATH := $(HOME)/.cargo/bin:$(PATH)
PORT ?= 8080
WASM_PACK_BUILD := wasm-pack build crate/wasm --release --target web --out-dir ../../www/pkg --out-name vsr

# The steps depend on each other's results (setup before builds, wasm before typecheck and test-web).
# A target runs once per make: the wasm package that lint's typecheck built is the one test-web loads.
.NOTPARALLEL:

.PHONY: run test setup setup-test wasm serve lint lint-rust lint-workflows typecheck test-native test-wasm test-web test-cluster \
	test-parallel test-slurm test-python test-python-install test-browsers bench-wasm bench-python web-package site

run: setup wasm serve

test: setup-test lint test-native test-python test-python-install test-cluster test-wasm wasm test-web

setup:
	bash scripts/setup.sh

setup-test:
	bash scripts/setup.sh --test

## The page's wasm module and its JS glue, into www/pkg (build output, not committed).
wasm:
	$(WASM_PACK_BUILD)

serve:
	PORT=$(PORT) node scripts/serve.mjs

## The site: the page, its wasm core, the pretrained modules, the study files it shows and the
## guides it links (as web pages), in one folder with relative addresses (target/site).
site: setup wasm
	node scripts/site.mjs

lint: lint-rust typecheck lint-workflows

## The Pages workflow never runs here (no GitHub runner): its form is checked against GitHub's
## workflow schema (check-jsonschema's copy of it, in the test virtual environment).
lint-workflows:
	$(PY_VENV)/bin/check-jsonschema --builtin-schema vendor.github-workflows .github/workflows/*.yml

lint-rust:
	cargo fmt --all --check
	cargo clippy --all-targets -- -D warnings
	cargo clippy -p vsr-python --all-targets -- -D warnings
	cargo clippy -p vsr-wasm --lib --tests --target wasm32-unknown-unknown -- -D warnings

## The page's types: TypeScript (an npm dev dependency) checks every file of www/, JavaScript
## with JSDoc types, strict (tsconfig.json), and its calls into the wasm package against the
## declarations wasm-bindgen writes (www/pkg/vsr.d.ts): so after the wasm build. Emits nothing.
typecheck: wasm
	npm run --silent typecheck

test-native:
	cargo test --release

## The Python package: its abi3 wheel built by maturin (release profile, as the binary), put
## in the virtual environment scripts/setup.sh --test made (target/py-venv; a fresh one in CI),
## then its pytest suite, which checks it against the `vsr` binary built here.
PY_VENV := target/py-venv
test-python:
	cargo build --release --bin vsr
	rm -rf target/wheels
	$(PY_VENV)/bin/maturin build --release -m python/Cargo.toml --out target/wheels
	$(PY_VENV)/bin/pip install --force-reinstall --no-deps target/wheels/vsr-*.whl
	$(PY_VENV)/bin/pytest -q python/tests

## The documented install (docs/python.md) in a fresh virtual environment: pip builds
## "./python[examples,gym]" (maturin from PyPI as its build backend, then cargo), the pycma example
## on a tiny budget and gymnasium's check_env on vsr.gym.WalkEnv run from it.
PY_FRESH := target/py-fresh
test-python-install:
	rm -rf $(PY_FRESH)
	python3 -m venv $(PY_FRESH)
	CARGO_TARGET_DIR=$(CURDIR)/target $(PY_FRESH)/bin/pip install --quiet --disable-pip-version-check "./python[examples,gym]"
	$(PY_FRESH)/bin/python python/examples/cma_evolve.py --evaluations 30 --seconds 1
	$(PY_FRESH)/bin/python -c 'from gymnasium.utils.env_checker import check_env; \
	  from vsr.gym import WalkEnv; check_env(WalkEnv(seconds=2.0), skip_render_check=True); \
	  print("check_env: WalkEnv passes")'

## Evaluations per second through vsr.evaluate against `vsr evaluate` on the same batch, and a
## pycma run (the figures of docs/python.md); needs `make test-python` first.
bench-python:
	cargo build --release -p vsr-python --example native_batch
	$(PY_VENV)/bin/python python/examples/bench_evaluate.py
	$(PY_VENV)/bin/python python/examples/cma_evolve.py

## The campaign recipes of docs/campaigns.md, as written, on campaigns/smoke.toml in an empty
## folder: GNU parallel, then Slurm on a real single-node Slurm (about 80 s; needs root).
test-cluster: test-parallel test-slurm

test-parallel:
	bash tests/cluster/parallel.sh

test-slurm:
	bash tests/cluster/slurm.sh

## The wasm boundary under Node (crate/wasm/tests/wasm.rs).
test-wasm:
	wasm-pack test --node crate/wasm

## The page in headless Chromium (needs `make wasm`). A test still going after 10 minutes fails
## (none needs half of that on this machine), and the runner ends once every file has reported,
## so a stray server or browser never holds CI until its time runs out.
test-web:
	node --test --test-timeout=600000 --test-force-exit tests/web/

## Opt-in, not part of `make test`: the page in Debian firefox-esr (puppeteer-core) and
## WebKitGTK (WebKitWebDriver, MiniBrowser under xvfb-run) walks, evolves as `vsr evolve` and
## measures as `vsr evaluate` (docs/playground.md); prints its figures and times, and
## Chromium's in the same sitting (the quick evolution's time in each browser).
test-browsers:
	bash scripts/setup.sh --browsers
	$(WASM_PACK_BUILD)
	$(if $(VSR_BIN),,cargo build --release --bin vsr)
	xvfb-run -a node --test --test-concurrency=1 tests/browsers/

## The wasm core and <vsr-robot> as an npm package, and its size (docs/embed.md).
web-package: setup wasm
	node scripts/web-package.mjs

bench-wasm: setup wasm
	node tests/bench/wasm_bench.mjs

