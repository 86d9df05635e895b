#!/usr/bin/env bash
# What a plot costs (issue 34): `lightbench --plot KIND` for the specular curves and the lobe,
# computing the samples alone (--plot-data) and computing, building the chart and painting
# it into an 800x600 PNG (--render), beside `lightbench --version` (starting the process),
# alternating, RUNS times each. The Plots panel rebuilds its chart on each change of the
# scene (a slider step): the render's time less the start is an upper bound of that step
# (it also encodes a PNG). No X server is needed (no --probe). Prints each run and medians,
# with the load average.
# Usage: bench/plot.sh [RUNS]   (default 7; builds first, like scripts/run)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-7}
ensure_packages
build lightbench >/dev/null
exe="$BUILD_DIR/app/lightbench"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A times
ms() { awk "BEGIN {printf \"%.1f\", ($2 - $1) * 1000}"; }
for ((r = 0; r < RUNS; r++)); do
    for kind in specular lobe; do
        for what in start data render; do
            case $what in
            start) args=(--version) ;;
            data) args=(--plot "$kind" --plot-data "$work/p.csv") ;;
            render) args=(--plot "$kind" --render "$work/p.png") ;;
            esac
            start=$(date +%s.%N)
            "$exe" "${args[@]}" >/dev/null
            end=$(date +%s.%N)
            t=$(ms "$start" "$end")
            times[$kind-$what]+="$t "
            echo "run $((r + 1)), $kind, $what: $t ms, load $(cut -d' ' -f1-3 /proc/loadavg)"
        done
    done
done
for key in specular-start specular-data specular-render lobe-start lobe-data lobe-render; do
    median=$(printf '%s\n' ${times[$key]} | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    echo "$key: median $median ms (runs: ${times[$key]})"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
