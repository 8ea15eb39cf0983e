#!/usr/bin/env bash
# The designer pictures of docs/designer.md: for every example layout, a tour
# (docs/tours/NAME.txt) and the plan of the physical floor with the tour drawn
# on it (docs/images/plan-NAME.svg and .png); the same for two generated
# layouts (docs/examples/), one on an L-shaped floor.
# Usage: scripts/make-plans.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
bin="$build/impossible"
images="$root/docs/images"
tours="$root/docs/tours"
examples="$root/docs/examples"
mkdir -p "$images" "$tours" "$examples"

"$bin" generate --play-area 6x6 --rooms 10 --seed 3 --out "$examples/generated-6x6.json"
printf '{"polygon": [[-3, -3], [3, -3], [3, 0], [0, 0], [0, 3], [-3, 3]]}\n' > "$examples/l-floor.json"
"$bin" generate --play-area-file "$examples/l-floor.json" --rooms 8 --seed 8 --out "$examples/generated-l.json"

plan() {  # NAME LAYOUT
  local name=$1 layout=$2
  "$bin" tour "$layout" --out "$tours/$name.txt" > /dev/null
  "$bin" plan "$layout" --path "$tours/$name.txt" --out "$images/plan-$name.svg" --png "$images/plan-$name.png" \
    --max-size 640 2> /dev/null
}
for layout in "$root"/layouts/*.json; do
  plan "$(basename "$layout" .json)" "$layout"
done
plan generated-6x6 "$examples/generated-6x6.json"
plan generated-l "$examples/generated-l.json"
echo "wrote $(ls "$images"/plan-*.png | wc -l) plans to $images and tours to $tours"
