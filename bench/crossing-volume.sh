#!/bin/sh
# Crossing objects and volumes: what each adds to a frame (bench/README.md,
# "Moving props and volumes"), each figure with its error against `trace`.
# Pairs of layouts seen from the same pose, the second without the feature:
#   crossing     layouts/crossing.json: the table and the chair half through
#                the door (each drawn twice: cut in the kitchen, imaged in
#                the pantry) / the same moved 1.3 m away from the door
#                (wholly in the kitchen, static);
#   volume       layouts/scanner_lab.json: the scanner volume / no volume.
# Runs `impossible bench --error --size 640x360` on the two, alternately,
# RUNS times each (default 5), and prints the medians of the frame time
# and the draw calls and the id mismatches against the tracer.
#   bench/crossing-volume.sh [BUILD_DIR]   (default: build)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
runs=${RUNS:-5}
frames=${FRAMES:-20}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$build/impossible" ] || { echo "crossing-volume.sh: missing $build/impossible" >&2; exit 1; }

cp -r "$root/layouts/models" "$tmp/models"
python3 - "$root" "$tmp" <<'PY'
import json, sys
root, tmp = sys.argv[1], sys.argv[2]
c = json.load(open(root + "/layouts/crossing.json"))
json.dump(c, open(tmp + "/crossing.json", "w"))
for p in c["rooms"][0]["props"][:2]:  # the table and the chair, 1.3 m towards +z
    if "box" in p:
        p["box"]["min"][2] += 1.3
        p["box"]["max"][2] += 1.3
    else:
        p["position"][2] += 1.3
json.dump(c, open(tmp + "/crossing_apart.json", "w"))
v = json.load(open(root + "/layouts/scanner_lab.json"))
json.dump(v, open(tmp + "/volume.json", "w"))
v["portals"] = []
json.dump(v, open(tmp + "/volume_none.json", "w"))
PY

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# bench LAYOUT POSE ROOM -> "median_ms draws id_mismatch_pct"
bench() {
  "$build/impossible" bench "$tmp/$1" --room "$3" --pose="$2" --size 640x360 --frames "$frames" --error 2>/dev/null |
    awk '$1 == "base" { print $2, $8, $12 }'
}

pair() {  # NAME WITH WITHOUT POSE ROOM
  with_ms="" without_ms=""
  for i in $(seq "$runs"); do
    set -- "$1" "$2" "$3" "$4" "$5" "$(bench "$2" "$4" "$5")" "$(bench "$3" "$4" "$5")"
    with_ms="$with_ms $(echo "$6" | cut -d' ' -f1)"
    without_ms="$without_ms $(echo "$7" | cut -d' ' -f1)"
    with_rest=$(echo "$6" | cut -d' ' -f2-)
    without_rest=$(echo "$7" | cut -d' ' -f2-)
  done
  w=$(echo "$with_ms" | median)
  wo=$(echo "$without_ms" | median)
  echo "$1: with $w ms (draws, id mismatch %: $with_rest), without $wo ms ($without_rest), ratio $(echo "$w $wo" | awk '{ printf "%.3f", $1 / $2 }')"
}

pair crossing crossing.json crossing_apart.json "-1.5,1.5,1.8,-35.8,-26,0" kitchen
pair volume volume.json volume_none.json "0.3,1.6,2.0,10,0,0" lab
