#!/bin/sh
# Install the headless browser the end-to-end tests drive (Debian's chromium and
# chromium-driver). Idempotent: does nothing when both binaries are present.
# Works as root without sudo, and through sudo for an ordinary user.
set -eu

if [ -x /usr/bin/chromium ] && [ -x /usr/bin/chromedriver ]; then
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    as_root=""
elif command -v sudo >/dev/null 2>&1; then
    as_root="sudo"
else
    echo "install-browser.sh: need root or sudo to install chromium and chromium-driver" >&2
    exit 1
fi

export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update
$as_root apt-get install -y --no-install-recommends chromium chromium-driver

if [ ! -x /usr/bin/chromium ] || [ ! -x /usr/bin/chromedriver ]; then
    echo "install-browser.sh: chromium or chromedriver still missing after apt-get install" >&2
    exit 1
fi
