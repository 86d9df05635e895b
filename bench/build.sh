#!/usr/bin/env bash
# Clean builds of this checkout, one variant after another and round after round (the
# machine's speed drifts by a third within an hour here, so only variants built in the same
# minutes compare): each variant configured in a folder of its own below the checkout and
# built from nothing with every core, without ccache unless the variant asks for it. Prints
# each build's wall time with the load average before it, then the medians and each median's
# ratio to the first variant's.
#
#   bench/build.sh [ROUNDS] [VARIANT...]   (default 2 rounds; variants below)
#
# A variant is NAME or NAME=CMAKE-OPTIONS, options separated by commas:
#   plain     -DLIGHTBENCH_PCH=OFF,-DLIGHTBENCH_UNITY=OFF (every file alone, as CI's last pass)
#   default   the build's defaults (unity batches, the tests' shared precompiled headers)
#   pch-only  -DLIGHTBENCH_UNITY=OFF        unity-only  -DLIGHTBENCH_PCH=OFF
#   batch16   -DLIGHTBENCH_UNITY_BATCH_SIZE=16
#   ccache-cold  the defaults through ccache, its cache emptied first (a fresh machine)
#   ccache-warm  the defaults through ccache, on the cache the variant before it filled, in the
#                same folder (a developer's build after a clean; CI on a machine that built)
# e.g. bench/build.sh 2 plain default ccache-cold ccache-warm
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../scripts/setup.sh"
ROUNDS=${1:-2}
shift || true
variants=("$@")
[[ ${#variants[@]} -gt 0 ]] || variants=(plain default)
ensure_packages
cache=$(mktemp -d "${TMPDIR:-/tmp}/lightbench-bench-ccache.XXXXXX")
trap 'rm -rf "$cache"' EXIT

options_of() {
    case "$1" in
    plain) echo "-DLIGHTBENCH_PCH=OFF -DLIGHTBENCH_UNITY=OFF -DLIGHTBENCH_CCACHE=OFF" ;;
    default) echo "-DLIGHTBENCH_CCACHE=OFF" ;;
    pch-only) echo "-DLIGHTBENCH_UNITY=OFF -DLIGHTBENCH_CCACHE=OFF" ;;
    unity-only) echo "-DLIGHTBENCH_PCH=OFF -DLIGHTBENCH_CCACHE=OFF" ;;
    batch16) echo "-DLIGHTBENCH_UNITY_BATCH_SIZE=16 -DLIGHTBENCH_CCACHE=OFF" ;;
    ccache-cold | ccache-warm) echo "-DLIGHTBENCH_CCACHE=ON" ;;
    *=*) echo "${1#*=}" | tr ',' ' ' ;;
    *) echo "bench/build.sh: unknown variant $1" >&2; exit 2 ;;
    esac
}

declare -A times
for ((r = 1; r <= ROUNDS; r++)); do
    for variant in "${variants[@]}"; do
        name=${variant%%=*}
        # ccache-warm builds where ccache-cold did: the same paths, as a second build has.
        dir="$ROOT/build-bench-${name/ccache-warm/ccache-cold}"
        [[ $name == ccache-cold ]] && rm -rf "${cache:?}"/*
        rm -rf "$dir"
        load=$(cut -d' ' -f1 /proc/loadavg)
        start=$(date +%s.%N)
        # shellcheck disable=SC2046
        CCACHE_DIR=$cache cmake -S "$ROOT" -B "$dir" -DCMAKE_BUILD_TYPE=Release \
            -DBUILD_TESTING=ON $(options_of "$variant") >/dev/null
        CCACHE_DIR=$cache cmake --build "$dir" -j"$(nproc)" >"$dir.log" 2>&1 ||
            { echo "bench/build.sh: $name failed, see $dir.log" >&2; exit 1; }
        seconds=$(echo "$(date +%s.%N) - $start" | bc)
        printf 'round %d  %-12s %6.1f s  (load %s, %s)\n' "$r" "$name" "$seconds" "$load" "$(date +%H:%M)"
        times[$name]+="$seconds "
    done
done
rm -rf "$ROOT"/build-bench-*

median() { tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
first=""
echo "medians of $ROUNDS rounds ($(nproc) cores):"
for variant in "${variants[@]}"; do
    name=${variant%%=*}
    m=$(echo "${times[$name]}" | median)
    [[ -n $first ]] || first=$m
    printf '  %-12s %6.1f s  %.2fx\n' "$name" "$m" "$(echo "$m / $first" | bc -l)"
done
