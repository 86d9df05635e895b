#!/usr/bin/env bash
# Mesh files: load plus first frame of generated binary PLYs (1M triangles, 1M with normals,
# 10M: a big scan) at 1920x1080, lightbench against f3d (Debian's f3d package), alternating
# runs inside one Xvfb, wall time and peak memory (GNU time's maximum resident set: the process
# or its largest child); lightbench twice: as it comes (the import helper's own PLY reader) and
# with LIGHTBENCH_IMPORT_READER=assimp (Assimp's reader, as before the helper had its own); then
# a 5M-triangle file: its load and the frame rate at 1280x720; then a 10M-triangle file (a big
# scan): load and first frame at 1920x1080, and the memory of the workbench and of its import
# helper together (bench/tree_peak.py samples both). The tori are closed, so
# lightbench culls back faces (--cull-back-faces on: the same picture); f3d runs as it comes.
# Then lightbench's own breakdown (LIGHTBENCH_PHASES): milliseconds since its run began when
# each part ended and its resident memory then, medians over the runs; and the 1M file's floor
# (the helper's read alone plus one frame of the mesh, against f3d's time).
# Usage: bench/mesh.sh [RUNS]   (default 7; builds first, like scripts/run; needs python3)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-7}
DATA=${LIGHTBENCH_BENCH_DATA:-$BUILD_DIR/bench-data}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages f3d time python3 binutils
    build lightbench >/dev/null
    mkdir -p "$DATA"
    gen() { [[ -f "$DATA/$1" ]] || python3 "$ROOT/bench/make_ply.py" "$DATA/$1" "${@:2}" >&2; }
    gen torus-1m.ply 1000000
    gen torus-1m-normals.ply 1000000 --normals
    gen torus-5m.ply 5000000
    gen torus-10m.ply 10000000
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$RUNS"
fi
exe="$BUILD_DIR/app/lightbench"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# timed NAME COMMAND...: appends "seconds kilobytes" to $out/NAME, and lightbench's
# phases line (if any) to $out/NAME.phases
timed() {
    local name=$1; shift
    /usr/bin/time -f "%e %M" -o "$out/t" "$@" >/dev/null 2>"$out/err" ||
        { cat "$out/err" >&2; exit 1; }
    cat "$out/t" >>"$out/$name"
    sed -n 's/^phases: //p' "$out/err" >>"$out/$name.phases"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| file | tool | median wall (s) | median peak (MB) | wall runs (s) |"
echo "|---|---|---|---|---|"
for file in torus-1m.ply torus-1m-normals.ply torus-10m.ply; do
    for ((i = 0; i < RUNS; i++)); do # alternating, so drifts hit all alike
        LIGHTBENCH_PHASES=1 timed "lb-$file" "$exe" --mesh "$DATA/$file" --render "$out/lb.png" \
            --size 1920x1080 --cull-back-faces on
        LIGHTBENCH_IMPORT_READER=assimp timed "assimp-$file" "$exe" --mesh "$DATA/$file" \
            --render "$out/lb.png" --size 1920x1080 --cull-back-faces on
        timed "f3d-$file" f3d --output="$out/f3d.png" --resolution=1920,1080 "$DATA/$file"
    done
    for tool in lb assimp f3d; do
        s=$(awk '{print $1}' "$out/$tool-$file" | median)
        m=$(awk '{print $2}' "$out/$tool-$file" | median)
        name=$([[ $tool == lb ]] && echo lightbench || ([[ $tool == assimp ]] && echo "lightbench, Assimp's reader" || echo f3d))
        printf '| %s | %s | %.2f | %.0f | %s |\n' "$file" "$name" \
            "$s" "$(echo "$m / 1024" | bc -l)" "$(awk '{printf "%s ", $1}' "$out/$tool-$file")"
    done
    fs=$(awk '{print $1}' "$out/f3d-$file" | median); fm=$(awk '{print $2}' "$out/f3d-$file" | median)
    for tool in lb assimp; do
        ls=$(awk '{print $1}' "$out/$tool-$file" | median); lm=$(awk '{print $2}' "$out/$tool-$file" | median)
        printf '| %s | ratio %s / f3d | %.2fx | %.2fx | |\n' "$file" \
            "$([[ $tool == lb ]] && echo lightbench || echo "Assimp's reader")" \
            "$(echo "$ls / $fs" | bc -l)" "$(echo "$lm / $fm" | bc -l)"
    done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

echo
echo "lightbench's phases (ms since its run began, and its resident MB then; medians; wall"
echo "includes start and exit):"
for file in torus-1m.ply torus-1m-normals.ply torus-10m.ply; do
    line="$file:"
    for key in openGl import meshToGpu frame png; do
        v=$(sed -E "s/.*\"$key\":([0-9.]+).*/\1/" "$out/lb-$file.phases" | median)
        mb=$(sed -E "s/.*\"${key}MB\":([0-9]+).*/\1/" "$out/lb-$file.phases" | median)
        line+=" $key $v ($mb MB)"
    done
    echo "$line"
done

# The floor of the 1M file's time: the first frame needs the whole mesh, so no run is shorter
# than the helper's read alone (Assimp and the stream, into /dev/null) plus one frame of the
# mesh drawn again and again (--bench-frames: its code generated and its arrays uploaded).
for ((i = 0; i < RUNS; i++)); do
    /usr/bin/time -f "%e" -o "$out/t" "$BUILD_DIR/app/lightbench-import" "$DATA/torus-1m.ply" \
        >"$out/stream" 2>"$out/err" || { cat "$out/err" >&2; exit 1; }
    cat "$out/t" >>"$out/helper-1m"
    # Of which the file's reading: the stream's info record says it ("seconds=").
    strings -n 6 "$out/stream" | sed -n 's/^seconds=//p' >>"$out/read-1m"
    LIGHTBENCH_IMPORT_READER=assimp "$BUILD_DIR/app/lightbench-import" "$DATA/torus-1m.ply" \
        >"$out/stream" 2>"$out/err" || { cat "$out/err" >&2; exit 1; }
    strings -n 6 "$out/stream" | sed -n 's/^seconds=//p' >>"$out/assimp-1m"
    "$exe" --mesh "$DATA/torus-1m.ply" --size 1920x1080 --bench-frames 10 \
        --cull-back-faces on >"$out/frames" 2>"$out/err" || { cat "$out/err" >&2; exit 1; }
    sed -nE 's/.*"fps":([0-9.e+-]+).*/\1/p' "$out/frames" >>"$out/fps-1m"
done
helper=$(median <"$out/helper-1m")
frame=$(awk '{print 1 / $1}' "$out/fps-1m" | median)
f3d=$(awk '{print $1}' "$out/f3d-torus-1m.ply" | median)
read=$(median <"$out/read-1m")
assimp=$(median <"$out/assimp-1m")
printf 'floor of torus-1m.ply: helper alone %.3f s (runs: %s) + one frame %.3f s = %.3f s, %.2fx f3d'"'"'s %.2f s\n' \
    "$helper" "$(xargs <"$out/helper-1m")" "$frame" "$(echo "$helper + $frame" | bc -l)" \
    "$(echo "($helper + $frame) / $f3d" | bc -l)" "$f3d"
printf '  (the helper'"'"'s PLY reader alone %.3f s of it; Assimp'"'"'s ReadFile on the same file %.3f s)\n' \
    "$read" "$assimp"

echo
echo "5M triangles, 1280x720, $RUNS runs (--bench-frames 20 after the load), culling off and on:"
for ((i = 0; i < RUNS; i++)); do
    for cull in off on; do
        "$exe" --mesh "$DATA/torus-5m.ply" --size 1280x720 --bench-frames 20 \
            --cull-back-faces $cull >>"$out/5m-$cull"
    done
done
for cull in off on; do
    for key in loadSeconds fps peakMB helperPeakMB; do
        v=$(sed -E "s/.*\"$key\":([0-9.e+-]+).*/\1/" "$out/5m-$cull" | median)
        printf 'culling %s: %s median %s (runs: %s)\n' $cull "$key" "$v" \
            "$(sed -E "s/.*\"$key\":([0-9.e+-]+).*/\1/" "$out/5m-$cull" | xargs printf '%.2f ')"
    done
