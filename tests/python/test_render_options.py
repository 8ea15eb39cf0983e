"""Every rasteriser option of `render` reaches Python as a keyword argument
of Renderer, with the same names as api::RenderOptions: each stereo, clip,
depth and technique mode (and samples, the budget, shadows, occlusion test,
culling) equals the command's PNGs byte for byte; bad values name the
argument."""
import pytest

import impossible
from helpers import SOURCE_DIR, cli
from png_reader import read_png

SIZE = (96, 54)

# (layout, the command's flags, Renderer's keyword arguments, render()'s)
CASES = [
    ("four_rooms", [], {}, {}),
    ("four_rooms", ["--stereo", "viewport-index"], {"stereo": "viewport-index"}, {}),
    ("four_rooms", ["--stereo", "two-pass"], {"stereo": "two-pass"}, {}),
    ("mirror_hall", ["--clip", "oblique"], {"clip": "oblique"}, {}),
    ("four_rooms", ["--depth", "standard"], {"depth": "standard"}, {}),
    ("four_rooms", ["--technique", "hybrid", "--texture-from-level", "1", "--portal-texture", "0.5"],
     {"technique": "hybrid", "texture_from_level": 1, "texture_scale": 0.5}, {}),
    ("four_rooms", ["--technique", "z-clear", "--max-depth", "1"], {"technique": "z-clear"}, {"max_depth": 1}),
    ("four_rooms", ["--no-cull", "--occlusion-test"], {"cull": False, "occlusion_test": True}, {}),
    ("four_rooms", ["--samples", "4"], {"samples": 4}, {}),
    ("lamp_hall", ["--shadow-size", "64"], {"shadow_size": 64}, {}),
    ("lamp_hall", ["--no-shadows"], {"shadows": False}, {}),
    ("four_rooms", ["--max-portal-passes", "3"], {"max_portal_passes": 3}, {}),
]


@pytest.mark.parametrize("layout,flags,options,view", CASES, ids=[" ".join(c[1]) or "defaults" for c in CASES])
def test_every_mode_equals_the_command(tmp_path, layout, flags, options, view):
    path = SOURCE_DIR / "layouts" / f"{layout}.json"
    color, ids = tmp_path / "c.png", tmp_path / "i.png"
    cli("render", path, "--size", f"{SIZE[0]}x{SIZE[1]}", *flags, "--out", color, "--ids", ids)
    frame = impossible.Renderer(impossible.load(path), size=SIZE, **options).render(**view)
    assert frame["color"].tobytes() == read_png(color).tobytes()
    assert frame["ids"].tobytes() == read_png(ids).tobytes()


def test_bad_options_name_the_argument():
    layout = impossible.builtin()
    with pytest.raises(ValueError, match="stereo must be one of 'clip-shift', 'viewport-index', 'two-pass', not 'x'"):
        impossible.Renderer(layout, size=(8, 6), stereo="x")
    with pytest.raises(ValueError, match="technique must be one of"):
        impossible.Renderer(layout, size=(8, 6), technique="stencils")
    r = impossible.Renderer(layout, size=(8, 6), technique="z-clear")
    with pytest.raises(impossible.Error, match=r"technique z-clear draws one level of doors: max_depth 8 \(give max_depth 1\)"):
        r.render()
    with pytest.raises(impossible.Error, match="shadow_size 5000 is not in 0..4096"):
        impossible.Renderer(layout, size=(8, 6), shadow_size=5000).render()
