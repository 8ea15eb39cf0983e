"""The differential fuzzer's kinds for issue 22 (tools/diff_fuzz.py):
crossing objects, moving props and hands ("crossing"), and volume portals
("volume"). Mixed into diff_fuzz.Case; each make_* builds the layout from
the case's random stream, each *_pose the view, and view_extra() the
options that go with it (--time, --hands).

crossing, one of five sub-kinds per case:
  straddle     1-3 boxes standing half through the door of a coincident or
               wall pair (any door angle), cut in their room and imaged in
               the other;
  moving       a box whose motion carries it through the door (and back,
               sometimes looping), rendered at a random --time, often right
               at its crossing;
  hands        both hands near the door (--hands), one often through it
               while the head is not, turned at random;
  corridor     a box straddling one door of an endless corridor, so that its
               images are seen through the other doors, deep;
  model        the project's chair (layouts/models/chair.glb) half through
               the door.
volume, one of three sub-kinds:
  plain        one or two volumes (any orientation, 5 cm to 3 m) in a room,
               showing an overlapping room with its own props, tinted;
  door         the same seen through a door pair from another room;
  mirror       the same in front of a mirror in a wall.
Poses: at the object or volume from anywhere, millimetres from a cut or a
volume face, one eye in the door box with a hand beside it, edge-on to a
volume's face (the eye in its plane) and grazing it, inside the volume.
"""
import math
import os

CROSSING_SUBKINDS = ["straddle", "moving", "hands", "corridor", "model"]
VOLUME_SUBKINDS = ["plain", "door", "mirror"]
CHAIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "layouts", "models", "chair.glb")


def rounded(v, digits=6):
    return [round(x, digits) for x in v]


def frame_of(portal):
    n = portal["normal"]
    up = portal.get("up", [0.0, 1.0, 0.0])
    d = sum(up[i] * n[i] for i in range(3))
    u = [up[i] - d * n[i] for i in range(3)]
    length = math.sqrt(sum(x * x for x in u))
    u = [x / length for x in u]
    r = [u[1] * n[2] - u[2] * n[1], u[2] * n[0] - u[0] * n[2], u[0] * n[1] - u[1] * n[0]]
    return r, u, n


def yaw_towards(v):
    return math.degrees(math.atan2(-v[0], -v[2])) if abs(v[0]) + abs(v[2]) > 1e-12 else 0.0


def pitch_towards(v):
    return math.degrees(math.atan2(v[1], math.hypot(v[0], v[2])))


