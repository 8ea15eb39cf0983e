"""Renderer.render, Renderer.trace and impossible.trace against the CLI's
PNGs, byte for byte, on every layout; the renderer's arguments and contexts."""
import re
import sys
import threading
import time

import numpy as np
import pytest

import impossible
from helpers import LAYOUTS, SOURCE_DIR, cli
from png_reader import read_png

SIZE = (160, 90)
CASES = [None] + LAYOUTS  # None: the built-in default layout


def case_id(path):
    return "builtin" if path is None else path.stem


def load(path):
    return impossible.builtin() if path is None else impossible.load(path)


def cli_images(tmp_path, command, path, *options):
    layout = [] if path is None else [path]
    color, ids = tmp_path / "color.png", tmp_path / "ids.png"
    _, err = cli(command, *layout, "--size", f"{SIZE[0]}x{SIZE[1]}", "--out", color, "--ids", ids, *options)
    return read_png(color), read_png(ids), err


def assert_frame(frame, color, ids):
    assert frame["color"].dtype == np.uint8 and frame["ids"].dtype == np.uint8
    assert frame["color"].shape == (SIZE[1], 2 * SIZE[0], 3)
    assert frame["ids"].shape == (SIZE[1], 2 * SIZE[0])
    assert frame["color"].tobytes() == color.tobytes()
    assert frame["ids"].tobytes() == ids.tobytes()


def stats_of(stderr):
    line = next(l for l in stderr.splitlines() if l.startswith("stats: "))
    return {k: int(v) for k, v in re.findall(r"(\w+)=(\d+)", line)}


@pytest.mark.parametrize("path", CASES, ids=case_id)
def test_render_equals_cli(tmp_path, path):
    color, ids, err = cli_images(tmp_path, "render", path, "--stats")
    frame = impossible.Renderer(load(path), size=SIZE).render()
    assert_frame(frame, color, ids)
    assert frame["stats"] == stats_of(err)


@pytest.mark.parametrize("path", CASES, ids=case_id)
def test_trace_equals_cli(tmp_path, path):
    color, ids, _ = cli_images(tmp_path, "trace", path)
    frame = impossible.trace(load(path), size=SIZE)
    assert_frame(frame, color, ids)
    assert "stats" not in frame


def test_pose_room_depth_samples_time(tmp_path):
    path = SOURCE_DIR / "layouts" / "corridor.json"
    options = ["--pose", "0.2,1.5,0.5,30,-10,5", "--room", "corridor", "--max-depth", "3", "--samples", "4"]
    color, ids, _ = cli_images(tmp_path, "render", path, *options)
    renderer = impossible.Renderer(impossible.load(path), size=SIZE, samples=4)
    frame = renderer.render(pose=(0.2, 1.5, 0.5, 30, -10, 5), room="corridor", max_depth=3, time=2.5)
    assert_frame(frame, color, ids)
    color, ids, _ = cli_images(tmp_path, "trace", path, *options)
    assert_frame(renderer.trace(pose=[0.2, 1.5, 0.5, 30, -10, 5], room="corridor", max_depth=3), color, ids)


@pytest.mark.parametrize("depth", [0, 1])
def test_light_depth_as_the_cli(tmp_path, depth):
    """light_depth= lights what --light-depth lights (rasteriser and tracer)."""
    path = SOURCE_DIR / "layouts" / "lamp_hall.json"
    options = ["--room", "annex", "--pose", "1.9,2.0,0.0,90,-35,0", "--light-depth", str(depth)]
    color, ids, _ = cli_images(tmp_path, "render", path, *options)
    renderer = impossible.Renderer(impossible.load(path), size=SIZE)
    pose = (1.9, 2.0, 0.0, 90, -35, 0)
    assert_frame(renderer.render(pose=pose, room="annex", light_depth=depth), color, ids)
    color, ids, _ = cli_images(tmp_path, "trace", path, *options)
    assert_frame(renderer.trace(pose=pose, room="annex", light_depth=depth), color, ids)
    assert_frame(impossible.trace(impossible.load(path), size=SIZE, pose=pose, room="annex", light_depth=depth),
                 color, ids)


