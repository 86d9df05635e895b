# Sourced by scripts/run and scripts/test: installs the Debian packages that are missing
# (apt-get, only when something is missing), then configures and builds with CMake (Release).

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD_DIR=${LIGHTBENCH_BUILD_DIR:-$ROOT/build}
# -noreset: Xvfb signals xvfb-run (SIGUSR1) at each server reset, which follows the last client's
# exit; one arriving during xvfb-run's clean-up made it report a failed rm and exit 5 with
# Xvfb left running (seen in CI under ASan, 3 runs in 22 here; none in 40 with -noreset).
XVFB_SCREEN="-screen 0 1920x1080x24 -noreset"

# qt6-qpa-plugins holds the xcb platform; xvfb + xauth + Mesa give OpenGL without a display.
# qt6-tools-dev + qt6-l10n-tools: CMake's LinguistTools (lupdate, lrelease) for the window's
# languages; qt6-translations-l10n and libqscintilla2-qt6-l10n: Qt's and the editor's own words.
# qt6-charts-dev: the Plots panel and --plot (Qt's own charts, polar ones too); qt6-svg-dev:
# QSvgGenerator for --plot's SVG.
PACKAGES=(cmake g++ make qt6-base-dev libqt6opengl6-dev qt6-qpa-plugins libglm-dev
          libqscintilla2-qt6-dev libassimp-dev libmimalloc-dev libpng-dev
          xvfb xauth libgl1-mesa-dri fonts-dejavu-core
          qt6-tools-dev qt6-l10n-tools qt6-translations-l10n libqscintilla2-qt6-l10n
          qt6-charts-dev qt6-svg-dev
          ccache lld)
# ccache: a second build of what was built before (a clean build folder, another branch and
# back, CI on a machine that built) compiles from the cache; lld links the tests' some 80
# executables in a fifth of GNU ld's time (cmake/build_speed.cmake).
# Only the tests need these: Debian's corpus of ~600 model files, valid and broken; Python for
# CodeRunner's template (resources/autograders/) and the autograders' checks of their JSON.
TEST_PACKAGES=(assimp-testmodels python3)
# Only scripts/package needs these: dpkg-shlibdeps (dpkg-dev) and `file` for the package's
# dependencies, and the checkers of the package and of the desktop's files it installs.
PACKAGE_PACKAGES=(dpkg-dev file lintian desktop-file-utils appstream shared-mime-info man-db)

# ensure_packages [EXTRA...]: installs whatever of PACKAGES and EXTRA is missing.
ensure_packages() {
    local missing=()
    for p in "${PACKAGES[@]}" "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
    done
    [[ ${#missing[@]} -eq 0 ]] && return 0
    echo "lightbench: installing ${missing[*]}" >&2
    local sudo=()
    if [[ $(id -u) -ne 0 ]]; then
        command -v sudo >/dev/null || { echo "lightbench: need root or sudo to install ${missing[*]}" >&2; exit 1; }
        sudo=(sudo)
    fi
    local start=$SECONDS
    "${sudo[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
        "${missing[@]}" >&2
    echo "lightbench: installed in $((SECONDS - start)) s" >&2
}

# What build() gives CMake besides the build type and the tests (scripts/test --sanitize adds).
CMAKE_OPTIONS=()

# build [TARGET...]: configures once (tests included) and builds the TARGETs, or everything;
# says how long it took (CI's log, bench/README.md's "Build and CI").
build() {
    local start=$SECONDS
    cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON \
        "${CMAKE_OPTIONS[@]}" >/dev/null
    cmake --build "$BUILD_DIR" -j"$(nproc)" ${1:+--target "$@"}
    echo "lightbench: configured and built $(basename "$BUILD_DIR") in $((SECONDS - start)) s" \
        "(load average $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null))" >&2
}

# Qt warns on every start without a runtime directory (containers, CI); give it a private one.
if [[ -z "${XDG_RUNTIME_DIR:-}" ]]; then
    export XDG_RUNTIME_DIR="/tmp/lightbench-runtime-$(id -u)"
    mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
fi
