#!/bin/sh
# SPDX-License-Identifier: MIT
# Fetch Debian source packages into a directory, through a private source
# list: the system's apt configuration (sources, lists, cache) is not touched.
# Usage: scripts/deb_source.sh DIR PACKAGE...
#   DIR/apt/     the private sources.list, package lists and apt state
#   DIR/PACKAGE  a symlink to the unpacked source tree (DIR/PACKAGE-VERSION)
# Needs dpkg-dev (dpkg-source; scripts/deps.sh installs it).  The source list
# names the same mirror and suite as the system's binary packages, so the
# sources match the installed versions.
set -eu
dir=$1
shift
mkdir -p "$dir/apt/lists/partial" "$dir/apt/cache/archives/partial"
dir=$(cd "$dir" && pwd)
# the suite and mirror the system uses (Debian 12: bookworm, deb.debian.org)
. /etc/os-release
suite=${VERSION_CODENAME:-bookworm}
list="$dir/apt/sources.list"
printf 'deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian %s main\n' "$suite" >"$list"
# as root, apt would hand the downloads to its _apt user, who may not write
# here: keep them as root (no warning about an unsandboxed download)
sandbox=""
[ "$(id -u)" -eq 0 ] && sandbox="-o APT::Sandbox::User=root"
apt_private() {
    # shellcheck disable=SC2086
    apt-get -qq $sandbox -o Dir::Etc::SourceList="$list" -o Dir::Etc::SourceParts=/nonexistent \
        -o Dir::State::Lists="$dir/apt/lists" -o Dir::Cache="$dir/apt/cache" \
        -o Debug::NoLocking=1 "$@"
}
need=""
for pkg in "$@"; do [ -e "$dir/$pkg" ] || need="$need $pkg"; done
[ -z "$need" ] && exit 0
echo "deb_source: fetching$need (Debian sources, private list $list)" >&2
apt_private update >&2
for pkg in $need; do
    (cd "$dir" && apt_private source "$pkg" >&2)
    src=$(cd "$dir" && ls -d "$pkg"-[0-9]*/ 2>/dev/null | head -n 1)
    [ -n "$src" ] || { echo "deb_source: $pkg: no source tree unpacked" >&2; exit 1; }
    ln -sfn "${src%/}" "$dir/$pkg"
done
