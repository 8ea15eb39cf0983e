#!/usr/bin/env bash
# Install, build and run every test. Usage: scripts/test.sh [BUILD_DIR] [cmake args...]
# CI also runs it with -DIMPOSSIBLE_SANITIZE=ON in a second build directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
"$root/scripts/build.sh" "$build" -DIMPOSSIBLE_WERROR=ON "$@"
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
