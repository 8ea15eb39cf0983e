#!/usr/bin/env python3
"""Writes the example headset profiles in profiles/ (docs/headsets.md).

The angles, sizes and IPDs are published figures (each file's "source"); the
visible areas are approximations: a circle about each eye's lens axis (where
the view axis meets the image), clipped to the image, with the radius chosen
so that the hidden share matches the published share of the runtime's
hidden-area mesh. The share printed (and written as "_hidden_share") is
counted at pixel centres with the renderers' even-odd rule. A profile with
eye poses (canted-5deg.json) has each eye's "position" and "orientation" (a
unit quaternion x, y, z, w) instead of "ipd".

A profile can also carry a runtime's own visibility mask instead of an
approximation: valve-index.json (its line loop) and valve-index-mesh.json
(its visible triangles) are written from a mask file, by default
tools/hmd_data/valve-index-openxr.json: per eye "angles" [left, right, up,
down] in degrees and "line_loop" [[x, y], ...] in the eye's tangent space
(the plane z = -1, x right, y up), optionally "triangles" (three [x, y] a
triangle). The profile keeps the mask in that space ("visibility_mask"); the
program maps it into the image through the angles and clips it to the image
(docs/headsets.md, "Visibility masks"). The share printed is counted the
same way, at pixel centres of a 300 x 300 grid.

Usage: tools/hmd_profiles.py [--index-mask FILE]   (run from the repository root)
"""
import argparse
import json
import math


def circle(radius, cx, cy, n=48):
    pts = []
    for k in range(n):
        t = 2 * math.pi * k / n
        p = [round(min(1, max(0, cx + radius * math.cos(t))), 4), round(min(1, max(0, cy + radius * math.sin(t))), 4)]
        if not pts or pts[-1] != p:
            pts.append(p)
    if pts[0] == pts[-1]:
        pts.pop()
    return pts


def hidden_share(poly, n=300):
    hidden = 0
    for j in range(n):
        y = (j + .5) / n
        xs = []
        for k in range(len(poly)):
            a, b = poly[k], poly[(k + 1) % len(poly)]
            if (a[1] > y) != (b[1] > y):
                xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
        for i in range(n):
            x = (i + .5) / n
            if sum(1 for c in xs if c > x) % 2 == 0:
                hidden += 1
    return hidden / n / n


def tangents_to_image(angles, points):
    """Tangent-space points (x, y) as normalised image points (u, v), v from
    the top: the program's math::tangent_to_image."""
    l, r, u, d = [math.tan(math.radians(a)) for a in angles]
    return [[(x - l) / (r - l), (u - y) / (u - d)] for x, y in points]


def triangles_hidden_share(triangles, n=300):
    """The share of pixel centres in no triangle (each by the even-odd rule)."""
    hidden = 0
    for j in range(n):
        y = (j + .5) / n
        spans = []
        for t in range(0, len(triangles), 3):
            tri = triangles[t:t + 3]
            xs = sorted(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                        for a, b in zip(tri, tri[1:] + tri[:1]) if (a[1] > y) != (b[1] > y))
            if xs:
                spans.append(xs)
        for i in range(n):
            x = (i + .5) / n
            if not any(xs[0] <= x < xs[1] for xs in spans):
                hidden += 1
    return hidden / n / n


def mask_eye(data, form, size):
    """One eye of a profile with a visibility mask in tangent space, and its hidden share."""
    angles = data["angles"]
    fov = dict(zip(("left", "right", "up", "down"), angles))
    if form == "line_loop":
        mask = {"line_loop": data["line_loop"]}
        share = hidden_share(tangents_to_image(angles, data["line_loop"]))
    else:
        vertices, indices = [], []
        for p in data["triangles"]:
            if p not in vertices:
                vertices.append(p)
            indices.append(vertices.index(p))
        mask = {"vertices": vertices, "indices": indices}
        share = triangles_hidden_share(tangents_to_image(angles, data["triangles"]))
    return {"fov": fov, "resolution": size, "visibility_mask": mask}, share


