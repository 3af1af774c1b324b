#!/usr/bin/env bash
# The Slurm recipe of docs/campaigns.md, as written, on a real single-node Slurm
# (scripts/slurm-local.sh: Debian slurm-wlm and munge, daemons started by hand), on
# campaigns/smoke.toml copied into an empty folder: campaign.sbatch, three dependent job
# arrays and a merge-and-report job; then the outputs are counted, and the daemons stopped.
# `make test-cluster` runs it; needs root (or sudo) to install and start the daemons.
set -euo pipefail
source "$(dirname "$0")/lib.sh"

(cd "$repo" && nice cargo build --release --bin vsr --quiet)
state=$(mktemp -d "${TMPDIR:-/tmp}/vsr-slurm.XXXXXX")
export VSR_SLURM_STATE=$state SLURM_CONF=$state/slurm.conf
dir=$(bare_folder slurm)
trap '"$repo/scripts/slurm-local.sh" stop; rm -rf "$dir" "$state"' EXIT
"$repo/scripts/slurm-local.sh" start

recipe campaign.sbatch campaigns/smoke.toml > "$dir/campaign.sbatch"
recipe slurm campaigns/smoke.toml > "$dir/submit.sh"
start=$(date +%s)
(cd "$dir" && bash -euo pipefail submit.sh) || fail "submitting failed"
say "submitted: $(squeue -h | wc -l) jobs and arrays in the queue"
while [ -n "$(squeue -h)" ]; do
  [ $(($(date +%s) - start)) -lt 900 ] || { squeue; fail "jobs still queued after 900 s"; }
  sleep 1
done
took=$(($(date +%s) - start))
tasks=$(find "$dir/slurm-logs" -name '*_*.out' | wc -l)
[ "$tasks" -eq 51 ] || fail "$tasks array task logs, expected 51"
grep -q '^15 runs of 15 in' "$dir"/slurm-logs/report-*.out \
  || { cat "$dir"/slurm-logs/report-*.out; fail "merge did not find 15 of 15 runs"; }
check_smoke_outputs "$dir"
say "the Slurm recipe took $took s from submission to report ($tasks array tasks)"
