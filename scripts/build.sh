#!/usr/bin/env bash
# Installs what is missing, configures and builds.
# Usage: scripts/build.sh [BUILD_DIR] [--target T] [cmake args...]
# BUILD_DIR defaults to build/ in the repository. The main job
# (render-default.sh) and the tests (test.sh) both come through here with the
# same configuration, so they share one build tree and nothing is compiled
# twice; --target builds one target (the program) instead of everything.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
target=()
if [ "${1:-}" = "--target" ]; then target=(--target "$2"); shift 2; fi
"$root/scripts/setup.sh"
generator=()
# A tree configured before by another generator keeps it.
[ -f "$build/CMakeCache.txt" ] || generator=(-G Ninja)
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DIMPOSSIBLE_WERROR=ON "$@" >/dev/null
cmake --build "$build" "${target[@]}" -j"$(nproc)"
