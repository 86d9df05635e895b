#!/usr/bin/env bash
# CI as a new machine runs it: a fresh clone of COMMIT (default HEAD) in a temporary folder,
# with ../shared beside it as CI has it, through `.ci/run`, timed; each step's own lines
# (installed, configured and built, tests, package) and the load average are picked out of
# its log at the end. The caches (ccache's, Mesa's and Qt's shader caches: XDG_CACHE_HOME) are
# fresh, empty ones unless --warm-cache is given (then the user's own, as a machine that built
# before has them). Packages already installed stay installed: on a machine that has none,
# the first step's install adds its own time (its "installed in" line).
#
#   bench/ci.sh [--warm-cache] [COMMIT]
#
# Keeps the log in the temporary folder and prints its path; the clone is removed.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
warm=0
if [[ ${1:-} == --warm-cache ]]; then
    warm=1
    shift
fi
commit=${1:-HEAD}
work=$(mktemp -d "${TMPDIR:-/tmp}/lightbench-ci.XXXXXX")
git clone -q "$ROOT" "$work/main"
git -C "$work/main" checkout -q "$(git -C "$ROOT" rev-parse "$commit")"
[[ -d $ROOT/../shared ]] && ln -s "$(cd "$ROOT/../shared" && pwd)" "$work/shared"
[[ $warm -eq 1 ]] || export XDG_CACHE_HOME="$work/cache"
log="$work/ci.log"
echo "bench/ci.sh: $(git -C "$work/main" log --oneline -1) in $work/main, load $(cut -d' ' -f1-3 /proc/loadavg)"
start=$SECONDS
status=0
(cd "$work/main" && bash .ci/run) >"$log" 2>&1 || status=$?
echo "bench/ci.sh: .ci/run exited $status after $((SECONDS - start)) s, load $(cut -d' ' -f1-3 /proc/loadavg)"
grep -E "^(lightbench: (installed|configured|tests took)|ci: |Total Test time|[0-9]+% tests passed)" "$log" || true
rm -rf "$work/main" "$work/cache"
echo "bench/ci.sh: the whole log is $log"
exit $status
