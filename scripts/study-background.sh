#!/usr/bin/env bash
# Runs a campaign in the background of a working session and commits its outputs as they
# finish, on the branch `study-NAME` (NAME: the campaign file's name) in a separate worktree
# (../study-NAME), so that the main tree stays free for building and testing. Resumable: run
# it again after a stop (merge the branch into main first, so the new worktree starts with
# what was done) and the campaign skips what exists and continues each run from its
# checkpoint (docs/campaigns.md).
#
#   scripts/study-background.sh campaigns/noninferiority.toml [--jobs 2]
#
# The `vsr` binary is built from the worktree's clean commit, in its own target folder
# (../target-study), so a rebuild of the main tree never changes the program of the runs in
# flight and the run files name a clean code version; merge `study-NAME` into main to land
# the results.
set -euo pipefail
cd "$(dirname "$0")/.."
campaign="$1"; shift
root="$(pwd)"
# nice alone does not yield to other sessions' work where the kernel groups processes by
# session (autogroup): lower this session's group too, best effort.
echo 19 > /proc/self/autogroup 2>/dev/null || true
label="$(basename "$campaign" .toml)"
wt="$root/../study-$label"
bin="$root/../study-bin-$label"

git show-ref --quiet "refs/heads/study-$label" || git branch "study-$label"
[ -d "$wt" ] || git worktree add -q "$wt" "study-$label"
mkdir -p "$bin"
( cd "$wt" && CARGO_TARGET_DIR="$root/../target-study" nice cargo build -q --release --bin vsr )
cp "$root/../target-study/release/vsr" "$bin/vsr"

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
  # How far it has come, in this script's log (a binary older than `campaign status` says nothing).
  ( cd "$wt" && date -u +%H:%M && "$bin/vsr" campaign status "$campaign" 2>/dev/null ) || true
done
wait "$runner" || echo "study-background: the campaign stopped with an error (see $wt/study/logs)" >&2
commit
