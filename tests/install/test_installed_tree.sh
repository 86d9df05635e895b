#!/usr/bin/env bash
# An installed tree as a user gets it: this build installed with `cmake --install` into a
# temporary prefix, then moved to another folder (only paths relative to bin/lightbench may
# lead to its helpers), then checked by scripts/check_installed_tree: the layout, the desktop
# files, and the headless modes and the window run from there. Bad inputs it tries: a shader
# with a syntax error (--check), a wrong program (--grade), a broken OBJ (--mesh: the import
# helper's own reason, not "cannot start"); and no installed file may name this build tree.
#   test_installed_tree.sh CMAKE BUILD_DIR SOURCE_DIR [--sanitized]
set -euo pipefail
cmake=$1 build=$2 source=$3
shift 3
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lightbench-install-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# Stripped, as the package is: debug information (the sanitizer build's -g1) names the build
# tree where it compiled, which no run-time lookup reads.
"$cmake" --install "$build" --prefix "$tmp/installed" --strip >"$tmp/install.log" ||
    { cat "$tmp/install.log" >&2; exit 1; }
mv "$tmp/installed" "$tmp/moved"
"$source/scripts/check_installed_tree" --build-dir "$build" "$@" "$tmp/moved"
