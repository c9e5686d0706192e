#!/usr/bin/env bash
# Run by scripts/test.sh inside a PostgreSQL cluster (FIELDBAL_TEST_POSTGRES_URL):
# every test (SQLite, and the replica tests on PostgreSQL), then the suites
# that go through HTTP once more with each test server on a PostgreSQL
# database of its own (FIELDBAL_TEST_ENGINE=postgres, tests/common/engine.rs).
set -euo pipefail
cd "$(dirname "$0")/.."
: "${FIELDBAL_TEST_POSTGRES_URL:?run through scripts/test.sh or scripts/with-postgres.sh}"
cargo test --locked --all-targets "$@"
# Compiled above; this only runs them again. Browser tests stay on SQLite.
http_suites=()
for f in tests/api_*.rs tests/job_*.rs tests/hardening_writes.rs tests/edge_access.rs \
         tests/fit_http.rs tests/identification_api.rs tests/residual_unbalance_api.rs; do
  [ -e "$f" ] && http_suites+=(--test "$(basename "$f" .rs)")
done
FIELDBAL_TEST_ENGINE=postgres cargo test --locked "${http_suites[@]}" "$@"
