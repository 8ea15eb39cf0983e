"""The differential fuzzer's kind for issue 23 (tools/diff_fuzz.py): prism
rooms (layout-format.md, "Rooms of any shape"). Mixed into diff_fuzz.Case;
make_prism builds the layout from the case's random stream and prism_pose
the view.

prism, one of five sub-kinds per case:
  convex    a convex floor of 3-12 corners (some edges a few centimetres
            long), doors in two of its walls leading to a second prism room;
  turned    a rectangle turned by any angle (sometimes 30 or 45 degrees
            exactly), a door in a slanted wall;
  concave   an L, a U or a random star-shaped floor; a door in a wall beside
            a reflex corner, so that the corner hides it from part of the room;
  corridor  a curved corridor of 10 to 40 walls (an arc as a chain of short
            walls), with doors in its two end walls joined to each other (an
            endless curved corridor) or to a second room;
  trapdoor  a door in the floor of one prism room and the ceiling of another
            (a room below), sometimes a second door in a wall.
Poses: anywhere in the room looking at a door, 0.1 mm to 2 cm from a slanted
wall looking at it, grazing a wall along its plane, through a door from just
in front (one eye often behind its plane), along a corridor, looking down a
trapdoor or up through it, random looks.
"""
import math

PRISM_SUBKINDS = ["convex", "turned", "concave", "corridor", "trapdoor"]


def area2(poly):
    return sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in range(len(poly)))


def inside_polygon(poly, x, z):
    inside = False
    j = len(poly) - 1
    for i in range(len(poly)):
        (ax, az), (bx, bz) = poly[i], poly[j]
        if (az > z) != (bz > z) and x < ax + (z - az) * (bx - ax) / (bz - az):
            inside = not inside
        j = i
    return inside


def segment_distance(px, pz, a, b):
    dx, dz = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dz * dz
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - a[0]) * dx + (pz - a[1]) * dz) / length2))
    return math.hypot(px - a[0] - t * dx, pz - a[1] - t * dz)


def boundary_distance(poly, x, z):
    return min(segment_distance(x, z, poly[i], poly[(i + 1) % len(poly)]) for i in range(len(poly)))


def inward_normal(poly, i):
    """The unit normal of wall i (corner i to i + 1) into the room, [x, 0, z]."""
    a, b = poly[i], poly[(i + 1) % len(poly)]
    dx, dz = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dz)
    sign = 1.0 if area2(poly) > 0 else -1.0
    return [-sign * dz / length, 0.0, sign * dx / length]


def turn(points, angle, centre):
    c, s = math.cos(angle), math.sin(angle)
    return [[centre[0] + c * x - s * z, centre[1] + s * x + c * z] for x, z in points]


