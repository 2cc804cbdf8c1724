#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# What a build spent its time on, from ninja's own log.
#
#   packaging/build-times.sh [BUILD_DIR]      (default: build)
#
# Reads BUILD_DIR/.ninja_log and prints the build's total step time (the sum
# over every step of its own duration: with -j2 about twice the wall time),
# the share of each area (core, ui, app, tests, bench, autogen: moc and the
# compiling of its output), compile against link, and the 15 slowest steps.
# Each step is counted once: ninja writes a line for every output of a step
# (autogen's timestamp and mocs_compilation.cpp, say), all with the step's
# command hash, and a step built again since writes a newer line.
# Meant for a clean build (an empty BUILD_DIR); on an incremental one it
# measures what that build did, plus whatever older lines remain.
set -euo pipefail
dir=${1:-build}
log=$dir/.ninja_log
[ -f "$log" ] || { echo "no $log: build with Ninja first" >&2; exit 2; }
build_abs=$(cd "$dir" && pwd)

awk -v build="$build_abs/" '
function area(path) {
    sub("^" build, "", path)
    if (path ~ /_autogen\//) return "autogen"
    if (path ~ /^tests\/bench\//) return "bench"
    if (path ~ /^tests\//) return "tests"
    if (path ~ /^core\//) return "core"
    if (path ~ /^ui\//) return "ui"
    if (path ~ /^app\//) return "app"
    return "other"
}
function kind(path) {
    if (path ~ /\.o$/) return "compile"
    if (path ~ /\.gch$/ || path ~ /cmake_pch/) return "compile"
    if (path ~ /_autogen\// || path ~ /timestamp$/) return "moc"
    return "link/other"
}
/^#/ { next }
{
    # The last line of each output wins (a step built again writes anew).
    start[$4] = $1; end[$4] = $2; hash[$4] = $5
}
END {
    for (out in hash) {
        h = hash[out]
        if (h in seen) continue
        seen[h] = 1
        ms = end[out] - start[out]
        total += ms
        byArea[area(out)] += ms
        byKind[kind(out)] += ms
        n++
        steps[n] = sprintf("%10.1f s  %s", ms / 1000, out)
        key[n] = ms
    }
    printf "%d steps, total step time %.0f s\n", n, total / 1000
    printf "by area:\n"
    split("core ui app tests bench autogen other", order, " ")
    for (i = 1; i <= 7; i++) {
        a = order[i]
        if (a in byArea)
            printf "  %-8s %7.0f s  %5.1f %%\n", a, byArea[a] / 1000, 100 * byArea[a] / total
    }
    printf "by kind:\n"
    for (k in byKind)
        printf "  %-11s %7.0f s  %5.1f %%\n", k, byKind[k] / 1000, 100 * byKind[k] / total
    # The slowest steps: a selection of the 15 largest, n is small.
    printf "slowest steps:\n"
    for (j = 1; j <= 15 && j <= n; j++) {
        best = 0
        for (i = 1; i <= n; i++)
            if (!(i in taken) && (best == 0 || key[i] > key[best])) best = i
        taken[best] = 1
        print steps[best]
    }
}' "$log"
