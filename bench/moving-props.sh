#!/bin/sh
# Moving props: what a frame's dynamic objects cost the rasteriser
# (bench/README.md, "Moving props and volumes"). For N = 100 and 1000 crates
# spread over two 20 x 20 m rooms joined by a door (their positions from a
# fixed linear congruential sequence), writes the layout twice: with every
# crate moving (a 4 s back-and-forth path, so each is a dynamic object placed
# by walk::place_objects each frame, some crossing the door) and with none
# moving (all in their cells' meshes), and runs `impossible bench` on both at
# --time 1 (--size 640x360 --frames FRAMES, RUNS runs, still and moving
# alternating run by run; medians printed, and the median of the per-run
# ratios moving / still).
#   bench/moving-props.sh [BUILD_DIR]   (default: build)
set -eu
build=${1:-build}
runs=${RUNS:-3}
frames=${FRAMES:-20}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -x "$build/impossible" ] || { echo "moving-props.sh: missing $build/impossible" >&2; exit 1; }

layout() {  # N MOVING(0/1) > file
    awk -v n="$1" -v moving="$2" 'BEGIN {
        s = 12345
        printf "{ \"format\": \"impossible-layout\", \"version\": 1,\n"
        printf "  \"start\": { \"room\": \"a\", \"position\": [0, 1.6, 9], \"yaw_deg\": 0 },\n"
        printf "  \"rooms\": [ { \"id\": \"a\", \"min\": [-10, 0, -10], \"max\": [10, 3, 10], \"props\": [\n"
        for (i = 0; i < n; ++i) {
            s = (s * 1103515245 + 12345) % 2147483648; x = -9 + 18 * s / 2147483648
            s = (s * 1103515245 + 12345) % 2147483648; z = -9 + 18 * s / 2147483648
            printf "%s    { \"id\": \"c%d\", \"box\": { \"min\": [%.3f, 0, %.3f], \"max\": [%.3f, 0.3, %.3f] }, \"color\": [0.9, 0.5, 0.1]", (i ? ",\n" : ""), i, x, z, x + 0.2, z + 0.2
            if (moving) printf ", \"motion\": { \"path\": [[0, 0, 0, 0], [2, 0, 0, -1.5], [4, 0, 0, 0]], \"loop\": true }"
            printf " }"
        }
        printf " ] },\n    { \"id\": \"b\", \"min\": [-10, 0, -10], \"max\": [10, 3, 10], \"checker\": 0.5 } ],\n"
        printf "  \"portals\": [\n"
        printf "    { \"id\": \"ab\", \"room\": \"a\", \"center\": [0, 1.5, 0], \"normal\": [0, 0, 1], \"width\": 6, \"height\": 3, \"target\": \"ba\" },\n"
        printf "    { \"id\": \"ba\", \"room\": \"b\", \"center\": [0, 1.5, 0], \"normal\": [0, 0, -1], \"width\": 6, \"height\": 3, \"target\": \"ab\" } ] }\n"
    }'
}

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# One bench run of a layout: "frame_ms submit_ms draw_calls".
run() {
    "$build/impossible" bench "$1" --time 1 --size 640x360 --frames "$frames" --json "$tmp/out.json" > /dev/null
    echo "$(grep -o '"frame_ms_median": *[-0-9.e+]*' "$tmp/out.json" | head -n 1 | sed 's/.*: *//')" \
        "$(grep -o '"submit_ms_median": *[-0-9.e+]*' "$tmp/out.json" | head -n 1 | sed 's/.*: *//')" \
        "$(grep -o '"draw_calls": *[0-9.]*' "$tmp/out.json" | head -n 1 | sed 's/.*: *//')"
}

for n in 100 1000; do
    for moving in 0 1; do
        layout "$n" "$moving" > "$tmp/props-$n-$moving.json"
        "$build/impossible" validate "$tmp/props-$n-$moving.json" > /dev/null 2>&1
    done
    # Still and moving alternate run by run, so that the machine's load
    # hits both alike; the ratio is taken per run, then its median.
    frame0="" cpu0="" frame1="" cpu1="" ratios=""
    r=0
    while [ $r -lt "$runs" ]; do
        set -- $(run "$tmp/props-$n-0.json") $(run "$tmp/props-$n-1.json")
        frame0="$frame0 $1" cpu0="$cpu0 $2" draws0=$3
        frame1="$frame1 $4" cpu1="$cpu1 $5" draws1=$6
        ratios="$ratios $(echo "$4 $1" | awk '{ printf "%.3f", $1 / $2 }')"
        r=$((r + 1))
    done
    echo "props=$n moving=0 frame_ms=$(echo "$frame0" | median) submit_ms=$(echo "$cpu0" | median) draw_calls=$draws0"
    echo "props=$n moving=1 frame_ms=$(echo "$frame1" | median) submit_ms=$(echo "$cpu1" | median) draw_calls=$draws1"
    echo "props=$n moving/still per run:$ratios median $(echo "$ratios" | median)"
done
