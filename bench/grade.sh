#!/usr/bin/env bash
# Grading a class: 100 submissions x 20 cases at 320x240 (the example exercise,
# resources/examples/exercise_lighting.json), made of the five sample submissions in
# tests/data/grading 20 times each (correct, reflection sign wrong, normal matrix wrong, not
# compiling, endless loop), graded by one `lightbench --grade` run inside Xvfb, each
# submission in its own process, two at a time (and, alternating, one at a time, and two at a
# time without --report: the CSV is written again, whole, after each submission, and this
# says what that costs). Prints the wall time per run and the medians.
# Usage: bench/grade.sh [RUNS]   (default 3; builds first, like scripts/run)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-3}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages
    build lightbench >/dev/null
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$RUNS"
fi
exe="$BUILD_DIR/app/lightbench"
samples="$ROOT/tests/data/grading"
class=$(mktemp -d)
trap 'rm -rf "$class"' EXIT
for i in $(seq -w 1 20); do
    for s in reflect_sign normal_matrix syntax loop; do
        cp "$samples/$s.vert" "$class/$s-$i.vert"
        cp "$samples/$s.frag" "$class/$s-$i.frag"
    done
    cp "$samples/correct/lighting.vert" "$class/correct-$i.vert"
    cp "$samples/correct/lighting.frag" "$class/correct-$i.frag"
done
# Alternating: the default (a process per core, two here), one process at a time, and the
# default with no report.
variants=(default 1 no-report)
declare -A times
for ((r = 0; r < RUNS; r++)); do
    for processes in "${variants[@]}"; do
        report=(--report "$class/grades.csv")
        [[ $processes == no-report ]] && report=()
        start=$(date +%s.%N)
        LIGHTBENCH_GRADE_PROCESSES=$([[ $processes == 1 ]] && echo 1 || echo 0) \
            "$exe" --grade "$class"/*.vert \
            --exercise "$ROOT/resources/examples/exercise_lighting.json" "${report[@]}" >/dev/null
        end=$(date +%s.%N)
        t=$(awk "BEGIN {printf \"%.1f\", $end - $start}")
        times[$processes]+="$t "
        echo "run $((r + 1)), processes $processes: $t s, load $(cut -d' ' -f1-3 /proc/loadavg)"
    done
done
for processes in "${variants[@]}"; do
    median=$(printf '%s\n' ${times[$processes]} | sort -g |
             awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    echo "100 submissions x 20 cases at 320x240, processes $processes: median $median s" \
         "(runs: ${times[$processes]})"
done
cut -d, -f2 "$class/grades.csv" | tail -n +2 | sort | uniq -c
