#!/usr/bin/env bash
# Edit to pixels of two builds, alternating run by run in one Xvfb, with Mesa's shader cache off
# and on (a fresh cache folder per run, as a first edit finds it): the three shader pairs of
# bench/edit.sh, default trial (the helper). For a change to a program's way to the pixels.
# Usage: bench/edit_side_by_side.sh BEFORE_EXE AFTER_EXE [ROUNDS] [EDITS]  (default 3 rounds,
# 10 edits). Prints the medians, their ratio and every run, then the load average.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
OLD=${1:?before executable}
NEW=${2:?after executable}
ROUNDS=${3:-3}
EDITS=${4:-10}
R=$ROOT
if [[ -z "${LIGHTBENCH_IN_XVFB:-}" ]]; then
    ensure_packages
    LIGHTBENCH_IN_XVFB=1 exec xvfb-run -a -s "$XVFB_SCREEN" bash "$0" "$@"
fi
for ((r = 0; r < ROUNDS; r++)); do
  for cache in off on; do
    for which in old new; do
      exe=$OLD; [[ $which == new ]] && exe=$NEW
      cfg=$(mktemp -d)
      cdir=$(mktemp -d)
      ce=(MESA_SHADER_CACHE_DISABLE=true)
      [[ $cache == on ]] && ce=(MESA_SHADER_CACHE_DISABLE=false MESA_SHADER_CACHE_DIR="$cdir")
      env XDG_CONFIG_HOME="$cfg" "${ce[@]}" "$exe" --bench-edits "$EDITS" \
          --vertex "$R/bench/shaders/long.vert" --fragment "$R/bench/shaders/long.frag" |
          sed "s/^{/{\"build\":\"$which\",\"cache\":\"$cache\",/"
      rm -rf "$cfg" "$cdir"
    done
  done
done | python3 -c '
import json, os, statistics, sys
rows = [json.loads(line) for line in sys.stdin if line.startswith("{")]
print("| shaders | shader cache | before (median ms) | after (median ms) | ratio | before, all runs | after, all runs |")
print("|---|---|---|---|---|---|---|")
for name in dict.fromkeys(r["shaders"] for r in rows):
    for cache in ("off", "on"):
        b = [r["editToPixelsMs"] for r in rows if r["shaders"] == name and r["cache"] == cache and r["build"] == "old"]
        a = [r["editToPixelsMs"] for r in rows if r["shaders"] == name and r["cache"] == cache and r["build"] == "new"]
        mb, ma = statistics.median(b), statistics.median(a)
        print("| %s | %s | %.1f | %.1f | %.2fx | %s | %s |" % (name, cache, mb, ma, ma / mb,
              " ".join("%.0f" % x for x in b), " ".join("%.0f" % x for x in a)))
print()
print("load average: %.2f %.2f %.2f" % os.getloadavg())
'
