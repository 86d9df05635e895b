#!/usr/bin/env bash
# What the known mistakes cost a failing submission (issue 33, part 3): the grading child
# (`lightbench --grade-one`) on the reflection-sign and normal-matrix samples, against the
# example exercise as shipped (7 mistakes) and against the same exercise without its
# "mistakes" list, alternating, RUNS times each. Prints each run and the medians, with the
# load average. A passing submission draws no mistake: its time is unchanged.
# Usage: bench/grade_hints.sh [RUNS]   (default 5; builds first, like scripts/run)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-5}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages
    build lightbench >/dev/null
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$RUNS"
fi
exe="$BUILD_DIR/app/lightbench"
samples="$ROOT/tests/data/grading"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
with="$ROOT/resources/examples/exercise_lighting.json"
without="$work/no_mistakes.json"
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); del d["exercise"]["mistakes"]
json.dump(d, open(sys.argv[2], "w"))' "$with" "$without"
declare -A times
for ((r = 0; r < RUNS; r++)); do
    for sample in reflect_sign normal_matrix; do
        for variant in with without; do
            exercise=$([[ $variant == with ]] && echo "$with" || echo "$without")
            start=$(date +%s.%N)
            "$exe" --grade-one "$samples/$sample.frag" --exercise "$exercise" >"$work/out.json"
            end=$(date +%s.%N)
            t=$(awk "BEGIN {printf \"%.2f\", $end - $start}")
            times[$sample-$variant]+="$t "
            hint=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("mistake", {}).get("name", "none"))' "$work/out.json")
            echo "run $((r + 1)), $sample, $variant mistakes: $t s (hint: $hint), load $(cut -d' ' -f1-3 /proc/loadavg)"
        done
    done
done
for key in reflect_sign-with reflect_sign-without normal_matrix-with normal_matrix-without; do
    median=$(printf '%s\n' ${times[$key]} | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    echo "$key: median $median s (runs: ${times[$key]})"
done
