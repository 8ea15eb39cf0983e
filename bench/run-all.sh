#!/bin/sh
# Every measurement of bench/README.md, in one command:
#   bench/run-all.sh [BUILD_DIR]      (default: build; RUNS=3 FRAMES=30 to change the repetitions)
# Each set is run RUNS times; within a run its configurations are interleaved
# frame by frame, so ratios are measured in one run. Writes bench/results/
# (CSV, JSON and the printed tables per run), bench/results/summary.md
# (medians over the runs) and the plots (bench/plot.sh).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${1:-$root/build}
bin=$build/impossible
out=$here/results
runs=${RUNS:-3}
frames=${FRAMES:-30}
[ -x "$bin" ] || { echo "run-all.sh: no $bin; build first (cmake --build $build --target impossible)" >&2; exit 1; }
mkdir -p "$out"
rm -f "$out"/*.csv "$out"/*.json "$out"/*.txt

# run NAME ARGS...: one measurement set, RUNS times.
run() {
    name=$1
    shift
    i=1
    while [ "$i" -le "$runs" ]; do
        # The error against the tracer is the same in every run (summarise.sh
        # reads the first run's): traced in the first run only.
        if [ "$i" -eq 2 ]; then
            for a in "$@"; do
                shift
                [ "$a" = "--error" ] || set -- "$@" "$a"
            done
        fi
        echo "== $name, run $i of $runs" >&2
        "$bin" bench "$@" --frames "$frames" --csv "$out/$name.$i.csv" --json "$out/$name.$i.json" \
            >"$out/$name.$i.txt"
        i=$((i + 1))
    done
}

L=$root/layouts
# Speed against error: every technique, with its error against the tracer.
run techniques_default "$L/default.json" --size 640x360 --sweep techniques
run techniques_corridor "$L/corridor.json" --size 640x360 --sweep techniques
run techniques_vr "$L/vr_study.json" --size 640x360 --sweep techniques
# Scaling, on the VR-study layout: doors opened pair by pair, then resolution.
run portals_vr "$L/vr_study.json" --size 1280x720 --max-depth 4 --sweep portals:0,2,4,6 --error
run size_vr "$L/vr_study.json" --max-depth 4 --size 1280x720 --sweep size:320x180,640x360,1280x720,1920x1080 --error
run triangles_vr "$L/vr_study.json" --max-depth 4 --size 1280x720 \
    --sweep boxes:0,100,1000,1000/all,1000/separate,4000,10000,10000/all --error
# A large glTF mesh (a bumpy sphere of about a million triangles, made here):
# in view, and behind the eye, where per-object culling drops it.
sphere=$(mktemp -d)
trap 'rm -rf "$sphere"' EXIT
"$build/tools/make_sphere_glb" 1000000 "$sphere/sphere.glb" >/dev/null
cat >"$sphere/sphere.json" <<'EOF_SPHERE'
{ "format": "impossible-layout", "version": 1,
  "start": { "room": "r", "position": [0, 1.6, 1.5] },
  "rooms": [ { "id": "r", "min": [-3, 0, -5], "max": [3, 3, 2], "color": [0.7, 0.7, 0.7],
    "props": [ { "gltf": "sphere.glb", "position": [0, 1.3, -0.7], "scale": 1.2 } ] } ] }
EOF_SPHERE
run sphere_front "$sphere/sphere.json" --size 640x360 --error
run sphere_behind "$sphere/sphere.json" --size 640x360 --pose 0,1.6,1.5,180,0,0 --error
# Textures and materials: the gallery's start view, with its error.
run gallery "$L/gallery.json" --size 640x360 --error
# Recursion depth: behind an occluding wall, and in the open corridor.
run depth_wall "$L/corridor_wall.json" --size 1280x720 --sweep depth:1,2,4,8,16,64 --error
run depth_wall_occlusion "$L/corridor_wall.json" --size 1280x720 --occlusion-test --sweep depth:1,2,4,8,16,64 --error
run depth_open "$L/corridor.json" --size 1280x720 --sweep depth:1,2,4,8,16,64 --error
# Mirrors and windows: a door, a mirror and a window of the same size in one
# view (per-portal times), then each filling the view from 0.6 m; and two
# facing mirrors by depth.
run kinds_all "$L/three_kinds.json" --size 640x360 --error --profile-frames 5
run kind_door "$L/three_kinds.json" --size 640x360 --room atelier --pose -2.6,1.3,-2.4,0,0,0 --error
run kind_mirror "$L/three_kinds.json" --size 640x360 --room atelier --pose 0,1.3,-2.4,0,0,0 --error
run kind_window "$L/three_kinds.json" --size 640x360 --room atelier --pose 2.6,1.3,-2.4,0,0,0 --error
run depth_mirrors "$L/mirror_hall.json" --size 640x360 --room hall --pose 2.2,1.5,-0.5,-60,-10,0 --sweep depth:1,2,4,8,16,32,64 --error

sh "$here/summarise.sh" "$out" >"$out/summary.md"
sh "$here/plot.sh" "$out"
echo "wrote $out/summary.md and the plots in $out" >&2
