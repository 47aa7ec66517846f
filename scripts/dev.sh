#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine:
#   scripts/dev.sh run    install what is missing, build Release, render the built-in scene
#   scripts/dev.sh test   install what is missing, build, run the whole test suite
#                         (Release, then again under -fsanitize=address,undefined), then fuzz the
#                         scene parser and the model import for a fixed budget (fuzz/run.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian packages only (docs/dependencies.md): nothing vendored, nothing downloaded at build time.
PACKAGES=(
  g++ cmake make pkg-config
  libglm-dev nlohmann-json3-dev libcli11-dev libstb-dev libassimp-dev libdeflate-dev libtbb-dev libhwy-dev libembree-dev libopenexr-dev
  libgif-dev libwebp-dev libjpeg62-turbo-dev
  libsdl2-dev libimgui-dev
  slurmctld slurmd slurm-client munge
  libgtest-dev libbenchmark-dev libosmesa6-dev assimp-testmodels fonts-dejavu-core
  xvfb xdotool x11-apps imagemagick bubblewrap help2man
  pybind11-dev python3-dev python3-numpy python3-pytest python3-nbclient python3-nbformat python3-ipykernel python3-ipywidgets
  clang libclang-rt-14-dev
)

install_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "illum: installing ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

jobs=$(nproc 2>/dev/null || echo 2)

build() {  # build DIR [TARGET] -- [cmake args...]
  local dir=$1 target=${2:-all}
  shift 2 || shift $#
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
  cmake --build "$dir" -j "$jobs" --target "$target"
}

case "${1:-}" in
  run)
    install_packages
    build build illum_cli
    ./build/apps/illum/illum render -o illum.png
    ;;
  test)
    install_packages
    build build all
    (cd build && ctest --output-on-failure -j "$jobs")
    echo "illum: the same suite under AddressSanitizer and UndefinedBehaviorSanitizer"
    build build-asan all -DILLUM_SANITIZE=ON -DILLUM_BUILD_BENCH=OFF
    # Every test again, but the docs pictures' byte-for-byte check: the run above holds their bytes,
    # and drawing all of them again under the sanitizers (6 of its 13 minutes) would take the run
    # past an hour on two cores; the code that draws them is under the sanitizers in its own tests.
    (cd build-asan && ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$PWD/../tests/lsan.supp \
      UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$jobs" -E '^Docs\.EveryPictureIsWhatItsCommandDraws$')
    echo "illum: fuzzing (libFuzzer, ASan+UBSan) for a fixed budget"
    fuzz/run.sh --ci
    ;;
  *)
    echo "usage: scripts/dev.sh run|test" >&2
    exit 2
    ;;
esac
