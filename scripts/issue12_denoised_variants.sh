#!/usr/bin/env bash
# Issue 12, session 24 (amp24): the measurement of the de-noised all-rows
# conditioning of `amplitude_95` (docs/method.md §8, "Session 24, amp24";
# measured, not kept). Builds main with
# docs/experiments/issue12-denoised-conditioning.patch applied in a
# throw-away git worktree, then runs scripts/issue12_table.py's ten-speed
# cases (1,000 jobs, session 21's seeds; stated and samples) for the shipped
# bound and each variant, chosen by the patch's environment switches
# (AMP24B_SPLIT: session 24's second round, amp24b, the product term redone
# for the de-noised estimate; method §8 there). Not run
# by CI (NumPy; a release build, then about 10 minutes on a busy 2-core
# machine).
# Usage: scripts/issue12_denoised_variants.sh [jobs] [cases] > out.txt
set -euo pipefail
jobs=${1:-1000}
cases=${2:-4,5,6,7,8,9,10,11,16,17,18,19}
repo=$(git rev-parse --show-toplevel)
tmp=$(mktemp -d)
git -C "$repo" worktree add --detach "$tmp/wt" HEAD >/dev/null
trap 'git -C "$repo" worktree remove --force "$tmp/wt"; rm -rf "$tmp"' EXIT
git -C "$tmp/wt" apply "$repo/docs/experiments/issue12-denoised-conditioning.patch"
# The checkout's own target directory (warm); the patched binary is copied
# out, and the next build of the checkout replaces it.
(cd "$tmp/wt" && CARGO_TARGET_DIR="$repo/target" cargo build --release --locked >&2)
bin="$tmp/fieldbal"
cp "$repo/target/release/fieldbal" "$bin"
for variant in "AMP24_OLD=1" "AMP24_NONE=1" "AMP24_S0=1" "AMP24_S0=1 AMP24_VINV=1" "AMP24_VINV=1" "AMP24_ADDG=1" "AMP24_NOADD=1" \
  "AMP24B_SPLIT=1" "AMP24B_SPLIT=2" "AMP24B_SPLIT=2 AMP24_S0=1" "AMP24B_SPLIT=2 AMP24_VINV=1" \
  "AMP24B_SPLIT=2 AMP24_S0=1 AMP24_VINV=1" "AMP24B_SPLIT=4" "AMP24B_SPLIT=5" "AMP24B_SPLIT=6" "AMP24B_SPLIT=7"; do
  for mode in table samples; do
    echo "== $variant $mode"
    env $variant nice -n 10 python3 "$repo/scripts/issue12_table.py" "$bin" "$jobs" "$mode" "$cases"
  done
done
