#!/usr/bin/env bash
# Edit to pixels: in the real window under Xvfb, each of EDITS edits of the fragment shader
# (a new comment, so no cache can answer) is compiled and timed from the end of the typing
# pause to the first frame swapped with the new program. Beside it, in the same process and
# context: the bare glCompileShader + glLinkProgram of the same sources, and the same plus one
# draw call and glFinish. Medians. Mesa's shader cache is off for the whole run.
# Each shader pair is measured with every program trial (LIGHTBENCH_PROGRAM_TRIAL): "helper"
# (the default: a program with loops is tried in lightbench-trial before it draws), "window"
# (tried in the window's own context) and "off" (drawn untried), one process each, in turn.
# With SHADER_CACHE=on, Mesa's shader cache is on instead (in a fresh folder of its own), as
# users have it: each edit is new text to the helper's compile, and the window's compile of the
# same text after it may find the helper's work there.
# Usage: [SHADER_CACHE=on] bench/edit.sh [EDITS] [ROUNDS]   (default 50 edits, 1 round; builds
# first, like scripts/run)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
EDITS=${1:-50}
ROUNDS=${2:-1}
ensure_packages
build lightbench >/dev/null
config=$(mktemp -d) # a fresh session: no saved layout or shaders
cache=$(mktemp -d)
trap 'rm -rf "$config" "$cache"' EXIT
cache_env=(MESA_SHADER_CACHE_DISABLE=true)
[[ ${SHADER_CACHE:-off} == on ]] && cache_env=(MESA_SHADER_CACHE_DISABLE=false MESA_SHADER_CACHE_DIR=$cache)
for ((round = 0; round < ROUNDS; round++)); do
    for trial in helper window off; do
        env XDG_CONFIG_HOME="$config" "${cache_env[@]}" LIGHTBENCH_PROGRAM_TRIAL=$trial \
            xvfb-run -a -s "$XVFB_SCREEN" "$BUILD_DIR/app/lightbench" --bench-edits "$EDITS" \
            --vertex "$ROOT/bench/shaders/long.vert" --fragment "$ROOT/bench/shaders/long.frag"
    done
done | python3 -c '
import json, os, statistics, sys
rows = [json.loads(line) for line in sys.stdin]
print("| shaders | fragment lines | trial | edit to pixels (ms) | compile + link (ms) | ratio | compile + link + first draw (ms) | ratio | vs. trial off |")
print("|---|---|---|---|---|---|---|---|---|")
def med(name, trial, key):
    return statistics.median(r[key] for r in rows if r["shaders"] == name and r["trial"] == trial)
seen = []
for r in rows:
    key = (r["shaders"], r["trial"])
    if key in seen:
        continue
    seen.append(key)
    name, trial = key
    e, c, d = (med(name, trial, k) for k in ("editToPixelsMs", "rawCompileLinkMs", "rawCompileLinkFirstDrawMs"))
    print("| %s | %d | %s | %.1f | %.1f | %.1fx | %.1f | %.2fx | %.2fx |" % (name, r["fragmentLines"],
          trial, e, c, e / c, d, e / d, e / med(name, "off", "editToPixelsMs")))
print()
print("load average: %.2f %.2f %.2f" % os.getloadavg())
'
