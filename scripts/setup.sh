#!/usr/bin/env bash
# Installs what building and testing VSR Playground needs, skipping whatever is already
# present at the right version, so running it twice is cheap. Written for a fresh Debian
# machine (as root, or with sudo for apt); needs Rust (rustup) and Node.js >= 18.19.
#
#   scripts/setup.sh          wasm target, wasm-pack, the exact wasm-bindgen-cli, npm packages
#   scripts/setup.sh --test   the same, plus rustfmt, clippy, Debian chromium for the browser test,
#                             Debian parallel, slurm-wlm and munge for the campaign recipes' tests,
#                             and a Python virtual environment (target/py-venv) with maturin,
#                             numpy, pytest, cma and gymnasium from PyPI for the Python package's tests
#                             and check-jsonschema for the Pages workflow's form
#   scripts/setup.sh --browsers the same as without a flag, plus Debian firefox-esr, webkit2gtk-driver
#                             (WebKitWebDriver and MiniBrowser), xvfb and xauth for `make test-browsers`
set -euo pipefail

cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

WASM_PACK_VERSION=0.15.1
with_test=0
with_browsers=0
for arg in "$@"; do
  case "$arg" in
    --test) with_test=1 ;;
    --browsers) with_browsers=1 ;;
    *) echo "setup.sh: unknown argument '$arg' (expected --test or --browsers)" >&2; exit 2 ;;
  esac
done

say() { printf 'setup: %s\n' "$*"; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else echo "setup: '$*' needs root" >&2; exit 1
  fi
}

apt_install() {
  as_root apt-get update -q
  DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -q --no-install-recommends "$@"
}

require_rust() {
  if ! command -v cargo >/dev/null || ! command -v rustup >/dev/null; then
    echo "setup: Rust is missing; install it with rustup (https://rustup.rs) and run again" >&2
    exit 1
  fi
}

require_node() {
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    say "installing Node.js and npm (Debian)"
    apt_install nodejs npm
  fi
}

rust_tools() {
  if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    say "adding the wasm32-unknown-unknown target"
    rustup target add wasm32-unknown-unknown
  fi
  if [ "$with_test" -eq 1 ]; then
    for component in rustfmt clippy; do
      if ! rustup component list --installed | grep -q "^$component"; then
        rustup component add "$component"
      fi
    done
  fi
}

wasm_pack() {
  if ! command -v wasm-pack >/dev/null; then
    say "installing wasm-pack $WASM_PACK_VERSION"
    cargo install --locked wasm-pack --version "$WASM_PACK_VERSION"
  fi
}

# wasm-bindgen-cli must be exactly the wasm-bindgen version in Cargo.lock: wasm-pack
# (build and test) uses the one on PATH and cannot download one here.
wasm_bindgen_cli() {
  local want have
  want=$(awk '$0 == "name = \"wasm-bindgen\"" { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
  if [ -z "$want" ]; then
    echo "setup: no wasm-bindgen entry in Cargo.lock" >&2
    exit 1
  fi
  have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
  if [ "$have" != "$want" ]; then
    say "installing wasm-bindgen-cli $want (found '${have:-none}')"
    cargo install wasm-bindgen-cli --version "=$want"
  fi
}

# npm ci wipes node_modules; run it only when package-lock.json changed since the last one.
npm_packages() {
  local stamp=node_modules/.setup-package-lock.json
  if ! cmp -s package-lock.json "$stamp"; then
    say "installing npm packages (npm ci)"
    npm ci --no-audit --no-fund
    cp package-lock.json "$stamp"
  fi
}

chromium() {
  if [ ! -x /usr/bin/chromium ]; then
    say "installing Debian chromium"
    apt_install chromium
  fi
}

# The page in Firefox and WebKitGTK (tests/browsers/): their Debian builds, and an X server
# for MiniBrowser's window.
browsers() {
  local missing=()
  [ -x /usr/bin/firefox-esr ] || missing+=(firefox-esr)
  [ -x /usr/bin/WebKitWebDriver ] || missing+=(webkit2gtk-driver)
  command -v xvfb-run >/dev/null || missing+=(xvfb)
  command -v xauth >/dev/null || missing+=(xauth)
  if [ ${#missing[@]} -gt 0 ]; then
    say "installing Debian ${missing[*]}"
    apt_install "${missing[@]}"
  fi
}

# The campaign recipes' tests (tests/cluster/): GNU parallel, and a single-node Slurm.
cluster_tools() {
  local missing=()
  command -v parallel >/dev/null || missing+=(parallel)
  command -v slurmctld >/dev/null || missing+=(slurm-wlm)
  command -v munged >/dev/null || missing+=(munge)
  if [ ${#missing[@]} -gt 0 ]; then
    say "installing Debian ${missing[*]}"
    apt_install "${missing[@]}"
  fi
}

# The Python package's build and test tools, in their own virtual environment.
PY_VENV=target/py-venv
PY_PACKAGES=(maturin numpy pytest cma gymnasium check-jsonschema)
python_tools() {
  if ! command -v python3 >/dev/null || ! python3 -c 'import venv, ensurepip' 2>/dev/null; then
    say "installing Debian python3 and python3-venv"
    apt_install python3 python3-venv
  fi
  if [ ! -x "$PY_VENV/bin/python" ]; then
    say "making the Python virtual environment $PY_VENV"
    python3 -m venv "$PY_VENV"
  fi
  if ! "$PY_VENV/bin/python" -c 'import maturin, numpy, pytest, cma, gymnasium, check_jsonschema' 2>/dev/null; then
    say "installing ${PY_PACKAGES[*]} (PyPI) into $PY_VENV"
    "$PY_VENV/bin/pip" install --quiet --disable-pip-version-check "${PY_PACKAGES[@]}"
  fi
}

require_rust
require_node
rust_tools
wasm_pack
wasm_bindgen_cli
npm_packages
if [ "$with_test" -eq 1 ]; then chromium; cluster_tools; python_tools; fi
if [ "$with_browsers" -eq 1 ]; then browsers; fi
say "ok"
