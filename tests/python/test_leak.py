"""Many frames in one process leak nothing: the resident set (VmRSS) after 200
frames is within a bound of what it was after the first 20. A frame at this
size is 691 KB of arrays, so leaking its pixels would add 120 MB over the 180
frames measured; the bound allows 4 MB (allocator and driver caches)."""
import gc

import impossible
from helpers import SOURCE_DIR

BOUND_KB = 4096


def rss_kb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS in /proc/self/status")


def grown_kb(draw, frames=200, settle=20):
    before = None
    for k in range(frames):
        frame = draw(k)
        assert frame["color"].shape[2] == 3
        del frame
        if k + 1 == settle:
            gc.collect()
            before = rss_kb()
    gc.collect()
    return rss_kb() - before


def test_renders_leak_nothing():
    renderer = impossible.Renderer(impossible.load(SOURCE_DIR / "layouts" / "three_kinds.json"), size=(320, 180))
    poses = [(0.1 * (k % 7), 1.6, 0.05 * (k % 5), 10.0 * k, 0, 0) for k in range(7)]
    grown = grown_kb(lambda k: renderer.render(pose=poses[k % 7], room=renderer.layout.start_room))
    print(f"render: RSS grew {grown} KB from frame 20 to frame 200")
    assert grown < BOUND_KB


def test_traces_leak_nothing():
    layout = impossible.load(SOURCE_DIR / "layouts" / "three_kinds.json")
    grown = grown_kb(lambda k: impossible.trace(layout, size=(80, 45), threads=1))
    print(f"trace: RSS grew {grown} KB from frame 20 to frame 200")
    assert grown < BOUND_KB


def test_renderers_leak_nothing():
    """Renderers made and dropped: their contexts and GL objects go with them.
    (Terminating the EGL display with each leaked 24 KB a renderer in Mesa:
    1.4 MB here.)"""
    layout = impossible.load(SOURCE_DIR / "layouts" / "three_kinds.json")
    grown = grown_kb(lambda k: impossible.Renderer(layout, size=(32, 18)).render(), frames=80, settle=20)
    print(f"renderers: RSS grew {grown} KB from renderer 20 to renderer 80")
    assert grown < 768
