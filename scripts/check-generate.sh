#!/usr/bin/env bash
# Checks `impossible generate` end to end: for 50 seeds on square floors from
# 3 x 3 m to 8 x 8 m and an L-shaped floor, the generated layout must pass
# `validate` with every room reachable and inside the play area, and the
# `tour` of it, replayed by `walk`, must visit every room. The same seed must
# write the same bytes. Prints one line per floor and a total.
# Usage: scripts/check-generate.sh [BUILD_DIR] [SEEDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
seeds=${2:-50}
bin="$build/impossible"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '{"polygon": [[-3, -3], [3, -3], [3, 0], [0, 0], [0, 3], [-3, 3]]}\n' > "$work/l.json"
# floor name, generate's floor options, rooms
floors=(
  "3x3|--play-area 3x3|2"
  "4x4|--play-area 4x4|3"
  "5x5|--play-area 5x5|4"
  "6x6|--play-area 6x6|5"
  "7x7|--play-area 7x7|6"
  "8x8|--play-area 8x8|6"
  "L6x6|--play-area-file $work/l.json|4"
)
failures=0
total=0
for entry in "${floors[@]}"; do
  IFS='|' read -r name options rooms <<< "$entry"
  ok=0; physical=0; virtual=0; closest=100
  for seed in $(seq 1 "$seeds"); do
    total=$((total + 1))
    layout="$work/$name-$seed.json"
    # shellcheck disable=SC2086
    if ! "$bin" generate $options --rooms "$rooms" --seed "$seed" --out "$layout" 2> "$work/err"; then
      echo "FAIL $name seed $seed: generate: $(cat "$work/err")"; failures=$((failures + 1)); continue
    fi
    # shellcheck disable=SC2086
    if ! "$bin" generate $options --rooms "$rooms" --seed "$seed" 2> /dev/null | cmp -s - "$layout"; then
      echo "FAIL $name seed $seed: not deterministic"; failures=$((failures + 1)); continue
    fi
    if ! "$bin" validate "$layout" --json > "$work/report.json" 2> "$work/err"; then
      echo "FAIL $name seed $seed: validate: $(head -1 "$work/err")"; failures=$((failures + 1)); continue
    fi
    problems=$(jq -r '[.unreachable_rooms[], .rooms_outside_play_area[], .doors_outside_play_area[]] | length' "$work/report.json")
    over=$(jq -r '[.overlaps[] | select(.noticeable)] | length' "$work/report.json")
    if [ "$problems" != 0 ] || [ "$over" != 0 ]; then
      echo "FAIL $name seed $seed: $problems rooms or doors unreachable or outside, $over overlaps over the limit"
      failures=$((failures + 1)); continue
    fi
    if ! "$bin" tour "$layout" --out "$work/tour.txt" > "$work/tour.out" 2> "$work/err"; then
      echo "FAIL $name seed $seed: tour: $(head -1 "$work/err")"; failures=$((failures + 1)); continue
    fi
    visited=$("$bin" walk "$layout" --path "$work/tour.txt" | jq -r .room | sort -u | wc -l)
    if [ "$visited" != "$rooms" ]; then
      echo "FAIL $name seed $seed: the walk visits $visited of $rooms rooms"; failures=$((failures + 1)); continue
    fi
    ok=$((ok + 1))
    physical=$(awk -v a="$physical" '/^physical distance:/ {print a + $3}' "$work/tour.out")
    virtual=$(awk -v a="$virtual" '/^virtual distance:/ {print a + $3}' "$work/tour.out")
    closest=$(awk -v a="$closest" '/^closest approach/ {v = $(NF-1) + 0; print (v < a ? v : a)}' "$work/tour.out")
  done
  awk -v n="$name" -v ok="$ok" -v s="$seeds" -v r="$rooms" -v p="$physical" -v v="$virtual" -v c="$closest" \
    'BEGIN { printf "%-5s %d rooms: %d/%d seeds pass; tour mean %.1f m physical, %.1f m virtual; closest to the edge %.2f m\n", n, r, ok, s, (ok ? p / ok : 0), (ok ? v / ok : 0), c }'
done
echo "$((total - failures))/$total layouts pass"
[ "$failures" = 0 ]
