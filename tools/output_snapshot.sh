#!/usr/bin/env bash
# Writes what `render`, `trace`, `walk`, `validate`, `plan`, `tour` and
# `generate` produce for every layout into OUTDIR, so that a refactoring can
# be checked byte for byte: run it with the old and the new binary and
# `diff -r` the two folders.
#
# Usage: tools/output_snapshot.sh BINARY OUTDIR
set -uo pipefail
bin=$(realpath "$1")
out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
cd "$root"

layouts=(layouts/*.json tests/data/layouts/*.json tests/data/layouts/hard/*.json)
size=160x90

# Each command's status and messages go into its own .log, with the layout's
# path spelled the same way in both runs.
run() {  # NAME ARGS...
    local name=$1; shift
    "$bin" "$@" >"$out/$name.stdout" 2>"$out/$name.stderr"
    echo "$?" >"$out/$name.status"
}

for l in "${layouts[@]}"; do
    n=$(echo "$l" | tr '/' '_' | sed 's/\.json$//')
    run "$n.validate" validate "$l"
    run "$n.validate-json" validate "$l" --json
    run "$n.render" render "$l" --size $size --out "$out/$n.render.png" --ids "$out/$n.render-ids.png"
    run "$n.render-vi" render "$l" --size $size --stereo viewport-index --clip oblique \
        --out "$out/$n.render-vi.png" --ids "$out/$n.render-vi-ids.png"
    run "$n.render-2p" render "$l" --size $size --stereo two-pass --depth standard --no-cull \
        --out "$out/$n.render-2p.png" --ids "$out/$n.render-2p-ids.png"
    run "$n.render-ms" render "$l" --size $size --samples 4 --max-depth 3 \
        --out "$out/$n.render-ms.png" --ids "$out/$n.render-ms-ids.png"
    run "$n.render-stats" render "$l" --size $size --stats --out "$out/$n.render-stats.png"
    run "$n.trace" trace "$l" --size $size --out "$out/$n.trace.png" --ids "$out/$n.trace-ids.png"
    run "$n.trace-ss" trace "$l" --size 80x45 --samples 4 --max-depth 3 --out "$out/$n.trace-ss.png"
    run "$n.plan" plan "$l" --out "$out/$n.plan.svg" --png "$out/$n.plan.png" --max-size 300
    run "$n.tour" tour "$l" --out "$out/$n.tour.txt"
    if [ -s "$out/$n.tour.txt" ]; then
        run "$n.walk" walk "$l" --path "$out/$n.tour.txt"
        run "$n.plan-path" plan "$l" --path "$out/$n.tour.txt" --out "$out/$n.plan-path.svg"
    fi
done
run walk-preview walk layouts/rotated.json --path tests/data/preview/through_rotated_door.txt
for seed in 1 2 3 7; do
    run "generate-$seed" generate --play-area 4x4 --rooms 3 --seed $seed --out "$out/generate-$seed.json"
    run "generate-l-$seed" generate --play-area 6x5 --rooms 4 --seed $seed --max-overlap 60
done
run render-default render --size $size --out "$out/default.png"
run compare compare "$out/layouts_default.render.png" "$out/layouts_default.trace.png" \
    --ids-a "$out/layouts_default.render-ids.png" --ids-b "$out/layouts_default.trace-ids.png"
# Messages name the output folder; make them independent of it.
sed -i "s#$out#OUT#g" "$out"/*.stdout "$out"/*.stderr
echo "snapshot: $(ls "$out" | wc -l) files in $out"
