#!/usr/bin/env bash
# The main job on a fresh machine: install, build, and render the built-in
# default layout to stereo.png (and its cell-id map to stereo-ids.png).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" "$root/build"
"$root/build/impossible" render --ids stereo-ids.png "$@"
echo "wrote stereo.png and stereo-ids.png"
