# Shared by the cluster recipe tests (parallel.sh, slurm.sh): the recipes are read from
# docs/campaigns.md, where each sits in the fenced block after a `<!-- recipe: NAME ... -->`
# line, and run on a copy of campaigns/smoke.toml in an empty folder.

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
export PATH="$repo/target/release:$HOME/.cargo/bin:$PATH"

fail() { printf '%s: FAIL: %s\n' "$(basename "$0")" "$*" >&2; exit 1; }
say() { printf '%s: %s\n' "$(basename "$0")" "$*"; }

# The block named $1 in docs/campaigns.md, with its `campaign=` line pointing at $2.
recipe() {
  local text
  text=$(awk -v name="$1" '
    index($0, "<!-- recipe: " name " ") == 1 { found = 1; next }
    found && /^```/ { if (inside) exit; inside = 1; next }
    inside { print }' "$repo/docs/campaigns.md" || true)
  [ -n "$text" ] || fail "no recipe '$1' in docs/campaigns.md"
  printf '%s\n' "$text" | sed "s|^campaign=.*|campaign=$2|"
}

# A fresh empty folder holding only campaigns/smoke.toml; prints its path.
bare_folder() {
  local dir
  dir=$(mktemp -d "${TMPDIR:-/tmp}/vsr-$1.XXXXXX")
  mkdir "$dir/campaigns"
  cp "$repo/campaigns/smoke.toml" "$dir/campaigns/smoke.toml"
  printf '%s\n' "$dir"
}

# The smoke campaign's outputs in $1/campaigns/smoke-out: every run, validation and
# ablation, a CSV with a row per run, a report whose every figure exists.
check_smoke_outputs() {
  local out=$1/campaigns/smoke-out count figures
  for pair in runs:15 validation:30 ablation:6; do
    count=$(find "$out/${pair%%:*}" -maxdepth 1 -name '*.json' 2>/dev/null | wc -l)
    [ "$count" -eq "${pair#*:}" ] || fail "$count files in ${pair%%:*}/, expected ${pair#*:}"
  done
  count=$(($(wc -l < "$out/campaign.csv") - 1))
  [ "$count" -eq 15 ] || fail "campaign.csv has $count rows, expected 15"
  [ -s "$out/report/report.md" ] || fail "no report.md"
  figures=$(grep -o '[A-Za-z0-9_.-]*\.svg' "$out/report/report.md" | sort -u)
  [ -n "$figures" ] || fail "report.md shows no figure"
  for figure in $figures; do
    grep -q '<svg' "$out/report/$figure" 2>/dev/null || fail "figure $figure missing or not SVG"
  done
  say "ok: 15 runs, 30 validations, 6 ablations, 15 CSV rows, $(echo "$figures" | wc -l) figures"
}
