#!/usr/bin/env bash
# Reads the reports the sanitizer build's processes left in DIR (scripts/test --sanitize) and
# fails when any is a finding. One kind is expected and only counted: the import helper's
# memory limit at work. AddressSanitizer refuses an absurd size with a report of its own
# (allocation-size-too-big, out-of-memory), after which the helper ends with its
# "out of memory" exit code (app/import_main.cpp), which the tests ask for. A file with no
# finding in it (LeakSanitizer's "Unable to get registers from thread": a process killed by
# its parent, a helper at a deadline, while its leak check ran) is shown and not counted.
# Usage: check_reports.sh DIR
set -uo pipefail
dir=$1
findings=0 expected=0 notes=0
for report in "$dir"/*; do
    [[ -f "$report" ]] || continue
    if grep -q "import_main.cpp" "$report" &&
        grep -qE "allocation-size-too-big|out-of-memory|rss-limit-exceeded|failed to allocate" "$report"; then
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