class PrismCases:
    # --- rooms -----------------------------------------------------------
    def prism(self, rid, floor, y0, y1, props_count=0):
        """A prism room; its floor corners rounded to the micrometre (the
        polygon as written is the one every program reads)."""
        r = self.r
        floor = [[round(x, 6), round(z, 6)] for x, z in floor]
        if r.random() < 0.5:
            floor.reverse()  # either winding
        room = {"id": rid, "floor": floor, "y": [round(y0, 6), round(y1, 6)], "color": self.prism_colour()}
        if r.random() < 0.3:
            room["checker"] = round(r.uniform(0.2, 1.0), 3)
        if r.random() < 0.3:
            room["face_colors"] = {"wall%d" % r.randrange(len(floor)): self.prism_colour(),
                                   "walls": self.prism_colour()}
        props = self.prism_props(floor, y0, props_count)
        if props:
            room["props"] = props
        self.rooms.append(room)
        return room

    def prism_colour(self):
        return [round(self.r.uniform(0.15, 0.95), 3) for _ in range(3)]

    def prism_props(self, floor, y0, count):
        r, props = self.r, []
        for _ in range(count):
            p = self.point_in(floor, 0.2)
            if p is None:
                break
            s = [r.uniform(0.05, 0.5), r.uniform(0.05, 1.2), r.uniform(0.05, 0.5)]
            corners = [(p[0] + dx * s[0] / 2, p[1] + dz * s[2] / 2) for dx in (-1, 1) for dz in (-1, 1)]
            if all(inside_polygon(floor, x, z) and boundary_distance(floor, x, z) > 0.01 for x, z in corners):
                props.append({"box": {"min": [round(p[0] - s[0] / 2, 6), round(y0, 6), round(p[1] - s[2] / 2, 6)],
                                      "max": [round(p[0] + s[0] / 2, 6), round(y0 + s[1], 6),
                                              round(p[1] + s[2] / 2, 6)]},
                              "color": self.prism_colour()})
        return props

    def point_in(self, floor, margin):
        """A random point of the floor at least `margin` from its walls."""
        r = self.r
        xs, zs = [p[0] for p in floor], [p[1] for p in floor]
        for _ in range(200):
            x, z = r.uniform(min(xs), max(xs)), r.uniform(min(zs), max(zs))
            if inside_polygon(floor, x, z) and boundary_distance(floor, x, z) >= margin:
                return [x, z]
        return None

    # --- floors ------------------------------------------------------------
    def convex_floor(self, centre, radius):
        r = self.r
        n = r.randint(3, 12)
        angles = sorted(r.uniform(0, 2 * math.pi) for _ in range(n))
        if r.random() < 0.3 and n > 3:  # two corners a few centimetres apart
            angles[1] = angles[0] + r.uniform(0.01, 0.05) / radius
            angles.sort()  # the moved corner may pass the next one
        squash = r.uniform(0.6, 1.0)  # an ellipse: still convex
        pts = [[centre[0] + radius * math.cos(a), centre[1] + radius * squash * math.sin(a)] for a in angles]
        return pts if abs(area2(pts)) > 1.0 else self.turned_floor(centre, radius, radius)

    def turned_floor(self, centre, hx, hz):
        r = self.r
        angle = r.choice([math.pi / 6, math.pi / 4, r.uniform(0, math.pi)])
        return turn([[-hx, -hz], [hx, -hz], [hx, hz], [-hx, hz]], angle, centre)

    def concave_floor(self, centre, size):
        r = self.r
        shape = r.choice(["L", "U", "star"])
        if shape == "L":
            a, b = r.uniform(0.35, 0.65) * size, r.uniform(0.35, 0.65) * size
            pts = [[0, 0], [size, 0], [size, b], [a, b], [a, size], [0, size]]
        elif shape == "U":
            a, b = r.uniform(0.25, 0.4) * size, r.uniform(0.3, 0.7) * size
            pts = [[0, 0], [size, 0], [size, size], [size - a, size], [size - a, size - b], [a, size - b], [a, size],
                   [0, size]]
        else:
            n = r.randint(5, 9)
            pts = []
            for k in range(2 * n):
                radius = size / 2 if k % 2 == 0 else r.uniform(0.3, 0.45) * size
                a = math.pi * k / n
                pts.append([size / 2 + radius * math.cos(a), size / 2 + radius * math.sin(a)])
        angle = r.uniform(0, 2 * math.pi) if r.random() < 0.5 else 0.0
        return turn([[x - size / 2, z - size / 2] for x, z in pts], angle, centre)

    def corridor_floor(self, centre, walls):
        """An arc corridor: `walls` walls in all (two ends, the rest split
        between the outer and inner arcs)."""
        r = self.r
        k = max(4, (walls - 2) // 2)  # segments per arc
        radius, width = r.uniform(1.5, 6), r.uniform(0.9, 2.0)
        span = r.uniform(0.5, 1.6) * math.pi
        start = r.uniform(0, 2 * math.pi)
        outer = [[centre[0] + (radius + width) * math.cos(start + span * i / k),
                  centre[1] + (radius + width) * math.sin(start + span * i / k)] for i in range(k + 1)]
        inner = [[centre[0] + radius * math.cos(start + span * i / k), centre[1] + radius * math.sin(start + span * i / k)]
                 for i in range(k, -1, -1)]
        return outer + inner, k  # wall k runs from the outer end to the inner end; the last wall closes the start

    # --- portals -------------------------------------------------------------
    def wall_door(self, pid, room, wall, target, w=None, ph=None, margin=0.01):
        """A door in wall `wall` of prism room `room` (normal into it)."""
        r = self.r
        floor, (y0, y1) = room["floor"], room["y"]
        a, b = floor[wall], floor[(wall + 1) % len(floor)]
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        w = min(w if w is not None else log_uniform_p(r, 0.05, length), length - 2 * margin)
        ph = min(ph if ph is not None else r.uniform(min(1.0, (y1 - y0) / 2), y1 - y0 - 0.02), y1 - y0 - 0.02)
        t = r.uniform(margin + w / 2, length - margin - w / 2) / length
        c = [a[0] + t * (b[0] - a[0]), r.uniform(y0 + ph / 2 + 0.005, y1 - ph / 2 - 0.005), a[1] + t * (b[1] - a[1])]
        self.portal(pid, room["id"], c, inward_normal(floor, wall), w, ph, target, self.box_depth())
        return w, ph

    def floor_door(self, pid, room, target, w, ph, ceiling=False, at=None):
        """A trapdoor in the floor (or ceiling) of a prism room."""
        floor, (y0, y1) = room["floor"], room["y"]
        half = math.hypot(w, ph) / 2 + 0.02
        p = at or self.point_in(floor, half)
        if p is None:
            return False
        n = [0.0, -1.0, 0.0] if ceiling else [0.0, 1.0, 0.0]
        self.portal(pid, room["id"], [p[0], y1 if ceiling else y0, p[1]], n, w, ph, target, self.box_depth())
        return True

    def door_pair(self, a, wall_a, b, wall_b, prefix=("a_door", "b_door"), w=None, ph=None):
        """Doors of one size in wall_a of room a and wall_b of room b, joined."""
        r = self.r
        room_h = min(a["y"][1] - a["y"][0], b["y"][1] - b["y"][0])
        span = min(self.wall_length(a, wall_a), self.wall_length(b, wall_b)) - 0.02
        w = min(w if w is not None else log_uniform_p(r, 0.05, span), span)
        ph = min(ph if ph is not None else r.uniform(min(1.0, room_h / 2), room_h - 0.02), room_h - 0.02)
        w, ph = round(w, 6), round(ph, 6)
        self.wall_door(prefix[0], a, wall_a, prefix[1], w, ph)
        self.wall_door(prefix[1], b, wall_b, prefix[0], w, ph)

    # --- the layouts -------------------------------------------------------------
    def make_prism(self):
        r, o = self.r, self.origin
        self.sub = PRISM_SUBKINDS[(self.number // 7) % len(PRISM_SUBKINDS)]
        centre = [o[0], o[2]]
        y0, h = o[1], r.uniform(2.2, 3.5)
        other = [o[0] + r.uniform(-3, 3), o[2] + r.uniform(-3, 3)] if r.random() < 0.6 else \
            [o[0] + r.uniform(-40, 40), o[2] + r.uniform(-40, 40)]
        if self.sub == "corridor":
            floor, k = self.corridor_floor(centre, r.randint(10, 40))
            a = self.prism("a", floor, y0, y0 + h, r.randint(0, 2))
            ends = [k, len(a["floor"]) - 1] if a["floor"] == [[round(x, 6), round(z, 6)] for x, z in floor] else \
                [len(floor) - 2 - k, len(floor) - 1]
            w = round(r.uniform(0.5, 0.98) * min(self.wall_length(a, e) for e in ends), 6)
            ph = round(h - r.uniform(0.05, 0.5), 6)
            if r.random() < 0.6:
                self.wall_door("end0", a, ends[0], "end1", w, ph)
                self.wall_door("end1", a, ends[1], "end0", w, ph)
            else:
                b = self.prism("b", self.convex_floor(other, r.uniform(2, 4)), y0, y0 + h, r.randint(0, 2))
                self.door_pair(a, ends[0], b, self.longest_wall(b), w=w, ph=ph)
            return
        if self.sub == "trapdoor":
            a = self.prism("a", self.convex_floor(centre, r.uniform(2, 4)) if r.random() < 0.5 else
                           self.concave_floor(centre, r.uniform(4, 7)), y0, y0 + h, r.randint(0, 3))
            below = r.uniform(2.2, 3.5)
            b = self.prism("b", self.convex_floor(other, r.uniform(2, 4)), y0 - below, y0, r.randint(0, 2))
            w, ph = round(r.uniform(0.3, 1.2), 6), round(r.uniform(0.3, 1.2), 6)
            if not self.floor_door("a_down", a, "b_up", w, ph) or not self.floor_door("b_up", b, "a_down", w, ph,
                                                                                     ceiling=True):
                del self.portals[:]
                self.door_pair(a, self.longest_wall(a), b, self.longest_wall(b), ("a_down", "b_up"), 0.8, 1.8)
            return
        if self.sub == "concave":
            a = self.prism("a", self.concave_floor(centre, r.uniform(4, 8)), y0, y0 + h, r.randint(0, 3))
            wall = self.reflex_neighbour(a)
        elif self.sub == "turned":
            a = self.prism("a", self.turned_floor(centre, r.uniform(1, 4), r.uniform(1, 4)), y0, y0 + h, r.randint(0, 3))
            wall = r.randrange(4)
        else:
            a = self.prism("a", self.convex_floor(centre, r.uniform(1.5, 5)), y0, y0 + h, r.randint(0, 3))
            wall = self.longest_wall(a)
        b = self.prism("b", self.convex_floor(other, r.uniform(2, 4)) if r.random() < 0.5 else
                       self.turned_floor(other, r.uniform(1, 3), r.uniform(1, 3)), y0, y0 + r.uniform(2.2, 3.5),
                       r.randint(0, 2))
        self.door_pair(a, wall, b, self.longest_wall(b))

    def wall_length(self, room, i):
        f = room["floor"]
        a, b = f[i], f[(i + 1) % len(f)]
        return math.hypot(b[0] - a[0], b[1] - a[1])

    def longest_wall(self, room):
        return max(range(len(room["floor"])), key=lambda i: self.wall_length(room, i))

    def reflex_neighbour(self, room):
        """A wall next to a reflex corner (one long enough for a door), or the longest."""
        f = room["floor"]
        sign = 1.0 if area2(f) > 0 else -1.0
        walls = []
        for i in range(len(f)):
            a, b, c = f[i - 1], f[i], f[(i + 1) % len(f)]
            if sign * ((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])) < 0:
                walls += [w for w in ((i - 1) % len(f), i) if self.wall_length(room, w) > 0.3]
        return self.r.choice(walls) if walls else self.longest_wall(room)

    @staticmethod
    def room_bounds(room):
        """A room's box, or a prism's bounding box: ([x, y, z] min, max)."""
        if "floor" not in room:
            return room["min"], room["max"]
        xs, zs = [p[0] for p in room["floor"]], [p[1] for p in room["floor"]]
        return [min(xs), room["y"][0], min(zs)], [max(xs), room["y"][1], max(zs)]

    def prism_near_plane_note(self, room, near):
        """near_plane_note for a prism room: an eye closer to a wall, the
        floor or the ceiling than the rasteriser's near plane."""
        floor, (y0, y1) = room["floor"], room["y"]
        notes = []
        for eye, e in zip(("left", "right"), self.eyes()):
            if not inside_polygon(floor, e[0], e[2]) or not y0 <= e[1] <= y1:
                continue
            for i in range(len(floor)):
                d = segment_distance(e[0], e[2], floor[i], floor[(i + 1) % len(floor)])
                if d < near:
                    notes.append("the %s eye is %.3g µm from wall %d, inside the rasteriser's %g µm near plane"
                                 % (eye, d * 1e6, i, near * 1e6))
            for name, d in (("floor", e[1] - y0), ("ceiling", y1 - e[1])):
                if d < near:
                    notes.append("the %s eye is %.3g µm from the %s, inside the rasteriser's %g µm near plane"
                                 % (eye, d * 1e6, name, near * 1e6))
        return "; ".join(notes)

    # --- the pose -----------------------------------------------------------------
    def prism_pose(self):
        r = self.r
        a = self.rooms[0]
        if self.sub == "trapdoor" and r.random() < 0.4:
            a = self.rooms[1]  # below the trapdoor, looking up through it
        floor, (y0, y1) = a["floor"], a["y"]
        door = next(p for p in self.portals if p["room"] == a["id"])
        c, n = door["center"], door["normal"]
        max_depth = r.choice([1, 2, 8, 8, 16, 64])
        fov = r.uniform(40, 110)
        choice = r.random()
        p = self.point_in(floor, 0.05) or [sum(x for x, _ in floor) / len(floor), sum(z for _, z in floor) / len(floor)]
        eye = [p[0], r.uniform(y0 + 0.1, y1 - 0.1), p[1]]
        if choice < 0.25:  # anywhere, looking at the door
            v = [c[i] - eye[i] for i in range(3)]
            what = "looking at the door"
        elif choice < 0.4:  # millimetres from a wall, looking at it
            wall = r.randrange(len(floor))
            s = floor[wall]
            e = floor[(wall + 1) % len(floor)]
            t = r.uniform(0.1, 0.9)
            wn = inward_normal(floor, wall)
            dist = math.exp(r.uniform(math.log(1e-4), math.log(0.02)))
            eye = [s[0] + t * (e[0] - s[0]) + dist * wn[0], eye[1], s[1] + t * (e[1] - s[1]) + dist * wn[2]]
            v = [-wn[0] + r.uniform(-0.4, 0.4) * (e[0] - s[0]), r.uniform(-0.3, 0.3),
                 -wn[2] + r.uniform(-0.4, 0.4) * (e[1] - s[1])]
            what = "%.2g m from wall %d" % (dist, wall)
        elif choice < 0.55:  # grazing a wall along its plane
            wall = r.randrange(len(floor))
            s, e = floor[wall], floor[(wall + 1) % len(floor)]
            wn = inward_normal(floor, wall)
            dist = math.exp(r.uniform(math.log(1e-4), math.log(0.3)))
            t = r.uniform(0.05, 0.95)
            eye = [s[0] + t * (e[0] - s[0]) + dist * wn[0], eye[1], s[1] + t * (e[1] - s[1]) + dist * wn[2]]
            sgn = r.choice([-1, 1])
            v = [sgn * (e[0] - s[0]) + r.uniform(-0.05, 0.05) * wn[0], r.uniform(-0.1, 0.1),
                 sgn * (e[1] - s[1]) + r.uniform(-0.05, 0.05) * wn[2]]
            what = "grazing wall %d %.2g m off its plane" % (wall, dist)
        elif choice < 0.75:  # just in front of the door, one eye often behind its plane
            dist = math.exp(r.uniform(math.log(1e-4), math.log(0.05)))
            up = door.get("up", [0, 1, 0])
            right = [up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]]
            off = r.uniform(-0.3, 0.3) * door["width"]
            eye = [c[i] + dist * n[i] + off * right[i] for i in range(3)]
            if abs(n[1]) > 0.9:
                eye[1] = c[1] + n[1] * max(dist, 0.3)  # above or below a trapdoor
            v = [-n[i] + r.uniform(-0.5, 0.5) * right[i] for i in range(3)]
            what = "%.2g m in front of the door" % dist
        else:
            v = [r.uniform(-1, 1), r.uniform(-0.5, 0.5), r.uniform(-1, 1)]
            what = "random look"
        eye[1] = min(max(eye[1], y0 + 0.02), y1 - 0.02)
        horizontal = math.hypot(v[0], v[2])
        yaw = math.degrees(math.atan2(-v[0], -v[2])) if horizontal > 1e-9 else 0.0
        pitch = min(max(math.degrees(math.atan2(v[1], horizontal)), -90.0), 90.0)
        return [eye[0], eye[1], eye[2], yaw, pitch, 0.0], a["id"], max_depth, fov, "%s: %s" % (self.sub, what)


def log_uniform_p(r, lo, hi):
    return math.exp(r.uniform(math.log(lo), math.log(max(hi, lo * 1.0001))))
