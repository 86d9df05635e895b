#!/usr/bin/env bash
# What the outward check of a mesh file's faces (issue 48) costs: load plus first frame at
# 1920x1080 of generated binary PLY tori (1M and 10M triangles, wound outwards, and 1M wound
# clockwise, which the check turns), with --faces file (the file as it is, no check) against
# --faces outward (the default), alternating runs inside one Xvfb: median wall time and
# peak memory (GNU time's maximum resident set), the load average beside them.
# Usage: bench/faces.sh [RUNS]   (default 5; builds first, like scripts/run; needs python3)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-5}
DATA=${LIGHTBENCH_BENCH_DATA:-$BUILD_DIR/bench-data}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages time python3
    build lightbench >/dev/null
    mkdir -p "$DATA"
    gen() { [[ -f "$DATA/$1" ]] || python3 "$ROOT/bench/make_ply.py" "$DATA/$1" "${@:2}" >&2; }
    gen torus-1m.ply 1000000
    gen torus-1m-clockwise.ply 1000000 --clockwise
    gen torus-10m.ply 10000000
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$RUNS"
fi
exe="$BUILD_DIR/app/lightbench"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| file | --faces | median wall (s) | median peak (MB) | wall runs (s) |"
echo "|---|---|---|---|---|"
for file in torus-1m.ply torus-1m-clockwise.ply torus-10m.ply; do
    for ((i = 0; i < RUNS; i++)); do # alternating, so drifts hit both alike
        for faces in file outward; do
            /usr/bin/time -f "%e %M" -o "$out/t" "$exe" --mesh "$DATA/$file" --faces "$faces" \
                --render "$out/f.png" --size 1920x1080 >/dev/null 2>"$out/err" ||
                { cat "$out/err" >&2; exit 1; }
            cat "$out/t" >>"$out/$file-$faces"
        done
    done
    for faces in file outward; do
        s=$(awk '{print $1}' "$out/$file-$faces" | median)
        m=$(awk '{print $2}' "$out/$file-$faces" | median)
        printf '| %s | %s | %.2f | %.0f | %s |\n' "$file" "$faces" "$s" "$(echo "$m / 1024" | bc -l)" \
            "$(awk '{printf "%s ", $1}' "$out/$file-$faces")"
    done
    a=$(awk '{print $1}' "$out/$file-outward" | median); b=$(awk '{print $1}' "$out/$file-file" | median)
    am=$(awk '{print $2}' "$out/$file-outward" | median); bm=$(awk '{print $2}' "$out/$file-file" | median)
    printf '| %s | ratio outward / file | %.2fx | %.2fx | |\n' "$file" "$(echo "$a / $b" | bc -l)" \
        "$(echo "$am / $bm" | bc -l)"
    grep -h "turned" "$out/err" | sed 's/^/    said: /' || true
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
