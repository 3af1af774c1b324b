#!/usr/bin/env bash
# The GNU parallel recipe of docs/campaigns.md, as written, on campaigns/smoke.toml copied
# into an empty folder: three stages through `parallel`, merge, report; then the outputs are
# counted (make test runs it; needs Debian `parallel` and the release `vsr`).
set -euo pipefail
source "$(dirname "$0")/lib.sh"

command -v parallel >/dev/null || fail "GNU parallel is missing (scripts/setup.sh --test installs it)"
(cd "$repo" && nice cargo build --release --bin vsr --quiet)
dir=$(bare_folder parallel)
trap 'rm -rf "$dir"' EXIT
recipe parallel campaigns/smoke.toml > "$dir/recipe.sh"
start=$(date +%s)
(cd "$dir" && bash -euo pipefail recipe.sh > log.txt 2>&1) || { tail -20 "$dir/log.txt"; fail "the recipe failed"; }
grep -q '^15 runs of 15 in' "$dir/log.txt" || { tail -5 "$dir/log.txt"; fail "merge did not find 15 of 15 runs"; }
check_smoke_outputs "$dir"
say "the GNU parallel recipe took $(($(date +%s) - start)) s"
