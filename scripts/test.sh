#!/usr/bin/env bash
# The project's one test command: everything the tests need, then every test.
# Installs Debian's chromium + chromium-driver for the browser tests when
# missing, and runs the tests with a throw-away PostgreSQL cluster
# (scripts/with-postgres.sh, which installs Debian's postgresql when missing):
# first every test, then the HTTP suites again with the server on PostgreSQL.
# Arguments go to cargo test; a filter after `--` (`scripts/test.sh -- runs::`)
# means only the tests it matches, in both passes (on PostgreSQL the HTTP
# tests among them; scripts/test-both-engines.sh). Without one, every test.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -x scripts/install-browser.sh ]; then
  scripts/install-browser.sh
fi
exec scripts/with-postgres.sh scripts/test-both-engines.sh "$@"
