#!/usr/bin/env bash
# Install, build and run every test. Usage: scripts/test.sh [BUILD_DIR] [cmake args...]
# The build is the main job's (scripts/build.sh, the same configuration and
# tree), so a tree that render-default.sh built only adds the tests.
# CI also runs it with -DIMPOSSIBLE_SANITIZE=ON in a second build directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
# valgrind runs the image decoders' test (image_decode_valgrind).
"$root/scripts/setup.sh" valgrind
"$root/scripts/build.sh" "$build" "$@"
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
