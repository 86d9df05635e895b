#!/usr/bin/env bash
# Renders the icon's PNG sizes from the SVG (hicolor wants them for desktops and menus that
# cannot draw SVG). Run once after editing the SVG; the PNGs are committed beside it, so that
# building lightbench does not need librsvg. Needs rsvg-convert (Debian: librsvg2-bin).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
id=io.github.lightbench.Lightbench
command -v rsvg-convert >/dev/null || { echo "render.sh: needs rsvg-convert (apt-get install librsvg2-bin)" >&2; exit 1; }
for size in 16 24 32 48 64 128 256; do
    rsvg-convert --width "$size" --height "$size" --output "$id-$size.png" "$id.svg"
done