class ObjectCases:
    """Methods of diff_fuzz.Case for the kinds "crossing" and "volume"."""

    # --- crossing objects ----------------------------------------------
    def straddling_box(self, door, room):
        """An axis-aligned box whose centre lies within 0.6 of its size of
        the door's plane, over the rectangle."""
        r = self.r
        rt, up, n = frame_of(door)
        c = door["center"]
        s = [log_uniform_local(r, 0.03, 1.0) for _ in range(3)]
        a = r.uniform(-0.45, 0.45) * door["width"]
        b = r.uniform(-0.45, 0.45) * door["height"]
        along = r.uniform(-0.6, 0.6) * max(s)
        centre = [c[i] + a * rt[i] + b * up[i] + along * n[i] for i in range(3)]
        lo, hi = room["min"], room["max"]
        bmin = [centre[i] - s[i] / 2 for i in range(3)]
        bmax = [centre[i] + s[i] / 2 for i in range(3)]
        bmin[1], bmax[1] = max(bmin[1], lo[1] + 0.001), min(bmax[1], hi[1] - 0.001)
        if bmax[1] - bmin[1] < 0.01:
            bmin[1], bmax[1] = lo[1] + 0.001, lo[1] + 0.3
        return {"box": {"min": rounded(bmin), "max": rounded(bmax)}, "color": rnd_color_local(r)}

    def add_prop(self, room, prop):
        room.setdefault("props", []).append(prop)

    def make_crossing(self):
        r = self.r
        self.sub = r.choice(CROSSING_SUBKINDS)
        self.time, self.hands = None, None
        if self.sub == "corridor":
            self.make_corridor()
        elif r.random() < 0.5:
            self.make_coincident()
        else:
            self.make_wall_pair()
        door, a = self.portals[0], self.rooms[0]
        if self.sub in ("straddle", "corridor"):
            for _ in range(r.randint(1, 3 if self.sub == "straddle" else 1)):
                self.add_prop(a, self.straddling_box(door, a))
        elif self.sub == "model":
            c, (rt, up, n) = door["center"], frame_of(door)
            along = r.uniform(-0.25, 0.25)
            pos = [c[i] + along * n[i] + r.uniform(-0.3, 0.3) * door["width"] * rt[i] for i in range(3)]
            pos[1] = a["min"][1]
            self.add_prop(a, {"gltf": os.path.normpath(CHAIR), "position": rounded(pos),
                              "yaw_deg": round(r.uniform(-180, 180), 3), "scale": round(r.uniform(0.5, 2.5), 3)})
        elif self.sub == "moving":
            self.add_moving_box(door, a)
        else:
            self.hands = self.hands_near(door)

    def add_moving_box(self, door, room):
        """A box in front of the door that slides through it along -n."""
        r = self.r
        box = self.straddling_box(door, room)
        _, _, n = frame_of(door)
        size = max(box["box"]["max"][i] - box["box"]["min"][i] for i in range(3))
        push = [(-n[i]) * (size + r.uniform(0.3, 2.0)) for i in range(3)]
        start = [n[i] * (size * 0.6 + r.uniform(0.0, 0.5)) for i in range(3)]
        keys = [[0.0] + rounded(start), [round(r.uniform(0.5, 3), 3)] + rounded([start[i] + push[i] for i in range(3)])]
        if r.random() < 0.5:
            keys.append([round(keys[1][0] + r.uniform(0.5, 3), 3)] + rounded(start))
        box["id"] = "mover"
        box["motion"] = {"path": keys, "loop": r.random() < 0.5}
        self.add_prop(room, box)
        period = keys[-1][0]
        # Often right where the box meets the door.
        self.time = round(r.uniform(0, 2.5 * period) if r.random() < 0.5 else r.uniform(0.2, 0.8) * keys[1][0], 4)

    def hands_near(self, door):
        r = self.r
        rt, up, n = frame_of(door)
        c = door["center"]
        hands = []
        for _ in range(2):
            a = r.uniform(-0.5, 0.5) * door["width"]
            b = r.uniform(-0.5, 0.5) * min(door["height"], 1.5)
            along = r.uniform(-0.3, 0.3) if r.random() < 0.7 else r.uniform(-0.01, 0.01)
            p = [c[i] + a * rt[i] + b * up[i] + along * n[i] for i in range(3)]
            hands += p + [r.uniform(-180, 180), r.uniform(-60, 60), r.uniform(-90, 90)]
        return hands

    def crossing_pose(self):
        pose, room, max_depth, fov, what = self.make_pose()
        r = self.r
        if self.hands is not None and r.random() < 0.5:
            # The head in front of the door, the hands reaching from it.
            door = self.portals[0]
            rt, up, n = frame_of(door)
            c = door["center"]
            dist = log_uniform_local(r, 1e-3, 0.6)
            p = [c[i] + dist * n[i] + r.uniform(-0.3, 0.3) * door["width"] * rt[i] for i in range(3)]
            lo, hi = self.rooms[0]["min"], self.rooms[0]["max"]
            p[1] = min(max(c[1] + r.uniform(-0.2, 0.2), lo[1] + 0.05), hi[1] - 0.05)
            v = [-n[i] + r.uniform(-0.4, 0.4) for i in range(3)]
            pose = [p[0], p[1], p[2], yaw_towards(v), max(-60.0, min(60.0, pitch_towards(v))), 0.0]
            what = "%.2g m in front of the door, hands reaching" % dist
        return pose, room, max_depth, fov, what

    # --- volume portals --------------------------------------------------
    def volume(self, vid, room, target, lo, hi):
        r = self.r
        yaw = r.uniform(0, 2 * math.pi) if r.random() < 0.6 else r.choice([0, 0.5, 1, 1.5]) * math.pi
        pitch = r.uniform(-0.5, 0.5) if r.random() < 0.25 else 0.0
        n = [math.sin(yaw) * math.cos(pitch), math.sin(pitch), math.cos(yaw) * math.cos(pitch)]
        size = [log_uniform_local(r, 0.05, 3.0) for _ in range(3)]
        c = [r.uniform(lo[i] + 0.2, hi[i] - 0.2) for i in range(3)]
        v = {"id": vid, "room": room, "kind": "volume", "target": target, "center": rounded(c),
             "normal": rounded(n, 9), "width": round(size[0], 6), "height": round(size[1], 6),
             "depth": round(size[2], 6)}
        if abs(n[1]) > 0.9:
            v["up"] = [0, 0, -1]
        tint = self.tint()
        if tint is not None:
            v["tint"] = tint
        return v

    def make_volume(self):
        r, o = self.r, self.origin
        self.sub = r.choice(VOLUME_SUBKINDS)
        self.time, self.hands = None, None
        lo, hi = self.room_box(o, r.uniform(1.5, 4), r.uniform(1.5, 4), r.uniform(2.2, 3.5))
        a = self.room("a", lo, hi, self.props_near(o, lo, hi, r.randint(0, 3)))
        lo_t = [lo[i] + (r.uniform(-0.5, 0.5) if i != 1 else 0.0) for i in range(3)]
        hi_t = [hi[i] + r.uniform(-0.5, 0.5) for i in range(3)]
        self.room("t", lo_t, hi_t, self.props_near(o, lo_t, hi_t, r.randint(1, 4)))
        first = self.volume("scan", "a", "t", lo, hi)
        self.volumes = [first]
        if r.random() < 0.3:
            # A second volume beside the first, their bounding spheres apart.
            second = self.volume("scan2", "a", "t", lo, hi)
            radius = lambda v: 0.5 * math.sqrt(v["width"] ** 2 + v["height"] ** 2 + v["depth"] ** 2)
            gap = math.dist(first["center"], second["center"])
            if gap > radius(first) + radius(second) + 1e-3:
                self.volumes.append(second)
        if self.sub == "door":
            lo_b, hi_b = self.room_box([o[0] + r.uniform(-20, 20), o[1], o[2] + r.uniform(-20, 20)],
                                       r.uniform(1.5, 3), r.uniform(1.5, 3), hi[1] - lo[1])
            self.room("b", lo_b, hi_b)
            w, ph = r.uniform(0.5, 1.5), min(r.uniform(1.0, 2.2), hi[1] - lo[1] - 0.05)
            ca, na, w1 = self.wall_portal(lo, hi, r.randrange(4), w, ph, r)
            cb, nb, w2 = self.wall_portal(lo_b, hi_b, r.randrange(4), w, ph, r)
            w = min(w1, w2)
            self.portal("b_door", "b", cb, nb, w, ph, "a_door", self.box_depth())
            self.portal("a_door", "a", ca, na, w, ph, "b_door", self.box_depth())
        elif self.sub == "mirror":
            face = r.randrange(4)
            self.glass("a_mirror", "a", self.face_rect(lo, hi, face), "mirror")
        self.portals += self.volumes
        del a

    def volume_pose(self):
        r = self.r
        v = self.volumes[0]
        room = next(x for x in self.rooms if x["id"] == "a")
        lo, hi = room["min"], room["max"]
        max_depth = r.choice([1, 2, 8, 8, 16, 64])
        fov = r.uniform(40, 110)
        n = v["normal"]
        rt, up, _ = frame_of(v)
        c = v["center"]
        half = [v["width"] / 2, v["height"] / 2, v["depth"] / 2]
        choice = r.random()
        if self.sub == "door" and choice < 0.6:
            door = next(p for p in self.portals if p["id"] == "b_door")
            b = next(x for x in self.rooms if x["id"] == "b")
            dn = door["normal"]
            dist = log_uniform_local(r, 0.05, 2.0)
            p = [door["center"][i] + dist * dn[i] for i in range(3)]
            p[1] = min(max(p[1], b["min"][1] + 0.05), b["max"][1] - 0.05)
            look = [-dn[i] + r.uniform(-0.5, 0.5) for i in range(3)]
            return self.pose_at(p, look), "b", max(max_depth, 2), fov, "through a door at a volume"
        if choice < 0.3:
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            look = [c[i] - p[i] for i in range(3)]
            what = "in the room, towards the volume"
        elif choice < 0.55:
            # Edge-on: the eye in the plane of one of the volume's faces.
            axis = r.randrange(3)
            frame = (rt, up, n)
            sign = r.choice([-1, 1])
            along = [r.uniform(-1.5, 1.5) * half[k] if k != axis else sign * half[k] for k in range(3)]
            out = r.uniform(0.5, 2.0)
            k2 = (axis + 1) % 3
            along[k2] = math.copysign(half[k2] + out, along[k2] or 1.0)
            p = [c[i] + sum(along[k] * frame[k][i] for k in range(3)) for i in range(3)]
            look = [c[i] + sign * half[axis] * frame[axis][i] - p[i] for i in range(3)]
            what = "edge-on to a volume face"
        elif choice < 0.75:
            # Grazing a face, 0.1 mm to 5 cm off its plane.
            off = log_uniform_local(r, 1e-4, 0.05)
            axis = r.randrange(3)
            frame = (rt, up, n)
            sign = r.choice([-1, 1])
            p = [c[i] + sign * (half[axis] + off) * frame[axis][i] for i in range(3)]
            k2 = (axis + 1) % 3
            p = [p[i] + (half[k2] + r.uniform(0.3, 1.5)) * frame[k2][i] for i in range(3)]
            look = [-frame[k2][i] + r.uniform(-0.05, 0.05) for i in range(3)]
            what = "grazing a volume face %.2g m off" % off
        elif choice < 0.85:
            p = [c[i] + r.uniform(-0.8, 0.8) * (half[0] * rt[i] + half[1] * up[i] + half[2] * n[i]) for i in range(3)]
            look = [r.uniform(-1, 1), r.uniform(-0.3, 0.3), r.uniform(-1, 1)]
            what = "inside the volume"
        else:
            mirror = next((m for m in self.portals if m.get("kind") == "mirror"), None)
            target = mirror["center"] if mirror else c
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            look = [target[i] - p[i] for i in range(3)]
            what = "towards the mirror" if mirror else "random look at the volume"
        p = [min(max(p[i], lo[i] + 0.02), hi[i] - 0.02) for i in range(3)]
        return self.pose_at(p, look), "a", max_depth, fov, what

    def pose_at(self, p, look):
        roll = self.r.uniform(-20, 20) if self.r.random() < 0.2 else 0.0
        return [p[0], p[1], p[2], yaw_towards(look), max(-60.0, min(60.0, pitch_towards(look))), roll]

    def view_extra(self):
        extra = []
        if getattr(self, "time", None) is not None:
            extra += ["--time", "%.17g" % self.time]
        if getattr(self, "hands", None) is not None:
            extra += ["--hands=" + ",".join("%.17g" % v for v in self.hands)]
        return extra


def log_uniform_local(r, lo, hi):
    return math.exp(r.uniform(math.log(lo), math.log(hi)))


def rnd_color_local(r):
    return [round(r.uniform(0.15, 0.95), 3) for _ in range(3)]
