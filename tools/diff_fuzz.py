#!/usr/bin/env python3
"""Differential fuzzer: random layouts and poses, `render` against `trace`.

Each case is a seeded random layout (overlapping rooms, coincident and
transformed door pairs, free-standing doors, doors in walls, boxes 1 cm to
1 m deep, doors 1 cm to 20 m wide, rooms far from the origin, props beside
doors, facing doors for deep recursion) and a random pose (eyes millimetres
from walls, props and box faces, one eye inside a door's box, grazing views,
deep recursion). The case is rendered with `impossible render` and traced with
`impossible trace`, and `impossible compare` counts the cell-id mismatches
with its one-pixel edge tolerance. A case passes with 0 mismatches.

Every failure is printed as the command lines that reproduce it (the layout
file is kept in --keep DIR). The same --seed, --kinds and case number always
make the same layout and pose.

--kinds picks the kinds of layout (comma-separated; case N is of kind N
modulo their count). The default is the layouts above: coincident, wall_pair,
free_pair and corridor, in that order. The fifth, "glass", is mirrors and
windows (layout-format.md, "Mirrors and windows"), one of five sub-kinds per
case: mirrors (1-3 in walls, floor or ceiling, some side by side in one
face, touching), facing_mirrors (opposite walls, an endless row; sometimes
a third mirror or a window pair on a side wall), window_pair (a window in a
wall of each of two overlapping rooms, sometimes a mirror seen through it),
window_loop (a window pair on two walls of one room, facing or at a corner)
and door_glass (a door pair between two rooms with glass in both: the door
seen in a mirror, a mirror or window seen through the door, a mirror beside
the door in its wall). Glass is 1 cm to a whole face, tinted 0..1 per
channel (or white), windows reflect 0..1 (0 and 1 included, or the default);
props near the glass; 30 % of layouts 0.5-2 km from the origin. Poses:
anywhere looking at the glass; 0.1 mm to 5 cm in front of it (one eye often
behind its plane); straight into it, near or far (facing mirrors or
windows); grazing it 0.1 mm to 0.5 m off its plane; millimetres from a wall;
random looks; depth 1 to 64. A window branch below 1/256 of the light is cut
by both programs alike (shading/shading.hpp, kMinBranchWeight). A failure
says so when its render reached the portal-pass budget (docs/bounded-work.md)
or an eye lies inside the rasteriser's 10 µm near plane of a face of its
room (docs/accuracy.md, "Mirrors and windows", has a long run's failures).

"prism" is rooms of any floor shape (layout-format.md, "Rooms of any
shape"; tools/diff_fuzz_prisms.py): convex floors of 3-12 corners, turned
rectangles, concave floors (L, U, star) with a door beside a reflex corner,
curved corridors of 10-40 walls (endless or joined to a room) and trapdoors
in a floor and a ceiling; poses millimetres from slanted walls, grazing
walls, in front of the door (one eye behind its plane), above and below a
trapdoor, random looks.

--lit makes every case lit (layout-format.md, "Lights"): the same rooms,
portals and pose, with "lighting": "lights", a random ambient per room, 0-3
point or spot lights per room (random colour, intensity 0.3-12, sometimes a
range, spots with random axes and cones) kept out of box props, and a light
depth of 0-3. A lit case also compares colours: its interior PSNR (pixels away
from id edges) must reach 50 dB where no room has a prop and 40 dB where
props cast shadows (which the rasteriser takes from shadow maps). A lit case
below its bar whose differences are all explained is listed, not failed
(lit_explained; docs/accuracy.md, "Lights"): isolated pixels on a light's
edge are a "colour sliver", and so are differences along one pixel column or
row that go away one pixel wider and narrower (aligned_edge: a light's edge
through a line of pixel centres); a case where every pixel off by more than 8
levels is one the shadow maps change (the render with --no-shadows differs
there or beside it, and the tracer is no brighter there than that render),
a face one pixel thin that differs unlit too, or an isolated pixel, and
where the pixels the maps leave alone reach 50 dB, is a "shadow" case: the
licensed approximation of props' shadows (docs/lighting.md, "Shadows").

--headset draws every case through a random headset profile (--hmd,
docs/headsets.md) instead of its --fov: each eye's asymmetric angles (each
0.6-1.3 times the case's half field of view) and, in three cases of four, a
random star-shaped visible area; hidden pixels are black with id 0 in both.

    tools/diff_fuzz.py --binary build/impossible --seed 1 --cases 300
    tools/diff_fuzz.py --binary build/impossible --seed 1 --case 17 --keep /tmp/case17
    tools/diff_fuzz.py --binary build/impossible --seed 1 --cases 100 --kinds glass
    tools/diff_fuzz.py --binary build/impossible --seed 1 --cases 12 --every 3 --kinds prism

scripts/test.sh runs a smoke of each ctest below (a few cases of every kind,
tests/CMakeLists.txt); the full case sets are ctests labelled "long", which
.ci/run runs after it (tests/README.md).

A case whose every mismatching pixel lies on a feature one pixel thin (a door
seen nearly edge-on, a sub-pixel prop edge) is counted as a "sliver": the
rasteriser includes or drops such a feature by its 1/256-pixel vertex
snapping, the tracer by exact arithmetic (docs/accuracy.md). So is, in the
floor_door kind, a case whose every mismatch is a lone pixel empty in the
render on an edge between two rooms (is_door_edge_pixel: a door's bottom
edge within the vertex snapping of a pixel centre). Slivers are listed but
do not fail the run; any other mismatch does.

Exit status: 0 when every case passed, 1 when one failed, 2 for a usage error.
"""
import argparse
import concurrent.futures
import json
import math
import os
import random
import subprocess
import sys
import struct
import tempfile
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from diff_fuzz_objects import ObjectCases  # noqa: E402  (the kinds "crossing" and "volume")
from diff_fuzz_prisms import PrismCases, boundary_distance, inside_polygon  # noqa: E402  (the kind "prism")
from diff_fuzz_doors import DoorCases  # noqa: E402  (the kind "floor_door")

# The kinds a run cycles through by default (docs/accuracy.md's figures are
# for these); --kinds picks others. "glass" is mirrors and windows.
DEFAULT_KINDS = ["coincident", "wall_pair", "free_pair", "corridor"]
KINDS = DEFAULT_KINDS + ["glass", "crossing", "volume", "prism", "floor_door"]
# The layouts of the glass kind, one chosen per case (Case.make_glass).
GLASS_SUBKINDS = ["mirrors", "facing_mirrors", "window_pair", "window_loop", "door_glass"]


def rnd_color(r):
    return [round(r.uniform(0.15, 0.95), 3) for _ in range(3)]


def log_uniform(r, lo, hi):
    return math.exp(r.uniform(math.log(lo), math.log(hi)))


