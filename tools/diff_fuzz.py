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
file is kept in --keep DIR). The same --seed and case number always make the
same layout and pose.

    tools/diff_fuzz.py --binary build/impossible --seed 1 --cases 300
    tools/diff_fuzz.py --binary build/impossible --seed 1 --case 17 --keep /tmp/case17

A case whose every mismatching pixel lies on a feature one pixel thin (a door
seen nearly edge-on, a sub-pixel prop edge) is counted as a "sliver": the
rasteriser includes or drops such a feature by its 1/256-pixel vertex
snapping, the tracer by exact arithmetic (docs/accuracy.md). Slivers are
listed but do not fail the run; any other mismatch does.

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

KINDS = ["coincident", "wall_pair", "free_pair", "corridor"]


def rnd_color(r):
    return [round(r.uniform(0.15, 0.95), 3) for _ in range(3)]


def log_uniform(r, lo, hi):
    return math.exp(r.uniform(math.log(lo), math.log(hi)))


class Case:
    """One layout and one pose, made from (seed, number) alone."""

    def __init__(self, seed, number):
        self.seed, self.number = seed, number
        r = random.Random(seed * 1_000_003 + number)
        self.r = r
        self.kind = KINDS[number % len(KINDS)]
        far = r.random() < 0.3
        self.origin = [r.uniform(-2000, 2000), 0.0, r.uniform(-2000, 2000)] if far else [0.0, 0.0, 0.0]
        self.rooms, self.portals = [], []
        getattr(self, "make_" + self.kind)()
        self.pose, self.room, self.max_depth, self.fov, self.what = self.make_pose()

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

    def layout(self):
        return {"format": "impossible-layout", "version": 1,
                "name": "diff_fuzz seed %d case %d (%s)" % (self.seed, self.number, self.kind),
                "start": {"room": "a", "position": self.pose[:3]},
                "rooms": self.rooms, "portals": self.portals}

    def open_to_nothing(self):
        """Whether a portal's rectangle reaches outside its own room (by more
        than 1 µm): looking through its partner, a ray then leaves the room
        through that part and rightly meets nothing (id 0). In a layout where
        no portal does, every ray stays in closed rooms, and id 0 anywhere is
        a crack."""
        rooms = {room["id"]: room for room in self.rooms}
        for p in self.portals:
            n = p["normal"]
            up = p.get("up", [0.0, 1.0, 0.0])
            right = [up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]]
            room = rooms[p["room"]]
            for sr in (-0.5, 0.5):
                for su in (-0.5, 0.5):
                    corner = [p["center"][a] + sr * p["width"] * right[a] + su * p["height"] * up[a]
                              for a in range(3)]
                    if any(corner[a] < room["min"][a] - 1e-6 or corner[a] > room["max"][a] + 1e-6
                           for a in range(3)):
                        return True
        return False

    def view_args(self, size):
        pose = ",".join("%.17g" % v for v in self.pose)
        return ["--pose=" + pose, "--room", self.room, "--size", size, "--fov", "%.6g" % self.fov,
                "--max-depth", str(self.max_depth)]


def read_grey_png(path):
    """An 8-bit greyscale, non-interlaced PNG (what `--ids` writes) as rows."""
    data = open(path, "rb").read()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", chunk[:10])
            assert depth == 8 and colour == 0, path + ": not an 8-bit grey PNG"
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    raw, rows, prev, k = zlib.decompress(idat), [], bytearray(width), 0
    for _ in range(height):
        kind, line = raw[k], bytearray(raw[k + 1:k + 1 + width])
        k += 1 + width
        for x in range(width):
            a = line[x - 1] if x else 0
            b, c = prev[x], (prev[x - 1] if x else 0)
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


def thin_at(img, x, y):
    """The id at (x, y) differs from both neighbours across one axis: a
    feature one pixel thin there."""
    h, w, v = len(img), len(img[0]), img[y][x]
    across_x = 0 < x < w - 1 and img[y][x - 1] != v and img[y][x + 1] != v
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


def shell(args):
    return " ".join("'" + a + "'" if any(ch in a for ch in " ,()") else a for a in args)


