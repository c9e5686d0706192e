#!/usr/bin/env bash
# The project's one test command: everything the tests need, then every test.
# Installs Debian's chromium + chromium-driver for the browser tests when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -x scripts/install-browser.sh ]; then
  scripts/install-browser.sh
fi
cargo test --locked --all-targets "$@"