class Case(ObjectCases, PrismCases, DoorCases):
    """One layout and one pose, made from (seed, number) and the kinds alone."""

    def __init__(self, seed, number, kinds=DEFAULT_KINDS):
        self.seed, self.number = seed, number
        r = random.Random(seed * 1_000_003 + number)
        self.r = r
        self.kind = kinds[number % len(kinds)]
        self.sub = None  # the glass kind's sub-kind
        far = r.random() < 0.3
        self.origin = [r.uniform(-2000, 2000), 0.0, r.uniform(-2000, 2000)] if far else [0.0, 0.0, 0.0]
        self.rooms, self.portals = [], []
        getattr(self, "make_" + self.kind)()
        make_pose = {"glass": self.make_glass_pose, "crossing": self.crossing_pose,
                     "volume": self.volume_pose, "prism": self.prism_pose,
                     "floor_door": self.floor_door_pose}.get(self.kind, self.make_pose)
        self.pose, self.room, self.max_depth, self.fov, self.what = make_pose()

    # --- rooms and portals ---------------------------------------------
    def room(self, rid, lo, hi, props=()):
        room = {"id": rid, "min": [round(v, 6) for v in lo], "max": [round(v, 6) for v in hi],
                "color": rnd_color(self.r)}
        if self.r.random() < 0.3:
            room["checker"] = round(self.r.uniform(0.2, 1.0), 3)
        if props:
            room["props"] = list(props)
        self.rooms.append(room)
        return room

    def portal(self, pid, room, center, normal, w, h, target, depth=None):
        p = {"id": pid, "room": room, "center": [round(v, 6) for v in center],
             "normal": [round(v, 9) for v in normal], "width": round(w, 6), "height": round(h, 6),
             "target": target}
        if abs(normal[1]) > 0.9:
            p["up"] = [0, 0, -1]
        if depth is not None:
            p["depth"] = round(depth, 6)
        self.portals.append(p)

    def box_depth(self):
        return log_uniform(self.r, 0.01, 1.0)

    def props_near(self, center, lo, hi, count):
        """Boxes inside [lo, hi], some touching the door's neighbourhood."""
        r, props = self.r, []
        for k in range(count):
            s = [r.uniform(0.05, 0.6), r.uniform(0.05, 1.2), r.uniform(0.05, 0.6)]
            if k == 0:
                c = [center[0] + r.uniform(-1, 1), 0, center[2] + r.uniform(-1, 1)]
            else:
                c = [r.uniform(lo[0], hi[0]), 0, r.uniform(lo[2], hi[2])]
            bmin = [max(lo[0] + 0.01, c[0] - s[0] / 2), lo[1], max(lo[2] + 0.01, c[2] - s[2] / 2)]
            bmax = [min(hi[0] - 0.01, c[0] + s[0] / 2), lo[1] + s[1], min(hi[2] - 0.01, c[2] + s[2] / 2)]
            if all(bmax[a] - bmin[a] > 0.01 for a in range(3)):
                props.append({"box": {"min": [round(v, 6) for v in bmin], "max": [round(v, 6) for v in bmax]},
                              "color": rnd_color(r)})
        return props

    def room_box(self, centre, half_x, half_z, height):
        lo = [centre[0] - half_x, centre[1], centre[2] - half_z]
        hi = [centre[0] + half_x, centre[1] + height, centre[2] + half_z]
        return lo, hi

    def make_coincident(self):
        """Two overlapping rooms, a free-standing door with coincident portals."""
        r, o = self.r, self.origin
        hx, hz, h = r.uniform(1.5, 5), r.uniform(1.5, 5), r.uniform(2.2, 4)
        lo, hi = self.room_box(o, hx, hz, h)
        yaw = r.uniform(0, 2 * math.pi) if r.random() < 0.5 else r.choice([0, 0.5, 1, 1.5]) * math.pi
        n = [math.sin(yaw), 0.0, math.cos(yaw)]
        w = log_uniform(r, 0.01, 20)
        if r.random() < 0.7:
            w = min(w, 2 * hx)  # else the door may reach through the walls
        ph = min(r.uniform(0.01, h), h - 0.02) if w < 0.5 else r.uniform(min(1.0, h / 2), h - 0.01)
        c = [o[0] + r.uniform(-hx / 2, hx / 2), o[1] + ph / 2 + r.uniform(0, h - ph), o[2] + r.uniform(-hz / 2, hz / 2)]
        self.room("a", lo, hi, self.props_near(c, lo, hi, r.randint(0, 4)))
        lo2 = [lo[0] + r.uniform(-1, 1), lo[1], lo[2] + r.uniform(-1, 1)]
        hi2 = [hi[0] + r.uniform(-1, 1), hi[1] + r.uniform(-0.5, 0.5), hi[2] + r.uniform(-1, 1)]
        self.room("b", lo2, hi2, self.props_near(c, lo2, hi2, r.randint(0, 3)))
        d = self.box_depth()
        self.portal("a_door", "a", c, n, w, ph, "b_door", d)
        self.portal("b_door", "b", c, [-v for v in n], w, ph, "a_door", self.box_depth())

    def wall_portal(self, lo, hi, side, w, ph, r):
        """A portal in wall `side` (0:-x 1:+x 2:-z 3:+z) of the box, normal into it."""
        axis = 0 if side < 2 else 2
        other = 2 if axis == 0 else 0
        span = hi[other] - lo[other]
        w = min(w, span - 0.02)
        c = [0.0, 0.0, 0.0]
        c[axis] = lo[axis] if side % 2 == 0 else hi[axis]
        c[other] = r.uniform(lo[other] + w / 2 + 0.01, hi[other] - w / 2 - 0.01)
        c[1] = r.uniform(lo[1] + ph / 2 + 0.005, hi[1] - ph / 2 - 0.005)
        n = [0.0, 0.0, 0.0]
        n[axis] = 1.0 if side % 2 == 0 else -1.0
        return c, n, w

    def make_wall_pair(self):
        """Doors in walls of two rooms, the second turned and moved (rooms may overlap)."""
        r, o = self.r, self.origin
        h = r.uniform(2.2, 4)
        w = log_uniform(r, 0.01, 6)
        ph = min(log_uniform(r, 0.01, 2.5), h - 0.05)
        lo, hi = self.room_box(o, max(r.uniform(1.2, 4), w / 2 + 0.1), max(r.uniform(1.2, 4), w / 2 + 0.1), h)
        shift = [r.uniform(-30, 30), 0, r.uniform(-30, 30)] if r.random() < 0.5 else [r.uniform(-1, 1), 0, r.uniform(-1, 1)]
        ob = [o[0] + shift[0], o[1], o[2] + shift[2]]
        lo2, hi2 = self.room_box(ob, max(r.uniform(1.2, 4), w / 2 + 0.1), max(r.uniform(1.2, 4), w / 2 + 0.1), h)
        ca, na, w1 = self.wall_portal(lo, hi, r.randrange(4), w, ph, r)
        cb, nb, w2 = self.wall_portal(lo2, hi2, r.randrange(4), w, ph, r)
        w = min(w1, w2)
        ca, na, _ = (ca, na, w)
        self.room("a", lo, hi, self.props_near(ca, lo, hi, r.randint(0, 4)))
        self.room("b", lo2, hi2, self.props_near(cb, lo2, hi2, r.randint(0, 4)))
        self.portal("a_door", "a", ca, na, w, ph, "b_door", self.box_depth())
        self.portal("b_door", "b", cb, nb, w, ph, "a_door", self.box_depth())

    def make_free_pair(self):
        """Free-standing doors at any angle (pitched too), far apart."""
        r, o = self.r, self.origin
        hx, hz, h = r.uniform(2, 6), r.uniform(2, 6), r.uniform(2.5, 5)
        lo, hi = self.room_box(o, hx, hz, h)
        ob = [o[0] + r.uniform(-500, 500), o[1] + r.uniform(-20, 20), o[2] + r.uniform(-500, 500)]
        lo2, hi2 = self.room_box(ob, r.uniform(2, 6), r.uniform(2, 6), r.uniform(2.5, 5))

        def direction():
            yaw, pitch = r.uniform(0, 2 * math.pi), (r.uniform(-0.6, 0.6) if r.random() < 0.4 else 0.0)
            return [math.sin(yaw) * math.cos(pitch), math.sin(pitch), math.cos(yaw) * math.cos(pitch)]

        w = log_uniform(r, 0.05, 3)
        ph = log_uniform(r, 0.05, 2.2)
        ca = [o[0] + r.uniform(-hx / 2, hx / 2), o[1] + r.uniform(ph / 2 + 0.01, h - ph / 2 - 0.01), o[2] + r.uniform(-hz / 2, hz / 2)]
        cb = [(lo2[a] + hi2[a]) / 2 + (r.uniform(-0.5, 0.5) if a != 1 else 0) for a in range(3)]
        cb[1] = lo2[1] + ph / 2 + 0.3
        self.room("a", lo, hi, self.props_near(ca, lo, hi, r.randint(0, 4)))
        self.room("b", lo2, hi2, self.props_near(cb, lo2, hi2, r.randint(0, 4)))
        self.portal("a_door", "a", ca, direction(), w, ph, "b_door", self.box_depth())
        self.portal("b_door", "b", cb, direction(), w, ph, "a_door", self.box_depth())

    def make_corridor(self):
        """Two facing doors at the ends of one room: an endless corridor."""
        r, o = self.r, self.origin
        length, hx, h = r.uniform(2, 15), r.uniform(0.6, 2), r.uniform(2.2, 3.5)
        lo, hi = [o[0] - hx, o[1], o[2] - length / 2], [o[0] + hx, o[1] + h, o[2] + length / 2]
        self.room("a", lo, hi, self.props_near([o[0], 0, o[2]], lo, hi, r.randint(0, 3)))
        w, ph = 2 * hx - r.uniform(0.02, 0.5), h - r.uniform(0.02, 0.5)
        c = [o[0], o[1] + ph / 2 + r.uniform(0, h - ph - 0.01), 0]
        self.portal("north", "a", [c[0], c[1], lo[2]], [0, 0, 1], w, ph, "south", self.box_depth())
        self.portal("south", "a", [c[0], c[1], hi[2]], [0, 0, -1], w, ph, "north", self.box_depth())

    # --- mirrors and windows (the glass kind) ---------------------------
    # Faces of a room: 0 -x, 1 +x, 2 -z, 3 +z (walls), 4 floor, 5 ceiling.
    @staticmethod
    def face_frame(lo, hi, face):
        """(axis, plane coordinate, inward normal, width axis, height axis)
        of a face; the width axis is the portal's right (up × normal), the
        height axis its up ([0, 1, 0] on walls, [0, 0, -1] on floor and
        ceiling, which portal() sets)."""
        axis = (0, 0, 2, 2, 1, 1)[face]
        coord = lo[axis] if face % 2 == 0 else hi[axis]
        n = [0.0, 0.0, 0.0]
        n[axis] = 1.0 if face % 2 == 0 else -1.0
        wide, high = (2, 1) if axis == 0 else (0, 1) if axis == 2 else (0, 2)
        return axis, coord, n, wide, high

    def glass_size(self, span_w, span_h):
        """1 cm to the whole face: exactly the whole face (or its width or
        height) sometimes, else large or log-uniform from 1 cm."""
        r = self.r

        def one(span):
            x = r.random()
            return span if x < 0.2 else r.uniform(0.3 * span, span) if x < 0.6 else log_uniform(r, 0.01, span)
        return one(span_w), one(span_h)

    def face_rect(self, lo, hi, face, w=None, h=None, slot=(0.0, 1.0)):
        """A rectangle in `face` of the room [lo, hi], inside the slot (the
        share of the face's width it may take), normal into the room; w and
        h are drawn (glass_size) where not given and cut to the slot."""
        r = self.r
        axis, coord, n, wide, high = self.face_frame(lo, hi, face)
        a0 = lo[wide] + slot[0] * (hi[wide] - lo[wide])
        a1 = lo[wide] + slot[1] * (hi[wide] - lo[wide])
        span_h = hi[high] - lo[high]
        if w is None or h is None:
            w, h = self.glass_size(a1 - a0, span_h)
        w, h = min(w, a1 - a0), min(h, span_h)
        c = [0.0, 0.0, 0.0]
        c[axis] = coord
        c[wide] = r.uniform(a0 + w / 2, a1 - w / 2)
        c[high] = lo[high] + span_h / 2 + r.uniform(-(span_h - h) / 2, (span_h - h) / 2)
        return c, n, w, h

    def tint(self):
        """None (the default, white) half the time; else 0..1 per channel,
        sometimes with a channel or all at 0 or 1."""
        r = self.r
        x = r.random()
        if x < 0.5:
            return None
        if x < 0.55:
            return [r.choice([0.0, 1.0]) for _ in range(3)]
        return [round(r.uniform(0, 1), 3) for _ in range(3)]

    def reflectance(self):
        r = self.r
        x = r.random()
        return None if x < 0.15 else 0.0 if x < 0.3 else 1.0 if x < 0.45 else round(r.uniform(0, 1), 3)

    def glass(self, pid, room, rect, kind, target=None):
        c, n, w, h = rect
        self.portal(pid, room, c, n, w, h, target)
        p = self.portals[-1]
        p["kind"] = kind
        if kind == "mirror":
            del p["target"]
        tint = self.tint()
        if tint is not None:
            p["tint"] = tint
        if kind == "window":
            refl = self.reflectance()
            if refl is not None:
                p["reflectance"] = refl
        return p

    def glass_room(self, rid, centre, hx, hz, h):
        lo, hi = self.room_box(centre, hx, hz, h)
        room = self.room(rid, lo, hi)
        return room, room["min"], room["max"]

    def add_props(self, room, near, count):
        props = self.props_near(near, room["min"], room["max"], count)
        if props:
            room["props"] = props

    def make_glass(self):
        """Mirrors and windows in the faces of rooms, doors mixed in."""
        self.sub = self.r.choice(GLASS_SUBKINDS)
        self.focus = None  # the portal the pose is about
        getattr(self, "glass_" + self.sub)()
        if self.focus is None:
            self.focus = self.portals[0]

    def glass_mirrors(self):
        """One room, 1-3 mirrors (a few side by side in one face, touching
        sometimes), in walls and sometimes the floor or ceiling."""
        r, o = self.r, self.origin
        room, lo, hi = self.glass_room("a", o, r.uniform(0.8, 5), r.uniform(0.8, 5), r.uniform(2.2, 4))
        faces = r.sample([0, 1, 2, 3, 4, 5] if r.random() < 0.3 else [0, 1, 2, 3], r.randint(1, 3))
        for face in faces:
            k = 1 if r.random() < 0.7 else r.randint(2, 3)  # mirrors side by side
            cuts = sorted(r.uniform(0, 1) for _ in range(k - 1)) if r.random() < 0.5 else [i / k for i in range(1, k)]
            bounds = [0.0] + cuts + [1.0]
            for i in range(k):
                self.glass("m%d_%d" % (face, i), "a", self.face_rect(lo, hi, face, slot=(bounds[i], bounds[i + 1])),
                           "mirror")
        self.add_props(room, self.portals[0]["center"], r.randint(0, 4))

    def glass_facing_mirrors(self):
        """Two mirrors on opposite walls (an endless row of reflections),
        sometimes a third on a side wall or a window between them."""
        r, o = self.r, self.origin
        room, lo, hi = self.glass_room("a", o, r.uniform(0.5, 4), r.uniform(0.5, 8), r.uniform(2.2, 4))
        face = r.choice([0, 2])
        first = self.face_rect(lo, hi, face)
        if r.random() < 0.5:  # the same rectangle straight across
            axis = first[1].index(1.0)
            c = list(first[0])
            c[axis] = hi[axis]
            second = (c, [-v for v in first[1]], first[2], first[3])
        else:
            second = self.face_rect(lo, hi, face + 1)
        self.glass("near", "a", first, "mirror")
        self.glass("far", "a", second, "mirror")
        x = r.random()
        if x < 0.2:
            self.glass("side", "a", self.face_rect(lo, hi, r.choice([2, 3]) if face == 0 else r.choice([0, 1])),
                       "mirror")
        elif x < 0.35:  # a window pair beside them: two branches at each reflection
            side = r.choice([2, 3]) if face == 0 else r.choice([0, 1])
            w, h = self.glass_size(1.0, hi[1] - lo[1])
            self.glass("pane_a", "a", self.face_rect(lo, hi, side, w, h, slot=(0.0, 0.5)), "window", "pane_b")
            self.glass("pane_b", "a", self.face_rect(lo, hi, side, w, h, slot=(0.5, 1.0)), "window", "pane_a")
        self.add_props(room, first[0], r.randint(0, 3))
        self.focus = self.portals[r.randrange(2)]

    def overlapping_room(self, rid, lo, hi, h):
        """A second room overlapping the first (or up to 30 m away)."""
        r = self.r
        shift = [r.uniform(-30, 30), 0, r.uniform(-30, 30)] if r.random() < 0.3 else [r.uniform(-1, 1), 0, r.uniform(-1, 1)]
        centre = [(lo[0] + hi[0]) / 2 + shift[0], lo[1], (lo[2] + hi[2]) / 2 + shift[2]]
        return self.glass_room(rid, centre, r.uniform(0.8, 4), r.uniform(0.8, 4), h)

    def glass_window_pair(self):
        """A window in a wall of each of two overlapping rooms; sometimes a
        mirror in the far room, seen through the window."""
        r, o = self.r, self.origin
        h = r.uniform(2.2, 4)
        a, lo, hi = self.glass_room("a", o, r.uniform(0.8, 4), r.uniform(0.8, 4), h)
        b, lo2, hi2 = self.overlapping_room("b", lo, hi, h)
        fa, fb = r.randrange(4), r.randrange(4)
        ra = self.face_rect(lo, hi, fa)
        rb = self.face_rect(lo2, hi2, fb, ra[2], ra[3])
        w, ht = min(ra[2], rb[2]), min(ra[3], rb[3])  # a rectangle shrunk about its centre stays in its face
        self.glass("a_window", "a", (ra[0], ra[1], w, ht), "window", "b_window")
        self.glass("b_window", "b", (rb[0], rb[1], w, ht), "window", "a_window")
        if r.random() < 0.4:
            self.glass("b_mirror", "b", self.face_rect(lo2, hi2, r.choice([f for f in range(4) if f != fb])), "mirror")
        self.add_props(a, ra[0], r.randint(0, 4))
        self.add_props(b, rb[0], r.randint(0, 3))

    def glass_window_loop(self):
        """A window pair on two walls of one room (facing, or at a corner):
        the room from the partner's side, itself included."""
        r, o = self.r, self.origin
        room, lo, hi = self.glass_room("a", o, r.uniform(0.8, 5), r.uniform(0.8, 5), r.uniform(2.2, 4))
        fa = r.randrange(4)
        fb = fa ^ 1 if r.random() < 0.6 else r.choice([2, 3] if fa < 2 else [0, 1])
        ra = self.face_rect(lo, hi, fa)
        rb = self.face_rect(lo, hi, fb, ra[2], ra[3])
        w, ht = min(ra[2], rb[2]), min(ra[3], rb[3])
        self.glass("west", "a", (ra[0], ra[1], w, ht), "window", "east")
        self.glass("east", "a", (rb[0], rb[1], w, ht), "window", "west")
        if r.random() < 0.3:
            rest = [f for f in range(4) if f not in (fa, fb)]
            self.glass("mirror", "a", self.face_rect(lo, hi, r.choice(rest)), "mirror")
        self.add_props(room, ra[0], r.randint(0, 4))

    def glass_door_glass(self):
        """A door pair in the walls of two rooms and glass in both: a door
        seen in a mirror, a mirror (or window) seen through a door, glass
        beside the door in the same wall."""
        r, o = self.r, self.origin
        h = r.uniform(2.2, 4)
        a, lo, hi = self.glass_room("a", o, r.uniform(1.0, 4), r.uniform(1.0, 4), h)
        b, lo2, hi2 = self.overlapping_room("b", lo, hi, h)
        fa, fb = r.randrange(4), r.randrange(4)
        beside = r.random() < 0.3  # the door and a mirror share wall fa
        w, ph = log_uniform(r, 0.01, 3), min(log_uniform(r, 0.01, 2.5), h - 0.02)
        da = self.face_rect(lo, hi, fa, w, ph, slot=(0.0, 0.5) if beside else (0.0, 1.0))
        db = self.face_rect(lo2, hi2, fb, w, ph)
        w, ph = min(da[2], db[2]), min(da[3], db[3])
        self.portal("a_door", "a", da[0], da[1], w, ph, "b_door", self.box_depth())
        self.portal("b_door", "b", db[0], db[1], w, ph, "a_door", self.box_depth())
        if beside:
            self.glass("a_beside", "a", self.face_rect(lo, hi, fa, slot=(0.5, 1.0)), "mirror")
        others = [f for f in range(6) if f != fa]
        x = r.random()
        if x < 0.5:  # the door seen in a mirror: on the opposite wall mostly
            self.glass("a_mirror", "a", self.face_rect(lo, hi, fa ^ 1 if r.random() < 0.6 else r.choice(others)),
                       "mirror")
        elif x < 0.7:  # a window pair of room a, the door seen through it
            fw = r.sample([f for f in range(4) if f != fa], 2)
            wa = self.face_rect(lo, hi, fw[0])
            wb = self.face_rect(lo, hi, fw[1], wa[2], wa[3])
            ww, wh = min(wa[2], wb[2]), min(wa[3], wb[3])
            self.glass("a_pane", "a", (wa[0], wa[1], ww, wh), "window", "a_pane2")
            self.glass("a_pane2", "a", (wb[0], wb[1], ww, wh), "window", "a_pane")
        if r.random() < 0.6:  # glass seen through the door
            kind = "mirror" if r.random() < 0.7 else "window"
            fm = fb ^ 1 if r.random() < 0.6 else r.choice([f for f in range(6) if f != fb])
            if kind == "mirror":
                self.glass("b_mirror", "b", self.face_rect(lo2, hi2, fm), "mirror")
            else:  # a window of b looking into a
                wb = self.face_rect(lo2, hi2, fm)
                free = [f for f in range(4) if f != fa and not any(p["room"] == "a" and p["normal"] ==
                                                                   self.face_frame(lo, hi, f)[2] for p in self.portals)]
                if free:
                    wa = self.face_rect(lo, hi, r.choice(free), wb[2], wb[3])
                    ww, wh = min(wa[2], wb[2]), min(wa[3], wb[3])
                    self.glass("b_pane", "b", (wb[0], wb[1], ww, wh), "window", "a_pane3")
                    self.glass("a_pane3", "a", (wa[0], wa[1], ww, wh), "window", "b_pane")
        self.add_props(a, da[0], r.randint(0, 4))
        self.add_props(b, db[0], r.randint(0, 3))
        mine = [p for p in self.portals if p["room"] == "a"]
        self.focus = r.choice(mine)

    # --- the pose -------------------------------------------------------
    def make_pose(self):
        r = self.r
        a = self.rooms[0]
        lo, hi = a["min"], a["max"]
        door = self.portals[0]
        c, n = door["center"], door["normal"]
        choice = r.random()
        max_depth = r.choice([1, 2, 8, 8, 8, 16, 64]) if self.kind != "corridor" else r.choice([8, 16, 64])
        fov = r.uniform(40, 110)
        yaw_at = lambda v: math.degrees(math.atan2(-v[0], -v[2]))
        if choice < 0.25:  # anywhere in the room, looking at the door
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            v = [c[i] - p[i] for i in range(3)]
            what = "in the room, towards the door"
        elif choice < 0.45:  # millimetres in front of the door (one eye may be in its box)
            dist = log_uniform(r, 1e-4, 0.05)
            p = [c[i] + dist * n[i] for i in range(3)]
            p[1] = c[1] + r.uniform(-0.2, 0.2) * door["height"]
            v = [-n[0] + r.uniform(-1, 1), 0, -n[2] + r.uniform(-1, 1)]
            what = "%.2g m in front of the door" % dist
        elif choice < 0.6:  # millimetres from a wall, looking at it
            axis = r.choice([0, 2])
            side = r.choice([0, 1])
            dist = log_uniform(r, 1e-4, 0.02)
            p = [r.uniform(lo[i] + 0.3, hi[i] - 0.3) for i in range(3)]
            p[axis] = lo[axis] + dist if side == 0 else hi[axis] - dist
            v = [0.0, 0.0, 0.0]
            v[axis] = -1.0 if side == 0 else 1.0
            v[2 - axis] = r.uniform(-0.3, 0.3)
            what = "%.2g m from a wall" % dist
        elif choice < 0.75:  # grazing the door
            p = [c[i] + n[i] * r.uniform(0.05, 1.0) for i in range(3)]
            side = [n[2], 0.0, -n[0]]
            p = [p[i] + side[i] * r.uniform(0.5, 2.0) for i in range(3)]
            v = [-side[i] + n[i] * r.uniform(-0.05, 0.1) for i in range(3)]
            what = "grazing the door"
        else:  # at a prop or the room's centre, anywhere
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            v = [r.uniform(-1, 1), r.uniform(-0.3, 0.3), r.uniform(-1, 1)]
            what = "random look"
        p[1] = min(max(p[1], lo[1] + 0.05), hi[1] - 0.05)
        yaw = yaw_at(v) if abs(v[0]) + abs(v[2]) > 1e-9 else 0.0
        pitch = r.uniform(-30, 30) if r.random() < 0.3 else 0.0
        roll = r.uniform(-20, 20) if r.random() < 0.2 else 0.0
        pose = [p[0], p[1], p[2], yaw, pitch, roll]
        return pose, "a", max_depth, fov, what

    def make_glass_pose(self):
        """A pose about the focus portal of room a (a mirror, a window or a
        door): anywhere looking at it, millimetres in front of it (one eye
        may be behind its plane), looking straight into it (facing mirrors or
        windows: the endless row), grazing it, millimetres from a wall, or a
        random look."""
        r = self.r
        lo, hi = self.rooms[0]["min"], self.rooms[0]["max"]
        f = self.focus
        c, n = f["center"], f["normal"]
        up = f.get("up", [0.0, 1.0, 0.0])
        right = [up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]]
        kind = f.get("kind", "door")
        naxis = max(range(3), key=lambda i: abs(n[i]))
        facing = self.sub in ("facing_mirrors", "window_loop")
        max_depth = r.choice([2, 8, 16, 64, 64]) if facing else r.choice([1, 2, 4, 8, 8, 16, 64])
        fov = r.uniform(40, 110)

        def on_rect(share):
            return [c[i] + r.uniform(-share, share) * f["width"] * right[i] + r.uniform(-share, share) * f["height"] * up[i]
                    for i in range(3)]

        keep = naxis  # the axis the clamp below leaves alone
        straight = False
        choice = r.random()
        if choice < 0.2:  # anywhere in the room, looking at it
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            t = on_rect(0.5)
            v = [t[i] - p[i] for i in range(3)]
            what = "in the room, towards the " + kind
        elif choice < 0.4:  # millimetres in front of it
            dist = log_uniform(r, 1e-4, 0.05)
            t = on_rect(0.45)
            p = [t[i] + dist * n[i] for i in range(3)]
            side = r.uniform(-1, 1) if r.random() < 0.5 else 0.0  # else both eyes that close
            v = [-n[i] + side * right[i] + r.uniform(-0.3, 0.3) * up[i] for i in range(3)]
            what = "%.2g m in front of the %s" % (dist, kind)
        elif choice < 0.6:  # straight into it, from near or far
            dist = r.uniform(0.01, hi[naxis] - lo[naxis] - 0.01) if r.random() < 0.7 else log_uniform(r, 1e-4, 0.05)
            t = on_rect(0.4)
            p = [t[i] + dist * n[i] for i in range(3)]
            straight = r.random() < 0.6
            v = [-n[i] + (0 if straight else r.uniform(-0.05, 0.05) * right[i] + r.uniform(-0.05, 0.05) * up[i])
                 for i in range(3)]
            what = "%.2g m straight into the %s" % (dist, kind)
        elif choice < 0.75:  # grazing it, along its plane
            dist = log_uniform(r, 1e-4, 0.5)
            s = r.choice([-1, 1])
            p = [c[i] + dist * n[i] + s * right[i] * (f["width"] / 2 + r.uniform(0.05, 2.0)) for i in range(3)]
            v = [-s * right[i] + n[i] * r.uniform(-0.05, 0.1) for i in range(3)]
            what = "grazing the %s %.2g m off its plane" % (kind, dist)
        elif choice < 0.85:  # millimetres from a wall, looking at it
            keep = r.choice([0, 2])
            side = r.choice([0, 1])
            dist = log_uniform(r, 1e-4, 0.02)
            p = [r.uniform(lo[i] + 0.3, hi[i] - 0.3) if hi[i] - lo[i] > 0.6 else (lo[i] + hi[i]) / 2 for i in range(3)]
            p[keep] = lo[keep] + dist if side == 0 else hi[keep] - dist
            v = [0.0, 0.0, 0.0]
            v[keep] = -1.0 if side == 0 else 1.0
            v[2 - keep] = r.uniform(-0.3, 0.3)
            what = "%.2g m from a wall" % dist
        else:  # anywhere, a random look
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            v = [r.uniform(-1, 1), r.uniform(-0.3, 0.3), r.uniform(-1, 1)]
            what = "random look"
        for i in range(3):  # in the room, but for the distance chosen from a plane
            if i != keep:
                p[i] = min(max(p[i], lo[i] + 0.02), hi[i] - 0.02)
        horizontal = math.hypot(v[0], v[2])
        yaw = math.degrees(math.atan2(-v[0], -v[2])) if horizontal > 1e-9 else 0.0
        pitch = math.degrees(math.atan2(v[1], horizontal))
        if not straight and r.random() < 0.3:
            pitch += r.uniform(-30, 30)
        pitch = min(max(pitch, -90.0), 90.0)
        roll = r.uniform(-20, 20) if not straight and r.random() < 0.2 else 0.0
        return [p[0], p[1], p[2], yaw, pitch, roll], "a", max_depth, fov, what

    def layout(self, lit=False):
        kind = self.kind if self.sub is None else "%s, %s" % (self.kind, self.sub)
        out = {"format": "impossible-layout", "version": 1,
               "name": "diff_fuzz seed %d case %d (%s)" % (self.seed, self.number, kind),
               "start": {"room": self.room if self.kind in ("prism", "floor_door") else "a", "position": self.pose[:3]},
               "rooms": self.rooms, "portals": self.portals}
        if lit:
            self.add_lights(out)
        return out

    # --- lights (--lit) --------------------------------------------------
    def add_lights(self, out):
        """Makes the layout lit (layout-format.md, "Lights"): per room an
        ambient and 0-3 point or spot lights, strictly inside the room and
        outside its props, and a light depth of 0-3. Drawn from a generator
        of their own, so a case's rooms, portals and pose are those of the
        unlit case."""
        r = random.Random(self.seed * 1_000_003 + self.number + 0x5eed)
        out["lighting"] = "lights"
        out["light_depth"] = r.randint(0, 3)
        for room in out["rooms"]:
            room["ambient"] = [round(r.uniform(0.0, 0.3), 3) for _ in range(3)]
            lo, hi = self.room_bounds(room)
            lights = []
            for _ in range(r.randint(0, 3)):
                pos = self.light_position(r, lo, hi, room.get("props", []), room.get("floor"))
                if pos is None:
                    continue
                light = {"position": pos, "color": rnd_color(r), "intensity": round(log_uniform(r, 0.3, 12.0), 4)}
                if r.random() < 0.3:
                    light["range"] = round(log_uniform(r, 0.5, 20.0), 4)
                if r.random() < 0.4:
                    d = [r.gauss(0, 1) for _ in range(3)]
                    n = math.sqrt(sum(v * v for v in d)) or 1.0
                    inner = round(r.uniform(0.0, 50.0), 3)
                    light["spot"] = {"direction": [round(v / n, 9) for v in d], "inner_deg": inner,
                                     "outer_deg": round(r.uniform(inner + 1.0, 90.0), 3)}
                lights.append(light)
            if lights:
                room["lights"] = lights

    @staticmethod
    def light_position(r, lo, hi, props, floor=None):
        for _ in range(20):
            pos = [round(r.uniform(lo[i] + 0.05 * (hi[i] - lo[i]), hi[i] - 0.05 * (hi[i] - lo[i])), 6)
                   for i in range(3)]
            if floor is not None and not (inside_polygon(floor, pos[0], pos[2]) and
                                          boundary_distance(floor, pos[0], pos[2]) > 0.01):
                continue
            inside = False
            for prop in props:
                box = prop.get("box")
                if box and all(box["min"][i] - 1e-3 <= pos[i] <= box["max"][i] + 1e-3 for i in range(3)):
                    inside = True
                elif prop.get("gltf", "").startswith("quad-"):  # diff_fuzz_doors.py's 1 m quads, 0.2-1.2 m high
                    at = prop["position"]
                    inside = inside or (all(abs(pos[i] - at[i]) <= 0.8 for i in (0, 2)) and pos[1] <= 1.5)
                elif not box:
                    inside = True  # a model's bounds are not known here: keep lights out of layouts with models
            if not inside:
                return pos
        return None

    def casts_shadows(self):
        """Whether any room has a prop (its shadows come from shadow maps,
        an approximation with its own error budget)."""
        return any(room.get("props") for room in self.rooms)

    def open_to_nothing(self):
        """Whether a portal's rectangle reaches outside its own room (by more
        than 1 µm): looking through its partner, a ray then leaves the room
        through that part and rightly meets nothing (id 0). In a layout where
        no portal does, every ray stays in closed rooms, and id 0 anywhere is
        a crack."""
        rooms = {room["id"]: room for room in self.rooms}
        for p in self.portals:
            if p.get("kind") == "volume":
                continue
            n = p["normal"]
            up = p.get("up", [0.0, 1.0, 0.0])
            right = [up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]]
            room = rooms[p["room"]]
            if "floor" in room:
                continue  # the prism kind puts every portal in a face of its room
            for sr in (-0.5, 0.5):
                for su in (-0.5, 0.5):
                    corner = [p["center"][a] + sr * p["width"] * right[a] + su * p["height"] * up[a]
                              for a in range(3)]
                    if any(corner[a] < room["min"][a] - 1e-6 or corner[a] > room["max"][a] + 1e-6
                           for a in range(3)):
                        return True
        return False

    def eyes(self, ipd=0.064):
        """The two eyes (left, right) of the pose: yaw about +y, pitch about
        the head's right axis, roll about its forward axis (layout-format.md,
        "Head, eyes and walking"), the eyes at head -/+ ipd/2 · right."""
        yaw, pitch, roll = (math.radians(v) for v in self.pose[3:])
        forward = [-math.sin(yaw), 0.0, -math.cos(yaw)]
        right = [math.cos(yaw), 0.0, -math.sin(yaw)]
        forward = [math.cos(pitch) * forward[i] + math.sin(pitch) * (1.0 if i == 1 else 0.0) for i in range(3)]
        f_x_r = [forward[1] * right[2] - forward[2] * right[1], forward[2] * right[0] - forward[0] * right[2],
                 forward[0] * right[1] - forward[1] * right[0]]
        right = [math.cos(roll) * right[i] + math.sin(roll) * f_x_r[i] for i in range(3)]
        return [[self.pose[i] + s * ipd / 2 * right[i] for i in range(3)] for s in (-1, 1)]

    def near_plane_note(self, near=1e-5):
        """Where an eye is in its room closer to a face (or glass in it) than
        the rasteriser's near plane (10 µm, docs/accuracy.md "Contact
        distance"), which clips the face there: a note for a failure."""
        room = next(x for x in self.rooms if x["id"] == self.room)
        if "floor" in room:
            return self.prism_near_plane_note(room, near)
        notes = []
        for eye, e in zip(("left", "right"), self.eyes()):
            if not all(room["min"][a] <= e[a] <= room["max"][a] for a in range(3)):
                continue
            for face, name in enumerate(("-x", "+x", "-z", "+z", "floor", "ceiling")):
                axis = (0, 0, 2, 2, 1, 1)[face]
                d = e[axis] - room["min"][axis] if face % 2 == 0 else room["max"][axis] - e[axis]
                if d < near:
                    notes.append("the %s eye is %.3g µm from the %s face, inside the rasteriser's %g µm near plane"
                                 % (eye, d * 1e6, name, near * 1e6))
        return "; ".join(notes)

    def view_args(self, size):
        pose = ",".join("%.17g" % v for v in self.pose)
        return ["--pose=" + pose, "--room", self.room, "--size", size, "--fov", "%.6g" % self.fov,
                "--max-depth", str(self.max_depth)] + self.view_extra()


