#!/bin/sh
# Lights: what lighting costs a frame and how close it is to `trace`
# (bench/README.md, "Lights"). For one lit layout (default
# layouts/lamp_hall.json), three sweeps, each measured in one run
# (configurations interleaved frame by frame), RUNS times (default 5):
#   lights:fixed,0,1,8,32       the fixed light, or N lights in every room
#     (and 1/naive, 8/naive: without the portal tests; 8/no-cache: without
#     the light cache, drawn exactly every frame; 1/one-part, 8/one-part:
#     each lit room in one part, not split by where its path images reach)
#   light-depth:0,1,2,4         the layout's own lights, light depth K
#   shadow-size:0,128,256,512,1024   cube shadow maps' size (0: no prop shadows)
# and a light behind a closed wall: a room seen from inside with 8 lamps in
# the room beside it, no portal between them, against the same without the
# lamps (they cannot reach it, so they must cost its frame nothing);
# and prints, per configuration, the median frame time, its ratio to the
# sweep's first configuration (medians of the per-run ratios), the light
# images drawn, and the id mismatches and PSNR against the tracer.
# The view: VIEW (bench's view options; default, for the lamp hall: the
# hall's table and its shadow, the lamp's pool and the door,
# "--room hall --pose 0.2,1.7,1.0,32,-31,0"; empty: the layout's start).
#   bench/lights.sh [BUILD_DIR] [LAYOUT]   (default: build, layouts/lamp_hall.json)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
layout=${2:-$root/layouts/lamp_hall.json}
runs=${RUNS:-5}
frames=${FRAMES:-20}
size=${SIZE:-640x360}
view=${VIEW---room hall --pose 0.2,1.7,1.0,32,-31,0}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$build/impossible" ] || { echo "lights.sh: missing $build/impossible" >&2; exit 1; }

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

sweep() {  # SWEEP -> a table
  for i in $(seq "$runs"); do
    # shellcheck disable=SC2086  # $view is a list of options
    "$build/impossible" bench "$layout" $view --size "$size" --frames "$frames" --sweep "$1" --error 2>/dev/null |
      awk -v run="$i" '$1 ~ /=/ && NF >= 13 { print run, $1, $2, $NF, $(NF-1) }' >>"$tmp/$1.txt"
  done
  echo "| $1 | frame ms (median) | vs first | id mismatch % | PSNR dB |"
  echo "|---|---|---|---|---|"
  first=$(awk 'NR == 1 { print $2 }' "$tmp/$1.txt")
  for config in $(awk '$1 == 1 { print $2 }' "$tmp/$1.txt"); do
    ms=$(awk -v c="$config" '$2 == c { printf "%s ", $3 }' "$tmp/$1.txt" | median)
    ratio=$(awk -v c="$config" -v f="$first" '$2 == f { base[$1] = $3 } $2 == c { v[$1] = $3 }
      END { for (r in v) printf "%.4f ", v[r] / base[r] }' "$tmp/$1.txt" | median)
    psnr=$(awk -v c="$config" '$2 == c { print $4; exit }' "$tmp/$1.txt")
    mism=$(awk -v c="$config" '$2 == c { print $5; exit }' "$tmp/$1.txt")
    printf '| %s | %.3f | %.3f | %s | %s |\n' "$config" "$ms" "$ratio" "$mism" "$psnr"
  done
  echo
}

python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
def layout(lamps):
    seen = {"id": "seen", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.8, 0.78, 0.72], "checker": 0.5,
            "ambient": [0.2, 0.2, 0.2], "lights": [{"position": [0, 2.5, 0], "intensity": 3}]}
    beside = {"id": "beside", "min": [2, 0, -2], "max": [6, 3, 2], "color": [0.7, 0.7, 0.8]}
    if lamps:
        beside["lights"] = [{"position": [2.5 + 0.4 * i, 1.5, 0.5], "intensity": 5} for i in range(8)]
    return {"format": "impossible-layout", "version": 1, "name": "closed wall", "lighting": "lights",
            "light_depth": 4, "start": {"room": "seen", "position": [-1.5, 1.6, 1.5], "yaw_deg": -60},
            "rooms": [seen, beside], "portals": []}
json.dump(layout(True), open(tmp + "/closed_lamps.json", "w"))
json.dump(layout(False), open(tmp + "/closed_dark.json", "w"))
PY
closed_wall() {
  with="" without=""
  for i in $(seq "$runs"); do
    for l in closed_lamps closed_dark; do
      ms=$("$build/impossible" bench "$tmp/$l.json" --size "$size" --frames "$frames" 2>/dev/null | awk '$1 == "base" { print $2 }')
      if [ "$l" = closed_lamps ]; then with="$with $ms"; else without="$without $ms"; fi
    done
  done
  images=$("$build/impossible" validate "$tmp/closed_lamps.json" | grep -i "light path" | tr -s " " | paste -sd ";" - || true)
  echo "| closed wall | frame ms (median) |"
  echo "|---|---|"
  echo "| 8 lamps behind the wall | $(echo "$with" | median) |"
  echo "| no lamps behind the wall | $(echo "$without" | median) |"
  echo
  echo "validate: $images"
  echo
}

echo "lights.sh: $(basename "$layout") ${view:-(start)}, $size per eye, $frames frames x $runs runs"
sweep lights:fixed,0,1,8,32,1/naive,8/naive,1/one-part,8/one-part,8/no-cache
sweep light-depth:0,1,2,4
sweep shadow-size:0,128,256,512,1024
closed_wall
