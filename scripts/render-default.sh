#!/usr/bin/env bash
# The main job on a fresh machine: install what is missing, build the program,
# and render the built-in default layout to stereo.png (and its cell-id map to
# stereo-ids.png) in the current directory. Extra arguments go to `render`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh" "$root/build" --target impossible
"$root/build/impossible" render --ids stereo-ids.png "$@"
echo "wrote stereo.png and stereo-ids.png"