def read_grey_png(path):
    """An 8-bit greyscale, non-interlaced PNG (what `--ids` writes) as rows."""
    return read_png(path, 1)


def read_png(path, channels):
    """An 8-bit grey (channels 1) or RGB (channels 3) non-interlaced PNG, as
    rows of bytes (channels bytes a pixel)."""
    data = open(path, "rb").read()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", chunk[:10])
            assert depth == 8 and colour == {1: 0, 3: 2}[channels], path + ": not an 8-bit PNG of that kind"
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    stride, n = width * channels, channels
    raw, rows, prev, k = zlib.decompress(idat), [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[k], bytearray(raw[k + 1:k + 1 + stride])
        k += 1 + stride
        for x in range(stride):
            a = line[x - n] if x >= n else 0
            b, c = prev[x], (prev[x - n] if x >= n else 0)
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return rows


def colour_sliver(base):
    """Whether a lit case's colour differences are isolated pixels: at most
    0.05 % of the interior pixels (3x3 of one id in both maps) differ by more
    than 8 levels in a channel, and none of them has such a neighbour. A
    pixel on the edge of a light's pool (where its shadow ray grazes an
    aperture's or a blocker's edge, or a spot's cone) or next to a light's
    image, where 1/d^2 changes by more than a level within the pixel, is lit
    differently by the rasteriser (float, interpolated position) and the
    tracer (double, the pixel's centre): the colour counterpart of an id
    sliver."""
    r, t = read_png(base + "-r.png", 3), read_png(base + "-t.png", 3)
    ri, ti = read_grey_png(base + "-r-ids.png"), read_grey_png(base + "-t-ids.png")
    h, w = len(ri), len(ri[0])

    def interior(x, y):
        v = ri[y][x]
        return all(ri[y + dy][x + dx] == v and ti[y + dy][x + dx] == v
                   for dy in (-1, 0, 1) for dx in (-1, 0, 1) if 0 <= x + dx < w and 0 <= y + dy < h)

    bad = set()
    for y in range(h):
        for x in range(w):
            if max(abs(r[y][3 * x + c] - t[y][3 * x + c]) for c in range(3)) > 8 and interior(x, y):
                bad.add((x, y))
    if len(bad) > max(1, int(0.0005 * w * h)):
        return False
    return not any((x + dx, y + dy) in bad for x, y in bad for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)))


