#!/usr/bin/env bash
# Grading on a busy machine (issue 47), two builds side by side in one Xvfb, alternating:
#  1. one runaway submission's child alone (`--grade-one`, tests/data/grading/runaway: a while
#     whose condition never fails, which llvmpipe stops after 65,535 steps): its wall time;
#  2. a class of 40 (8 each of correct, reflection sign wrong, normal matrix wrong, not
#     compiling, runaway), graded by one `lightbench --grade` RUNS times on a quiet machine and
#     RUNS times while as many spinning shells as cores keep them busy: wall times, and how
#     many of the 40 grades (status and points) and how many report bytes differ from the
#     first quiet run's;
#  3. the issue's correct submission with a 5000-step loop in every pixel (about 360 times the
#     teacher's program's frame, 1.2 s of processor time at 320x240), graded HEAVY times under
#     load: how many times it was refused.
# Usage: bench/grade_load.sh BEFORE_EXE AFTER_EXE [RUNS] [HEAVY]   (default 3 and 4)
# Prints a table row per figure (medians of the runs) with the load average at the end.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
BEFORE=${1:?before executable}
AFTER=${2:?after executable}
RUNS=${3:-3}
HEAVY=${4:-4}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$@"
fi
exercise="$ROOT/resources/examples/exercise_lighting.json"
samples="$ROOT/tests/data/grading"
work=$(mktemp -d)
spinners=()
stop_load() {
    for pid in "${spinners[@]}"; do kill "$pid" 2>/dev/null || true; done
    wait "${spinners[@]}" 2>/dev/null || true
    spinners=()
}
trap 'stop_load; rm -rf "$work"' EXIT
start_load() {
    for ((i = 0; i < $(nproc); i++)); do
        sh -c 'while :; do :; done' &
        spinners+=($!)
    done
}
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
seconds() { # the wall time of a command, in seconds
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1 || true
    end=$(date +%s.%N)
    awk "BEGIN {printf \"%.2f\", $end - $start}"
}

# A build from before the exercise's "frameBudget" (issue 47) refuses the field: it gets the
# exercise without it (the default, 2 s, was its fixed budget).
declare -A exercises=([BEFORE]=$exercise [AFTER]=$exercise)
if ! "$BEFORE" --grade-one "$samples/correct" --exercise "$exercise" 2>/dev/null |
    grep -q '"status":"graded"'; then
    grep -v '"frameBudget"' "$exercise" >"$work/exercise-before.json"
    exercises[BEFORE]=$work/exercise-before.json
fi
mkdir "$work/class"
for i in 1 2 3 4 5 6 7 8; do
    for s in reflect_sign normal_matrix syntax runaway; do
        cp "$samples/$s.vert" "$work/class/$s-$i.vert"
        cp "$samples/$s.frag" "$work/class/$s-$i.frag"
    done
    cp "$samples/correct/lighting.vert" "$work/class/correct-$i.vert"
    cp "$samples/correct/lighting.frag" "$work/class/correct-$i.frag"
done
# The issue's heavy submission: the correct one with a 5000-step loop that changes nothing.
cp "$samples/correct/lighting.vert" "$work/heavy.vert"
sed 's|^    vec3 n = normalize (vNormalEye);$|&\n    for (int i = 0; i < 5000; i++)\n        n = normalize (n + vec3 (0.0));|' \
    "$samples/correct/lighting.frag" >"$work/heavy.frag"
grep -q 5000 "$work/heavy.frag"

row() { # name, before's figures, after's figures
    local b a
    b=$(printf '%s\n' $2 | median)
    a=$(printf '%s\n' $3 | median)
    printf '| %s | %s | %s | %s | %s | %s |\n' "$1" "$b" "$a" \
        "$(awk -v a="$a" -v b="$b" 'BEGIN {if (b > 0) printf "%.2fx", a / b; else print "-"}')" \
        "$2" "$3"
}
grades() { cut -d, -f1,2,8 "$1" | sort; } # submission, status, points

declare -A child quiet busy changed differ refused
for exe in BEFORE AFTER; do
    changed[$exe]=0 differ[$exe]=0 refused[$exe]=0
done
for ((r = 0; r < RUNS; r++)); do
    for exe in BEFORE AFTER; do
        child[$exe]+="$(seconds "${!exe}" --grade-one "$samples/runaway.vert" \
            --exercise "${exercises[$exe]}") "
    done
done
for ((r = 0; r < 2 * RUNS; r++)); do
    loaded=$((r % 2))
    ((loaded)) && start_load
    for exe in BEFORE AFTER; do
        report="$work/$exe-$r.csv"
        t=$(seconds "${!exe}" --grade "$work/class"/*.vert --exercise "${exercises[$exe]}" \
            --report "$report")
        if ((loaded)); then busy[$exe]+="$t "; else quiet[$exe]+="$t "; fi
        if ((r > 0)); then
            n=$(diff <(grades "$work/$exe-0.csv") <(grades "$report") | grep -c '^>' || true)
            changed[$exe]=$((changed[$exe] + n))
            cmp -s "$work/$exe-0.csv" "$report" || differ[$exe]=$((differ[$exe] + 1))
        fi
    done
    ((loaded)) && stop_load
    echo "class run $((r + 1)) of $((2 * RUNS)) ($([[ $loaded == 1 ]] && echo busy || echo quiet))," \
        "load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
done
start_load
for ((r = 0; r < HEAVY; r++)); do
    for exe in BEFORE AFTER; do
        "${!exe}" --grade "$work/heavy.vert" --exercise "${exercises[$exe]}" \
            --report "$work/heavy-$exe.csv" >/dev/null 2>&1 || true
        grep -q '^heavy,refused' "$work/heavy-$exe.csv" && refused[$exe]=$((refused[$exe] + 1))
    done
    echo "heavy run $((r + 1)) of $HEAVY, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
done
stop_load

echo "| figure | before | after | after / before | before's runs | after's runs |"
echo "|---|---|---|---|---|---|"
row "a runaway's child alone, s" "${child[BEFORE]}" "${child[AFTER]}"
row "40 submissions, quiet, s" "${quiet[BEFORE]}" "${quiet[AFTER]}"
row "40 submissions, every core busy, s" "${busy[BEFORE]}" "${busy[AFTER]}"
echo "| grades changed from the first quiet run, of 40 x $((2 * RUNS - 1)) | ${changed[BEFORE]} | ${changed[AFTER]} | | | |"
echo "| reports not byte-identical to the first, of $((2 * RUNS - 1)) | ${differ[BEFORE]} | ${differ[AFTER]} | | | |"
echo "| the 5000-step loop refused under load, of $HEAVY | ${refused[BEFORE]} | ${refused[AFTER]} | | | |"
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
