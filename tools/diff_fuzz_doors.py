"""The differential fuzzer's kind for issue 36 (tools/diff_fuzz.py): doors
standing on the floor, seen as users pose them. Mixed into diff_fuzz.Case;
make_floor_door builds the layout from the case's random stream and
floor_door_pose the view.

floor_door: two overlapping rooms (as the built-in default's hall and
annex), a free-standing door whose bottom edge lies exactly in the floor
(its box's bottom face in the floor), its partner coincident (the default's
pair) or standing on the other room's floor elsewhere. Centres, sizes and
turns are mostly round numbers (multiples of 0.5 m, 90 degrees), as users
type them. Box depths 0.01 to 0.5 m.

Poses (layout-format.md, "The portal box" and "What a pixel shows",
coplanar surfaces), one of five per case:
  behind     a head that walked round the door and stands 1 cm to 0.5 m
             behind its plane, over the rectangle or beside it, at round
             heights (1.5, 1.6, 1.7 m) and turns: it must see its own room;
  edge       in front of the door, looking at its bottom edge (a row of
             pixel centres often lies on it): the floor runs up to the door;
  across     the head 1-3 cm in front of the plane, turned 90 degrees so that
             one eye is behind it, looking down 30-89 degrees: that eye sees
             the target room's floor in the box;
  inside     the head itself 1-5 cm behind the plane having come through the
             door (the walker's case: the head is then in the target room,
             so the pose is the partner's side), looking down;
  random     anywhere in the room, random looks.
"""
import base64
import json
import math
import struct


FLOOR_DOOR_POSES = ["behind", "edge", "across", "inside", "random"]


