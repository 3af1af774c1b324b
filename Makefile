# VSR Playground: the two commands of the README, and their parts.
#   make run         install what is missing, build the page, serve it at http://127.0.0.1:8080
#   make test        install what is missing (and chromium), then every check and test
#   make bench-wasm  speed of the wasm build in Node (figures for the README)

SHELL := /bin/bash
export PATH := $(HOME)/.cargo/bin:$(PATH)
PORT ?= 8080
WASM_PACK_BUILD := wasm-pack build --release --target web --out-dir www/pkg --out-name vsr

# The steps depend on each other's results (setup before builds, wasm before test-web).
.NOTPARALLEL:

.PHONY: run test setup setup-test wasm serve lint test-native test-wasm test-web bench-wasm

run: setup wasm serve

test: setup-test lint test-native test-wasm wasm test-web

setup:
	bash scripts/setup.sh

setup-test:
	bash scripts/setup.sh --test

## The page's wasm module and its JS glue, into www/pkg (build output, not committed).
wasm:
	$(WASM_PACK_BUILD)

serve:
	PORT=$(PORT) node scripts/serve.mjs

lint:
	cargo fmt --check
	cargo clippy --all-targets -- -D warnings
	cargo clippy --lib --target wasm32-unknown-unknown -- -D warnings

test-native:
	cargo test --release

## The wasm boundary under Node (tests/wasm.rs).
test-wasm:
	wasm-pack test --node

## The page in headless Chromium (needs `make wasm`).
test-web:
	node --test tests/web/

bench-wasm: setup wasm
	node tests/bench/wasm_bench.mjs
