#!/bin/sh
# Lights: what lighting costs a frame and how close it is to `trace`
# (bench/README.md, "Lights"). For one lit layout (default
# layouts/lamp_hall.json), three sweeps, each measured in one run
# (configurations interleaved frame by frame), RUNS times (default 5):
#   lights:fixed,0,1,8,32       the fixed light, or N lights in every room
#   light-depth:0,1,2,4         the layout's own lights, light depth K
#   shadow-size:0,128,256,512,1024   cube shadow maps' size (0: no prop shadows)
# and prints, per configuration, the median frame time, its ratio to the
# sweep's first configuration (medians of the per-run ratios), the light
# images drawn, and the id mismatches and PSNR against the tracer.
#   bench/lights.sh [BUILD_DIR] [LAYOUT]   (default: build, layouts/lamp_hall.json)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
layout=${2:-$root/layouts/lamp_hall.json}
runs=${RUNS:-5}
frames=${FRAMES:-20}
size=${SIZE:-640x360}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$build/impossible" ] || { echo "lights.sh: missing $build/impossible" >&2; exit 1; }

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

sweep() {  # SWEEP -> a table
  for i in $(seq "$runs"); do
    "$build/impossible" bench "$layout" --size "$size" --frames "$frames" --sweep "$1" --error 2>/dev/null |
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

echo "lights.sh: $(basename "$layout"), $size per eye, $frames frames x $runs runs"
sweep lights:fixed,0,1,8,32
sweep light-depth:0,1,2,4
sweep shadow-size:0,128,256,512,1024