class DoorCases:
    """The floor_door kind, mixed into diff_fuzz.Case (self.r, self.origin,
    self.room, self.portal, self.box_depth, self.props_near)."""

    def round_or(self, value, step, share=0.7):
        """`value` rounded to a multiple of `step` in `share` of the cases."""
        return round(value / step) * step if self.r.random() < share else value

    @staticmethod
    def clear_of_box(props, c, reach):
        """The props that keep more than `reach` (x and z) from the door's
        centre: none meets its box, so none is a crossing object."""
        def clear(p):
            lo, hi = p["box"]["min"], p["box"]["max"]
            return any(lo[a] > c[a] + reach or hi[a] < c[a] - reach for a in (0, 2))
        return [p for p in props if clear(p)]

    def quad_prop(self, lo, hi, c, reach):
        """A 1 m × 1 m glTF quad standing 0.2-1.2 m above the floor, facing
        its yaw, 1-2 m from the door; one-sided in two cases of three."""
        r = self.r
        double = r.random() < 0.34
        name = "quad-two.gltf" if double else "quad-one.gltf"
        self.files = getattr(self, "files", {})
        self.files[name] = quad_gltf(double)
        for _ in range(20):
            at = [r.uniform(lo[0] + 0.8, hi[0] - 0.8), lo[1], r.uniform(lo[2] + 0.8, hi[2] - 0.8)]
            if abs(at[0] - c[0]) > reach + 0.8 or abs(at[2] - c[2]) > reach + 0.8:
                break
        return {"gltf": name, "position": [round(v, 6) for v in at], "yaw_deg": round(r.uniform(-180, 180), 3)}

    def make_floor_door(self):
        r, o = self.r, self.origin
        hx, hz = self.round_or(r.uniform(2.0, 5.0), 0.5), self.round_or(r.uniform(2.0, 5.0), 0.5)
        h = self.round_or(r.uniform(2.5, 3.5), 0.5)
        lo, hi = self.room_box(o, hx, hz, h)
        turns = r.choice([0, 1, 2, 3]) if r.random() < 0.8 else r.uniform(0, 4)
        yaw = turns * math.pi / 2
        n = [round(math.sin(yaw), 12), 0.0, round(math.cos(yaw), 12)]
        w = r.choice([0.8, 1.0, 1.2, 2.0]) if r.random() < 0.7 else r.uniform(0.3, 2.0)
        ph = r.choice([2.0, 2.2, 1.0]) if r.random() < 0.7 else r.uniform(0.5, h - 0.1)
        # Five decimals, so that the centre's height (ph / 2 above the floor,
        # written with six) puts the bottom edge exactly in the floor: halving
        # commutes with rounding a decimal to binary.
        ph = round(min(ph, h - 0.05), 5)
        cx = o[0] + self.round_or(r.uniform(-hx / 2, hx / 2), 0.5, 0.8)
        cz = o[2] + self.round_or(r.uniform(-hz / 2, hz / 2), 0.5, 0.8)
        c = [cx, lo[1] + ph / 2, cz]  # the bottom edge in the floor
        props_a = self.clear_of_box(self.props_near(c, lo, hi, r.randint(0, 2)), c, max(w, 1.0))
        if r.random() < 0.5:  # a one-sided (or double-sided) glTF quad: a caster of one side (--lit)
            props_a.append(self.quad_prop(lo, hi, c, max(w, 1.0)))
        self.room("a", lo, hi, props_a)
        coincident = r.random() < 0.6
        if coincident:
            lo2 = [lo[0] + self.round_or(r.uniform(-1, 1), 0.5), lo[1], lo[2] + self.round_or(r.uniform(-1, 1), 0.5)]
            hi2 = [hi[0] + self.round_or(r.uniform(-1, 1), 0.5), hi[1], hi[2] + self.round_or(r.uniform(-1, 1), 0.5)]
            cb, nb = c, [-v for v in n]
        else:
            ob = [o[0] + self.round_or(r.uniform(-20, 20), 1.0), o[1], o[2] + self.round_or(r.uniform(-20, 20), 1.0)]
            lo2, hi2 = self.room_box(ob, hx, hz, h)
            cb = [ob[0], lo2[1] + ph / 2, ob[2]]
            yaw_b = r.choice([0, 1, 2, 3]) * math.pi / 2
            nb = [round(math.sin(yaw_b), 12), 0.0, round(math.cos(yaw_b), 12)]
        self.room("b", lo2, hi2, self.clear_of_box(self.props_near(cb, lo2, hi2, r.randint(0, 2)), cb, max(w, 1.0)))
        depth = r.choice([0.01, 0.1, 0.25, 0.5]) if r.random() < 0.5 else log_uniform_01(r)
        self.portal("a_door", "a", c, n, w, ph, "b_door", depth)
        self.portal("b_door", "b", cb, nb, w, ph, "a_door", self.box_depth())
        self.sub = r.choice(FLOOR_DOOR_POSES)

    def floor_door_pose(self):
        r = self.r
        door = self.portals[0]
        c, n, w = door["center"], door["normal"], door["width"]
        floor = self.rooms[0]["min"][1]
        right = [n[2], 0.0, -n[0]]  # right as seen from in front (up × n, with up = +y)
        facing = math.degrees(math.atan2(n[0], n[2]))  # the yaw that looks along -n (at the door's front)
        max_depth = r.choice([1, 2, 8, 8, 16])
        fov = r.choice([90, 90, 60, 110]) if r.random() < 0.7 else r.uniform(40, 110)
        height = r.choice([1.5, 1.6, 1.7]) if r.random() < 0.8 else r.uniform(0.3, 2.4)
        room = "a"
        sub = self.sub
        if sub == "behind":  # walked round: behind the plane, over the rectangle or beside it
            back = r.choice([0.01, 0.05, 0.1, 0.2, 0.5]) if r.random() < 0.7 else r.uniform(0.005, 0.5)
            side = r.choice([0.0, 0.0, 0.25, -0.25, w / 2, w]) if r.random() < 0.8 else r.uniform(-w, w)
            p = [c[i] - back * n[i] + side * right[i] for i in range(3)]
            yaw = facing + r.choice([0, 180, 90, -90, 0, 180])
            pitch = r.choice([0, 0, -30, -60])
            what = "%.3g m behind the door, %.3g m to its side" % (back, side)
        elif sub == "edge":  # in front, looking at the bottom edge
            dist = r.choice([1.0, 1.5, 1.6, 2.0, 3.0]) if r.random() < 0.7 else r.uniform(0.3, 4)
            side = r.choice([0.0, 0.0, 0.5, -0.5]) if r.random() < 0.7 else r.uniform(-1, 1)
            p = [c[i] + dist * n[i] + side * right[i] for i in range(3)]
            yaw = facing + (r.choice([0, 0, 10, -10]) if r.random() < 0.8 else r.uniform(-40, 40))
            pitch = r.choice([0, 0, -20, -45]) if r.random() < 0.8 else r.uniform(-60, 10)
            what = "%.3g m in front, looking at the bottom edge" % dist
        elif sub in ("across", "inside"):
            ahead = r.choice([0.01, 0.02, 0.03]) if r.random() < 0.7 else r.uniform(0.001, 0.031)
            if sub == "inside":  # the head came through: it stands behind b_door in room b
                door = self.portals[1]
                c, n = door["center"], door["normal"]
                right = [n[2], 0.0, -n[0]]
                facing = math.degrees(math.atan2(n[0], n[2]))
                floor = self.rooms[1]["min"][1]
                room = "b"
                ahead = r.choice([0.01, 0.02, 0.05]) if r.random() < 0.7 else r.uniform(0.001, 0.1)
            side = r.choice([0.0, 0.0, 0.2, -0.2]) * w
            p = [c[i] + ahead * n[i] + side * right[i] for i in range(3)]
            yaw = facing + r.choice([90, -90]) + (0 if r.random() < 0.7 else r.uniform(-20, 20))
            pitch = r.choice([-30, -45, -60, -89]) if r.random() < 0.8 else r.uniform(-89, -10)
            what = "%.3g m in front, one eye across, looking down" % ahead
        else:
            lo, hi = self.rooms[0]["min"], self.rooms[0]["max"]
            p = [r.uniform(lo[i] + 0.05, hi[i] - 0.05) for i in range(3)]
            yaw, pitch = r.uniform(-180, 180), r.uniform(-60, 30)
            what = "random look"
        p[1] = floor + height
        pose = [round(p[0], 9), round(p[1], 9), round(p[2], 9), round(yaw, 9), pitch, 0.0]
        return pose, room, max_depth, fov, what


def quad_gltf(double_sided):
    """A glTF 2.0 file of one quad, x -0.5..0.5, y 0.2..1.2 at z = 0, facing
    +z, grey, its buffer embedded."""
    positions = [(-0.5, 0.2, 0.0), (0.5, 0.2, 0.0), (0.5, 1.2, 0.0), (-0.5, 1.2, 0.0)]
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += b"".join(struct.pack("<3f", 0.0, 0.0, 1.0) for _ in positions)
    data += struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    model = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [-0.5, 0.2, 0.0], "max": [0.5, 1.2, 0.0]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1.0]},
                       "doubleSided": double_sided}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    return json.dumps(model)


def log_uniform_01(r):
    return math.exp(r.uniform(math.log(0.01), math.log(0.5)))
