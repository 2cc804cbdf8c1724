#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs one test of the sanitizer build (packaging/dev.sh sanitize).
#
#   sanitized-test.sh REPORT_DIR PROGRAM [ARGS...]
#
# The test and every process it starts (slew-sim, slew) inherit the options
# below and write any sanitizer report to REPORT_DIR rather than to stderr,
# where a child's report would be lost. A report fails the test even when the
# process that wrote it exited 0 or was a child whose exit code nobody read;
# the reports are printed so ctest --output-on-failure shows them.
set -u
reports=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$reports"
mkdir -p "$reports"

# detect_leaks: LeakSanitizer at exit. abort_on_error: a report ends the
# process with SIGABRT, never a normal exit. The rest make reports readable.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:check_initialization_order=1:log_path=$reports/asan"
# halt_on_error goes with -fno-sanitize-recover=undefined in the build.
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:log_path=$reports/ubsan"
# Leaks inside system libraries only; every entry says why it is there.
export LSAN_OPTIONS="suppressions=$here/lsan-suppressions.txt:print_suppressions=0"

"$@"
status=$?

found=0
for report in "$reports"/*; do
    [ -e "$report" ] || continue
    found=1
    echo "==== sanitizer report: $report"
    cat "$report"
done
if [ $found -ne 0 ]; then
    echo "FAIL: sanitizer reported errors (exit status $status)"
    [ $status -ne 0 ] && exit $status
    exit 1
fi
exit $status
