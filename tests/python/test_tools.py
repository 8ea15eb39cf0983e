"""walk, Walker, read_path, tour, plan and generate against their commands."""
import json
import math

import pytest

import impossible
from helpers import SOURCE_DIR, cli

LAYOUT = SOURCE_DIR / "layouts" / "four_rooms.json"


@pytest.fixture(scope="module")
def toured(tmp_path_factory):
    """`impossible tour` of a layout: the path file and the layout."""
    path = tmp_path_factory.mktemp("tour") / "tour.txt"
    cli("tour", LAYOUT, "--out", path, "--step", "0.1")
    return path, impossible.load(LAYOUT)


def test_tour_equals_cli(toured):
    path, layout = toured
    lines = [l.split() for l in path.read_text().splitlines() if l and not l.startswith("#")]
    poses = impossible.tour(layout, step=0.1)
    assert len(poses) == len(lines) > 10
    shown = [[("%.4f" % v).replace("-0.0000", "0.0000") for v in pose] for pose in poses]
    assert shown == lines
    assert impossible.read_path(path) == [tuple(float(v) for v in line) for line in lines]


def test_walk_equals_cli(toured):
    path, layout = toured
    out, _ = cli("walk", LAYOUT, "--path", path)
    expected = [json.loads(line) for line in out.splitlines()]
    steps = impossible.walk(layout, impossible.read_path(path), fps=90)
    assert steps == expected
    # -0 is written 0 by `walk`: the same text once dumped.
    assert "-0.0," not in json.dumps(steps) and "-0.0]" not in json.dumps(steps)
    assert any(step["teleports"] for step in steps)
    assert [list(step) for step in steps[:1]] == [["frame", "room", "teleports", "position", "forward"]]
    walker = impossible.Walker(layout)
    assert walker.room == layout.start_room and walker.pose == layout.start
    assert [walker.step(pose) for pose in impossible.read_path(path)] == expected
    assert walker.room == expected[-1]["room"]


def test_walker_pose_renders_the_walked_frame(toured):
    """Walker.pose is the virtual head: its position and view direction are
    those `walk` prints."""
    path, layout = toured
    walker = impossible.Walker(layout)
    for pose in impossible.read_path(path)[:40]:
        step = walker.step(pose)
        assert walker.pose[:3] == pytest.approx(step["position"], abs=1e-9)


def test_walk_arguments():
    layout = impossible.builtin()
    with pytest.raises(ValueError, match="fps must be a finite number above 0"):
        impossible.walk(layout, [layout.start], fps=0)
    with pytest.raises(ValueError, match="within ±1000000"):
        impossible.walk(layout, [(0, 1.6, 2e6, 0, 0, 0)])
    with pytest.raises(TypeError, match="a list of poses"):
        impossible.walk(layout, "0 1.6 0 0 0 0")
    assert impossible.walk(layout, []) == []


def test_plan_equals_cli(tmp_path, toured):
    path, layout = toured
    svg = tmp_path / "plan.svg"
    cli("plan", LAYOUT, "--out", svg)
    assert impossible.plan(layout) == svg.read_text()
    cli("plan", LAYOUT, "--out", svg, "--path", path)
    assert impossible.plan(layout, path=impossible.read_path(path)) == svg.read_text()


@pytest.mark.parametrize(
    "options, kwargs",
    [
        (["--play-area", "6x4", "--rooms", "5", "--seed", "7"], dict(play_area=(6, 4), rooms=5, seed=7)),
        (
            ["--play-area", "5x5", "--rooms", "3", "--seed", "2", "--max-overlap", "20"],
            dict(play_area=(5, 5), rooms=3, seed=2, max_overlap=20),
        ),
        (["--play-area-file", "L", "--rooms", "4", "--seed", "11"], dict(play_area="L", rooms=4, seed=11)),
    ],
)
def test_generate_equals_cli(tmp_path, options, kwargs):
    polygon = [[0, 0], [6, 0], [6, 3], [3, 3], [3, 6], [0, 6]]
    (tmp_path / "l.json").write_text(json.dumps(polygon))
    options = [str(tmp_path / "l.json") if o == "L" else o for o in options]
    if kwargs["play_area"] == "L":
        kwargs["play_area"] = polygon
    out, _ = cli("generate", *options)
    text = impossible.generate(**kwargs)
    assert text == out
    assert impossible.parse(text).validate()["valid"]


def test_bad_tool_arguments(tmp_path):
    layout = impossible.builtin()
    with pytest.raises(impossible.Error, match="each side of the play area must be 1..1000 m"):
        impossible.generate((0.5, 4), rooms=2, seed=1)
    with pytest.raises(impossible.Error, match="simple polygon"):
        impossible.generate([(0, 0), (4, 4), (4, 0), (0, 4)], rooms=2, seed=1)
    with pytest.raises(ValueError, match="seed must be 0..2000000000"):
        impossible.generate((4, 4), rooms=2, seed=-1)
    with pytest.raises(impossible.Error, match="step must be in 0.005..1 m"):
        impossible.tour(layout, step=2)
    (tmp_path / "empty.txt").write_text("# no poses\n")
    with pytest.raises(impossible.Error, match="empty.txt: the path file holds no poses"):
        impossible.read_path(tmp_path / "empty.txt")
    with pytest.raises(impossible.Error, match=r"README\.md:3: expected 6 or 18 numbers"):
        impossible.read_path(SOURCE_DIR / "README.md")


def test_generate_refuses_play_areas_the_loader_would_refuse():
    """A corner that is no coordinate (NaN, 200 km out) is named; a layout
    generate writes always loads."""
    with pytest.raises(impossible.Error, match=r"corner 2 \(nan, 4\) is not a coordinate within \+-100000 m"):
        impossible.generate([(0, 0), (6, 0), (float("nan"), 4), (0, 4)], 2, 1)
    with pytest.raises(impossible.Error, match=r"corner 2 \(200000, 4\)"):
        impossible.generate([(0, 0), (6, 0), (200000, 4), (0, 4)], 2, 1)
    text = impossible.generate((4, 4), 3, 5)
    assert impossible.parse(text).rooms


def test_generate_fits_rooms_in_the_core_of_a_star():
    """A 10,000-corner star of 500 m spikes around a core 4 m across: its core
    holds two rooms, as `generate` now finds (it said no room fits); a third
    is refused naming the widest spot (issue 36)."""
    radii = [500 if k % 2 == 0 else 2 for k in range(10_000)]
    star = [(r * math.cos(2 * math.pi * k / 10_000), r * math.sin(2 * math.pi * k / 10_000)) for k, r in enumerate(radii)]
    layout = impossible.parse(impossible.generate(star, rooms=2, seed=1))
    report = layout.validate()
    assert report["valid"] and len(layout.rooms) == 2
    with pytest.raises(impossible.Error, match=r"could not fit 3 rooms .*\(its widest spot is a circle 4 m across at "
                                               r"\(0, 0\); try fewer rooms"):
        impossible.generate(star, rooms=3, seed=1)
