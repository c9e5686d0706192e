#!/usr/bin/env bash
# Issue 14: the same load as benches/load.sh (same bodies, benches/post.lua,
# wrk) on SQLite, on PostgreSQL with one replica, and on PostgreSQL with two
# replicas behind nginx (deploy/nginx.conf with its upstreams pointed at local
# ports), in one sitting. Needs a release binary (FIELDBAL_BIN, default
# target/release/fieldbal), wrk, nginx, python3, and runs inside
# scripts/with-postgres.sh (FIELDBAL_PG_DURABLE=1 keeps fsync on, as SQLite's
# synchronous=FULL does):
#   FIELDBAL_PG_DURABLE=1 scripts/with-postgres.sh benches/load-replicas.sh 15s 32
set -euo pipefail
cd "$(dirname "$0")/.."
DURATION=${1:-15s}
CONNS=${2:-32}
BIN=${FIELDBAL_BIN:-target/release/fieldbal}
: "${FIELDBAL_TEST_POSTGRES_URL:?run inside scripts/with-postgres.sh}"
WORK=$(mktemp -d)
PIDS=()
cleanup() {
  for p in "${PIDS[@]}"; do kill "$p" 2>/dev/null || true; wait "$p" 2>/dev/null || true; done
  rm -rf "$WORK"
}
trap cleanup EXIT

python3 - "$WORK" <<'PY'
import json, sys
ex = json.load(open("tests/data/examples/pump-two-plane-exact.json"))
json.dump({"session": ex["session"], "options": ex["options"]}, open(sys.argv[1] + "/solve.json", "w"))
json.dump(ex["session"], open(sys.argv[1] + "/session.json", "w"))
PY

serve() { # port database
  RUST_LOG=warn "$BIN" serve --listen "127.0.0.1:$1" --database "$2" >>"$WORK/server.log" 2>&1 &
  PIDS+=($!)
  for _ in $(seq 100); do curl -fsS "http://127.0.0.1:$1/healthz" >/dev/null 2>&1 && return; sleep 0.1; done
  cat "$WORK/server.log"; exit 1
}
database() { # name -> URL of a new database on the cluster
  local url="${FIELDBAL_TEST_POSTGRES_URL%/*}/$1"
  psql -q -d "$FIELDBAL_TEST_POSTGRES_URL" -c "CREATE DATABASE $1" >/dev/null
  echo "$url"
}
measure() { # label url
  for what in "solves /api/v1/solve 200 solve.json" "sessions /api/v1/sessions 201 session.json"; do
    set -- "$1" "$2" $what
    local rate
    rate=$(BODY_FILE="$WORK/$6" wrk -t2 -c"$CONNS" -d"$DURATION" -s benches/post.lua "$2" -- "$4" "$5" \
      | awk '/Requests\/sec/ {print $2}')
    printf '%-28s %-9s %10s /s\n' "$1" "$3" "$rate"
  done
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores"
serve 18181 "$WORK/load.db"
measure "sqlite, 1 process" http://127.0.0.1:18181
kill "${PIDS[0]}"; wait "${PIDS[0]}" 2>/dev/null || true; PIDS=()

db1=$(database fieldbal_bench_one)
serve 18182 "$db1"
measure "postgres, 1 replica" http://127.0.0.1:18182
kill "${PIDS[0]}"; wait "${PIDS[0]}" 2>/dev/null || true; PIDS=()

db2=$(database fieldbal_bench_two)
serve 18183 "$db2"
serve 18184 "$db2"
sed -e 's/replica-a:8080/127.0.0.1:18183/; s/replica-b:8080/127.0.0.1:18184/' \
    -e 's/listen 8080;/listen 127.0.0.1:18185;/' -e "s#pid /tmp/nginx.pid;#pid $WORK/nginx.pid;#" \
    -e "s#^http {#http {\n    client_body_temp_path $WORK; proxy_temp_path $WORK;#" \
    deploy/nginx.conf >"$WORK/nginx.conf"
nginx -c "$WORK/nginx.conf" -e "$WORK/nginx.err" -g 'daemon off; error_log stderr warn;' 2>>"$WORK/server.log" &
PIDS+=($!)
sleep 0.5
measure "postgres, 2 replicas+nginx" http://127.0.0.1:18185
# The same two replicas without the proxy: one wrk per replica, at once, half the connections each.
for what in "solves /api/v1/solve 200 solve.json" "sessions /api/v1/sessions 201 session.json"; do
  set -- $what
  both=()
  for port in 18183 18184; do
    BODY_FILE="$WORK/$4" wrk -t1 -c$((CONNS / 2)) -d"$DURATION" -s benches/post.lua "http://127.0.0.1:$port" -- "$2" "$3" \
      | awk '/Requests\/sec/ {print $2}' >"$WORK/rate.$port" &
    both+=($!)
  done
  wait "${both[@]}"
  printf '%-28s %-9s %10s /s\n' "postgres, 2 replicas direct" "$1" "$(cat "$WORK"/rate.1818[34] | awk '{s += $1} END {print s}')"
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "server errors logged: $(grep -c ERROR "$WORK/server.log" || true)"
