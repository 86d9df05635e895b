#!/usr/bin/env bash
# Edit to pixels: in the real window under Xvfb, each of EDITS edits of the fragment shader
# (a new comment, so no cache can answer) is compiled and timed from the end of the typing
# pause to the first frame swapped with the new program. Beside it, in the same process and
# context: the bare glCompileShader + glLinkProgram of the same sources, and the same plus one
# draw call and glFinish. Medians. Mesa's shader cache is off for the whole run.
# Usage: bench/edit.sh [EDITS]   (default 50; builds first, like scripts/run)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
EDITS=${1:-50}
ensure_packages
build lightbench >/dev/null
config=$(mktemp -d) # a fresh session: no saved layout or shaders
trap 'rm -rf "$config"' EXIT
XDG_CONFIG_HOME=$config MESA_SHADER_CACHE_DISABLE=true \
    xvfb-run -a -s "$XVFB_SCREEN" "$BUILD_DIR/app/lightbench" --bench-edits "$EDITS" \
    --vertex "$ROOT/bench/shaders/long.vert" --fragment "$ROOT/bench/shaders/long.frag" |
    python3 -c '
import json, sys
print("| shaders | fragment lines | edit to pixels (ms) | compile + link (ms) | ratio | compile + link + first draw (ms) | ratio |")
print("|---|---|---|---|---|---|---|")
for line in sys.stdin:
    r = json.loads(line)
    print("| %s | %d | %.1f | %.1f | %.1fx | %.1f | %.2fx |" % (r["shaders"], r["fragmentLines"],
          r["editToPixelsMs"], r["rawCompileLinkMs"], r["ratioToCompileLink"],
          r["rawCompileLinkFirstDrawMs"], r["ratioToCompileLinkFirstDraw"]))
'