def write_mask_profile(name_file, name, source, ipd, mask, form, size):
    left, hl = mask_eye(mask["left"], form, size)
    right, hr = mask_eye(mask["right"], form, size)
    share = "about %.1f %% of each eye's pixels (left %.2f %%, right %.2f %%)" % (50 * (hl + hr), 100 * hl, 100 * hr)
    print(name_file, share)
    with open("profiles/" + name_file, "w") as f:
        f.write('{\n  "name": %s,\n  "source": %s,\n  "_hidden_share": %s,\n  "ipd": %s,\n' %
                (json.dumps(name), json.dumps(source), json.dumps(share), ipd))
        for side, e in (("left", left), ("right", right)):
            f.write('  "%s": {\n    "fov": %s,\n    "resolution": %s,\n    "visibility_mask": {\n' %
                    (side, json.dumps(e["fov"]), json.dumps(e["resolution"])))
            m = e["visibility_mask"]
            if form == "line_loop":
                f.write('      "line_loop": [\n%s\n      ]\n' %
                        ",\n".join("        " + json.dumps(p) for p in m["line_loop"]))
            else:
                f.write('      "vertices": [\n%s\n      ],\n' %
                        ",\n".join("        " + json.dumps(p) for p in m["vertices"]))
                f.write('      "indices": [\n%s\n      ]\n' %
                        ",\n".join("        " + ", ".join(str(i) for i in m["indices"][k:k + 3])
                                    for k in range(0, len(m["indices"]), 3)))
            f.write("    }\n  }%s\n" % ("," if side == "left" else ""))
        f.write("}\n")


def eye(fov, size, radius):
    l, r, u, d = [math.tan(math.radians(fov[k])) for k in ("left", "right", "up", "down")]
    poly = circle(radius, -l / (r - l), u / (u - d))
    return {"fov": fov, "resolution": size, "visible_area": poly}, hidden_share(poly)


def canted_pose(x, yaw):
    """An eye at x on the head's x axis turned `yaw` degrees about its y axis
    (positive turns left): its position and unit quaternion (x, y, z, w)."""
    half = math.radians(yaw) / 2
    return {"position": [x, 0, 0], "orientation": [0, math.sin(half), 0, math.cos(half)]}


def write(name_file, name, source, ipd, left_fov, right_fov, size, radius, poses=None):
    left, hl = eye(left_fov, size, radius)
    right, hr = eye(right_fov, size, radius)
    share = "about %.1f %% of each eye's pixels (left %.2f %%, right %.2f %%)" % (50 * (hl + hr), 100 * hl, 100 * hr)
    print(name_file, share)
    with open("profiles/" + name_file, "w") as f:
        f.write('{\n  "name": %s,\n  "source": %s,\n  "_hidden_share": %s,\n' %
                (json.dumps(name), json.dumps(source), json.dumps(share)))
        if poses is None:
            f.write('  "ipd": %s,\n' % ipd)
        for k, (side, e) in enumerate((("left", left), ("right", right))):
            f.write('  "%s": {\n' % side)
            if poses is not None:
                f.write('    "position": %s,\n    "orientation": %s,\n' %
                        (json.dumps(poses[k]["position"]), json.dumps(poses[k]["orientation"])))
            f.write('    "fov": %s,\n    "resolution": %s,\n    "visible_area": [\n' %
                    (json.dumps(e["fov"]), json.dumps(e["resolution"])))
            f.write(",\n".join("      " + json.dumps(p) for p in e["visible_area"]))
            f.write("\n    ]\n  }%s\n" % ("," if side == "left" else ""))
        f.write("}\n")


VIVE_URL = "https://risa2000.github.io/hmdgdb/hmd_cfgs/Vive_Native_R90.html"
VIVE_LEFT = {"left": -54.41, "right": 46.75, "up": 55.67, "down": -55.91}
VIVE_RIGHT = {"left": -46.69, "right": 54.36, "up": 55.61, "down": -55.87}

write("htc-vive.json", "HTC Vive (approximate hidden area)",
      "Angles, per-eye resolution (OpenVR's recommended render target, 1852x2056) and IPD (72.4 mm, the "
      "contributor's setting) as recorded by hmdq and published in the HMD Geometry Database, " + VIVE_URL +
      " (OpenVR 1.10.32). The database gives the hidden-area mesh's share (19.10 % of each eye) but not its "
      "corners: the visible area here is an approximation, a circle about the lens axis clipped to the image with "
      "about that share, not the runtime's mesh.", 0.0724, VIVE_LEFT, VIVE_RIGHT, [1852, 2056], 0.5225)
