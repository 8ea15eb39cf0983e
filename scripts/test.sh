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
phase() { printf 'test.sh: %s took %d min %d s\n' "$1" $(($2 / 60)) $(($2 % 60)) >&2; }
start=$SECONDS
"$root/scripts/build.sh" "$build" "$@"
phase "the build" $((SECONDS - start))
# The web build and its browser tests' packages (docs/web.md), but for the
# sanitizer build, which has no browser tests.
if [[ " $* " != *"IMPOSSIBLE_SANITIZE=ON"* ]]; then
  start=$SECONDS
  "$root/scripts/web-build.sh"
  phase "the web build" $((SECONDS - start))
fi
cd "$build"
start=$SECONDS
status=0
ctest --output-on-failure -j"$(nproc)" --timeout 600 -LE long || status=$?
phase "the tests" $((SECONDS - start))
exit "$status"
