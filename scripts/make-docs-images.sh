#!/usr/bin/env bash
# Renders the pictures in README.md and docs/ with the project's own program.
# Usage: scripts/make-docs-images.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
bin="$build/impossible"
out="$root/docs/images"
mkdir -p "$out"
size=640x360

# The default layout from its start pose: what `impossible render` shows.
"$bin" render --size $size --out "$out/default.png" --ids "$out/default-ids.png"

render() {  # NAME LAYOUT [options...]
  local name=$1 layout=$2
  shift 2
  "$bin" render "$root/layouts/$layout" --size $size --out "$out/$name.png" "$@"
}
render four_rooms four_rooms.json
render tunnel tunnel.json
render rotated rotated.json
render corridor corridor.json
render loop loop.json
# The same corridor at two recursion limits: the flat fill marks where it stops.
render corridor-depth2 corridor.json --max-depth 2 --pose 0,1.6,3,0,0,0
# Mirrors and windows: the three kinds of portal.
render mirror_hall mirror_hall.json --max-depth 16
render glass_gallery glass_gallery.json
render window_pair window_pair.json --max-depth 16
render three_kinds three_kinds.json
render gallery gallery.json
render gallery-garden gallery.json --room garden --pose 1.5,1.5,2.6,25,-8,0
# Crossing objects, moving props, hands and volumes (issue 22).
render crossing crossing.json --room kitchen --pose=-1.5,1.5,1.8,-35.8,-26,0
render crossing-behind crossing.json --room kitchen --pose=-0.4,1.5,-1.8,180,-25,0
render sliding_box-2s sliding_box.json --time 2
render sliding_box-3s sliding_box.json --time 3
render hands_door hands_door.json --path "$root/layouts/hands_walk.txt" --frame 112
# The same hands (frame 112's, before any teleport, so physical = virtual) seen
# from behind the door: their tips are in the garden.
render hands_door-behind hands_door.json --room hall --pose 0.3,1.4,-0.3,145,-15,0 \
  --hands=-0.18,1.25,0.0556,0,0,0,0.18,1.25,0.0556,0,0,0
render scanner_lab scanner_lab.json
render scanner_lab-side scanner_lab.json --room lab --pose=-2.1,1.5,0.6,-50,-12,0
# Light through portals (issue 27): the lamp hall's pool of light on the
# annex floor, cut by the door frame; the mirror's second lamp; green light
# through a tinted window; spots down a corridor.
render lamp_hall lamp_hall.json --room hall --pose=-1.7,1.6,0.4,-80,-15,0
render lamp_hall-annex lamp_hall.json --room annex --pose 1.9,2.0,0.0,90,-35,0
render mirror_lamp mirror_lamp.json
render tinted_window tinted_window.json --room greenhouse --pose 5.2,1.7,0.4,80,-20,0
render spot_corridor spot_corridor.json --room corridor --pose 0,1.6,1.5,0,-12,0
# Rooms of any shape (issue 23): an L, a turned room, a curved corridor and a
# trapdoor seen from above and below.
render l_flat l_flat.json --room hall --pose=-2.0,1.6,2.2,-55.9,-5,0
render lit_flat lit_flat.json --room hall --pose=-2.2,2.2,2.3,-40,-30,0
render lit_flat-across lit_flat.json --room hall --pose 1.5,1.6,-1.6,138,-20,0
render turned_room turned_room.json
render curved_corridor curved_corridor.json
render curved_corridor-inside curved_corridor.json --room corridor --pose 2.0,1.5,0,180,0,0
render trapdoor trapdoor.json --room tower --pose 0.4,1.6,0.9,0,-55,0
render trapdoor-below trapdoor.json --room cellar --pose 0.4,-1.4,0.6,0,65,0
# Changes while walking (issue 40): the same place before and after the
# change, the "after" drawn at a frame of the walk (docs/changes.md).
render door_swap-before door_swap.json --room study --pose=-1,1.6,-1.2,180,0,0
render door_swap-after door_swap.json --path "$root/layouts/door_swap_walk.txt" --frame 100
render rerouted_corridor-before rerouted_corridor.json --room gallery --pose 1,1.6,1.4,0,0,0
render rerouted_corridor-after rerouted_corridor.json --path "$root/layouts/rerouted_corridor_walk.txt" --frame 220
# A headset profile (issue 24): the HTC Vive's asymmetric frusta and its
# hidden area, black, at a size of the Vive's aspect.
"$bin" render "$root/layouts/four_rooms.json" --hmd "$root/profiles/htc-vive.json" --size 360x400 \
  --out "$out/headset-vive.png"

# The preview window (HUD, minimap, boundary grid) at the end of a scripted walk
# into the tunnel, on a private X server. Only the HUD's frame time varies
# between runs.
shots=$(mktemp -d)
xvfb-run -a -s "-screen 0 1280x1024x24" "$bin" preview "$root/layouts/tunnel.json" \
  --path "$root/scripts/preview-tour.txt" --frames 7 --size 560x420 --screenshots "$shots"
cp "$shots/window-0006.png" "$out/preview.png"
rm -rf "$shots"
echo "wrote $(ls "$out" | wc -l) images to $out"
