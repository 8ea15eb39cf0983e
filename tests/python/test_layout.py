"""impossible.load, parse and builtin; Layout.validate against `validate --json`;
bad input raises impossible.Error with the CLI's FILE:LINE:COLUMN lines."""
import json
import re
import pathlib

import pytest

import impossible
from helpers import LAYOUTS, SOURCE_DIR, cli


@pytest.mark.parametrize("path", LAYOUTS, ids=lambda p: p.stem)
def test_validate_equals_cli(path):
    out, _ = cli("validate", path, "--json")
    layout = impossible.load(path)
    assert layout.validate() == json.loads(out)
    text, _ = cli("validate", path)
    assert layout.report() == text


def test_properties():
    layout = impossible.load(pathlib.Path(SOURCE_DIR / "layouts" / "corridor.json"))  # a PathLike
    report = layout.validate()
    assert layout.source.endswith("corridor.json")
    assert layout.rooms == [room["id"] for room in report["rooms"]]
    assert layout.start_room == report["start_room"]
    assert len(layout.start) == 6 and layout.portals
    builtin = impossible.builtin()
    assert builtin.validate()["valid"] and builtin.rooms == impossible.load(SOURCE_DIR / "layouts" / "default.json").rooms


def test_bad_layout_raises_with_its_lines(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"version": 1,\n "rooms": [ {"id": "a"} ]\n}\n')
    _, err = cli("validate", bad, check=False)
    lines = err.strip().splitlines()
    assert lines[0] == f"{bad}:1:1: missing required field \"format\""
    with pytest.raises(impossible.Error) as raised:
        impossible.load(bad)
    assert str(raised.value).splitlines() == lines
    assert isinstance(raised.value, ValueError)
    with pytest.raises(impossible.Error, match=r"(?m)^bad\.json:2:13: rooms\[0\]: missing required field \"min\"$"):
        impossible.parse(bad.read_text(), name="bad.json").validate()


def test_unreadable_inputs_raise(tmp_path):
    with pytest.raises(impossible.Error, match="missing.json: the file does not exist"):
        impossible.load(tmp_path / "missing.json")
    with pytest.raises(impossible.Error, match=r"^x\.json:1:6: invalid JSON"):
        impossible.parse("[1, 2", name="x.json")
    with pytest.raises(TypeError):
        impossible.load(42)


def test_parse_resolves_relative_files():
    path = SOURCE_DIR / "layouts" / "gallery.json"
    layout = impossible.parse(path.read_text(), name=str(path), base_dir=str(path.parent))
    assert layout.validate() == impossible.load(path).validate()


def test_version_is_the_projects():
    text = (SOURCE_DIR / "CMakeLists.txt").read_text()
    assert re.search(r"project\(impossible VERSION ([0-9.]+)", text).group(1) == impossible.__version__
