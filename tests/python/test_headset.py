"""Headsets through the module (docs/python.md, "Headsets"): hmd=, fov_angles=
and visible_area= of Renderer and trace against the CLI's --hmd and
--fov-angles, byte for byte; impossible.load_hmd_profile; the argument rules."""
import pytest

import impossible
from helpers import SOURCE_DIR, cli
from png_reader import read_png

VIVE = SOURCE_DIR / "profiles" / "htc-vive.json"
LAYOUT = SOURCE_DIR / "layouts" / "four_rooms.json"
SIZE = (93, 103)


def cli_frame(tmp_path, command, *options):
    color, ids = tmp_path / "color.png", tmp_path / "ids.png"
    cli(command, LAYOUT, "--out", color, "--ids", ids, *options)
    return read_png(color).tobytes(), read_png(ids).tobytes()


def frame_bytes(frame):
    return frame["color"].tobytes(), frame["ids"].tobytes()


@pytest.mark.parametrize("command", ["render", "trace"])
def test_hmd_as_the_cli(tmp_path, command):
    expected = cli_frame(tmp_path, command, "--hmd", VIVE, "--size", f"{SIZE[0]}x{SIZE[1]}")
    layout = impossible.load(LAYOUT)
    if command == "render":
        frame = impossible.Renderer(layout, size=SIZE, hmd=VIVE).render()
    else:
        frame = impossible.trace(layout, size=SIZE, hmd=str(VIVE))
    assert frame["ids"].shape == (SIZE[1], 2 * SIZE[0])
    assert frame_bytes(frame) == expected
    assert (frame["ids"] == 0).mean() > 0.15  # the hidden area, about 19 % of each eye


def test_fov_angles_and_visible_area_as_the_profile(tmp_path):
    profile = impossible.load_hmd_profile(VIVE)
    assert profile["size"] == (1852, 2056) and profile["ipd"] == 0.0724
    assert profile["fov_angles"][:4] == (-54.41, 46.75, 55.67, -55.91)
    assert len(profile["visible_area"]) == 2 and len(profile["visible_area"][0]) >= 3
    layout = impossible.load(LAYOUT)
    by_profile = impossible.trace(layout, size=SIZE, hmd=VIVE)
    by_numbers = impossible.trace(layout, size=SIZE, ipd=profile["ipd"], fov_angles=profile["fov_angles"],
                                  visible_area=profile["visible_area"])
    assert frame_bytes(by_numbers) == frame_bytes(by_profile)


@pytest.mark.parametrize("command", ["render", "trace"])
def test_fov_angles_as_the_cli(tmp_path, command):
    angles = (-50, 40, 45, -35)
    expected = cli_frame(tmp_path, command, "--fov-angles", ",".join(map(str, angles)), "--size", "64x48")
    layout = impossible.load(LAYOUT)
    if command == "render":
        frame = impossible.Renderer(layout, size=(64, 48), fov_angles=angles).render()
    else:
        frame = impossible.trace(layout, size=(64, 48), fov_angles=angles)
    assert frame_bytes(frame) == expected
    mirrored = angles + (-angles[1], -angles[0], angles[2], angles[3])
    assert frame_bytes(impossible.trace(layout, size=(64, 48), fov_angles=mirrored)) == expected


def test_bad_headset_arguments(tmp_path):
    layout = impossible.builtin()
    bad = tmp_path / "bad.json"
    bad.write_text('{"name": "x", "source": "y",\n "left": {"fov": {"left": -95, "right": 40, "up": 40, "down": -40},\n'
                   '  "resolution": [8, 8]},\n "right": {"fov": {"left": -40, "right": 40, "up": 40, "down": -40},\n'
                   '  "resolution": [8, 8]}}\n')
    with pytest.raises(impossible.Error, match=f"^{bad}:2:[0-9]+: left.fov.left: .*89.5"):
        impossible.trace(layout, hmd=bad)
    with pytest.raises(impossible.Error, match=f"^{bad}:2:"):
        impossible.Renderer(layout, hmd=bad)
    with pytest.raises(impossible.Error, match=f"^{bad}:2:"):
        impossible.load_hmd_profile(bad)
    with pytest.raises(ValueError, match="fov and hmd exclude each other"):
        impossible.trace(layout, fov=80, hmd=VIVE)
    with pytest.raises(ValueError, match="fov_angles and hmd exclude each other"):
        impossible.trace(layout, fov_angles=(-40, 40, 40, -40), hmd=VIVE)
    with pytest.raises(ValueError, match="fov and fov_angles exclude each other"):
        impossible.Renderer(layout, fov=80, fov_angles=(-40, 40, 40, -40))
    with pytest.raises(ValueError, match="visible_area needs fov_angles"):
        impossible.trace(layout, visible_area=(None, None))
    with pytest.raises(ValueError, match="fov_angles: expected 4 or 8 numbers"):
        impossible.trace(layout, fov_angles=(1, 2, 3))
    with pytest.raises(impossible.Error, match="right eye: fov: right .* must be at least 1 degree right of left"):
        impossible.trace(layout, size=(8, 8), fov_angles=(-40, 40, 40, -40, 10, 5, 40, -40))
    with pytest.raises(impossible.Error, match=r"left eye: visible_area\[1\] is not within 0..1"):
        impossible.trace(layout, size=(8, 8), fov_angles=(-40, 40, 40, -40),
                         visible_area=([(0, 0), (2, 0), (1, 1)], None))


def test_numbers_from_numpy_and_array_do_not_crash():
    """fov_angles and visible_area corners given as numpy arrays or an
    array.array: each item is a new object, once held only by a dangling
    handle (a segfault, three runs out of three)."""
    import array

    import numpy as np

    layout = impossible.builtin()
    plain = impossible.trace(layout, size=(8, 6), fov_angles=(-50, 40, 40, -45))
    for angles in (array.array("d", [-50, 40, 40, -45]), np.array([-50.0, 40, 40, -45])):
        frame = impossible.trace(layout, size=(8, 6), fov_angles=angles)
        assert frame["color"].tobytes() == plain["color"].tobytes()
    area = np.array([[0.5, 0], [1, 0.5], [0.5, 1], [0, 0.5]])
    listed = impossible.trace(layout, size=(8, 6), fov_angles=(-50, 40, 40, -45),
                              visible_area=([tuple(c) for c in area], None))
    masked = impossible.trace(layout, size=(8, 6), fov_angles=(-50, 40, 40, -45), visible_area=(area, None))
    assert masked["ids"].tobytes() == listed["ids"].tobytes()
    assert (masked["ids"][:, :8] == 0).any()