def compare_figures(stdout):
    """`impossible compare`'s key=value fields, its id mismatches (-1 where
    missing) and its interior PSNR in dB (inf for equal pictures, nan where
    missing)."""
    fields = dict(kv.split("=", 1) for kv in stdout.split() if "=" in kv)
    interior = fields.get("interior_psnr_db", "nan")
    return fields, int(fields.get("id_mismatches", "-1")), float("inf") if interior == "inf" else float(interior)


def aligned_edge(binary, layout_path, base, view, need):
    """A colour difference along one pixel column or row: ("colour-sliver",
    why) when the interior pixels that differ by more than 8 levels lie in
    at most two columns or two rows and the same view one pixel wider and
    taller, and one pixel narrower and lower, reaches the PSNR bar; else
    None. A light's edge (the border of a pool of light through a door) that
    runs exactly through a line of pixel centres puts every pixel of that
    line on the float side in one renderer and on the double side in the
    other, together: a colour sliver the isolated-pixel test misses. At
    another size the edge falls between centres and the renderers agree (a
    real offset of the edge would not go away)."""
    r, t = read_png(base + "-r.png", 3), read_png(base + "-t.png", 3)
    h, w = len(r), len(r[0]) // 3
    bad = [(x, y) for y in range(h) for x in range(w)
           if max(abs(r[y][3 * x + c] - t[y][3 * x + c]) for c in range(3)) > 8]
    if not bad or (len({x for x, _ in bad}) > 2 and len({y for _, y in bad}) > 2):
        return None
    at = view.index("--size")
    ew, eh = (int(v) for v in view[at + 1].split("x"))
    figures = []
    for dw in (1, -1):
        size = "%dx%d" % (ew + dw, eh + dw)
        v = view[:at + 1] + [size] + view[at + 2:]
        out = base + "-aligned"
        for cmd in ([binary, "render", layout_path] + v + ["--out", out + "-r.png", "--ids", out + "-ri.png"],
                    [binary, "trace", layout_path] + v + ["--threads", "1", "--out", out + "-t.png", "--ids",
                                                          out + "-ti.png"]):
            if subprocess.run(cmd, capture_output=True, text=True, timeout=600).returncode != 0:
                return None
        p = subprocess.run([binary, "compare", out + "-r.png", out + "-t.png", "--ids-a", out + "-ri.png",
                            "--ids-b", out + "-ti.png"], capture_output=True, text=True, timeout=600)
        for suffix in ("-r.png", "-ri.png", "-t.png", "-ti.png"):
            try:
                os.remove(out + suffix)
            except OSError:
                pass
        _, mismatches, psnr = compare_figures(p.stdout)
        if mismatches != 0 or not psnr >= need:
            return None
        figures.append("%s %.2f dB" % (size, psnr))
    return ("colour-sliver", "%d pixels on one pixel %s, a light's edge through their centres; at %s"
            % (len(bad), "column" if len({x for x, _ in bad}) <= 2 else "row", ", ".join(figures)))


