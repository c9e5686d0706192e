#!/bin/sh
# Instructions per request of `fieldbal serve`, counted by callgrind: unlike
# requests per second, the count does not depend on what else the machine is
# doing, so two builds compare exactly (issue 9).
#
#   benches/request-cost.sh BIN [solve|store] [requests, default 300]
#
# Runs the server under valgrind twice (no requests, then N requests on one
# kept-alive connection) and prints the difference per request. Needs valgrind
# and python3.
set -eu
cd "$(dirname "$0")/.."
BIN=$1; LOAD=${2:-solve}; N=${3:-300}
PORT=${PORT:-18082}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
python3 benches/bodies.py "$WORK"
case $LOAD in
  solve) path=/api/v1/solve; body=solve.json ;;
  store) path=/api/v1/sessions; body=session.json ;;
esac

count() { # requests -> total instructions of the server's life
  rm -f "$WORK"/db.sqlite*
  if curl -fsS "http://127.0.0.1:$PORT/healthz" >/dev/null 2>&1; then
    echo "something already answers on port $PORT: set PORT" >&2; exit 1
  fi
  valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.out" "$BIN" serve \
    --listen "127.0.0.1:$PORT" --database "$WORK/db.sqlite" >"$WORK/log" 2>&1 &
  pid=$!
  i=0
  until curl -fsS "http://127.0.0.1:$PORT/healthz" >/dev/null 2>&1; do
    i=$((i + 1)); [ "$i" -lt 600 ] || { cat "$WORK/log"; kill "$pid"; exit 1; }; sleep 0.2
  done
  python3 - "$PORT" "$path" "$WORK/$body" "$1" <<'PY'
import http.client, sys
port, path, body, n = sys.argv[1], sys.argv[2], open(sys.argv[3], "rb").read(), int(sys.argv[4])
c = http.client.HTTPConnection("127.0.0.1", int(port))
for _ in range(n):
    c.request("POST", path, body=body, headers={"Content-Type": "application/json"})
    r = c.getresponse(); r.read()
    assert r.status in (200, 201), r.status
PY
  kill -INT "$pid"; wait "$pid" 2>/dev/null || true
  awk '/^totals:/ {print $2}' "$WORK/cg.out"
}
base=$(count 0)
total=$(count "$N")
echo "$LOAD: $(( (total - base) / N )) instructions per request ($N requests, $BIN)"
