#!/usr/bin/env bash
# Run by scripts/test.sh inside a PostgreSQL cluster (FIELDBAL_TEST_POSTGRES_URL):
# every test (SQLite, and the replica tests on PostgreSQL), then the tests
# that go through HTTP once more with each test server on a PostgreSQL
# database of its own (FIELDBAL_TEST_ENGINE=postgres, tests/common/engine.rs).
set -euo pipefail
cd "$(dirname "$0")/.."
: "${FIELDBAL_TEST_POSTGRES_URL:?run through scripts/test.sh or scripts/with-postgres.sh}"
cargo test --locked --all-targets "$@"
# Compiled above; this only runs them again. Browser tests stay on SQLite.
# Arguments before `--` go to cargo, those after it to the test binaries.
cargo_args=()
test_args=()
seen=0
for a in "$@"; do
  if [ "$seen" = 0 ] && [ "$a" = -- ]; then
    seen=1
  elif [ "$seen" = 0 ]; then
    cargo_args+=("$a")
  else
    test_args+=("$a")
  fi
done
on_postgres() {
  FIELDBAL_TEST_ENGINE=postgres cargo test --locked "$@"
}
# Binaries whose every module goes through HTTP: whole.
on_postgres --test api --test job "${cargo_args[@]}" -- "${test_args[@]}"
# Elsewhere the modules that go through HTTP, by name (module paths).
on_postgres --test hardening "${cargo_args[@]}" -- writes:: "${test_args[@]}"
on_postgres --test edge "${cargo_args[@]}" -- access:: "${test_args[@]}"
on_postgres --test fit "${cargo_args[@]}" -- http:: "${test_args[@]}"
on_postgres --test identification --test residual "${cargo_args[@]}" -- api:: "${test_args[@]}"