def lit_explained(case, binary, base, view, bar=50.0):
    """Why a lit case's colours miss their PSNR bar, if the differences are
    ones the comparison licenses; None where they are not (a real failure).

    Each pixel of the interior (3x3 of one id in both maps) that differs from
    the tracer's by more than 8 levels must be one of:
    - a shadow-map pixel (only where a room has props): the render with
      --no-shadows differs there or at a neighbour (the maps darken it, or
      the exact shadow reaches a pixel past the map's edge), and the tracer
      is no brighter there than that render (8 levels' slack): a shadow only
      takes light away. Props' shadows are the one approximation of the
      rasteriser's lighting (docs/lighting.md, "Shadows"), and where they
      fall is the maps' alone;
    - a geometry pixel: the same case unlit (the fixed light) differs there
      too by more than 8 levels, on a feature one pixel thin in that
      difference: a face one pixel thin that the id map cannot show, as both
      faces belong to one room (an id sliver's counterpart, not lighting's);
    - one of at most max(1, 0.05 %) isolated pixels (no such neighbour), as a
      colour sliver (colour_sliver).
    And the PSNR over the interior pixels that the maps leave alone, less
    those above, must reach `bar` (50 dB, the bar of a layout without
    props): away from the maps the rasteriser's lighting is exact to float
    rounding. Inside a map's pixels only "no brighter" is checked. Returns
    (status, detail): status "shadow" where shadow-map pixels account for
    some of the differences, "colour-sliver" where none do."""
    r, t = read_png(base + "-r.png", 3), read_png(base + "-t.png", 3)
    ri, ti = read_grey_png(base + "-r-ids.png"), read_grey_png(base + "-t-ids.png")
    h, w = len(ri), len(ri[0])

    def differ(a, b, x, y, by=0):
        return any(abs(a[y][3 * x + c] - b[y][3 * x + c]) > by for c in range(3))

    def interior(x, y):
        v = ri[y][x]
        return all(ri[y + dy][x + dx] == v and ti[y + dy][x + dx] == v
                   for dy in (-1, 0, 1) for dx in (-1, 0, 1) if 0 <= x + dx < w and 0 <= y + dy < h)

    pixels = [(x, y) for y in range(h) for x in range(w) if interior(x, y)]
    bad = set(p for p in pixels if differ(r, t, *p, by=8))
    shadow, mapped = set(), set()
    if case.casts_shadows():
        subprocess.run([binary, "render", base + ".json"] + view + ["--no-shadows", "--out", base + "-s.png"],
                       capture_output=True, check=True, timeout=600)
        s = read_png(base + "-s.png", 3)
        mapped = set((x, y) for y in range(h) for x in range(w) if differ(r, s, x, y))
        shadow = set((x, y) for x, y in bad
                     if all(t[y][3 * x + c] <= s[y][3 * x + c] + 8 for c in range(3))
                     and any((x + dx, y + dy) in mapped for dx in (-1, 0, 1) for dy in (-1, 0, 1)))
    geometry = set()
    if bad - shadow:
        unlit_layout = json.loads(json.dumps(case.layout(False)))
        for room in unlit_layout["rooms"]:  # add_lights wrote them into the case's rooms
            room.pop("ambient", None)
            room.pop("lights", None)
        with open(base + "-u.json", "w") as f:
            json.dump(unlit_layout, f, indent=1)
        for step, out in (("render", "-ur.png"), ("trace", "-ut.png")):
            subprocess.run([binary, step, base + "-u.json"] + view + ["--out", base + out],
                           capture_output=True, check=True, timeout=600)
        ur, ut = read_png(base + "-ur.png", 3), read_png(base + "-ut.png", 3)
        unlit = set((x, y) for y in range(h) for x in range(w) if differ(ur, ut, x, y, by=8))

        def thin(x, y):
            return (((x - 1, y) not in unlit and (x + 1, y) not in unlit) or
                    ((x, y - 1) not in unlit and (x, y + 1) not in unlit))
        geometry = set(p for p in bad - shadow if p in unlit and thin(*p))
    rest = bad - shadow - geometry
    isolated = not any((x + dx, y + dy) in rest for x, y in rest for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)))
    if not isolated or len(rest) > max(1, int(0.0005 * w * h)):
        return None
    kept = [p for p in pixels if p not in mapped and p not in bad]
    se = sum((r[y][3 * x + c] - t[y][3 * x + c]) ** 2 for x, y in kept for c in range(3))
    psnr = float("inf") if se == 0 else 10 * math.log10(255.0 ** 2 * 3 * len(kept) / se)
    if not psnr >= bar:
        return None
    detail = "%d pixels differ by > 8 levels: %d where the shadow maps change the render, %d on faces one pixel " \
        "thin that differ unlit too, %d isolated; PSNR where the maps change nothing %.2f dB" % (
            len(bad), len(bad & shadow), len(bad & geometry), len(rest), psnr)
    return ("shadow" if bad & shadow else "colour-sliver"), detail


