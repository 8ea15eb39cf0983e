"""The example of docs/python.md runs, cell after cell, from the repository's
root; the plotting cell (it imports matplotlib) runs where matplotlib is
installed, on the Agg backend."""
import importlib.util
import os
import re

from helpers import SOURCE_DIR

DOC = SOURCE_DIR / "docs" / "python.md"


def cells():
    return re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S)


def test_example_runs(monkeypatch, capsys):
    monkeypatch.chdir(SOURCE_DIR)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    found = cells()
    plotting = [c for c in found if "matplotlib" in c]
    assert len(found) == 6 and len(plotting) == 1
    namespace = {}
    for cell in found:
        if cell in plotting and importlib.util.find_spec("matplotlib") is None:
            continue  # matplotlib is optional; everything before it ran
        exec(compile(cell, str(DOC), "exec"), namespace)
    out = capsys.readouterr().out
    assert "4 rooms, expansion ratio 4.0" in out
    assert "(90, 320, 3) uint8" in out
    steps, passes = namespace["steps"], namespace["passes"]
    assert len(passes) == len(steps) == len(namespace["poses"]) > 100
    assert max(passes) > 0 and min(passes) < max(passes)
    assert namespace["busiest"]["stats"]["portal_passes_drawn"] == max(passes)
    assert sum(len(s["teleports"]) for s in steps) > 0
    assert namespace["masked"]["ids"].shape == (103, 186)
    assert 0.17 < (namespace["masked"]["ids"] == 0).mean() < 0.21  # the Vive's hidden area, 19 % of each eye
    assert "% of the pixels hidden" in out
    assert namespace["lit"].closed and namespace["frame"]["color"].shape == (90, 320, 3)
    assert os.getcwd() == str(SOURCE_DIR)
