#!/usr/bin/env bash
# Criterion medians of the old and the new code in one sitting (issue 15):
# every benchmark of benches/solve.rs and benches/conic.rs is run on the old
# build, then the new, then again new, then old (ABBA), so that a machine
# getting busier or quieter moves both alike; the table gives the mean of
# each side's two criterion medians and their ratio.
#
#   benches/before-after.sh OLD_REV          # e.g. 5e3a66a
#
# The old revision is checked out in a throw-away worktree under /tmp and built
# into this checkout's target/ (its Cargo.lock replaced by this one, so the
# dependencies are the same builds); the worktree is removed at the end.
# OLD_SOLVE / OLD_CONIC / NEW_SOLVE / NEW_CONIC (bench executables) skip the builds.
set -euo pipefail
rev=${1:?usage: $0 OLD_REV}
cd "$(dirname "$0")/.."
root=$PWD
out=$(mktemp -d)
executables() { # crate dir → "solve-path conic-path" from cargo's --no-run output
    (cd "$1" && CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$root/target}" cargo bench --no-run --bench solve --bench conic 2>&1) |
        sed -n 's/.*Executable benches\/\(solve\|conic\)\.rs (\(.*\))/\1 \2/p'
}
if [ -z "${OLD_SOLVE:-}" ]; then
    wt=/tmp/before-after-$rev
    git worktree add --detach "$wt" "$rev" >/dev/null
    trap 'git worktree remove --force "$wt"; rm -rf "$out"' EXIT
    cp Cargo.lock "$wt/Cargo.lock"
    while read -r name path; do
        cp "$path" "$out/$name-old"
    done < <(executables "$wt")
    OLD_SOLVE=$out/solve-old OLD_CONIC=$out/conic-old
else
    trap 'rm -rf "$out"' EXIT
fi
if [ -z "${NEW_SOLVE:-}" ]; then
    while read -r name path; do
        cp "$path" "$out/$name-new"
    done < <(executables "$root")
    NEW_SOLVE=$out/solve-new NEW_CONIC=$out/conic-new
fi

solve_ids=(
    "solve two planes, 4 sensors, 1 speed"
    "solve two planes, 4 sensors, 1 speed, stated noise"
    "large/solve 16 planes, 32 sensors, 40 speeds"
    "large/validate 16 planes, 32 sensors, 40 speeds"
    "limits/solve 64 planes, 256 sensors, 3 speeds"
    "limits/solve 267 planes, 267 sensors, 1 speed"
)
conic_ids=(
    "min_max 11x4" "bounded_least_squares 11x4" "bounded_min_max 11x4"
    "balancing::solve min_max 11x4 session"
    "min_max 1000x16" "bounded_least_squares 1000x16" "bounded_min_max 1000x16"
)
run() { # side executable id → the median line of criterion's output
    CRITERION_HOME="$out/criterion-$1" "$2" --bench --exact "$3" \
        --warm-up-time 1 --measurement-time 3 2>/dev/null |
        awk -v side="$1" -v id="$3" '/time:/ {
            match($0, /\[[^]]*\]/); split(substr($0, RSTART + 1, RLENGTH - 2), f, " ")
            print side "\t" id "\t" f[3] " " f[4] }'
}
for id in "${solve_ids[@]}" "${conic_ids[@]}"; do
    case " ${solve_ids[*]} " in
        *" $id "*) old=$OLD_SOLVE new=$NEW_SOLVE ;;
        *) old=$OLD_CONIC new=$NEW_CONIC ;;
    esac
    for side in old new new old; do
        exe=$old
        [ "$side" = new ] && exe=$new
        run "$side" "$exe" "$id" | tee -a "$out/medians.tsv"
    done
done
python3 - "$out/medians.tsv" <<'PY'
import sys
unit = {"ns": 1e-9, "µs": 1e-6, "us": 1e-6, "ms": 1e-3, "s": 1.0}
runs = {}
for line in open(sys.argv[1]):
    side, id_, t = line.rstrip("\n").split("\t")
    value, u = t.split()
    runs.setdefault(id_, {}).setdefault(side, []).append(float(value) * unit[u])
def fmt(s):
    for u, f in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if s >= f:
            return f"{s / f:.3g} {u}"
    return f"{s / 1e-9:.3g} ns"
print("| benchmark | old | new | old / new |\n| --- | --- | --- | --- |")
for id_, r in runs.items():
    old, new = (sum(r[k]) / len(r[k]) for k in ("old", "new"))
    print(f"| {id_} | {fmt(old)} | {fmt(new)} | {old / new:.1f}× |")
PY
