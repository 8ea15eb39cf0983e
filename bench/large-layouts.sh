#!/bin/sh
# Large layouts: how loading, validation and rendering scale with the number
# of rooms (bench/README.md, "Large layouts").
#   bench/large-layouts.sh [BUILD_DIR]   (default: build)
# For N = 10, 30, 100, 300, 1000 rooms: writes the grid layout of N rooms
# (make_large_layout, src/design/large_layout.hpp), times its load, report and
# scene build in process (time_layout, median of 5), the whole
# `impossible validate` (wall clock, median of RUNS), and the start view
# (`impossible bench --size 640x360 --frames FRAMES`, median of RUNS runs,
# the sizes interleaved run by run). Writes bench/results/large_layouts.csv
# and, with gnuplot, bench/results/load_vs_rooms.svg.
set -eu
build=${1:-build}
runs=${RUNS:-3}
frames=${FRAMES:-20}
sizes=${SIZES:-"10 30 100 300 1000"}
here=$(cd "$(dirname "$0")" && pwd)
results=$here/results
mkdir -p "$results"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for tool in "$build/impossible" "$build/tools/make_large_layout" "$build/tools/time_layout"; do
    [ -x "$tool" ] || { echo "large-layouts.sh: missing $tool (cmake --build $build)" >&2; exit 1; }
done

now_ns() { date +%s%N; }
median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
json_number() { grep -o "\"$1\": *[-0-9.e+]*" "$2" | head -n 1 | sed 's/.*: *//'; }

for n in $sizes; do
    "$build/tools/make_large_layout" "$n" "$tmp/large_$n.json"
    "$build/impossible" validate "$tmp/large_$n.json" >"$tmp/validate_$n.txt" 2>&1 || {
        cat "$tmp/validate_$n.txt" >&2; exit 1; }
    "$build/tools/time_layout" "$tmp/large_$n.json" 5 >"$tmp/stages_$n.txt"
    : >"$tmp/validate_ms_$n"
    : >"$tmp/frame_ms_$n"
done

# Runs interleaved over the sizes, so that machine noise hits them alike.
r=1
while [ "$r" -le "$runs" ]; do
    for n in $sizes; do
        t0=$(now_ns)
        "$build/impossible" validate "$tmp/large_$n.json" >/dev/null 2>&1
        t1=$(now_ns)
        echo "$(( (t1 - t0) / 1000 ))" | awk '{ printf "%.1f ", $1 / 1000 }' >>"$tmp/validate_ms_$n"
        "$build/impossible" bench "$tmp/large_$n.json" --size 640x360 --frames "$frames" \
            --json "$tmp/bench_${n}_$r.json" >/dev/null
        printf '%s ' "$(json_number frame_ms_median "$tmp/bench_${n}_$r.json")" >>"$tmp/frame_ms_$n"
    done
    r=$((r + 1))
done
# The error of the same view against the tracer, once per size (not timed).
for n in $sizes; do
    "$build/impossible" bench "$tmp/large_$n.json" --size 640x360 --frames 1 --warmup 0 --profile-frames 0 \
        --error --json "$tmp/error_$n.json" >/dev/null
done

csv=$results/large_layouts.csv
echo "n,rooms,portals,load_ms,report_ms,scene_ms,validate_ms,frame_ms,draw_calls,triangles,id_mismatch_percent,psnr_db" >"$csv"
for n in $sizes; do
    read -r rooms portals load report scene <"$tmp/stages_$n.txt"
    validate=$(median <"$tmp/validate_ms_$n")
    frame=$(median <"$tmp/frame_ms_$n")
    draws=$(json_number draw_calls "$tmp/bench_${n}_1.json")
    tris=$(json_number triangles "$tmp/bench_${n}_1.json")
    mism=$(json_number id_mismatch_percent "$tmp/error_$n.json")
    psnr=$(json_number psnr_db "$tmp/error_$n.json")
    psnr=${psnr:-identical}  # null: the images are equal
    echo "$n,$rooms,$portals,$load,$report,$scene,$validate,$frame,$draws,$tris,$mism,$psnr" >>"$csv"
done
cat "$csv"

if ! command -v gnuplot >/dev/null 2>&1; then
    echo "large-layouts.sh: no gnuplot, so no plot (apt-get install gnuplot-nox)" >&2
    exit 0
fi
# An n log n reference through the 1000-room validate time.
awk -F, 'NR > 1 { print $2, $4, $5, $6, $7, $8 }' "$csv" >"$tmp/large.dat"
ref=$(awk 'END { print $5 / ($1 * log($1)) }' "$tmp/large.dat")
gnuplot <<GP
set terminal svg size 640,400 dynamic
set output "$results/load_vs_rooms.svg"
set title "Grid layouts of N rooms (2N - 2 doors), median ms"
set grid
set key top left
set logscale xy
set xlabel "rooms"; set ylabel "ms"
set xrange [8:1300]
plot "$tmp/large.dat" using 1:5 with linespoints pt 7 title "impossible validate (process, wall)", \
     "$tmp/large.dat" using 1:2 with linespoints pt 5 title "load (parse, check)", \
     "$tmp/large.dat" using 1:3 with linespoints pt 9 title "report (placement, overlaps)", \
     "$tmp/large.dat" using 1:4 with linespoints pt 11 title "scene build", \
     "$tmp/large.dat" using 1:6 with linespoints pt 13 title "start view frame, 640x360", \
     $ref * x * log(x) with lines dt 2 title "n log n through validate at 1000"
GP
echo "wrote $csv and $results/load_vs_rooms.svg"
