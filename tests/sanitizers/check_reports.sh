#!/usr/bin/env bash
# Reads the reports the sanitizer build's processes left in DIR (scripts/test --sanitize) and
# fails when any is a finding. Files are named KIND.EXECUTABLE.PID (log_exe_name=1; UBSan's
# through tests/sanitizers/sanitizer_support.cpp).
#
# First the canary (CANARY, tests/sanitizers/canary.cpp) makes one UBSan and one leak report
# on purpose: when they do not arrive, the reports go somewhere else and the run fails rather
# than pass for want of them. Then one kind is expected and only counted: the import helper's
# memory limit at work. AddressSanitizer refuses an absurd size with a report of its own
# (allocation-size-too-big, out-of-memory), after which the helper ends with its
# "out of memory" exit code (app/cli/import_main.cpp), which the tests ask for. A file with no
# finding in it (LeakSanitizer's "Unable to get registers from thread": a process killed by
# its parent while its leak check ran; "Tracer caught signal", its tracer's own crash, after
# which scripts/test runs the failed tests once more) is shown and not counted.
# Usage: check_reports.sh DIR CANARY
set -uo pipefail
dir=$1 canary=$2

"$canary" >/dev/null 2>&1
if ! grep -qs "signed-integer-overflow" "$dir"/ubsan.lb_sanitizer_canary.* ||
    ! grep -qs "detected memory leaks" "$dir"/asan.lb_sanitizer_canary.*; then
    echo "sanitizers: the canary's reports did not reach $dir: nothing here can be trusted" >&2
    exit 1
fi
rm -f "$dir"/*.lb_sanitizer_canary.*

findings=0 expected=0 notes=0
for report in "$dir"/*; do
    [[ -f "$report" ]] || continue
    errors=$(grep -c "ERROR: " "$report")
    if [[ $(basename "$report") == asan.lightbench-import.* && $errors -eq 1 ]] &&
        grep -qE "^SUMMARY: AddressSanitizer: (allocation-size-too-big|out-of-memory|rss-limit-exceeded)" "$report"; then
        expected=$((expected + 1))
        continue
    fi
    if ! grep -qE "ERROR: |runtime error|WARNING: " "$report"; then
        notes=$((notes + 1))
        echo "sanitizers: no finding in $report: $(head -c 300 "$report" | tr '\n' ' ')"
        continue
    fi
    findings=$((findings + 1))
    echo "=== sanitizer report: $report" >&2
    head -c 20000 "$report" >&2
done
echo "sanitizers: $findings report(s) to fix, $expected expected (the import helper's memory" \
    "limit), $notes without a finding"
[[ $findings -eq 0 ]]
