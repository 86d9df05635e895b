#!/usr/bin/env bash
# Two builds measured side by side inside one Xvfb, alternating run by run: the frame rate of
# the default scene (Phong and Gouraud, 1280x720) and the window's edit to pixels. For a
# change that may cost speed: build the commit before it elsewhere and compare.
# Usage: bench/side_by_side.sh BEFORE_EXE AFTER_EXE [RUNS] [EDITS]   (default 5 runs, 20 edits)
# Prints every run and the medians with their ratio (after / before), then the load average.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
BEFORE=${1:?before executable}
AFTER=${2:?after executable}
RUNS=${3:-5}
EDITS=${4:-20}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$@"
fi

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
field() { sed -E "s/.*\"$1\":([0-9.e+-]+).*/\1/"; }

compare() { # name, then a function of an executable that prints one number
    local name=$1 run=$2 before=() after=()
    for ((i = 0; i < RUNS; i++)); do
        before+=("$($run "$BEFORE")")
        after+=("$($run "$AFTER")")
    done
    local b a
    b=$(printf '%s\n' "${before[@]}" | median)
    a=$(printf '%s\n' "${after[@]}" | median)
    printf '| %s | %.1f | %.1f | %.2fx | %s | %s |\n' "$name" "$b" "$a" \
        "$(awk -v a="$a" -v b="$b" 'BEGIN {print a / b}')" \
        "$(printf '%.1f ' "${before[@]}")" "$(printf '%.1f ' "${after[@]}")"
}

phong() { "$1" --size 1280x720 --bench-frames 30 | field fps; }
gouraud() { "$1" --size 1280x720 --bench-frames 30 --shading gouraud | field fps; }
edit() { # a fresh session each time; Mesa's shader cache off, as in bench/edit.sh
    local config
    config=$(mktemp -d)
    XDG_CONFIG_HOME=$config MESA_SHADER_CACHE_DISABLE=true "$1" --bench-edits "$EDITS" |
        head -1 | field editToPixelsMs
    rm -rf "$config"
}

echo "| measure | before (median) | after (median) | ratio | before, all runs | after, all runs |"
echo "|---|---|---|---|---|---|"
compare "default Phong (fps)" phong
compare "default Gouraud (fps)" gouraud
compare "edit to pixels, built-in Phong (ms)" edit
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
