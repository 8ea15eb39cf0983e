"""A layout with changes (layout-format.md, "Changes while walking"): walk's
steps name the changes made at them, as `impossible walk` prints them, the
walker gives the layout with the pairing in force, and paired_at the one at
frame k of a walk, drawn as `render`/`trace --path FILE --frame k` draw it."""
import json

import pytest

import impossible
from helpers import SOURCE_DIR, cli
from png_reader import read_png

LAYOUT = SOURCE_DIR / "layouts" / "door_swap.json"
PATH = SOURCE_DIR / "layouts" / "door_swap_walk.txt"
SIZE = (96, 54)


def cli_walk(*options):
    out, _ = cli("walk", LAYOUT, "--path", PATH, *options)
    return [json.loads(line) for line in out.splitlines()]


def test_walk_names_the_changes_as_the_cli_does():
    layout = impossible.load(LAYOUT)
    lines = impossible.read_path(PATH)
    expected = cli_walk()
    steps = impossible.walk(layout, lines)
    assert steps == expected
    made = [step["frame"] for step in steps if "changes" in step]
    assert len(made) == 1 and steps[made[0]]["changes"] == ["swap"]
    # The view options of the seen test, as walk's.
    assert impossible.walk(layout, lines, fov=30, size=(200, 720), max_depth=2) == cli_walk(
        "--fov", "30", "--size", "200x720", "--max-depth", "2")
    with pytest.raises(ValueError, match="size"):
        impossible.walk(layout, lines, size=(0, 10))


def test_the_walker_gives_the_layout_of_the_pairing_in_force():
    layout = impossible.load(LAYOUT)
    walker = impossible.Walker(layout)
    assert walker.layout.portals == layout.portals
    assert walker.changes == [{"id": "swap", "armed": False, "made_frame": None}]
    for k, line in enumerate(impossible.read_path(PATH)):
        step = walker.step(line)
        if "changes" in step:
            assert walker.changes == [{"id": "swap", "armed": True, "made_frame": k}]
            break
        assert walker.layout.portals == layout.portals
    else:
        pytest.fail("the swap was not made")
    paired = walker.layout
    assert len(paired.portals) < len(layout.portals)  # closed doors are left out
    assert paired.rooms == layout.rooms and paired.source == layout.source
    # With the view options of the seen test (keywords only).
    assert impossible.Walker(layout, fov=30, max_depth=2).changes[0]["made_frame"] is None
    with pytest.raises(TypeError):
        impossible.Walker(layout, (10, 10))


def frame_of(tmp_path, command, k):
    color, ids = tmp_path / "color.png", tmp_path / "ids.png"
    cli(command, LAYOUT, "--path", PATH, "--frame", k, "--size", f"{SIZE[0]}x{SIZE[1]}", "--out", color, "--ids", ids)
    return read_png(color).tobytes(), read_png(ids).tobytes()


def test_paired_at_draws_frame_k_as_render_path_frame(tmp_path):
    layout = impossible.load(LAYOUT)
    lines = impossible.read_path(PATH)
    steps = impossible.walk(layout, lines)
    made = next(step["frame"] for step in steps if "changes" in step)
    assert impossible.paired_at(layout, lines, made - 1).portals == layout.portals
    differs = 0
    # Frame 100: in the study, turned round, the swapped door in view.
    for k in (made - 1, made, 100, len(lines) - 1):
        paired = impossible.paired_at(layout, lines, k)
        walker = impossible.Walker(layout)
        for line in lines[: k + 1]:
            walker.step(line)
        assert paired.portals == walker.layout.portals
        with impossible.Renderer(paired, size=SIZE) as renderer:
            frame = renderer.render(pose=walker.pose, room=walker.room, time=k / 90)
            assert (frame["color"].tobytes(), frame["ids"].tobytes()) == frame_of(tmp_path, "render", k)
            if k == 100:
                traced = renderer.trace(pose=walker.pose, room=walker.room, time=k / 90)
                assert (traced["color"].tobytes(), traced["ids"].tobytes()) == frame_of(tmp_path, "trace", k)
        with impossible.Renderer(layout, size=SIZE) as loaded:
            unchanged = loaded.render(pose=walker.pose, room=walker.room, time=k / 90)
            differs += unchanged["color"].tobytes() != frame["color"].tobytes()
    assert differs >= 1  # frame 100 sees the garden through the swapped door
    with pytest.raises(IndexError):
        impossible.paired_at(layout, lines, len(lines))
    with pytest.raises(ValueError, match="fps"):
        impossible.paired_at(layout, lines, 0, fps=0)
