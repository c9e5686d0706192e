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
# A filter after `--` (`scripts/test.sh -- runs::`) means only those tests,
# in both passes: on PostgreSQL the HTTP tests among them. With none (CI)
# both passes run as they always did.
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
# The test arguments split into flags and filters: a filter is a word that
# is neither a flag nor a flag's value.
flags=()
filters=()
value_of=""
for a in ${test_args[@]+"${test_args[@]}"}; do
  if [ -n "$value_of" ]; then
    flags+=("$a")
    value_of=""
  else
    case "$a" in
      --skip | --test-threads | --color | --format | --logfile | --shuffle-seed | -Z)
        flags+=("$a")
        value_of=1
        ;;
      -*) flags+=("$a") ;;
      *) filters+=("$a") ;;
    esac
  fi
done
# Binaries whose every module goes through HTTP: whole (the user's filters,
# if any, choose among their tests as in the first pass).
on_postgres --test api --test job ${cargo_args[@]+"${cargo_args[@]}"} -- ${test_args[@]+"${test_args[@]}"}
# Elsewhere the modules that go through HTTP, by name (module paths). Without
# a filter (CI) those are the filters. libtest runs a test matching any one
# filter, so with the user's filters the tests are listed first and only
# those matching both, one of the user's filters and one of the modules,
# are run, by exact name (none: that binary is skipped).
in_modules() { # in_modules BINARIES... -- MODULES...
  local bins=() mods=() names=() what=""
  while [ "$1" != -- ]; do bins+=(--test "$1"); what+="$1 "; shift; done
  shift
  mods=("$@")
  what+="in ${mods[*]}"
  if [ ${#filters[@]} = 0 ]; then
    on_postgres "${bins[@]}" ${cargo_args[@]+"${cargo_args[@]}"} -- "${mods[@]}" ${test_args[@]+"${test_args[@]}"}
    return
  fi
  # The user's arguments choose from the list as from a run (--exact,
  # --ignored, --skip included); a name is kept when a module's filter
  # matches it as libtest would (a substring).
  local listed name mod
  listed="$(cargo test --locked "${bins[@]}" ${cargo_args[@]+"${cargo_args[@]}"} -q -- --list ${test_args[@]+"${test_args[@]}"})"
  while IFS= read -r name; do
    for mod in "${mods[@]}"; do
      case "$name" in *"$mod"*) names+=("$name"); break ;; esac
    done
  done < <(sed -n 's/: test$//p' <<<"$listed")
  if [ ${#names[@]} = 0 ]; then
    echo "test-both-engines: no test of $what matches ${filters[*]}; none run on PostgreSQL"
    return
  fi
  local kept=() f
  for f in ${flags[@]+"${flags[@]}"}; do
    [ "$f" = --exact ] || kept+=("$f")
  done
  on_postgres "${bins[@]}" ${cargo_args[@]+"${cargo_args[@]}"} -- --exact "${names[@]}" ${kept[@]+"${kept[@]}"}
}
in_modules hardening -- writes::
in_modules edge -- access::
in_modules fit -- http::
in_modules identification residual -- api::