def thin_at(img, x, y):
    """The id at (x, y) differs from both neighbours across one axis: a
    feature one pixel thin there. An eye image's edge (the side-by-side
    image's sides and the seam between the eyes, x = w/2) counts as a
    differing neighbour: a feature one pixel wide against it is what the
    frustum leaves of something that may be thinner still."""
    h, w, v = len(img), len(img[0]), img[y][x]
    half = w // 2
    left = x == 0 or x == half or img[y][x - 1] != v
    right = x == w - 1 or x == half - 1 or img[y][x + 1] != v
    across_x = left and right and not (x in (0, half) and x + 1 in (half, w))
    across_y = 0 < y < h - 1 and img[y - 1][x] != v and img[y + 1][x] != v
    return across_x or across_y


def is_sliver(render_ids, trace_ids, open_to_nothing=False):
    """Every mismatching pixel (beyond the one-pixel tolerance) is a feature
    one pixel thin in one of the images: a sub-pixel sliver (a door seen
    almost edge-on), which the rasteriser includes or drops by its
    1/256-pixel vertex snapping while the tracer is exact. A sliver of empty
    space (id 0) counts only where the layout has a portal reaching outside
    its room (Case.open_to_nothing); in closed rooms it would be a crack."""
    h, w = len(trace_ids), len(trace_ids[0])

    def near(img, x, y, v):
        return any(img[j][i] == v for j in range(max(0, y - 1), min(h, y + 2))
                   for i in range(max(0, x - 1), min(w, x + 2)))

    found = False
    for y in range(h):
        for x in range(w):
            r, t = render_ids[y][x], trace_ids[y][x]
            if near(trace_ids, x, y, r) and near(render_ids, x, y, t):
                continue  # within the one-pixel edge tolerance
            found = True
            if (0 in (r, t) and not open_to_nothing) or not (thin_at(trace_ids, x, y) or thin_at(render_ids, x, y)):
                return False
    return found


