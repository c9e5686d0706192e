#!/usr/bin/env bash
# Record the old code's answers for tests/perf_equivalence.rs (issue 15).
#
#   tests/data/perf/record_old_answers.sh OLD_FIELDBAL [REV]
#
# OLD_FIELDBAL: the release `fieldbal` binary of the code before issue 15
# (commit 5e3a66a, built in a throw-away worktree); REV names it in the file.
# The test writes its seeded jobs as files, the old binary solves each, and
# only what the test compares is kept (corrections, predicted residual
# amplitudes, warning codes), so the file stays a few tens of kB.
set -euo pipefail
old=${1:?usage: $0 OLD_FIELDBAL [REV]}
rev=${2:-5e3a66a}
cd "$(dirname "$0")/../../.."
jobs=$(mktemp -d)
trap 'rm -rf "$jobs"' EXIT
FIELDBAL_PERF_JOBS_DIR=$jobs cargo test --test perf_equivalence \
    the_jobs_written_for_the_old_binary_parse_back_to_the_same_sessions -- --exact
mkdir "$jobs/out"
for f in "$jobs"/*.json; do
    "$old" solve "$f" > "$jobs/out/$(basename "$f")"
done
python3 - "$jobs" "$rev" > tests/data/perf/old_answers.json <<'PY'
import json, os, sys
jobs, rev = sys.argv[1], sys.argv[2]
out = {}
for f in sorted(os.listdir(jobs)):
    if not f.endswith(".json"):
        continue
    job = json.load(open(os.path.join(jobs, f)))
    s = json.load(open(os.path.join(jobs, "out", f)))
    out[f[:-5]] = {
        "name": job["session"]["name"],
        "corrections": [{"plane": c["plane"], "mass_g": c["mass_g"], "angle_deg": c["angle_deg"]}
                        for c in s["corrections"]],
        "predicted_residual": [{"amplitude": r["amplitude"]} for r in s["predicted_residual"]],
        "warnings": sorted({w["code"] for w in s.get("warnings", [])}),
    }
json.dump({"recorded_by": f"fieldbal solve of commit {rev} (release), record_old_answers.sh",
           "jobs": out}, sys.stdout, separators=(",", ":"))
print()
PY
echo "wrote tests/data/perf/old_answers.json ($(wc -c < tests/data/perf/old_answers.json) bytes)"
