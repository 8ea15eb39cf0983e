"""Walker and walk with the hands of 18-number path lines: their rooms as
`impossible walk` prints them, and their virtual poses, so that frame k of a
walk is drawn with its hands as `render`/`trace --path FILE --frame k` draw it."""
import json

import pytest

import impossible
from helpers import SOURCE_DIR, cli
from png_reader import read_png

LAYOUT = SOURCE_DIR / "layouts" / "hands_door.json"
PATH = SOURCE_DIR / "layouts" / "hands_walk.txt"
SIZE = (96, 54)


def test_walk_with_hands_equals_cli():
    out, _ = cli("walk", LAYOUT, "--path", PATH)
    expected = [json.loads(line) for line in out.splitlines()]
    lines = impossible.read_path(PATH, hands=True)
    assert len(lines) == len(expected) > 100
    assert all(len(line) == 18 for line in lines)
    assert [line[:6] for line in lines] == impossible.read_path(PATH)
    assert impossible.walk(impossible.load(LAYOUT), lines) == expected
    assert len({step["hands"][0] for step in expected}) == 2  # the hands reach through the door


def frame_of(tmp_path, command, k):
    color, ids = tmp_path / "color.png", tmp_path / "ids.png"
    cli(command, LAYOUT, "--path", PATH, "--frame", k, "--size", f"{SIZE[0]}x{SIZE[1]}", "--out", color, "--ids", ids)
    return read_png(color).tobytes(), read_png(ids).tobytes()


def test_walker_hands_draw_the_walked_frame(tmp_path):
    layout = impossible.load(LAYOUT)
    lines = impossible.read_path(PATH, hands=True)
    walker = impossible.Walker(layout)
    flat = impossible.Walker(layout)  # the same lines given as 18 numbers
    assert walker.hands is None and walker.hand_rooms is None
    renderer = impossible.Renderer(layout, size=SIZE)
    drawn = 0
    for k, line in enumerate(lines):
        step = walker.step(line[:6], hands=(line[6:12], line[12:]))
        assert flat.step(line) == step
        assert list(walker.hand_rooms) == step["hands"]
        assert flat.hands == walker.hands and len(walker.hands) == 2
        if k % 90 != 45:
            continue
        frame = renderer.render(pose=walker.pose, room=walker.room, hands=walker.hands, time=k / 90)
        assert (frame["color"].tobytes(), frame["ids"].tobytes()) == frame_of(tmp_path, "render", k)
        without = renderer.render(pose=walker.pose, room=walker.room, time=k / 90)
        assert without["color"].tobytes() != frame["color"].tobytes()  # the hands are in view
        if drawn == 0:
            traced = renderer.trace(pose=walker.pose, room=walker.room, hands=walker.hands, time=k / 90)
            assert (traced["color"].tobytes(), traced["ids"].tobytes()) == frame_of(tmp_path, "trace", k)
        drawn += 1
    assert drawn >= 2
    walker.step(lines[0][:6])
    assert walker.hands is None and walker.hand_rooms is None


def test_walker_hands_arguments():
    layout = impossible.builtin()
    walker = impossible.Walker(layout)
    start = layout.start
    with pytest.raises(ValueError, match="given twice"):
        walker.step(start * 3, hands=(start, start))
    with pytest.raises(ValueError, match="within ±1000000"):
        walker.step(start, hands=(start, (0, 1.6, 2e6, 0, 0, 0)))
    with pytest.raises(ValueError, match="two poses"):
        walker.step(start, hands=(start,))
    with pytest.raises(ValueError, match=r"expected 6 numbers .* or 18 .*, got 12"):
        impossible.walk(layout, [start * 2])


@pytest.mark.parametrize("fps", [90, 7.5])
def test_walk_gives_the_moving_props_rooms_as_cli(tmp_path, fps):
    layout_path = SOURCE_DIR / "layouts" / "sliding_box.json"
    path = tmp_path / "still.txt"
    # Standing still at the start for 7 s: the crate goes through the door and back.
    path.write_text("".join("-1.6 1.6 1.4 -50 0 0\n" for _ in range(int(7 * fps))))
    out, _ = cli("walk", layout_path, "--path", path, "--fps", fps)
    expected = [json.loads(line) for line in out.splitlines()]
    got = impossible.walk(impossible.load(layout_path), impossible.read_path(path), fps=fps)
    assert got == expected
    assert {step["props"]["crate"] for step in got} == {"hall", "yard"}