def test_hands_and_time_as_the_cli(tmp_path):
    """hands= and time= draw what --hands and --time draw (rasteriser and tracer)."""
    path = SOURCE_DIR / "layouts" / "rotated.json"
    pose = (0.0, 1.6, 0.6, 0, -10, 0)
    hands = ((-0.2, 1.3, 0.3, 10, 0, 0), (0.15, 1.4, -0.05, -20, 30, 5))
    text = ",".join(str(v) for hand in hands for v in hand)
    options = ["--pose", ",".join(map(str, pose)), "--room", "hall", "--hands", text, "--time", "1.25"]
    renderer = impossible.Renderer(impossible.load(path), size=SIZE)
    color, ids, _ = cli_images(tmp_path, "render", path, *options)
    with_hands = renderer.render(pose=pose, room="hall", hands=hands, time=1.25)
    assert_frame(with_hands, color, ids)
    assert renderer.render(pose=pose, room="hall")["color"].tobytes() != color.tobytes()  # the hands are drawn
    color, ids, _ = cli_images(tmp_path, "trace", path, *options)
    assert_frame(renderer.trace(pose=pose, room="hall", hands=list(hands), time=1.25), color, ids)


def test_several_renderers_in_one_process(tmp_path):
    paths = [SOURCE_DIR / "layouts" / name for name in ("three_kinds.json", "mirror_hall.json")]
    expected = [cli_images(tmp_path, "render", p)[:2] for p in paths]
    first = impossible.Renderer(impossible.load(paths[0]), size=SIZE)
    second = impossible.Renderer(impossible.load(paths[1]), size=SIZE, backend="any")
    for _ in range(2):  # interleaved: each draws in its own context
        assert_frame(first.render(), *expected[0])
        assert_frame(second.render(), *expected[1])
    software = impossible.Renderer(impossible.load(paths[1]), size=SIZE, backend="osmesa")
    assert "llvmpipe" in software.gl_renderer
    assert_frame(software.render(), *expected[1])
    assert_frame(first.render(), *expected[0])
    del second, software  # the display stays for the renderer left
    assert_frame(first.render(), *expected[0])


def test_arrays_own_their_pixels():
    renderer = impossible.Renderer(impossible.builtin(), size=(8, 4))
    frame = renderer.render()
    color = frame["color"]
    assert color.flags["C_CONTIGUOUS"] and not color.flags["OWNDATA"]  # the frame's own buffer, not a copy
    again = renderer.render()["color"]
    del frame, renderer
    assert color.tobytes() == again.tobytes()


def test_bad_arguments():
    layout = impossible.builtin()
    with pytest.raises(ValueError, match="backend must be 'egl', 'osmesa' or 'any'"):
        impossible.Renderer(layout, backend="vulkan")
    renderer = impossible.Renderer(layout, size=(16, 9))
    with pytest.raises(ValueError, match="hands: expected two poses"):
        impossible.trace(layout, size=(16, 9), hands=[])
    with pytest.raises(TypeError, match="hands: expected two poses"):
        renderer.render(hands="0,1,0,0,0,0")
    with pytest.raises(ValueError, match=r"hands\[1\]: expected 6 numbers"):
        renderer.render(hands=[(0, 1, 0, 0, 0, 0), (0, 1, 0)])
    with pytest.raises(ValueError, match=r"hands\[0\]: .* not a finite number"):
        renderer.render(hands=[(0, float("inf"), 0, 0, 0, 0), (0, 1, 0, 0, 0, 0)])
    with pytest.raises(impossible.Error, match="time is not a finite number"):
        renderer.render(time=float("nan"))
    with pytest.raises(ValueError, match="expected 6 numbers"):
        renderer.render(pose=(0, 1.6, 0))
    with pytest.raises(TypeError, match="expected 6 numbers"):
        renderer.render(pose="0,1.6,0,0,0,0")
    with pytest.raises(ValueError, match="not a finite number"):
        renderer.render(pose=(0, float("nan"), 0, 0, 0, 0))
    with pytest.raises(impossible.Error, match="there is no room 'attic'"):
        renderer.render(room="attic")
    with pytest.raises(impossible.Error, match="max_depth 300 is not in 0..250"):
        renderer.render(max_depth=300)
    with pytest.raises(impossible.Error, match="size 0x9 is not within 1..8192"):
        impossible.Renderer(layout, size=(0, 9)).render()
    with pytest.raises(impossible.Error, match="the head is in no room"):
        renderer.render(pose=(500, 1.6, 0, 0, 0, 0))
    with pytest.raises(impossible.Error, match="samples 3 is not 1, 2, 4, 8 or 16"):
        impossible.trace(layout, size=(16, 9), samples=3)


