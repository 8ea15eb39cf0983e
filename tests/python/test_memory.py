"""Many renderers in one process (docs/bounded-work.md, "Other bounds"): the
renderers of a thread share one GL context and its compiled programs, and
keep together no more frame buffers than one frame may use, so 100
renderers of a lit layout, each having drawn a frame, hold about 1.3 MB
each plus the shadow maps' bound (256 MB); before, each held its context,
its programs and its own maps, 20 MB (4.1 GB for 200). A renderer closed or
deleted gives its memory back to the system.
Each measure runs in an interpreter of its own, so that nothing else this
file does is in its resident set (VmRSS)."""
import json
import subprocess
import sys

import pytest

import impossible
from helpers import SOURCE_DIR

LIT = SOURCE_DIR / "layouts" / "lamp_hall.json"
SIZE = (160, 90)
# Scene buffers, light images, targets: the programs are the context's
# (render::SharedPrograms; when each renderer compiled the variants it drew
# with, 100 lamp-hall renderers held 636 MB, and 768 MB with the shadow
# lookups' variants; 388 MB now).
PER_RENDERER_MB = 2
SHADOW_MAPS_MB = 256  # render::kMaxShadowMapBytes: all the renderers' maps together

# Makes N renderers after a first one (the driver's one-time costs: LLVM, the
# display), has each draw a frame, drops them all; prints what the resident
# set grew by with them and after them, in MB.
MEASURE = r"""
import gc, json, sys
import impossible

def rss_mb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024

layout, n, size = impossible.load(sys.argv[1]), int(sys.argv[2]), (int(sys.argv[3]), int(sys.argv[4]))
impossible.Renderer(layout, size=size).render()
gc.collect()
base = rss_mb()
renderers = [impossible.Renderer(layout, size=size) for _ in range(n)]
for r in renderers:
    r.render()
held = rss_mb() - base
del renderers, r
gc.collect()
print(json.dumps({"held": held, "after": rss_mb() - base}))
"""


def measure(n):
    done = subprocess.run([sys.executable, "-c", MEASURE, str(LIT), str(n), *map(str, SIZE)], capture_output=True,
                          text=True, timeout=300, check=True)
    mb = json.loads(done.stdout)
    print(f"{n} lit renderers: held {mb['held']:.0f} MB, {mb['after']:.0f} MB after they were deleted")
    return mb


def test_many_lit_renderers_hold_a_bounded_share():
    n = 100
    mb = measure(n)
    assert mb["held"] < n * PER_RENDERER_MB + SHADOW_MAPS_MB
    assert mb["after"] < 32  # every renderer's share given back


def test_a_renderer_whose_buffers_were_released_draws_the_same_frame():
    """25 others draw after the first: their maps (13 MB each at 512²) pass the
    bound, and the first's, the least recently drawn, are released and drawn
    again at its next frame."""
    layout = impossible.load(LIT)
    first = impossible.Renderer(layout, size=SIZE)
    before = first.render()
    others = [impossible.Renderer(layout, size=SIZE) for _ in range(25)]
    for r in others:
        r.render()
    again = first.render()
    assert again["color"].tobytes() == before["color"].tobytes()
    assert again["ids"].tobytes() == before["ids"].tobytes()


def test_close_frees_the_renderer_at_once():
    layout = impossible.builtin()
    with impossible.Renderer(layout, size=(16, 9)) as renderer:
        assert not renderer.closed
        frame = renderer.render()
    assert renderer.closed
    with pytest.raises(ValueError, match="^render: the renderer is closed$"):
        renderer.render()
    renderer.close()  # again: nothing
    assert renderer.size == (16, 9) and renderer.layout.name == layout.name and "llvmpipe" in renderer.gl_renderer
    traced = renderer.trace(threads=1)  # the tracer needs no context
    assert traced["color"].shape == frame["color"].shape
