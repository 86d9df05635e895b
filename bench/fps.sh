#!/usr/bin/env bash
# Frames per second at 1280x720 under Xvfb (Mesa llvmpipe here), for the default scene, a
# generated 1M-triangle torus, 16 and 32 objects of 1,024 triangles each beside the same
# spheres as one mesh (the same triangles on the same pixels: what each object costs), and
# the default scene textured (the checker, an image, an image with mipmaps). Each figure is the
# median of RUNS processes; each process
# draws FRAMES frames offscreen through the same renderer as the window (--bench-frames).
# Usage: bench/fps.sh [RUNS] [FRAMES]   (builds first, like scripts/run)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
RUNS=${1:-7}
FRAMES=${2:-30}
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages
    build lightbench >/dev/null
    # One Xvfb for every case, so that they are measured side by side.
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$RUNS" "$FRAMES"
fi
exe="$BUILD_DIR/app/lightbench"

measure() { # name, lightbench options...
    local name=$1; shift
    local fps=()
    for ((i = 0; i < RUNS; i++)); do
        fps+=("$("$exe" --size 1280x720 --bench-frames "$FRAMES" "$@" |
                 sed -E 's/.*"fps":([0-9.e+-]+).*/\1/')")
    done
    local median
    median=$(printf '%s\n' "${fps[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
    local tris
    tris=$("$exe" --size 64x64 --bench-frames 1 "$@" | sed -E 's/.*"triangles":([0-9]+).*/\1/')
    printf '| %s | %s | %.1f | %s |\n' "$name" "$tris" "$median" "$(printf '%.1f ' "${fps[@]}")"
}

echo "| scene | triangles | median fps | all runs |"
echo "|---|---|---|---|"
measure "default (sphere, Phong shading)"
measure "default, Gouraud" --shading gouraud
measure "torus 1M triangles, Phong shading" --shape torus --tessellation 500
measure "torus 1M triangles, Gouraud" --shape torus --tessellation 500 --shading gouraud
grid=$(mktemp -d)
trap 'rm -rf "$grid"' EXIT
for n in 16 32; do
    python3 "$(dirname "${BASH_SOURCE[0]}")/grid_objects.py" "$grid/$n.json" $n
    python3 "$(dirname "${BASH_SOURCE[0]}")/grid_objects.py" "$grid/$n-merged.json" $n \
        --merged "$grid/$n.obj"
done
measure "16 spheres of 1,024 triangles, 16 materials (4x4 grid)" --scene "$grid/16.json"
measure "the same 16 spheres as one mesh (one draw)" --scene "$grid/16-merged.json"
measure "one sphere of as many triangles" --tessellation 128
measure "32 spheres of 1,024 triangles, 32 materials (8x4 grid)" --scene "$grid/32.json"
measure "the same 32 spheres as one mesh (one draw)" --scene "$grid/32-merged.json"
examples="$(dirname "${BASH_SOURCE[0]}")/../resources/examples"
measure "default, texture on (the checker, linear)" --texture on
measure "default, 512x512 image, linear" --texture-file "$examples/bricks.png"
measure "default, 512x512 image, trilinear mipmaps" --texture-file "$examples/bricks.png" \
    --texture-mipmaps on
measure "texture filtering example (3 floors: nearest, linear, mipmaps)" \
    --scene "$examples/texture_filtering.json"
