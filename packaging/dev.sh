#!/usr/bin/env bash
# One entry point for developers and CI.
#
#   packaging/dev.sh run [slew arguments]   install what is missing, build, start Slew
#   packaging/dev.sh test                   install what is missing, build, run every test
#   packaging/dev.sh bench                  build and run the benchmarks (tests/bench)
#   packaging/dev.sh package                build a Debian package (build/slew_*.deb)
#   packaging/dev.sh sanitize [ctest args]  build with ASan+UBSan (build-sanitize) and run the tests
#
# Works on a fresh Debian 12: missing packages (packaging/debian-packages.txt)
# are installed with apt-get, through sudo when not root.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/.." && pwd)
build=${SLEW_BUILD_DIR:-$top/build}
jobs=$(nproc 2>/dev/null || echo 2)

install_missing() {
    local wanted missing=()
    wanted=$(grep -vE '^\s*(#|$)' "$here/debian-packages.txt")
    for pkg in $wanted; do
        dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "== installing: ${missing[*]}"
    local sudo=()
    [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

configure_and_build() {
    cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${SLEW_BUILD_TYPE:-RelWithDebInfo}" >/dev/null
    cmake --build "$build" -j "$jobs"
}

# The sanitizer build: its own directory, so it never mixes with build/.
# ctest runs each test under packaging/sanitized-test.sh (tests/CMakeLists.txt),
# which fails it on any ASan, LSan or UBSan report.
sanitize_build=${SLEW_SANITIZE_BUILD_DIR:-$top/build-sanitize}
sanitize_configure_and_build() {
    cmake -S "$top" -B "$sanitize_build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSLEW_SANITIZE=ON >/dev/null
    cmake --build "$sanitize_build" -j "$jobs"
}

cmd=${1:-}
[ $# -gt 0 ] && shift
case "$cmd" in
run)
    install_missing
    configure_and_build
    exec "$build/app/slew" "$@"
    ;;
test)
    install_missing
    configure_and_build
    cd "$build"
    # Serial, not parallel: several tests time real replies on 2 cores.
    # The summary line ("100% tests passed, 0 tests failed out of N") is
    # ctest's last line; --output-on-failure shows what a failing test printed.
    ctest --output-on-failure --timeout 600 "$@"
    ;;
bench)
    install_missing
    configure_and_build
    found=0
    for b in "$build"/tests/bench/*/bench_*; do
        [ -x "$b" ] || continue
        found=1
        echo "== $(basename "$b")"
        "$b"
    done
    [ $found -eq 1 ] || { echo "no benchmarks built"; exit 1; }
    ;;
package)
    install_missing
    configure_and_build
    (cd "$build" && cpack -G DEB)
    ;;
sanitize)
    install_missing
    sanitize_configure_and_build
    cd "$sanitize_build"
    ctest --output-on-failure --timeout 1800 "$@"
    ;;
*)
    echo "usage: $0 run [slew arguments] | test [ctest arguments] | bench | package | sanitize [ctest arguments]" >&2
    exit 2
    ;;
esac
