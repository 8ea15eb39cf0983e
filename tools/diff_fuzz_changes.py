#!/usr/bin/env python3
"""Differential fuzzer for layouts that change while walked (issue 40;
layout-format.md, "Changes while walking"; docs/changes.md): random layouts
with random `changes`, random walks, and at each change `render` against
`trace` and the seen test against the tracer's pixel rays.

Each case (seed, number) is:
  layout  3-4 overlapping box rooms (each holds the common square
          |x|, |z| <= 3.5 m), 3-5 slots on a 2 m grid in that square, each
          with a coincident pair of free-standing doors in two different
          rooms (normals opposite, turned by multiples of 90 degrees or at
          random, boxes 1 cm to 0.5 m deep, one or two door sizes), 0-2 box
          props per room outside the square; in 40 % of the cases a mirror
          in a wall of one room (sometimes tinted), in 30 % a window pair in
          walls of two rooms (random reflectance): the seen test and the
          rays pass them, the walk never reaches them;
  view    --size 96x64, --fov 60-110 or, in a quarter of the cases, a random
          headset profile (--hmd; tools/diff_fuzz.py's headset_profile:
          asymmetric angles, often a visible area), --max-depth 1-8: the
          same for walk, render and trace;
  changes 1-3 valid changes: 1-2 pairs of doors of equal size in different
          rooms, each door at most once in a change, no pair already
          partners; `when` is an `enter` room, an `after` naming an earlier
          change, a `time`, or several of them;
  walk    a path file built leg by leg: from the head's virtual pose (which
          `impossible walk` prints), sometimes a look round (90 or 180
          degrees, or any turn) then a walk to 1 m in front of a door of the
          head's room (in 70 % of the legs where there is one, a door that
          leads, with the pairing walk has made so far, into a room a
          change not yet made names in `enter`), a turn to face it and a
          walk 0.7 m through it; at most 10 legs or 200 frames. The
          virtual way points go through the walker's W (from the pose it
          prints) to physical poses; the path is cut after the first frame
          of a leg that teleports, and the next leg starts there. Head
          height 1.6 m (doors stand on the floor and pairs have equal
          sizes, so W never moves it).

`impossible walk` is run on the path with the case's view options (--size,
--fov, --max-depth: the seen test's eyes). Then, for each frame K at which
a change is made:
  - `trace --path --frame K --portal-rays 1` (every pixel centre of both
    eyes; trace/portal_rays.hpp) reports the portals its rays reach through
    portals only, room faces and props ignored, with the pairing frame K
    started with: exactly the pairing and eyes the seen test decided on at
    K (cli.md, trace). None of the change's affected doors (the doors it
    names and their partners before it, the script keeps the pairing frame
    by frame from walk's "changes") may be among them: a door reached there
    is one the seen test called unseen while a pixel showed it.
  - frame K and one or two later frames (K + 1, and K + 2..15 where the path
    is long enough) are rendered and traced with `--path --frame` and
    compared as tools/diff_fuzz.py compares: 0 cell-id mismatches beyond the
    one-pixel edge tolerance, or every mismatch on a feature one pixel thin
    or, as in its floor_door kind (these doors stand on the floor too), a
    lone pixel empty in the render on a door's bottom edge
    (is_door_edge_pixel; docs/accuracy.md, "Doors standing on the floor"):
    a "sliver", listed, not failed.
A case with no change made (the affected doors never out of view) compares
its last frame only, and is counted as such.

    tools/diff_fuzz_changes.py --binary build/impossible --seed 1 --cases 40
    tools/diff_fuzz_changes.py --binary build/impossible --seed 1 --case 7 --keep /tmp/changes7

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
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from diff_fuzz import (compare_figures, headset_profile, is_door_edge_pixel, is_sliver, read_grey_png,  # noqa: E402
                       rnd_color, shell)

STEP = 0.08  # metres a frame
TURN = 12.0  # degrees a frame
HEAD_Y = 1.6
GRID = [-2.0, 0.0, 2.0]


def yaw_of(forward):
    """The yaw (degrees) that looks along `forward` (yaw 0 looks along -z, 90 along -x)."""
    return math.degrees(math.atan2(-forward[0], -forward[2]))


def rotate_y(v, deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    return [c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2]]


class ChangeCase:
    """One layout with changes, made from (seed, number) alone; the walk is
    made by make_walk, which runs `impossible walk` leg by leg."""

    def __init__(self, seed, number):
        self.seed, self.number = seed, number
        r = random.Random(seed * 9_000_011 + number)
        self.r = r
        self.size = "96x64"
        self.fov = r.choice([60, 90, 90, 110])
        self.max_depth = r.choice([1, 2, 4, 8])
        self.rooms, self.portals, self.changes = [], [], []
        self.make_rooms()
        self.make_doors()
        self.make_glass()
        self.make_changes()
        # A headset profile (--hmd, tools/diff_fuzz.py's headset_profile:
        # asymmetric angles, often a visible area) instead of --fov, in a
        # quarter of the cases: walk's seen test and the rays then both
        # leave the hidden pixels out.
        self.headset = headset_profile(seed, number, self.fov) if r.random() < 0.25 else None
        self.hmd_path = None

    # --- the layout ------------------------------------------------------
    def make_rooms(self):
        r = self.r
        for k in range(r.randint(3, 4)):
            o = [round(r.uniform(-0.5, 0.5), 2), 0.0, round(r.uniform(-0.5, 0.5), 2)]
            hx, hz, h = round(r.uniform(4.0, 5.5), 2), round(r.uniform(4.0, 5.5), 2), round(r.uniform(2.6, 3.5), 2)
            lo, hi = [o[0] - hx, 0.0, o[2] - hz], [o[0] + hx, h, o[2] + hz]
            room = {"id": "r%d" % k, "min": lo, "max": hi, "color": rnd_color(r)}
            if r.random() < 0.3:
                room["checker"] = round(r.uniform(0.3, 1.0), 2)
            props = []
            for _ in range(r.randint(0, 2)):  # outside the walked square
                side = r.choice([-1, 1])
                along = r.uniform(-3, 3)
                off = side * r.uniform(3.7, 3.9)
                c = [off, 0, along] if r.random() < 0.5 else [along, 0, off]
                s = [r.uniform(0.1, 0.25), r.uniform(0.2, 1.5), r.uniform(0.1, 0.25)]
                props.append({"box": {"min": [round(c[0] - s[0], 4), 0, round(c[2] - s[2], 4)],
                                      "max": [round(c[0] + s[0], 4), round(s[1], 4), round(c[2] + s[2], 4)]},
                              "color": rnd_color(r)})
            if props:
                room["props"] = props
            self.rooms.append(room)

    def make_doors(self):
        r = self.r
        sizes = [(r.choice([0.8, 1.0, 1.2]), r.choice([2.0, 2.2]))]
        if r.random() < 0.4:
            sizes.append((r.choice([0.6, 1.4]), r.choice([1.9, 2.3])))
        spots = [(x, z) for x in GRID for z in GRID]
        r.shuffle(spots)
        self.slots = []
        for k in range(r.randint(3, 5)):
            x, z = spots[k]
            yaw = r.choice([0, 90, 180, 270]) if r.random() < 0.8 else r.uniform(0, 360)
            n = [round(math.sin(math.radians(yaw)), 12), 0.0, round(math.cos(math.radians(yaw)), 12)]
            w, h = sizes[k % len(sizes)] if k < len(sizes) else r.choice(sizes)
            a, b = r.sample(range(len(self.rooms)), 2)
            c = [x, h / 2, z]  # standing on the floor
            fa, fb = "d%df" % k, "d%db" % k
            self.door(fa, self.rooms[a]["id"], c, n, w, h, fb)
            self.door(fb, self.rooms[b]["id"], c, [-v for v in n], w, h, fa)
            self.slots.append(k)
        self.start_room = self.portals[0]["room"] if r.random() < 0.7 else r.choice(self.rooms)["id"]
        for _ in range(100):  # a start clear of every door's box (the glass is in walls)
            p = [round(r.uniform(-3, 3), 2), HEAD_Y, round(r.uniform(-3, 3), 2)]
            if all(math.hypot(p[0] - d["center"][0], p[2] - d["center"][2]) > 1.0 for d in self.portals):
                break
        self.start = p
        self.start_yaw = round(r.uniform(-180, 180), 1)

    def door(self, pid, room, c, n, w, h, target):
        depth = self.r.choice([0.01, 0.05, 0.2]) if self.r.random() < 0.6 else math.exp(
            self.r.uniform(math.log(0.01), math.log(0.5)))
        self.portals.append({"id": pid, "room": room, "center": [round(v, 6) for v in c],
                             "normal": [round(v, 12) for v in n], "width": w, "height": h, "target": target,
                             "depth": round(depth, 4)})

    def make_glass(self):
        """Sometimes a mirror in a wall of one room, and a window pair in
        walls of two rooms: the seen test and the rays pass them (reflected,
        and to the other room), the walk never reaches them."""
        r = self.r

        def in_wall(room):
            lo, hi = room["min"], room["max"]
            side = r.choice([0, 1, 2, 3])  # -x, +x, -z, +z
            axis, other = (0, 2) if side < 2 else (2, 0)
            c = [0.0, 0.0, 0.0]
            c[axis] = lo[axis] if side % 2 == 0 else hi[axis]
            n = [0.0, 0.0, 0.0]
            n[axis] = 1.0 if side % 2 == 0 else -1.0
            w, h = round(r.uniform(0.5, 2.5), 2), round(r.uniform(0.5, 1.8), 2)
            c[other] = round(r.uniform(-1.5, 1.5), 2)  # within the wall: every room spans ±3.5 m
            c[1] = round(r.uniform(h / 2 + 0.1, hi[1] - h / 2 - 0.1), 3)
            return {"room": room["id"], "center": c, "normal": n, "width": w, "height": h}

        free = list(self.rooms)  # the window pair's rooms: not the mirror's (their holes would overlap)
        if r.random() < 0.4:
            room = r.choice(self.rooms)
            free.remove(room)
            m = dict({"id": "mirror"}, **in_wall(room), kind="mirror")
            if r.random() < 0.5:
                m["tint"] = [round(r.uniform(0.3, 1), 3) for _ in range(3)]
            self.portals.append(m)
        if r.random() < 0.3:
            a, b = r.sample(free, 2)
            wa, wb = in_wall(a), in_wall(b)
            wb["width"], wb["height"] = h = wa["width"], wa["height"]
            wb["center"][1] = round(r.uniform(h[1] / 2 + 0.1, b["max"][1] - h[1] / 2 - 0.1), 3)
            self.portals.append(dict({"id": "window_a"}, **wa, kind="window", target="window_b",
                                     reflectance=round(r.uniform(0, 1), 3)))
            self.portals.append(dict({"id": "window_b"}, **wb, kind="window", target="window_a"))

    def make_changes(self):
        r = self.r
        doors = [p for p in self.portals if p.get("kind", "door") == "door"]
        partner = {p["id"]: p["target"] for p in doors}
        by_id = {p["id"]: p for p in doors}
        for k in range(r.randint(1, 3)):
            used, pairs = set(), []
            for _ in range(r.choice([1, 1, 2])):
                for _ in range(50):
                    x, y = r.sample(sorted(by_id), 2)
                    px, py = by_id[x], by_id[y]
                    if (x in used or y in used or px["room"] == py["room"] or partner.get(x) == y
                            or (px["width"], px["height"]) != (py["width"], py["height"])):
                        continue
                    pairs.append([x, y])
                    used |= {x, y}
                    break
            if not pairs:
                continue
            when = {}
            if r.random() < 0.75:
                when["enter"] = r.choice(self.rooms)["id"]
            if self.changes and r.random() < 0.4:
                when["after"] = r.choice(self.changes)["id"]
            if r.random() < 0.2 or not when:
                when["time"] = round(r.uniform(0, 2), 2)
            self.changes.append({"id": "c%d" % k, "when": when, "pairs": pairs})
            for x, y in pairs:  # the pairing were it made in file order (for "no pair already partners")
                for d in (x, y):
                    if partner.get(d) is not None and partner[d] not in used:
                        partner[partner[d]] = None
                partner[x], partner[y] = y, x

    def layout(self):
        return {"format": "impossible-layout", "version": 1,
                "name": "diff_fuzz_changes seed %d case %d" % (self.seed, self.number),
                "start": {"room": self.start_room, "position": self.start, "yaw_deg": self.start_yaw},
                "rooms": self.rooms, "portals": self.portals, "changes": self.changes}

    def view_args(self):
        eyes = ["--hmd", self.hmd_path] if self.hmd_path else ["--fov", str(self.fov)]
        return ["--size", self.size] + eyes + ["--max-depth", str(self.max_depth)]

    # --- the walk --------------------------------------------------------
    def run_walk(self, binary, layout_path, path_path, lines):
        with open(path_path, "w") as f:
            f.write("\n".join(lines) + "\n")
        p = subprocess.run([binary, "walk", layout_path, "--path", path_path] + self.view_args(),
                           capture_output=True, text=True, timeout=120)
        if p.returncode != 0:
            raise RuntimeError("walk exit %d: %s" % (p.returncode, p.stderr.strip()))
        return [json.loads(line) for line in p.stdout.splitlines() if line.strip()]

    def pairing_after(self, out):
        """The doors' partners after the changes walk made in `out`, and the
        ids of those changes."""
        pairing = {p["id"]: p["target"] for p in self.portals if p.get("kind", "door") == "door"}
        by_id = {c["id"]: c for c in self.changes}
        made = set()
        for line in out:
            for cid in line.get("changes", []):
                pairing = affected_and_apply(pairing, by_id[cid])[1]
                made.add(cid)
        return pairing, made

    def make_walk(self, binary, layout_path, path_path, max_frames=200, max_legs=10):
        """The path's lines and walk's output for them."""
        r = self.r
        phys = [list(self.start), self.start_yaw, 0.0]  # physical position, yaw, pitch
        lines = []

        def add(pos, yaw, pitch):
            phys[0], phys[1], phys[2] = list(pos), yaw, pitch
            lines.append("%.6f %.6f %.6f %.4f %.4f 0" % (pos[0], pos[1], pos[2], yaw, pitch))

        add(phys[0], phys[1], 0.0)
        out = self.run_walk(binary, layout_path, path_path, lines)
        for _ in range(max_legs):
            if len(lines) >= max_frames:
                break
            last = out[-1]
            # W: virtual = R(theta) physical + t (doors upright: a turn about y and a move).
            theta = yaw_of(last["forward"]) - phys[1]
            rp = rotate_y(phys[0], theta)
            t = [last["position"][i] - rp[i] for i in range(3)]

            def to_phys(v):
                return rotate_y([v[i] - t[i] for i in range(3)], -theta)

            start_leg = len(lines)
            vpos = list(last["position"])
            vyaw = yaw_of(last["forward"])
            pitch = phys[2]

            def turn_to(target_yaw, target_pitch):
                nonlocal vyaw, pitch
                d = (target_yaw - vyaw + 180) % 360 - 180
                steps = max(1, int(math.ceil(max(abs(d), abs(target_pitch - pitch)) / TURN)))
                y0, p0 = vyaw, pitch
                for s in range(1, steps + 1):
                    vyaw, pitch = y0 + d * s / steps, p0 + (target_pitch - p0) * s / steps
                    add(to_phys(vpos), vyaw - theta, pitch)

            def walk_to(target):
                nonlocal vpos
                d = [target[0] - vpos[0], 0.0, target[2] - vpos[2]]
                length = math.hypot(d[0], d[2])
                if length < 1e-6:
                    return
                turn_to(yaw_of(d), 0.0)
                steps = max(1, int(math.ceil(length / STEP)))
                v0 = list(vpos)
                for s in range(1, steps + 1):
                    vpos = [v0[0] + d[0] * s / steps, HEAD_Y, v0[2] + d[2] * s / steps]
                    add(to_phys(vpos), vyaw - theta, pitch)

            if r.random() < 0.6:  # a look round, turning round now and then
                turn = r.choice([180, 90, -90, 180]) if r.random() < 0.7 else r.uniform(-180, 180)
                turn_to(vyaw + turn, r.choice([0, 0, -20, 15]))
                for _ in range(r.randint(1, 4)):
                    add(to_phys(vpos), vyaw - theta, pitch)
            doors = [p for p in self.portals if p["room"] == last["room"] and p.get("kind", "door") == "door"]
            # Mostly a door into a room a change waits for (with the pairing
            # walk has made so far), so that more changes are armed.
            pairing, made = self.pairing_after(out)
            wanted = {c["when"].get("enter") for c in self.changes if c["id"] not in made}
            rooms = {p["id"]: p["room"] for p in self.portals}
            toward = [p for p in doors if pairing.get(p["id"]) and rooms[pairing[p["id"]]] in wanted]
            if toward and r.random() < 0.7:
                doors = toward
            if doors:
                d = r.choice(doors)
                c, n = d["center"], d["normal"]
                walk_to([c[0] + n[0], HEAD_Y, c[2] + n[2]])
                walk_to([c[0] - 0.7 * n[0], HEAD_Y, c[2] - 0.7 * n[2]])
            if len(lines) == start_leg:
                add(to_phys(vpos), vyaw - theta, pitch)
            out = self.run_walk(binary, layout_path, path_path, lines)
            for k in range(start_leg, len(lines)):
                if out[k]["teleports"]:  # cut after it: the next leg plans from there
                    del lines[k + 1:]
                    fields = lines[-1].split()
                    phys[0], phys[1], phys[2] = [float(v) for v in fields[:3]], float(fields[3]), float(fields[4])
                    out = self.run_walk(binary, layout_path, path_path, lines)
                    break
        for _ in range(r.randint(0, 3)):  # a last look round, for a change still waiting
            turn = r.uniform(-180, 180)
            steps = int(abs(turn) / TURN) + 1
            for s in range(1, steps + 1):
                add(phys[0], phys[1] + turn / steps, phys[2])
        out = self.run_walk(binary, layout_path, path_path, lines)
        return lines, out


def affected_and_apply(pairing, change):
    """The change's affected doors under `pairing` (its named doors and their
    partners just before it), and the pairing after it (layout-format.md)."""
    named = {d for pair in change["pairs"] for d in pair}
    affected = set(named) | {pairing[d] for d in named if pairing.get(d) is not None}
    after = dict(pairing)
    for d in named:
        old = pairing.get(d)
        if old is not None and old not in named:
            after[old] = None  # closed
    for x, y in change["pairs"]:
        after[x], after[y] = y, x
    return affected, after


def compare_frame(binary, layout_path, path_path, view, base, frame, portal_rays=False):
    """Renders and traces frame `frame`; (status, detail, commands, rays)."""
    at = ["--path", path_path, "--frame", str(frame)]
    out = "%s-f%d" % (base, frame)
    render = [binary, "render", layout_path] + at + view + ["--out", out + "-r.png", "--ids", out + "-r-ids.png"]
    trace = [binary, "trace", layout_path] + at + view + ["--threads", "1", "--out", out + "-t.png",
                                                          "--ids", out + "-t-ids.png"]
    if portal_rays:
        trace += ["--portal-rays", "1"]
    compare = [binary, "compare", out + "-r.png", out + "-t.png", "--ids-a", out + "-r-ids.png",
               "--ids-b", out + "-t-ids.png"]
    commands = [shell(render), shell(trace), shell(compare)]
    rays = None
    for step, cmd in (("render", render), ("trace", trace)):
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        if p.returncode != 0:
            return "error", "%s exit %d: %s" % (step, p.returncode, p.stderr.strip()), commands, rays
        if step == "trace" and portal_rays:
            found = [line for line in p.stderr.splitlines() if line.startswith("portal_rays:")]
            if len(found) != 1:
                return "error", "trace printed no portal_rays line: " + p.stderr.strip(), commands, rays
            rays = found[0].split()[1:]
    p = subprocess.run(compare, capture_output=True, text=True, timeout=600)
    fields, mismatches, _ = compare_figures(p.stdout)
    if mismatches == 0:
        status = "pass"
    else:
        ids = read_grey_png(out + "-r-ids.png"), read_grey_png(out + "-t-ids.png")
        # The doors stand on the floor: a lone pixel on a bottom edge is the
        # floor_door kind's sliver too (tools/diff_fuzz.py, is_door_edge_pixel).
        thin = is_sliver(*ids)
        edge = not thin and is_door_edge_pixel(*ids)
        status = "sliver" if thin or edge else "fail"
    detail = "frame %d: %d id mismatches (%s %%)%s" % (
        frame, mismatches, fields.get("id_mismatch_pct", "?"),
        "" if status != "sliver" else ", all on features one pixel thin" if thin else ", a door's bottom edge")
    return status, detail, commands, rays


def run_case(binary, seed, number, keep):
    case = ChangeCase(seed, number)
    work = keep or tempfile.mkdtemp(prefix="diff-fuzz-changes-")
    os.makedirs(work, exist_ok=True)
    base = os.path.join(work, "changes-%d-%d" % (seed, number))
    layout_path, path_path = base + ".json", base + "-walk.txt"
    with open(layout_path, "w") as f:
        json.dump(case.layout(), f, indent=1)
    if case.headset:
        case.hmd_path = base + "-hmd.json"
        with open(case.hmd_path, "w") as f:
            json.dump(case.headset, f)
    result = {"seed": seed, "case": number, "layout": layout_path, "path": path_path, "frames": [],
              "made": [], "problems": [], "headset": bool(case.headset),
              "glass": sorted({p["kind"] for p in case.portals if p.get("kind", "door") != "door"})}
    try:
        lines, out = case.make_walk(binary, layout_path, path_path)
    except (RuntimeError, subprocess.TimeoutExpired) as e:
        result.update(status="error", detail=str(e))
        return result
    result["length"] = len(lines)
    view = case.view_args()
    pairing = case.pairing_after([])[0]
    by_id = {c["id"]: c for c in case.changes}
    checks = []  # (frame, affected doors or None)
    for line in out:
        for cid in line.get("changes", []):
            affected, pairing = affected_and_apply(pairing, by_id[cid])
            result["made"].append([line["frame"], cid])
            checks.append((line["frame"], sorted(affected)))
    frames = {}
    for frame, affected in checks:
        if frames.get(frame) is None:
            frames[frame] = set()
        frames[frame].update(affected)
        for later in (frame + 1, frame + case.r.randint(2, 15)):
            if later < len(lines):
                frames.setdefault(later, None)
    if not checks:
        frames[len(lines) - 1] = None
    status = "pass"
    for frame in sorted(frames):
        affected = frames[frame]
        s, detail, commands, rays = compare_frame(binary, layout_path, path_path, view, base, frame,
                                                  affected is not None)
        result["frames"].append(frame)
        if s in ("fail", "error"):
            status = "fail"
            result["problems"].append({"what": detail, "commands": commands})
        elif s == "sliver":
            status = "sliver" if status == "pass" else status
            result.setdefault("slivers", []).append(detail)
        if rays is not None:
            result.setdefault("rays", {})[frame] = rays
            seen = sorted(set(rays) & affected)
            if seen:
                status = "fail"
                result["problems"].append({
                    "what": "frame %d: a change was made while pixel rays reach its affected doors %s "
                            "(portal_rays: %s)" % (frame, " ".join(seen), " ".join(rays)),
                    "commands": [commands[1]]})
    result["status"] = status
    result["pending"] = len(case.changes) - len(result["made"])
    if not keep:
        for name in os.listdir(work):
            if name.endswith(".png") and (status == "pass" or "-f" in name):
                os.remove(os.path.join(work, name))
        if status in ("pass", "sliver"):
            for p in (layout_path, path_path, case.hmd_path):
                if p:
                    os.remove(p)
            if not os.listdir(work):
                os.rmdir(work)
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default="build/impossible")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", type=int, default=40, help="cases 0..N-1")
    ap.add_argument("--first", type=int, default=0, help="first case number")
    ap.add_argument("--case", type=int, help="run this one case only")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--keep", help="keep every case's layout, walk and images in this folder")
    ap.add_argument("--json", help="write every case's result here")
    a = ap.parse_args()
    numbers = [a.case] if a.case is not None else list(range(a.first, a.first + a.cases))
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        for res in pool.map(lambda n: run_case(a.binary, a.seed, n, a.keep), numbers):
            results.append(res)
            if res["status"] == "sliver":
                print("sliver seed %d case %d: %s" % (res["seed"], res["case"], "; ".join(res["slivers"])))
            elif res["status"] != "pass":
                print("FAIL seed %d case %d: %s" % (res["seed"], res["case"], res.get("detail", "%d problems" % len(
                    res["problems"]))))
                for problem in res["problems"]:
                    print("  " + problem["what"])
                    for cmd in problem["commands"]:
                        print("    " + cmd)
                print("  reproduce: tools/diff_fuzz_changes.py --binary %s --seed %d --case %d --keep "
                      "/tmp/diff-fuzz-changes-case" % (a.binary, res["seed"], res["case"]))
    failed = [r for r in results if r["status"] in ("fail", "error")]
    slivers = [r for r in results if r["status"] == "sliver"]
    made = sum(len(r["made"]) for r in results)
    print("diff_fuzz_changes seed %d: %d cases, %d walk frames, %d changes made (%d cases with none), "
          "%d frames compared, %d portal-ray checks, %d slivers, %d failed"
          % (a.seed, len(results), sum(r.get("length", 0) for r in results), made,
             sum(1 for r in results if not r["made"]), sum(len(r["frames"]) for r in results),
             sum(len(r.get("rays", {})) for r in results), len(slivers), len(failed)))
    print("views and glass: %d cases through a headset profile, %d with a mirror, %d with a window pair"
          % (sum(r["headset"] for r in results), sum("mirror" in r["glass"] for r in results),
             sum("window" in r["glass"] for r in results)))
    print("%d passed, %d failed" % (len(results) - len(failed), len(failed)))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(results, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
