#!/usr/bin/env python3
"""Measures `impossible generate` against issue 23's goals (docs/designer.md).

For each case (4 x 4 m with 6 rooms, 6 x 6 m with 10 rooms, a 6 x 6 m L with
8 rooms) and each seed, it runs `generate --out`, and counts the layout as a
success when generate exits 0 and:
  - `validate --json` finds it valid, with no unreachable room, no room or
    door outside the play area and no noticeable overlap;
  - every room is at least 1.5 m wide (measured here from the file: across
    the room from the middle of each wall, see room_width);
  - `tour` visits every room, and its path replayed by `walk` enters every
    room;
  - a second run of the same command writes the same bytes.
It prints per case: successes, the mean expansion ratio (validate's), the
narrowest room, generate's time per layout (median and max), and the room
shapes written. Exit status 1 when a layout fails.

Usage: tools/generate_goals.py [--bin build/impossible] [--seeds 50] [--cases 4x4,6x6,L]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

L_FLOOR = [[-3, -3], [3, -3], [3, 0], [0, 0], [0, 3], [-3, 3]]
CASES = {
    "4x4": (["--play-area", "4x4"], 6, 2.4),
    "6x6": (["--play-area", "6x6"], 10, 3.0),
    "L": (None, 8, None),
}


def outline(room):
    if "floor" in room:
        return [tuple(p) for p in room["floor"]]
    (x0, _, z0), (x1, _, z1) = room["min"], room["max"]
    return [(x0, z0), (x1, z0), (x1, z1), (x0, z1)]


def ray_exit(poly, p, d):
    """Distance along p + t d (t > 1e-9) to the first edge crossed."""
    best = float("inf")
    n = len(poly)
    for i in range(n):
        a, b = poly[i], poly[(i + 1) % n]
        e = (b[0] - a[0], b[1] - a[1])
        den = d[0] * e[1] - d[1] * e[0]
        if abs(den) < 1e-15:
            continue
        w = (a[0] - p[0], a[1] - p[1])
        t = (w[0] * e[1] - w[1] * e[0]) / den
        u = (w[0] * d[1] - w[1] * d[0]) / den
        if t > 1e-9 and -1e-12 <= u <= 1 + 1e-12:
            best = min(best, t)
    return best


def room_width(poly):
    """The narrowest distance across the room, from the middle of each wall
    straight in (a rectangle's short side; an L's narrower arm; a corridor's
    width) over walls at least 0.3 m long."""
    area2 = sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
                for i in range(len(poly)))
    sign = 1.0 if area2 > 0 else -1.0
    width = float("inf")
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        length = ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) ** 0.5
        if length < 0.3:
            continue
        d = ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        inward = (-d[1] * sign, d[0] * sign)
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        width = min(width, ray_exit(poly, mid, inward))
    return width


def shape_name(room):
    if "floor" not in room:
        return "box"
    n = len(room["floor"])
    return {4: "turned", 6: "L"}.get(n, "corridor")


def check(bin_path, args, rooms, seed, work):
    out = os.path.join(work, f"g{seed}.json")
    command = [bin_path, "generate", *args, "--rooms", str(rooms), "--seed", str(seed), "--out", out]
    start = time.perf_counter()
    run = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    result = {"seconds": seconds, "ok": False}
    if run.returncode != 0:
        result["why"] = "generate: " + run.stderr.strip()
        return result
    again = subprocess.run(command[:-2] + ["--out", out + ".2"], capture_output=True)
    if again.returncode != 0 or open(out, "rb").read() != open(out + ".2", "rb").read():
        result["why"] = "not the same bytes twice"
        return result
    layout = json.load(open(out))
    result["width"] = min(room_width(outline(r)) for r in layout["rooms"])
    result["shapes"] = [shape_name(r) for r in layout["rooms"]]
    report = subprocess.run([bin_path, "validate", out, "--json"], capture_output=True, text=True)
    if report.returncode != 0:
        result["why"] = "validate: " + report.stdout[:300] + report.stderr[:300]
        return result
    r = json.loads(report.stdout)
    result["ratio"] = r["summary"]["expansion_ratio"]
    bad = (r["unreachable_rooms"], r["rooms_outside_play_area"], r["doors_outside_play_area"],
           [o for o in r["overlaps"] if o["noticeable"]])
    if any(bad):
        result["why"] = f"validate findings {bad}"
        return result
    if result["width"] < 1.5 - 1e-6:
        result["why"] = f"a room {result['width']:.3f} m wide"
        return result
    tour_path = os.path.join(work, f"t{seed}.txt")
    tour = subprocess.run([bin_path, "tour", out, "--out", tour_path], capture_output=True, text=True)
    if tour.returncode != 0 or f"rooms visited: {rooms} of {rooms}" not in tour.stdout:
        result["why"] = "tour: " + (tour.stdout + tour.stderr).strip().replace("\n", "; ")[:300]
        return result
    walk = subprocess.run([bin_path, "walk", out, "--path", tour_path], capture_output=True, text=True)
    visited = {json.loads(line)["room"] for line in walk.stdout.splitlines() if line.strip()}
    if walk.returncode != 0 or len(visited) != rooms:
        result["why"] = f"walk visits {len(visited)} of {rooms} rooms"
        return result
    result["ok"] = True
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", default=os.path.join(os.path.dirname(__file__), "..", "build", "impossible"))
    parser.add_argument("--seeds", type=int, default=50)
    parser.add_argument("--cases", default="4x4,6x6,L")
    a = parser.parse_args()
    failures = 0
    with tempfile.TemporaryDirectory() as work:
        floor = os.path.join(work, "l.json")
        with open(floor, "w") as f:
            json.dump({"polygon": L_FLOOR}, f)
        print("| case | rooms | successes | mean expansion ratio (goal) | narrowest room, m | "
              "generate s, median / max | room shapes written |")
        print("|---|---|---|---|---|---|---|")
        for name in a.cases.split(","):
            args, rooms, goal = CASES[name]
            args = args or ["--play-area-file", floor]
            results = [check(a.bin, args, rooms, seed, work) for seed in range(1, a.seeds + 1)]
            ok = [r for r in results if r["ok"]]
            for seed, r in enumerate(results, 1):
                if not r["ok"]:
                    print(f"FAIL {name} seed {seed}: {r['why']}", file=sys.stderr)
            failures += len(results) - len(ok)
            ratios = [r["ratio"] for r in results if "ratio" in r]
            mean = statistics.mean(ratios) if ratios else 0.0
            times = [r["seconds"] for r in results]
            shapes = {}
            for r in results:
                for s in r.get("shapes", []):
                    shapes[s] = shapes.get(s, 0) + 1
            width = min((r["width"] for r in results if "width" in r), default=0.0)
            goal_text = f" (≥ {goal})" if goal else ""
            shape_text = ", ".join(f"{k} {v}" for k, v in sorted(shapes.items()))
            print(f"| {name} | {rooms} | {len(ok)}/{len(results)} | {mean:.3f}{goal_text} | {width:.3f} | "
                  f"{statistics.median(times):.2f} / {max(times):.2f} | {shape_text} |")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
