#!/usr/bin/env bash
# Runs a campaign in the background of a working session and commits its outputs as they
# finish, on the `study` branch in a separate worktree (../study-wt), so that the main tree
# stays free for building and testing. Resumable: run it again after a stop and the campaign
# skips what exists and continues each run from its checkpoint (docs/campaigns.md).
#
#   scripts/study-background.sh campaigns/noninferiority.toml [--jobs 2]
#
# It copies the `vsr` binary built in this tree (target/release/vsr) beside the worktree, so a
# rebuild here never changes the program of the runs in flight; merge `study` into main to
# land the results (`git merge study`).
set -euo pipefail
cd "$(dirname "$0")/.."
campaign="$1"; shift
root="$(pwd)"
wt="$root/../study-wt"
bin="$root/../study-bin"
label="$(basename "$campaign" .toml)"

git show-ref --quiet refs/heads/study || git branch study
[ -d "$wt" ] || git worktree add -q "$wt" study
mkdir -p "$bin"
cp target/release/vsr "$bin/vsr"

commit() {
  cd "$wt"
  git add -A study >/dev/null 2>&1 || true
  if ! git diff --cached --quiet; then
    done_runs=$(git diff --cached --name-only --diff-filter=A -- 'study/runs/*.json' \
      | xargs -r -n1 basename | sed 's/\.json$//' | tr '\n' ' ')
    git commit -q -m "study ($label): ${done_runs:-checkpoints of the runs in flight}"
  fi
  cd "$root"
}

( cd "$wt" && nice -n 19 "$bin/vsr" campaign run "$campaign" "$@" ) &
runner=$!
while kill -0 "$runner" 2>/dev/null; do
  sleep 600
  commit
done
wait "$runner" || echo "study-background: the campaign stopped with an error (see $wt/study/logs)" >&2
commit
