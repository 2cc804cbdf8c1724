#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One entry point for developers and CI.
#
#   packaging/dev.sh run [slew arguments]   install what is missing, build, start Slew
#   packaging/dev.sh build                  install what is missing, build (build/)
#   packaging/dev.sh test                   install what is missing, build, run every test
#   packaging/dev.sh bench                  build and run the benchmarks (tests/bench)
#   packaging/dev.sh package                build a Debian package (build/slew_*.deb), stripped
#   packaging/dev.sh sanitize-build         build with ASan+UBSan (build-sanitize)
#   packaging/dev.sh sanitize [ctest args]  build with ASan+UBSan (build-sanitize) and run the tests
#   packaging/dev.sh fuzz [SECONDS]         build the libFuzzer targets (build-fuzz), run each SECONDS
#
# Works on a fresh Debian 12: missing packages (packaging/debian-packages.txt)
# are installed with apt-get, through sudo when not root.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
top=$(cd "$here/.." && pwd)
build=${SLEW_BUILD_DIR:-$top/build}
jobs=$(nproc 2>/dev/null || echo 2)
# Tests at a time: two a core. The suite mostly waits (on Hamlib's programs,
# the broker, real sockets, a rehearsal's clock): on 2 cores it used 155 s
# of CPU in 164 s at four at a time, and took 318 s at two. Each test waits
# on its own clock or long enough for a loaded machine (README, "Build
# time"). SLEW_TEST_JOBS sets another number.
test_jobs=${SLEW_TEST_JOBS:-$(( jobs * 2 ))}

install_missing() {
    local wanted missing=()
    wanted=$(grep -vE '^\s*(#|$)' "$here/debian-packages.txt")
    for pkg in $wanted; do
        dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
    done
    local sudo=()
    [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    # The fresh-machine test asks apt-cache for the list's dependencies,
    # which needs the package lists even when nothing is missing.
    if [ ${#missing[@]} -eq 0 ]; then
        compgen -G '/var/lib/apt/lists/*_Packages*' > /dev/null || "${sudo[@]}" apt-get update -q
        return 0
    fi
    echo "== installing: ${missing[*]}"
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}

configure_and_build() {
    cmake -S "$top" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="${SLEW_BUILD_TYPE:-RelWithDebInfo}" \
        -DSLEW_SHARED_LIBRARIES=ON >/dev/null
    cmake --build "$build" -j "$jobs"
}

# The sanitizer build: its own directory, so it never mixes with build/.
# ctest runs each test under packaging/sanitized-test.sh (tests/CMakeLists.txt),
# which fails it on any ASan, LSan or UBSan report.
sanitize_build=${SLEW_SANITIZE_BUILD_DIR:-$top/build-sanitize}
sanitize_configure_and_build() {
    cmake -S "$top" -B "$sanitize_build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSLEW_SANITIZE=ON \
        -DSLEW_SHARED_LIBRARIES=ON >/dev/null
    cmake --build "$sanitize_build" -j "$jobs"
}

# The libFuzzer build: clang, its own directory, only the fuzz targets and
# what they link. clang and its sanitizer runtimes are a developer's tool, not
# a build dependency, so they are installed here rather than listed in
# debian-packages.txt.
fuzz_build=${SLEW_FUZZ_BUILD_DIR:-$top/build-fuzz}
fuzz_targets=(parser rotctldrequest tle gpcsv ommxml gpjson ommkvn configfile transponders remotemessages)
install_fuzz_tools() {
    local missing=()
    for pkg in clang libclang-rt-14-dev; do
        dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "== installing: ${missing[*]}"
    local sudo=()
    [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
}
fuzz_configure_and_build() {
    cmake -S "$top" -B "$fuzz_build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_COMPILER=clang++ -DSLEW_FUZZ=ON >/dev/null
    cmake --build "$fuzz_build" -j "$jobs" --target "${fuzz_targets[@]/#/fuzz_}"
}
# Runs one target for $2 seconds over a scratch copy of its seed corpus (new
# inputs never land in the source tree) and prints its speed and coverage.
# A crash input is saved under build-fuzz/crashes/ and fails the command.
fuzz_run() {
    local target=$1 seconds=$2
    local work=$fuzz_build/corpus/$target seeds=$top/tests/fuzz/corpus/$target
    local log=$fuzz_build/fuzz_$target.log status=0
    mkdir -p "$work" "$fuzz_build/crashes"
    local dict=()
    [ -f "$top/tests/fuzz/$target.dict" ] && dict=(-dict="$top/tests/fuzz/$target.dict")
    echo "== fuzz_$target for ${seconds}s"
    "$fuzz_build/tests/fuzz/fuzz_$target" "$work" "$seeds" "${dict[@]}" \
        -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
        -artifact_prefix="$fuzz_build/crashes/$target-" >"$log" 2>&1 || status=$?
    local runs speed cov
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    cov=$(grep -E '^#[0-9]+' "$log" | tail -n 1 | grep -oE 'cov: [0-9]+ ft: [0-9]+' || true)
    echo "   ${runs:-?} cases, ${speed:-?} cases/s, ${cov:-no coverage line}, corpus $(ls "$work" | wc -l) files"
    if [ $status -ne 0 ]; then
        echo "   FAILED (exit $status): the report is in $log; the input under $fuzz_build/crashes/"
        grep -E 'ERROR|SUMMARY|runtime error|fuzz_' "$log" | head -n 5 | sed 's/^/   /'
    fi
    return $status
}

cmd=${1:-}
[ $# -gt 0 ] && shift
case "$cmd" in
build)
    install_missing
    configure_and_build
    ;;
sanitize-build)
    install_missing
    sanitize_configure_and_build
    ;;
run)
    install_missing
    configure_and_build
    exec "$build/app/slew" "$@"
    ;;
test)
    install_missing
    configure_and_build
    cd "$build"
    # The summary line ("100% tests passed, 0 tests failed out of N") is
    # ctest's last line; --output-on-failure shows what a failing test printed.
    ctest --output-on-failure --timeout 600 -j "$test_jobs" "$@"
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
    ls -l "$build"/slew_*.deb
    ;;
sanitize)
    install_missing
    sanitize_configure_and_build
    cd "$sanitize_build"
    # As many at a time as the normal suite: one at a time took 14 of CI's
    # 90 minutes, two a core takes about 4 on 2 cores.
    ctest --output-on-failure --timeout 1800 -j "$test_jobs" "$@"
    ;;
fuzz)
    seconds=${1:-60}
    install_fuzz_tools
    fuzz_configure_and_build
    failed=0
    for t in "${fuzz_targets[@]}"; do
        fuzz_run "$t" "$seconds" || failed=1
    done
    exit $failed
    ;;
*)
    echo "usage: $0 run [slew arguments] | build | test [ctest arguments] | bench | package | sanitize-build | sanitize [ctest arguments] | fuzz [seconds]" >&2
    exit 2
    ;;
esac
