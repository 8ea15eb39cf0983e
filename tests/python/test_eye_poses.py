"""Each eye's pose through the module (docs/python.md, "Headsets"): eye_poses=
of Renderer and trace against the CLI's --eye-poses and a profile's poses,
byte for byte; load_hmd_profile's eye_poses; the argument rules."""
import math

import pytest

import impossible
from helpers import SOURCE_DIR, cli
from png_reader import read_png

CANTED = SOURCE_DIR / "profiles" / "canted-5deg.json"
LAYOUT = SOURCE_DIR / "layouts" / "four_rooms.json"
SIZE = (72, 60)
# Each eye turned 5 degrees outwards, as --eye-poses gives it.
EYES = ((-0.032, 0, 0, 5, 0, 0), (0.032, 0, 0, -5, 0, 0))


def cli_frame(tmp_path, command, *options):
    color, ids = tmp_path / "color.png", tmp_path / "ids.png"
    cli(command, LAYOUT, "--out", color, "--ids", ids, "--size", f"{SIZE[0]}x{SIZE[1]}", *options)
    return read_png(color).tobytes(), read_png(ids).tobytes()


def frame_bytes(frame):
    return frame["color"].tobytes(), frame["ids"].tobytes()


@pytest.mark.parametrize("command", ["render", "trace"])
def test_eye_poses_as_the_cli(tmp_path, command):
    expected = cli_frame(tmp_path, command, "--eye-poses", ",".join(str(n) for eye in EYES for n in eye))
    layout = impossible.load(LAYOUT)
    if command == "render":
        frame = impossible.Renderer(layout, size=SIZE, eye_poses=EYES).render()
    else:
        frame = impossible.trace(layout, size=SIZE, eye_poses=EYES)
    assert frame_bytes(frame) == expected
    assert frame_bytes(impossible.trace(layout, size=SIZE)) != expected  # the eyes are turned


@pytest.mark.parametrize("command", ["render", "trace"])
def test_profile_poses_as_the_cli(tmp_path, command):
    expected = cli_frame(tmp_path, command, "--hmd", CANTED)
    layout = impossible.load(LAYOUT)
    if command == "render":
        frame = impossible.Renderer(layout, size=SIZE, hmd=CANTED).render()
    else:
        frame = impossible.trace(layout, size=SIZE, hmd=CANTED)
    assert frame_bytes(frame) == expected


def test_profile_poses_as_numbers():
    profile = impossible.load_hmd_profile(CANTED)
    half = math.radians(2.5)
    assert profile["eye_poses"] == (((-0.03175, 0.0, 0.0), (0.0, math.sin(half), 0.0, math.cos(half))),
                                    ((0.03175, 0.0, 0.0), (0.0, -math.sin(half), 0.0, math.cos(half))))
    assert impossible.load_hmd_profile(SOURCE_DIR / "profiles" / "htc-vive.json")["eye_poses"] is None
    layout = impossible.load(LAYOUT)
    by_profile = impossible.trace(layout, size=SIZE, hmd=CANTED)
    by_numbers = impossible.trace(layout, size=SIZE, fov_angles=profile["fov_angles"],
                                  visible_area=profile["visible_area"], eye_poses=profile["eye_poses"])
    assert frame_bytes(by_numbers) == frame_bytes(by_profile)
    # The angles of --eye-poses give the same frame as the quaternions.
    by_angles = impossible.trace(layout, size=SIZE, fov_angles=profile["fov_angles"],
                                 visible_area=profile["visible_area"],
                                 eye_poses=((-0.03175, 0, 0, 5, 0, 0), (0.03175, 0, 0, -5, 0, 0)))
    assert frame_bytes(by_angles) == frame_bytes(by_profile)


def test_bad_eye_poses():
    layout = impossible.builtin()
    with pytest.raises(ValueError, match="eye_poses and ipd exclude each other"):
        impossible.trace(layout, size=(8, 8), ipd=0.07, eye_poses=EYES)
    with pytest.raises(ValueError, match="^ipd: .*canted-5deg.json gives each eye's position and orientation"):
        impossible.Renderer(layout, hmd=CANTED, ipd=0.07)
    with pytest.raises(ValueError, match="eye_poses: expected two poses"):
        impossible.trace(layout, size=(8, 8), eye_poses=EYES[:1])
    with pytest.raises(ValueError, match=r"eye_poses\[1\]: pitch 90.0 is not within ±89.5 degrees"):
        impossible.trace(layout, size=(8, 8), eye_poses=(EYES[0], (0, 0, 0, 0, 90, 0)))
    with pytest.raises(impossible.Error, match="^eye_poses: right eye: the position is 1.5 m from the head centre"):
        impossible.trace(layout, size=(8, 8), eye_poses=(EYES[0], (0, 1.5, 0, 0, 0, 0)))
    with pytest.raises(impossible.Error, match="^eye_poses: left eye: the orientation is not a unit quaternion"):
        impossible.trace(layout, size=(8, 8), eye_poses=(((0, 0, 0), (0, 0, 0, 2)), EYES[1]))
    with pytest.raises(TypeError, match="eye_poses"):
        impossible.trace(layout, size=(8, 8), eye_poses="left right")