done

echo
echo "10M triangles (a big scan), $RUNS runs: --render at 1920x1080 (wall and GNU time's peak: the"
echo "largest process), the same under bench/tree_peak.py (the workbench and its helper sampled"
echo "together: the pair's peak), --bench-frames 1 at 1920x1080 (load), lightbench's phases:"
for ((i = 0; i < RUNS; i++)); do
    LIGHTBENCH_PHASES=1 timed lb-10m "$exe" --mesh "$DATA/torus-10m.ply" --render "$out/lb.png" \
        --size 1920x1080 --cull-back-faces on
    python3 "$ROOT/bench/tree_peak.py" "$exe" --mesh "$DATA/torus-10m.ply" --render "$out/lb.png" \
        --size 1920x1080 --cull-back-faces on 2>&1 >/dev/null |
        sed -n 's/^tree_peak_mb=\([0-9]*\).*/\1/p' >>"$out/10m-tree"
    "$exe" --mesh "$DATA/torus-10m.ply" --size 1920x1080 --bench-frames 1 \
        --cull-back-faces on >>"$out/10m-frames"
done
printf 'render: wall median %s s (runs: %s), largest process median %.0f MB\n' \
    "$(awk '{print $1}' "$out/lb-10m" | median)" "$(awk '{printf "%s ", $1}' "$out/lb-10m")" \
    "$(echo "$(awk '{print $2}' "$out/lb-10m" | median) / 1024" | bc -l)"
printf 'the pair (workbench + helper) at its peak: median %s MB (runs: %s)\n' \
    "$(median <"$out/10m-tree")" "$(xargs <"$out/10m-tree")"
v=$(sed -E 's/.*"loadSeconds":([0-9.e+-]+).*/\1/' "$out/10m-frames")
printf 'loadSeconds median %s (runs: %s)\n' "$(median <<<"$v")" "$(xargs printf '%.2f ' <<<"$v")"
line="phases:"
for key in openGl import meshToGpu frame png; do
    line+=" $key $(sed -E "s/.*\"$key\":([0-9.]+).*/\1/" "$out/lb-10m.phases" | median)"
done
echo "$line"