def is_door_edge_pixel(render_ids, trace_ids):
    """Every mismatching pixel is alone (no other within one pixel), empty
    (id 0) in the render, and lies on an edge between two rooms in both
    images, the tracer's id among them: a pixel centre within the
    rasteriser's vertex snapping of a door's bottom edge, where the
    rasteriser puts it on the door's side and the view through the door
    finds the target floor on its clipping plane (docs/accuracy.md, "Doors
    standing on the floor"). Only the floor_door kind is judged by it."""
    h, w = len(trace_ids), len(trace_ids[0])

    def around(img, x, y):
        return [img[j][i] for j in range(max(0, y - 1), min(h, y + 2)) for i in range(max(0, x - 1), min(w, x + 2))
                if (i, j) != (x, y)]

    bad = [(x, y) for y in range(h) for x in range(w)
           if not (trace_ids[y][x] in around(render_ids, x, y) + [render_ids[y][x]] and
                   render_ids[y][x] in around(trace_ids, x, y) + [trace_ids[y][x]])]
    for x, y in bad:
        r, t = render_ids[y][x], trace_ids[y][x]
        if r != 0 or t == 0 or any(abs(x - a) <= 1 and abs(y - b) <= 1 and (a, b) != (x, y) for a, b in bad):
            return False
        rooms = set(around(render_ids, x, y)) | set(around(trace_ids, x, y))
        if 0 in set(around(trace_ids, x, y)) or t not in around(render_ids, x, y) or len(rooms - {0}) < 2:
            return False
    return bool(bad)


def shell(args):
    return " ".join("'" + a + "'" if any(ch in a for ch in " ,()") else a for a in args)


# --lit: the colour PSNR (over interior pixels, away from id edges) a lit
# case must reach: issue 27's goals, 50 dB where no prop casts a shadow,
# 40 dB where shadow maps approximate props' shadows.
LIT_MIN_PSNR_NO_PROPS = 50.0
LIT_MIN_PSNR_PROPS = 40.0


def headset_profile(seed, number, fov):
    """--headset: a random headset profile (docs/headsets.md) for the case,
    from its own generator (the layout and pose stay those of the case):
    each eye's asymmetric angles about the case's field of view, and, in
    three cases of four, a random star-shaped visible area."""
    r = random.Random(seed * 7_000_013 + number)
    half = fov / 2.0

    def angles():
        return {"left": round(-half * r.uniform(0.6, 1.3), 4), "right": round(half * r.uniform(0.6, 1.3), 4),
                "up": round(half * r.uniform(0.6, 1.3), 4), "down": round(-half * r.uniform(0.6, 1.3), 4)}

    def area():
        cx, cy, corners = r.uniform(0.35, 0.65), r.uniform(0.35, 0.65), r.randint(3, 40)
        out = []
        for k in range(corners):
            # Star-shaped about (cx, cy), each corner within the image: simple.
            a = 2 * math.pi * k / corners
            dx, dy = math.cos(a), math.sin(a)
            reach = min((1 - cx) / dx if dx > 1e-9 else -cx / dx if dx < -1e-9 else 9,
                        (1 - cy) / dy if dy > 1e-9 else -cy / dy if dy < -1e-9 else 9)
            rad = min(r.uniform(0.25, 0.75), reach)
            out.append([round(cx + rad * dx, 5), round(cy + rad * dy, 5)])
        return out

    eyes = {}
    for eye in ("left", "right"):
        eyes[eye] = {"fov": angles(), "resolution": [16, 16]}
        if r.random() < 0.75:
            eyes[eye]["visible_area"] = area()
    return dict({"name": "diff_fuzz", "source": "random"}, **eyes)


