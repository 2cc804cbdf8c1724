#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian package as a station gets it: built from BUILD_DIR with CPack,
# unpacked into a scratch root (dpkg -x, no maintainer scripts, nothing on
# this machine touched), and checked there: stripped binaries, the control
# fields, the service unit, the config example, the manual pages; then both
# programs run from the scratch root with LD_LIBRARY_PATH unset, so they can
# only use the system's libraries, as on a station without the build tree.
#
#   check-package.sh BUILD_DIR SYSTEMD_ANALYZE FILE
set -euo pipefail
usage="usage: check-package.sh BUILD_DIR SYSTEMD_ANALYZE FILE"
build=${1:?$usage}
analyze=${2:?$usage}
file_command=${3:?$usage}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work/out" > "$work/cpack.log" 2>&1 \
    || { cat "$work/cpack.log"; fail "cpack could not build the package"; }
deb=$(ls "$work"/out/slew_*.deb)
root=$work/root
dpkg-deb -x "$deb" "$root"
dpkg-deb -e "$deb" "$work/control"
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB; installed size $(du -sk "$root" | cut -f1) KiB"

# Stripped: no debug sections and no symbol table in either program.
for program in slew slew-sim slewctl; do
    binary=$root/usr/bin/$program
    [ -x "$binary" ] || fail "no /usr/bin/$program in the package"
    kind=$("$file_command" -b "$binary")
    grep -q ', stripped' <<<"$kind" || fail "file(1) says /usr/bin/$program is: $kind"
    sections=$(readelf -S --wide "$binary")
    if grep -qE '\.debug_|\.symtab' <<<"$sections"; then
        fail "/usr/bin/$program is not stripped"
    fi
    # Everything it links is a system library, found by the system's paths.
    # grep reads to the end (no -q): under pipefail, a grep that quits at
    # the first match can leave the writer dead of SIGPIPE, and the pipe
    # then counts as failed.
    if readelf -d "$binary" | grep -E 'RPATH|RUNPATH' > /dev/null; then
        fail "/usr/bin/$program carries a library search path: $(readelf -d "$binary" | grep -E 'RPATH|RUNPATH')"
    fi
done

# The control fields: the Qt libraries and libhamlib as dependencies, the licence.
fields=$work/control/control
grep -qE '^Depends:.*libqt6widgets6' "$fields" || fail "Depends lacks the Qt widgets library: $(grep ^Depends "$fields")"
grep -qE '^Depends:.*libqt6charts6' "$fields" || fail "Depends lacks Qt Charts"
grep -qE '^Depends:.*libqt6serialport6' "$fields" || fail "Depends lacks Qt SerialPort"
grep -qE '^Depends:.*libhamlib4' "$fields" || fail "Depends lacks libhamlib, which the in-process radio link uses"
grep -qE '^Depends:.*libqt6sql6-sqlite' "$fields" || fail "Depends lacks Qt's SQLite driver, which the pass records use"
grep -qE '^Depends:.*libmosquitto1' "$fields" || fail "Depends lacks libmosquitto, which remote operation uses"
grep -q 'License: GPL-3.0-or-later' "$fields" || fail "the description does not state the licence"
grep -q '^License: GPL-3.0+' "$root/usr/share/doc/slew/copyright" || fail "no copyright file with the licence"

# The station service, its settings and the manuals.
unit=$root/lib/systemd/system/slew-station@.service
[ -f "$unit" ] || fail "no slew-station@.service"
grep -qx 'ExecStart=/usr/bin/slew --headless --config /etc/slew/%i.conf' "$unit" || fail "unexpected ExecStart"
[ -f "$root/etc/slew/example.conf" ] || fail "no /etc/slew/example.conf"
grep -qx '/etc/slew/example.conf' "$work/control/conffiles" || fail "example.conf is not a conffile"
# The broker example ships as an example: nothing in /etc/mosquitto.
for example in slew.conf slew.acl; do
    [ -f "$root/usr/share/doc/slew/examples/mosquitto/$example" ] || fail "no broker example $example"
done
[ ! -e "$root/etc/mosquitto" ] || fail "the package enables a broker configuration"
for script in postinst prerm postrm; do
    [ -x "$work/control/$script" ] || fail "no $script"
done
for page in slew slew-sim slewctl; do
    man=$root/usr/share/man/man1/$page.1.gz
    [ -f "$man" ] || fail "no manual page $page(1)"
    zcat "$man" | grep '^\.TH' > /dev/null || fail "$page(1) is not a manual page"
done

# Both programs run from the scratch root on the system's libraries alone.
version=$(env -u LD_LIBRARY_PATH -u QT_PLUGIN_PATH -u DISPLAY "$root/usr/bin/slew" --version) \
    || fail "slew --version failed"
grep -qE '^slew [0-9]+\.[0-9]+\.[0-9]+$' <<<"$version" || fail "slew --version printed '$version'"
help=$(env -u LD_LIBRARY_PATH -u QT_PLUGIN_PATH -u DISPLAY "$root/usr/bin/slew-sim" --help) \
    || fail "slew-sim --help failed"
grep -q -- '--listen' <<<"$help" || fail "slew-sim --help does not list --listen"
position=$(env -u LD_LIBRARY_PATH -u DISPLAY "$root/usr/bin/slewctl" 'sim:?start_az=42&start_el=7' get) \
    || fail "slewctl sim: get failed"
[ "$position" = "az 42.00 el 7.00" ] || fail "slewctl sim: get printed '$position'"
# The station service's settings file is one the program accepts.
env -u LD_LIBRARY_PATH -u DISPLAY "$root/usr/bin/slew" --headless --config "$root/etc/slew/example.conf" --help \
    > /dev/null || fail "slew --headless refuses the example config"

# systemd reads the unit without a complaint. systemd-analyze checks paths
# on this machine, so the copy it reads has them moved into the scratch root.
cp "$root/etc/slew/example.conf" "$root/etc/slew/check.conf"
sed -e "s|/usr/bin/slew|$root/usr/bin/slew|" -e "s|/etc/slew/|$root/etc/slew/|g" "$unit" \
    > "$work/slew-station@check.service"
complaints=$(SYSTEMD_LOG_LEVEL=notice "$analyze" verify --man=no "$work/slew-station@check.service" 2>&1) || true
[ -z "$complaints" ] || fail "systemd-analyze verify: $complaints"
echo "$version, slew-sim and slewctl run from the unpacked package; unit, config, manuals and licence in place"
