#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Would packaging/debian-packages.txt, installed on a fresh Debian 12 with
# --no-install-recommends, bring every system file this build used?
#
#   check-fresh-deps.sh SOURCE_DIR BUILD_DIR
#
# The files: the headers the compiler read (ninja's deps log, or with the
# Makefile generator the compiler's own dependency files), the CMake
# package configs found (the *_DIR entries of CMakeCache.txt), and the
# programs and libraries found (its FILEPATH entries: compiler, linker,
# groff, the peers the tests run) that the build or the tests use. Each file's owning package, from dpkg's file lists, must be
# in the list's hard-dependency closure: Depends and Pre-Depends, never
# Recommends, which --no-install-recommends leaves out. Exit 1 names every
# package outside it, with a file it owns.
set -uo pipefail
src=${1:?usage: check-fresh-deps.sh SOURCE_DIR BUILD_DIR}
build=${2:?usage: check-fresh-deps.sh SOURCE_DIR BUILD_DIR}
list=$src/packaging/debian-packages.txt
if [ -f "$build/build.ninja" ]; then
    generator=ninja
elif [ -f "$build/Makefile" ]; then
    generator=make
else
    echo "no build in $build (neither build.ninja nor Makefile): configure and build first"
    exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1. The closure. apt-cache prints each package once at column 0 and its
# dependencies indented; virtual packages come as <name>.
grep -vE '^\s*(#|$)' "$list" | awk '{print $1}' > "$work/listed"
xargs -a "$work/listed" apt-cache depends --recurse --no-recommends --no-suggests --no-conflicts \
      --no-breaks --no-replaces --no-enhances 2>"$work/apt-errors" \
  | grep -v '^ ' | tr -d '<>' | sed 's/:.*//' | sort -u > "$work/closure"
if [ ! -s "$work/closure" ] || ! grep -qx build-essential "$work/closure"; then
    echo "apt-cache gave no dependency closure for the list (run 'apt-get update' once):"
    cat "$work/apt-errors"
    exit 2
fi

# Essential and Priority: required packages are on every Debian 12, the
# smallest (debootstrap --variant=minbase) included, whatever the list says.
dpkg-query -W -f='${Package} ${Essential} ${Priority}\n' \
  | awk '$2 == "yes" || $3 == "required" {print $1}' >> "$work/closure"
sort -u "$work/closure" -o "$work/closure"

# 2. The files the build used.
if [ "$generator" = ninja ]; then
    (cd "$build" && ninja -t deps) | awk '/^    \//{print $1}' | grep -E '^/(usr|lib|etc)/' > "$work/files"
else
    # Make-style dependency files (target: dep dep \): every path on them.
    find "$build" \( -name '*.o.d' -o -name compiler_depend.make \) -exec cat {} + \
      | tr ' \\' '\n\n' | grep -E '^/(usr|lib|etc)/' | sed 's/:$//' > "$work/files"
    if [ ! -s "$work/files" ]; then
        echo "no dependency files in $build: build first"
        exit 2
    fi
fi
sed -nE 's/^[A-Za-z0-9_]+_DIR:PATH=(\/usr\/.*)$/\1/p' "$build/CMakeCache.txt" | while read -r dir; do
    ls "$dir"/*Config.cmake "$dir"/*-config.cmake 2>/dev/null | head -n 1
done >> "$work/files"
# A program or library CMake found counts when the build or a test's command
# line names it, or when it is a peer the tests declare (SLEW_TEST_PEER_*):
# CMake also finds things nobody then runs (git for CTest, valgrind, EGL).
if [ "$generator" = ninja ]; then
    cat "$build/build.ninja" "$build"/CMakeFiles/rules.ninja > "$work/commands"
else
    find "$build" \( -name build.make -o -name link.txt -o -name flags.make -o -name Makefile \) -exec cat {} + \
      > "$work/commands"
fi
find "$build" -name CTestTestfile.cmake -exec cat {} + >> "$work/commands"
sed -nE 's/^([A-Za-z0-9_]+):FILEPATH=(\/(usr|bin|lib)\/.*)$/\1 \2/p' "$build/CMakeCache.txt" \
  | while read -r key path; do
        case $key in
        SLEW_TEST_PEER_*|CMAKE_MAKE_PROGRAM) echo "$path" ;;
        # A compiler cache is used when present and never needed (the
        # build without it is the same build), so the list need not bring it.
        SLEW_CCACHE_PROGRAM) ;;
        *) grep -qF "$path" "$work/commands" && echo "$path" ;;
        esac
    done >> "$work/files"
sort -u "$work/files" -o "$work/files"

# 3. Owners. A file is looked up as named, then with symlinks resolved
# (alternatives, /bin -> /usr/bin), then under the other half of the /usr
# merge, since dpkg records the path the package shipped.
# realpath runs once over every file (-m: one line per file, existing or not),
# not once per file: a fork per header made this the slowest step of the suite.
tr '\n' '\0' < "$work/files" | xargs -0 realpath -m -- > "$work/resolved"
paste "$work/files" "$work/resolved" | awk -F'\t' '
    function other_half(p) {
        if (p ~ /^\/usr\/(lib|bin|sbin)\//) return substr(p, 5)
        if (p ~ /^\/(lib|bin|sbin)\//) return "/usr" p
        return ""
    }
    {
        f = $1; real = ($2 == "" ? $1 : $2)
        n = split(f SUBSEP real, ps, SUBSEP)
        for (i = 1; i <= n; ++i) {
            print f "\t" ps[i]
            o = other_half(ps[i]); if (o != "") print f "\t" o
        }
    }' > "$work/candidates"
# One pass over dpkg's lists: path -> package, then each file's first
# candidate that a package owns.
awk -F'\t' -v owners="$work/owners" -v unowned="$work/unowned" '
    FNR == 1 && FILENAME ~ /\.list$/ { pkg = FILENAME; sub(/.*\//, "", pkg); sub(/\.list$/, "", pkg); sub(/:.*/, "", pkg) }
    FILENAME ~ /\.list$/ { owner[$0] = pkg; next }
    { order[++n] = $1; if (!($1 in best) && ($2 in owner)) best[$1] = owner[$2] }
    END {
        for (i = 1; i <= n; ++i) {
            f = order[i]; if (f in done) continue; done[f] = 1
            if (f in best) print best[f], f > owners; else print f > unowned
        }
    }' /var/lib/dpkg/info/*.list "$work/candidates"
touch "$work/owners" "$work/unowned"

status=0
: > "$work/outside"
awk 'FNR == NR { inside[$1] = 1; next } !($1 in inside)' "$work/closure" "$work/owners" > "$work/outside"
if [ -s "$work/outside" ]; then
    echo "debian-packages.txt misses packages the build used; a fresh machine would not have them:"
    sort -u -k1,1 "$work/outside" | awk '{printf "  %-28s e.g. %s\n", $1, $2}'
    status=1
fi
if [ -s "$work/unowned" ]; then
    echo "files the build used that no Debian package owns (installed by hand?):"
    sed 's/^/  /' "$work/unowned"
    status=1
fi
[ $status -eq 0 ] && echo "fresh machine: all $(wc -l < "$work/files") system files the build used come from" \
    "$(cut -d' ' -f1 "$work/owners" | sort -u | wc -l) packages inside the closure of" \
    "$(wc -l < "$work/listed") listed ones ($(wc -l < "$work/closure") with their dependencies)"
exit $status