def run_case(binary, seed, number, size, keep, extra):
    case = Case(seed, number)
    work = keep or tempfile.mkdtemp(prefix="diff-fuzz-")
    os.makedirs(work, exist_ok=True)
    layout_path = os.path.join(work, "case-%d-%d.json" % (seed, number))
    with open(layout_path, "w") as f:
        json.dump(case.layout(), f, indent=1)
    base = os.path.join(work, "case-%d-%d" % (seed, number))
    view = case.view_args(size) + extra
    render = [binary, "render", layout_path] + view + ["--out", base + "-r.png", "--ids", base + "-r-ids.png"]
    trace = [binary, "trace", layout_path] + view + ["--threads", "1", "--out", base + "-t.png", "--ids", base + "-t-ids.png"]
    compare = [binary, "compare", base + "-r.png", base + "-t.png", "--ids-a", base + "-r-ids.png",
               "--ids-b", base + "-t-ids.png"]
    result = {"seed": seed, "case": number, "kind": case.kind, "what": case.what, "layout": layout_path}
    for step, cmd in (("render", render), ("trace", trace)):
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        if p.returncode != 0:
            result.update(status="error", detail="%s exit %d: %s" % (step, p.returncode, p.stderr.strip()),
                          commands=[shell(render), shell(trace), shell(compare)])
            return result
    p = subprocess.run(compare, capture_output=True, text=True, timeout=600)
    fields = dict(kv.split("=", 1) for kv in p.stdout.split() if "=" in kv)
    mismatches = int(fields.get("id_mismatches", "-1"))
    status = "pass" if mismatches == 0 else "fail"
    if status == "fail" and is_sliver(read_grey_png(base + "-r-ids.png"), read_grey_png(base + "-t-ids.png"),
                                      case.open_to_nothing()):
        status = "sliver"
    result.update(status=status, mismatches=mismatches,
                  pct=float(fields.get("id_mismatch_pct", "nan")), psnr=fields.get("psnr_db", "?"),
                  commands=[shell(render), shell(trace), shell(compare)])
    if not keep:
        for suffix in ("-r.png", "-r-ids.png", "-t.png", "-t-ids.png"):
            try:
                os.remove(base + suffix)
            except OSError:
                pass
        if result["status"] != "fail" and result["status"] != "error":
            os.remove(layout_path)
            os.rmdir(work)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default="build/impossible")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=100, help="cases 0..N-1")
    ap.add_argument("--first", type=int, default=0, help="first case number")
    ap.add_argument("--case", type=int, help="run this one case only")
    ap.add_argument("--size", default="96x64", help="eye size WxH")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--keep", help="keep every case's layout and images in this folder")
    ap.add_argument("--json", help="write every case's result here")
    ap.add_argument("extra", nargs="*", help="more options for render and trace (after --)")
    a = ap.parse_args()
    numbers = [a.case] if a.case is not None else list(range(a.first, a.first + a.cases))
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        futures = [pool.submit(run_case, a.binary, a.seed, n, a.size, a.keep, a.extra) for n in numbers]
        for fut in futures:
            res = fut.result()
            results.append(res)
            if res["status"] == "sliver":
                print("sliver seed %d case %d (%s, %s): %d id mismatches, all on features one pixel thin"
                      % (res["seed"], res["case"], res["kind"], res["what"], res["mismatches"]))
            elif res["status"] != "pass":
                print("FAIL seed %d case %d (%s, %s): %s" % (
                    res["seed"], res["case"], res["kind"], res["what"],
                    res.get("detail") or "%d id mismatches (%.4f %%)" % (res["mismatches"], res["pct"])))
                print("  reproduce: tools/diff_fuzz.py --binary %s --seed %d --case %d --keep /tmp/diff-fuzz-case"
                      % (a.binary, res["seed"], res["case"]))
                for cmd in res["commands"]:
                    print("    " + cmd)
    failed = [r for r in results if r["status"] in ("fail", "error")]
    slivers = [r for r in results if r["status"] == "sliver"]
    kinds = {}
    for r in results:
        k = kinds.setdefault(r["kind"], [0, 0])
        k[0] += 1
        k[1] += r["status"] in ("fail", "error")
    print("diff_fuzz seed %d: %d cases, %d with 0 mismatches, %d slivers (sub-pixel features, explained), %d failed (%s)"
          % (a.seed, len(results), len(results) - len(failed) - len(slivers), len(slivers), len(failed),
             ", ".join("%s %d/%d failed" % (k, v[1], v[0]) for k, v in sorted(kinds.items()))))
    print("%d passed, %d failed" % (len(results) - len(failed), len(failed)))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