def test_renderer_stays_on_its_thread():
    renderer = impossible.Renderer(impossible.builtin(), size=(16, 9))
    caught = []

    def other():
        try:
            renderer.render()
        except RuntimeError as e:
            caught.append(str(e))

    thread = threading.Thread(target=other)
    thread.start()
    thread.join()
    assert caught == ["a Renderer draws only on the thread that made it"]
    assert renderer.render()["color"].shape == (9, 32, 3)


@pytest.mark.parametrize("method", ["render", "trace"])
def test_gil_is_released(method):
    """Another thread counts while frames are drawn. The interpreter hands the
    GIL over only when its holder blocks (the switch interval is set far
    away), so the count moves only if the frame released it."""
    renderer = impossible.Renderer(impossible.load(SOURCE_DIR / "layouts" / "gallery.json"), size=(640, 360))
    draw = getattr(renderer, method)
    counted = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counted[0] += 1
            time.sleep(0)  # lets the drawing thread take the GIL back at once

    interval = sys.getswitchinterval()
    sys.setswitchinterval(100)
    thread = threading.Thread(target=count)
    thread.start()
    try:
        during = []
        for _ in range(4):
            before = counted[0]
            draw()
            during.append(counted[0] - before)
    finally:
        stop.set()
        thread.join()
        sys.setswitchinterval(interval)
    # Held, it is 0 every time; released, the other thread may still not be
    # scheduled on a busy machine during some short frame.
    assert max(during) > 10, during


def test_the_door_rules_of_issue_36():
    """layout-format.md, "The portal box" and the coplanar ties, through the
    module: a head that walked round the built-in default's door sees the
    hall; an eye across the plane looking down sees the annex's floor in the
    box, as the tracer does."""
    renderer = impossible.Renderer(impossible.builtin(), size=(80, 60))
    for method in (renderer.render, renderer.trace):
        behind = method(pose=(0, 1.6, -0.1, 0, 0, 0), room="hall")
        assert (behind["ids"] == 1).all()
    across = [method(pose=(0, 1.6, 0.02, -90, -60, 0), room="hall")["ids"] for method in (renderer.render, renderer.trace)]
    assert (across[0] == 2).sum() > 1000 and (across[1] == 2).sum() > 1000
    assert (across[0] != across[1]).sum() <= 2


@pytest.mark.parametrize("ev", [-2.0, 2.0])
def test_exposure_as_the_cli(tmp_path, ev):
    """exposure= exposes what --exposure exposes (rasteriser and tracer); a bad value raises ValueError."""
    path = SOURCE_DIR / "layouts" / "lamp_hall.json"
    options = ["--exposure", str(ev)]
    color, ids, _ = cli_images(tmp_path, "render", path, *options)
    renderer = impossible.Renderer(impossible.load(path), size=SIZE)
    frame = renderer.render(exposure=ev)
    assert_frame(frame, color, ids)
    assert frame["color"].tobytes() != renderer.render()["color"].tobytes()
    color, ids, _ = cli_images(tmp_path, "trace", path, *options)
    assert_frame(renderer.trace(exposure=ev), color, ids)
    assert_frame(impossible.trace(impossible.load(path), size=SIZE, exposure=ev), color, ids)
    with pytest.raises(ValueError, match="exposure"):
        renderer.render(exposure=21)
