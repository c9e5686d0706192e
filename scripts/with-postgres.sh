#!/usr/bin/env bash
# Run a command with a throw-away PostgreSQL cluster: installs Debian's
# `postgresql` when missing, initdb's a cluster in a temporary directory (as
# the non-root user `postgres` when run as root, since initdb refuses root),
# starts it on a free loopback port with its socket in that directory,
# exports FIELDBAL_TEST_POSTGRES_URL, runs "$@", and stops and removes the
# cluster on exit, whatever happens.
#   scripts/with-postgres.sh cargo test --test hardening replicas_postgres::
# FIELDBAL_PG_DURABLE=1 keeps fsync on (benchmarks); tests run without it.
set -euo pipefail

pg_bin() { ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1; }
if [ -z "$(pg_bin)" ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends postgresql >/dev/null
fi
bin="$(pg_bin)"

tmp="$(mktemp -d /tmp/fieldbal-pg.XXXXXX)"
as_owner=()
if [ "$(id -u)" -eq 0 ]; then
  id -u postgres >/dev/null 2>&1 || useradd --system --no-create-home --shell /usr/sbin/nologin postgres
  chown postgres "$tmp"
  as_owner=(runuser -u postgres --)
fi
stop() {
  "${as_owner[@]}" "$bin/pg_ctl" -D "$tmp/data" -m immediate stop >/dev/null 2>&1 || true
  rm -rf "$tmp"
}
trap stop EXIT
trap 'exit 130' INT TERM

"${as_owner[@]}" "$bin/initdb" -D "$tmp/data" -U fieldbal --auth=trust -E UTF8 --no-sync >"$tmp/initdb.log" 2>&1 \
  || { cat "$tmp/initdb.log"; exit 1; }
durable=(-c fsync=off -c synchronous_commit=off -c full_page_writes=off)
[ "${FIELDBAL_PG_DURABLE:-0}" = 1 ] && durable=()
started=""
for _ in 1 2 3 4 5 6 7 8 9 10; do
  port=$((20000 + RANDOM % 30000))
  # Free if nothing answers there.
  if (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then continue; fi
  if "${as_owner[@]}" "$bin/pg_ctl" -D "$tmp/data" -l "$tmp/server.log" -w -t 60 \
      -o "-p $port -c listen_addresses=127.0.0.1 -k $tmp -c max_connections=400 ${durable[*]}" \
      start >/dev/null; then
    started=1
    break
  fi
done
[ -n "$started" ] || { cat "$tmp/server.log"; echo "PostgreSQL did not start" >&2; exit 1; }

export FIELDBAL_TEST_POSTGRES_URL="postgres://fieldbal@127.0.0.1:$port/postgres"
"$@"
