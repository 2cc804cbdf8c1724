#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A fresh Debian in a directory (debootstrap --variant=minbase, the
# smallest system apt works on), for the two claims a new user relies on:
#
#   fresh-machine.sh [RELEASE] test          the committed source, copied in,
#                                            passes `packaging/dev.sh test` with
#                                            nothing but what dev.sh installs
#                                            from the list; the Debian package
#                                            of that build is then left in
#                                            $SLEW_FRESH_DIR/RELEASE/, for
#                                            `install` on the same release
#   fresh-machine.sh [RELEASE] install DEB   the package installs with apt-get
#                                            on a system without the build
#                                            dependencies, and both programs run
#
# RELEASE is bookworm (Debian 12, the default) or trixie (Debian 13).
# Needs root and Debian's package archive. Each release's base system is made
# once in $SLEW_FRESH_DIR/RELEASE (default /var/tmp/slew-fresh) and copied for
# each run, so every run starts from the same fresh system.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/.." && pwd)
release=bookworm
case ${1:-} in
bookworm|trixie) release=$1; shift ;;
esac
dir=${SLEW_FRESH_DIR:-/var/tmp/slew-fresh}/$release
[ "$(id -u)" -eq 0 ] || { echo "fresh-machine.sh needs root (debootstrap, chroot)"; exit 2; }

base=$dir/base
if [ ! -x "$base/usr/bin/apt-get" ]; then
    command -v debootstrap > /dev/null \
        || DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap
    # The archive this machine's apt uses.
    mirror=$(sed -nE 's/^URIs: *([^ ]+).*/\1/p' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -n 1)
    [ -n "$mirror" ] || mirror=$(awk '$1 == "deb" {print $2; exit}' /etc/apt/sources.list)
    rm -rf "$base"
    mkdir -p "$dir"
    debootstrap --variant=minbase "$release" "$base" "$mirror"
    # debootstrap writes only the release itself; the security archive and
    # the point updates are what an installed system has too.
    cat > "$base/etc/apt/sources.list" <<SOURCES
deb $mirror $release main
deb $mirror $release-updates main
deb ${mirror%/debian}/debian-security $release-security main
SOURCES
fi

run=$dir/run
cleanup() {
    for m in dev sys proc; do
        if mountpoint -q "$run/$m"; then umount -R "$run/$m" || umount -lR "$run/$m"; fi
    done
    rm -rf --one-file-system "$run"
}
trap cleanup EXIT
cleanup
cp -a "$base" "$run"
cp /etc/resolv.conf "$run/etc/resolv.conf" 2>/dev/null || true
# What the Debian installer writes on every installed system and
# debootstrap does not: without it "localhost" does not resolve, and the
# MQTT tests, whose broker's certificate names localhost, cannot connect.
[ -e "$run/etc/hosts" ] || printf '127.0.0.1\tlocalhost\n::1\t\tlocalhost ip6-localhost ip6-loopback\n' > "$run/etc/hosts"
# The host's /dev (with /dev/pts for the pseudo-terminal tests), as a
# slave so that nothing mounted or unmounted here reaches the host.
mount -t proc proc "$run/proc"
mount --rbind /sys "$run/sys" && mount --make-rslave "$run/sys"
mount --rbind /dev "$run/dev" && mount --make-rslave "$run/dev"
in_root() { chroot "$run" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 "$@"; }

case ${1:-} in
test)
    # The committed tree, as a clone has it.
    mkdir -p "$run/src"
    git -C "$top" archive HEAD | tar -x -C "$run/src"
    in_root bash -c 'cd /src && packaging/dev.sh test'
    # The package of the same build, as this release builds it.
    in_root bash -c 'cd /src && packaging/dev.sh package' | tail -n 1
    rm -f "$dir"/slew_*.deb
    cp "$run"/src/build/slew_*.deb "$dir/"
    echo "package: $(ls "$dir"/slew_*.deb)"
    ;;
install)
    deb=${2:?usage: fresh-machine.sh install DEB}
    cp "$deb" "$run/tmp/"
    in_root apt-get update -q
    in_root bash -c 'DEBIAN_FRONTEND=noninteractive apt-get install -y -q /tmp/'"$(basename "$deb")"
    in_root slew --version
    in_root slew-sim --help > /dev/null && echo "slew-sim --help: ok"
    echo "installed size: $(in_root dpkg-query -W -f='${Installed-Size}' slew) KiB"
    ;;
*)
    echo "usage: $0 [bookworm|trixie] test | install DEB" >&2
    exit 2
    ;;
esac
