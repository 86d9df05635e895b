#!/usr/bin/env bash
# Mesh files: load plus first frame of a generated 1M-triangle binary PLY at 1920x1080,
# lightbench against f3d (Debian's f3d package), alternating runs inside one Xvfb, wall time
# and peak memory (GNU time's maximum resident set: the process or its largest child); then
# a 5M-triangle file: its load and the frame rate at 1280x720.
# Usage: bench/mesh.sh [RUNS]   (default 7; builds first, like scripts/run; needs python3)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-7}
DATA=${LIGHTBENCH_BENCH_DATA:-$BUILD_DIR/bench-data}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages f3d time python3
    build lightbench >/dev/null
    mkdir -p "$DATA"
    gen() { [[ -f "$DATA/$1" ]] || python3 "$ROOT/bench/make_ply.py" "$DATA/$1" "${@:2}" >&2; }
    gen torus-1m.ply 1000000
    gen torus-1m-normals.ply 1000000 --normals
    gen torus-5m.ply 5000000
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$RUNS"
fi
exe="$BUILD_DIR/app/lightbench"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# timed NAME COMMAND...: appends "seconds kilobytes" to $out/NAME
timed() {
    local name=$1; shift
    /usr/bin/time -f "%e %M" -o "$out/t" "$@" >/dev/null 2>"$out/err" ||
        { cat "$out/err" >&2; exit 1; }
    cat "$out/t" >>"$out/$name"
}

echo "| file | tool | median wall (s) | median peak (MB) | wall runs (s) |"
echo "|---|---|---|---|---|"
for file in torus-1m.ply torus-1m-normals.ply; do
    for ((i = 0; i < RUNS; i++)); do # alternating, so drifts hit both alike
        timed "lb-$file" "$exe" --mesh "$DATA/$file" --render "$out/lb.png" --size 1920x1080
        timed "f3d-$file" f3d --output="$out/f3d.png" --resolution=1920,1080 "$DATA/$file"
    done
    for tool in lb f3d; do
        s=$(awk '{print $1}' "$out/$tool-$file" | median)
        m=$(awk '{print $2}' "$out/$tool-$file" | median)
        printf '| %s | %s | %.2f | %.0f | %s |\n' "$file" "$([[ $tool == lb ]] && echo lightbench || echo f3d)" \
            "$s" "$(echo "$m / 1024" | bc -l)" "$(awk '{printf "%s ", $1}' "$out/$tool-$file")"
    done
    ls=$(awk '{print $1}' "$out/lb-$file" | median); fs=$(awk '{print $1}' "$out/f3d-$file" | median)
    lm=$(awk '{print $2}' "$out/lb-$file" | median); fm=$(awk '{print $2}' "$out/f3d-$file" | median)
    printf '| %s | ratio lightbench / f3d | %.2fx | %.2fx | |\n' "$file" \
        "$(echo "$ls / $fs" | bc -l)" "$(echo "$lm / $fm" | bc -l)"
done

echo
echo "5M triangles, 1280x720, $RUNS runs (--bench-frames 20 after the load):"
for ((i = 0; i < RUNS; i++)); do
    "$exe" --mesh "$DATA/torus-5m.ply" --size 1280x720 --bench-frames 20 >>"$out/5m"
done
for key in loadSeconds fps peakMB helperPeakMB; do
    v=$(sed -E "s/.*\"$key\":([0-9.e+-]+).*/\1/" "$out/5m" | median)
    printf '%s median %s (runs: %s)\n' "$key" "$v" \
        "$(sed -E "s/.*\"$key\":([0-9.e+-]+).*/\1/" "$out/5m" | xargs printf '%.2f ')"
done