write("quest-2.json", "Oculus Quest 2 over Link (approximate hidden area)",
      "Angles and per-eye size (the distorted viewport, 1592x1664) as the Oculus runtime 1.53 reported them, "
      "recorded by hmdq and published in the HMD Geometry Database, "
      "https://risa2000.github.io/hmdgdb/hmd_cfgs/Quest2_Native_R72.html; IPD 63.5 mm (the runtime's eye "
      "offsets, +-31.75 mm). The database gives the hidden-area mesh's share (9.13 % of each eye) but not its "
      "corners: the visible area here is an approximation with about that share, not the runtime's mesh.", 0.0635,
      {"left": -52.0, "right": 45.0, "up": 48.0, "down": -50.0},
      {"left": -45.0, "right": 52.0, "up": 48.0, "down": -50.0}, [1592, 1664], 0.577)
write("bench-2064x2208.json", "Benchmark headset: 2064x2208 per eye, HTC Vive's angles, an 18 % hidden area",
      "Synthetic, for bench: the per-eye resolution issue 24 names (2064x2208), the HTC Vive's angles from the HMD "
      "Geometry Database (" + VIVE_URL + "), and a visible area (a circle about the lens axis clipped to the image) "
      "hiding about 18 % of each eye, within the 15-20 % the issue asks for and near the Vive's 19.10 % and the "
      "Varjo VR-2's 17.84 % in the same database. No real headset has exactly this profile.", 0.064, VIVE_LEFT,
      VIVE_RIGHT, [2064, 2208], 0.525)
write("canted-5deg.json", "Canted displays: each eye turned 5 degrees outwards (synthetic)",
      "Synthetic, for tests and docs/headsets.md: the eyes 63.5 mm apart (+-31.75 mm along the head's x axis), each "
      "turned 5 degrees outwards about the head's vertical axis, as the Valve Index's displays are canted; each "
      "eye's angles are about its own turned view axis, the Quest 2's from the HMD Geometry Database, and a visible "
      "area (a circle about the lens axis clipped to the image) hiding about 9 % of each eye. No real headset has "
      "exactly this profile.", None,
      {"left": -52.0, "right": 45.0, "up": 48.0, "down": -50.0},
      {"left": -45.0, "right": 52.0, "up": 48.0, "down": -50.0}, [1440, 1600], 0.577,
      [canted_pose(-0.03175, 5.0), canted_pose(0.03175, -5.0)])

parser = argparse.ArgumentParser(description="Writes the example headset profiles in profiles/.")
parser.add_argument("--index-mask", default="tools/hmd_data/valve-index-openxr.json",
                    help="the Valve Index's visibility masks in tangent space (see above)")
INDEX_MASK = json.load(open(parser.parse_args().index_mask))
INDEX_SOURCE = (
    "The Valve Index's own OpenXR visibility mask (SteamVR), as published in Vertices.pde of "
    "VRHiddenAreaMaskPreviewer by Rune Berg (MIT License), https://github.com/1runeberg/VRHiddenAreaMaskPreviewer; "
    "the numbers and their licence are in tools/hmd_data/valve-index-openxr.json. %s, in each eye's tangent "
    "space as the runtime returns it. The angles are not published with the masks: each eye's image edges are "
    "the bounding box of the same file's hidden triangles, which reach the image's edges (the visible triangles "
    "then hide 24.888 %% of each eye's area, the Index's published share, 24.88 %%). The size is the Index's "
    "panel, 1440x1600 per eye (SteamVR's recommended render target depends on its resolution setting); the IPD "
    "is this project's default, 64 mm (the masks give none), and the eyes have no poses (the masks give none).")
write_mask_profile("valve-index.json", "Valve Index (its OpenXR line loop)",
                   INDEX_SOURCE % "The mask is the runtime's line loop (XR_VISIBILITY_MASK_TYPE_LINE_LOOP_KHR); "
                   "2 of its 27 corners per eye lie above the image, so the program clips it", 0.064, INDEX_MASK,
                   "line_loop", [1440, 1600])
if "triangles" in INDEX_MASK["left"] and "triangles" in INDEX_MASK["right"]:  # a mask file may give the loop only
    write_mask_profile("valve-index-mesh.json", "Valve Index (its OpenXR visible triangles)",
                       INDEX_SOURCE % "The mask is the runtime's visible triangles "
                       "(XR_VISIBILITY_MASK_TYPE_VISIBLE_TRIANGLE_MESH_KHR), a fan of 27 triangles, its repeated "
                       "vertices merged into an index buffer", 0.064, INDEX_MASK, "triangles", [1440, 1600])
