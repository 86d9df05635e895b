#!/usr/bin/env bash
# Two import helpers measured side by side, alternating run by run: the wall time of
# `lightbench-import FILE > /dev/null` (Assimp's read plus the stream) for a small OBJ (the
# helper's start-up dominates: the workbench starts one for every mesh) and a generated
# 1M-triangle binary PLY. For a change to the helper or the platform layer under it: build the
# commit before it elsewhere (`cmake --build OTHER/build --target lightbench-import`).
# Usage: bench/import_side_by_side.sh BEFORE_HELPER AFTER_HELPER [RUNS]   (default 21)
# Prints the medians in milliseconds with their ratio (after / before), then the load average.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
BEFORE=${1:?before helper}
AFTER=${2:?after helper}
RUNS=${3:-21}
DATA=${LIGHTBENCH_BENCH_DATA:-$BUILD_DIR/bench-data}
mkdir -p "$DATA"
[[ -f "$DATA/torus-1m.ply" ]] || python3 "$ROOT/bench/make_ply.py" "$DATA/torus-1m.ply" 1000000 >&2

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
ms() { # helper file: milliseconds of one read
    local start end
    start=$(date +%s%N)
    "$1" "$2" >/dev/null 2>&1 || { echo "import_side_by_side: $1 failed on $2" >&2; exit 1; }
    end=$(date +%s%N)
    echo $(((end - start) / 1000)) | awk '{printf "%.1f\n", $1 / 1000}'
}

echo "| file | before (ms) | after (ms) | after / before |"
echo "|---|---|---|---|"
for file in /usr/share/assimp/models/OBJ/box.obj "$DATA/torus-1m.ply"; do
    before=() after=()
    ms "$BEFORE" "$file" >/dev/null # warm the page cache for both
    for ((i = 0; i < RUNS; i++)); do
        before+=("$(ms "$BEFORE" "$file")")
        after+=("$(ms "$AFTER" "$file")")
    done
    b=$(printf '%s\n' "${before[@]}" | median)
    a=$(printf '%s\n' "${after[@]}" | median)
    printf '| %s | %s | %s | %.2fx |\n' "$(basename "$file")" "$b" "$a" "$(awk -v a="$a" -v b="$b" 'BEGIN {print a / b}')"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