def run_case(binary, seed, number, size, keep, extra, kinds=DEFAULT_KINDS, lit=False, headset=False):
    case = Case(seed, number, kinds)
    work = keep or tempfile.mkdtemp(prefix="diff-fuzz-")
    os.makedirs(work, exist_ok=True)
    layout_path = os.path.join(work, "case-%d-%d.json" % (seed, number))
    with open(layout_path, "w") as f:
        json.dump(case.layout(lit), f, indent=1)
    for name, text in getattr(case, "files", {}).items():  # models the layout names, beside it
        with open(os.path.join(work, name), "w") as f:
            f.write(text)
    base = os.path.join(work, "case-%d-%d" % (seed, number))
    view = case.view_args(size) + extra
    if headset:
        # The case's --fov replaced by a profile (--size stays; the IPD is 0.064 as before).
        with open(base + "-hmd.json", "w") as f:
            json.dump(headset_profile(seed, number, case.fov), f)
        at = view.index("--fov")
        view[at:at + 2] = ["--hmd", base + "-hmd.json"]
    render = [binary, "render", layout_path] + view + ["--out", base + "-r.png", "--ids", base + "-r-ids.png"]
    trace = [binary, "trace", layout_path] + view + ["--threads", "1", "--out", base + "-t.png", "--ids", base + "-t-ids.png"]
    compare = [binary, "compare", base + "-r.png", base + "-t.png", "--ids-a", base + "-r-ids.png",
               "--ids-b", base + "-t-ids.png"]
    result = {"seed": seed, "case": number, "kind": case.kind, "what": case.what, "layout": layout_path}
    if case.sub is not None:
        result["sub"] = case.sub
    for step, cmd in (("render", render), ("trace", trace)):
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        if p.returncode != 0:
            result.update(status="error", detail="%s exit %d: %s" % (step, p.returncode, p.stderr.strip()),
                          commands=[shell(render), shell(trace), shell(compare)])
            return result
        if step == "render" and "--max-portal-passes" in p.stderr:
            # The frame reached its portal-pass budget (docs/bounded-work.md):
            # the rest shows the fill colour, which the tracer does not have.
            result["budget"] = p.stderr.strip()
    p = subprocess.run(compare, capture_output=True, text=True, timeout=600)
    fields, mismatches, psnr = compare_figures(p.stdout)
    status = "pass" if mismatches == 0 else "fail"
    if lit and status == "pass":
        # Lit cases compare colours too (ids do not depend on lighting).
        need = LIT_MIN_PSNR_PROPS if case.casts_shadows() else LIT_MIN_PSNR_NO_PROPS
        result["interior_psnr"] = psnr
        if not psnr >= need:
            result["detail"] = "interior PSNR %.2f dB < %.0f dB" % (psnr, need)
            if colour_sliver(base):
                status = "colour-sliver"
            else:
                explained = lit_explained(case, binary, base, view, LIT_MIN_PSNR_NO_PROPS)
                if not explained:
                    explained = aligned_edge(binary, layout_path, base, view, need)
                status = explained[0] if explained else "colour"
                if explained:
                    result["explained"] = explained[1]
    if status == "fail" and is_sliver(read_grey_png(base + "-r-ids.png"), read_grey_png(base + "-t-ids.png"),
                                      case.open_to_nothing()):
        status = "sliver"
    if status == "fail" and case.kind == "floor_door" and is_door_edge_pixel(read_grey_png(base + "-r-ids.png"),
                                                                             read_grey_png(base + "-t-ids.png")):
        status = "sliver"
    result.update(status=status, mismatches=mismatches,
                  pct=float(fields.get("id_mismatch_pct", "nan")), psnr=fields.get("psnr_db", "?"),
                  commands=[shell(render), shell(trace), shell(compare)])
    if status == "fail" and case.near_plane_note() and not extra:
        result["near"] = case.near_plane_note()
    if not keep:
        for suffix in ("-r.png", "-r-ids.png", "-t.png", "-t-ids.png", "-s.png", "-u.json", "-ur.png", "-ut.png",
                       "-hmd.json"):
            try:
                os.remove(base + suffix)
            except OSError:
                pass
        if result["status"] not in ("fail", "error", "colour"):
            os.remove(layout_path)
            for name in getattr(case, "files", {}):
                os.remove(os.path.join(work, name))
            os.rmdir(work)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default="build/impossible")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=100, help="cases 0..N-1")
    ap.add_argument("--first", type=int, default=0, help="first case number")
    ap.add_argument("--every", type=int, default=1,
                    help="every Nth case from --first (--cases counts the cases run): a short run that still"
                         " reaches sub-kinds chosen by the case number, as the prism kind's are")
    ap.add_argument("--case", type=int, help="run this one case only")
    ap.add_argument("--size", default="96x64", help="eye size WxH")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--keep", help="keep every case's layout and images in this folder")
    ap.add_argument("--json", help="write every case's result here")
    ap.add_argument("--kinds", default=",".join(DEFAULT_KINDS),
                    help="the kinds of layout, comma-separated, case N of kind N mod their count (default %(default)s;"
                         " all: " + ",".join(KINDS) + ")")
    ap.add_argument("--lit", action="store_true",
                    help='make every case lit ("lighting": "lights", random lights and light depth) and compare colours'
                         " too: interior PSNR >= %.0f dB, %.0f dB with props" % (LIT_MIN_PSNR_NO_PROPS, LIT_MIN_PSNR_PROPS))
    ap.add_argument("--headset", action="store_true",
                    help="draw every case through a random headset profile (--hmd: asymmetric angles per eye and,"
                         " in three cases of four, a random visible area; docs/headsets.md)")
    ap.add_argument("extra", nargs="*", help="more options for render and trace (after --)")
    a = ap.parse_args()
    kinds = a.kinds.split(",")
    if not kinds or any(k not in KINDS for k in kinds):
        ap.error("--kinds: %s: the kinds are %s" % (a.kinds, ", ".join(KINDS)))
    # The kinds select each case's layout: a case is reproduced with the same list.
    kinds_arg = ("" if kinds == DEFAULT_KINDS else " --kinds " + ",".join(kinds)) + (" --lit" if a.lit else "") + (
        " --headset" if a.headset else "")
    if a.every < 1:
        ap.error("--every: %d: must be 1 or more" % a.every)
    numbers = [a.case] if a.case is not None else list(range(a.first, a.first + a.cases * a.every, a.every))
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        futures = [pool.submit(run_case, a.binary, a.seed, n, a.size, a.keep, a.extra, kinds, a.lit, a.headset)
                   for n in numbers]
        for fut in futures:
            res = fut.result()
            results.append(res)
            label = res["kind"] + ("/" + res["sub"] if "sub" in res else "")
            if res["status"] == "colour-sliver" and "explained" in res:
                print("colour sliver seed %d case %d (%s, %s): %s; %s"
                      % (res["seed"], res["case"], label, res["what"], res["detail"], res["explained"]))
            elif res["status"] == "colour-sliver":
                print("colour sliver seed %d case %d (%s, %s): %s, isolated pixels on a light's edge"
                      % (res["seed"], res["case"], label, res["what"], res["detail"]))
            elif res["status"] == "shadow":
                print("shadow seed %d case %d (%s, %s): %s; %s"
                      % (res["seed"], res["case"], label, res["what"], res["detail"], res["explained"]))
            elif res["status"] == "sliver":
                print("sliver seed %d case %d (%s, %s): %d id mismatches, all on features one pixel thin"
                      % (res["seed"], res["case"], label, res["what"], res["mismatches"]))
            elif res["status"] != "pass":
                print("FAIL seed %d case %d (%s, %s): %s" % (
                    res["seed"], res["case"], label, res["what"],
                    res.get("detail") or "%d id mismatches (%.4f %%)" % (res["mismatches"], res["pct"])))
                for note in ("budget", "near"):
                    if note in res:
                        print("  " + res[note])
                print("  reproduce: tools/diff_fuzz.py --binary %s --seed %d --case %d%s%s --keep /tmp/diff-fuzz-case%s"
                      % (a.binary, res["seed"], res["case"], kinds_arg,
                         "" if a.size == "96x64" else " --size " + a.size,
                         " -- " + shell(a.extra) if a.extra else ""))
                for cmd in res["commands"]:
                    print("    " + cmd)
    failed = [r for r in results if r["status"] in ("fail", "error", "colour")]
    slivers = [r for r in results if r["status"] in ("sliver", "colour-sliver")]
    kinds = {}
    for r in results:
        k = kinds.setdefault(r["kind"], [0, 0])
        k[0] += 1
        k[1] += r["status"] in ("fail", "error", "colour")
    shadows = [r for r in results if r["status"] == "shadow"]
    print("diff_fuzz seed %d: %d cases, %d with 0 mismatches, %d slivers (sub-pixel features, explained), %s%d failed (%s)"
          % (a.seed, len(results), len(results) - len(failed) - len(slivers) - len(shadows), len(slivers),
             "%d shadow (props' shadow maps, explained), " % len(shadows) if a.lit else "", len(failed),
             ", ".join("%s %d/%d failed" % (k, v[1], v[0]) for k, v in sorted(kinds.items()))))
    subs = {}
    for r in results:
        if "sub" in r:
            subs.setdefault(r["kind"] + "/" + r["sub"], {"pass": 0, "sliver": 0, "shadow": 0, "fail": 0})[
                {"error": "fail", "colour": "fail", "colour-sliver": "sliver"}.get(r["status"], r["status"])] += 1
    if subs:
        print("by sub-kind: " + ", ".join("%s %d pass, %d sliver, %s%d failed" % (
            k, v["pass"], v["sliver"], "%d shadow, " % v["shadow"] if a.lit else "", v["fail"])
            for k, v in sorted(subs.items())))
    if a.lit:
        values = sorted(r["interior_psnr"] for r in results if "interior_psnr" in r)
        if values:
            print("lit: interior PSNR against trace over %d cases: min %.2f dB, median %.2f dB" % (
                len(values), values[0], values[len(values) // 2]))
    print("%d passed, %d failed" % (len(results) - len(failed), len(failed)))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
