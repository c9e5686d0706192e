#!/bin/sh
# Load figures of two builds of `fieldbal serve` side by side, in one sitting
# (issue 9: the v2 service must stay within 10 % of v1). Each round runs wrk
# against a fresh server of each binary in turn, so a busy machine slows both
# alike; the medians over the rounds are printed at the end.
#
#   benches/load-compare.sh OLD_BIN NEW_BIN [rounds, default 5] [duration, default 8s]
#
# A v1 binary: git worktree add /tmp/v1 eacb3bb && (cd /tmp/v1 && cargo build --release)
# Needs wrk (apt-get install wrk) and python3.
set -eu
cd "$(dirname "$0")/.."
OLD=$1; NEW=$2; ROUNDS=${3:-5}; DURATION=${4:-8s}
ADDR=127.0.0.1:${PORT:-18081}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
python3 benches/bodies.py "$WORK"

# One wrk run against a fresh server: prints requests/s.
run() { # BIN PATH BODY STATUS
  rm -f "$WORK"/load.db*
  if curl -fsS "http://$ADDR/healthz" >/dev/null 2>&1; then
    echo "something already answers on $ADDR: set PORT" >&2; exit 1
  fi
  RUST_LOG=${RUST_LOG:-info} "$1" serve --listen "$ADDR" --database "$WORK/load.db" \
    >"$WORK/server.log" 2>&1 &
  pid=$!
  i=0
  until curl -fsS "http://$ADDR/healthz" >/dev/null 2>&1; do
    i=$((i + 1)); [ "$i" -lt 100 ] || { cat "$WORK/server.log"; kill "$pid"; exit 1; }; sleep 0.1
  done
  BODY_FILE="$3" wrk -t2 -c32 -d"$DURATION" -s benches/post.lua "http://$ADDR" -- "$2" "$4" \
    | awk '/Requests\/sec/ {print $2} /unexpected/ {print "ERRORS: " $0 > "/dev/stderr"}'
  kill "$pid"; wait "$pid" 2>/dev/null || true
}

for load in solve store; do
  case $load in
    solve) path=/api/v1/solve; body=$WORK/solve.json; status=200 ;;
    store) path=/api/v1/sessions; body=$WORK/session.json; status=201 ;;
  esac
  r=1
  while [ "$r" -le "$ROUNDS" ]; do
    old=$(run "$OLD" $path "$body" $status)
    new=$(run "$NEW" $path "$body" $status)
    echo "$load round $r: old $old/s new $new/s (load average $(cut -d' ' -f1 /proc/loadavg))"
    echo "$load old $old" >>"$WORK/all"; echo "$load new $new" >>"$WORK/all"
    r=$((r + 1))
  done
done
python3 - "$WORK/all" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
for load in ("solve", "store"):
    old = statistics.median(float(v) for l, w, v in rows if l == load and w == "old")
    new = statistics.median(float(v) for l, w, v in rows if l == load and w == "new")
    print(f"{load}: median old {old:,.0f}/s, new {new:,.0f}/s, new/old {new / old:.2f}")
PY
