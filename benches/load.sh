#!/bin/sh
# Load measurement of `fieldbal serve` with wrk (Debian: apt-get install wrk).
# Starts a release build on a fresh SQLite file and measures
#   1. stateless solves:  POST /api/v1/solve   (two-plane pump example)
#   2. stored sessions:   POST /api/v1/sessions (the same session)
# Usage: benches/load.sh [duration, default 20s] [connections, default 32]
set -eu
cd "$(dirname "$0")/.."
DURATION=${1:-20s}
CONNS=${2:-32}
ADDR=127.0.0.1:${PORT:-18080}
WORK=$(mktemp -d)
trap 'kill "$PID" 2>/dev/null; wait "$PID" 2>/dev/null; rm -rf "$WORK"' EXIT

cargo build --release --quiet
python3 benches/bodies.py "$WORK"

RUST_LOG=${RUST_LOG:-info} ./target/release/fieldbal serve --listen "$ADDR" \
  --database "$WORK/load.db" >"$WORK/server.log" 2>&1 &
PID=$!
i=0
until curl -fsS "http://$ADDR/healthz" >/dev/null 2>&1; do
  i=$((i + 1)); [ "$i" -lt 100 ] || { cat "$WORK/server.log"; exit 1; }; sleep 0.1
done

echo "== stateless solves: POST /api/v1/solve, two-plane session ($(wc -c <"$WORK/solve.json") bytes)"
BODY_FILE="$WORK/solve.json" wrk -t2 -c"$CONNS" -d"$DURATION" --latency -s benches/post.lua \
  "http://$ADDR" -- /api/v1/solve 200
echo
echo "== stored sessions: POST /api/v1/sessions ($(wc -c <"$WORK/session.json") bytes)"
BODY_FILE="$WORK/session.json" wrk -t2 -c"$CONNS" -d"$DURATION" --latency -s benches/post.lua \
  "http://$ADDR" -- /api/v1/sessions 201
echo
echo "sessions stored: $(curl -fsS "http://$ADDR/api/v1/sessions?limit=1" | python3 -c 'import json,sys; print(json.load(sys.stdin)["total"])')"
echo "server log lines: $(wc -l <"$WORK/server.log"), errors: $(grep -c ERROR "$WORK/server.log" || true)"
