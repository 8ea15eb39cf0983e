#!/usr/bin/env bash
# Install, build and run the tests. Usage: scripts/test.sh [BUILD_DIR] [cmake args...]
# Every test but those labelled "long" (the browser tests' smokes included) (the differential fuzzer's full case
# sets; their smokes run here): .ci/run runs those next, by hand
# `cd build && ctest -L long` (tests/README.md).
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
# The web build and its browser tests' packages (docs/web.md), but for the
# sanitizer build, which has no browser tests.
if [[ " $* " != *"IMPOSSIBLE_SANITIZE=ON"* ]]; then
  "$root/scripts/web-build.sh"
fi
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 600 -LE long
