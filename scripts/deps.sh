#!/bin/sh
# SPDX-License-Identifier: MIT
# Install the Debian packages a make target needs, only those missing.
# Usage: scripts/deps.sh PACKAGE...   (as root, or with sudo available)
set -eu
missing=""
for pkg in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $pkg"
    fi
done
[ -z "$missing" ] && exit 0
echo "deps: installing$missing" >&2
if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "deps: need root or sudo to install:$missing" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
# `make -j` may run several of these at once; apt allows one at a time, so
# wait for the others (flock), and give dpkg's own lock time as well.
lock=/tmp/collide2d-deps.lock
run_apt() {
    # A fresh machine has no package lists yet; refresh once, then install.
    $SUDO apt-get update -qq >&2 || true
    # shellcheck disable=SC2086
    $SUDO apt-get install -y -qq --no-install-recommends -o DPkg::Lock::Timeout=600 $missing >&2
}
if command -v flock >/dev/null 2>&1; then
    exec 9>"$lock"
    flock 9
fi
run_apt
