#!/usr/bin/env python3
"""Checks that no module under src/ includes a module above it.

The modules, bottom first, are listed in LAYERS (the README's "How it works"
table describes each). A file in src/M may include headers of M itself and of
the modules before M in the list (the public headers, "impossible/...", count
as the api module's); anything else is reported, with the file and
line, and the exit status is 1. Run by ctest as `layers`.

Usage: tools/check_layers.py [SRC_DIR]
"""
import pathlib
import re
import sys

LAYERS = [
    "base", "math", "image", "assets", "layout", "shading", "links", "lights", "walk", "changes",
    "scene", "gl", "render", "trace", "design", "session", "api", "cli", "preview", "bench", "app", "web",
]

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')


def main() -> int:
    src = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent / "src")
    rank = {name: i for i, name in enumerate(LAYERS)}
    problems = []
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    for folder in folders:
        if folder not in rank:
            problems.append(f"src/{folder}: a module missing from LAYERS in tools/check_layers.py")
    for path in sorted(src.rglob("*.[ch]pp")):
        module = path.relative_to(src).parts[0]
        if module not in rank:
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m or m.group(1) == module:
                continue
            used = m.group(1)
            # The public headers (include/impossible/) are the api module's.
            if used == "impossible":
                used = "api"
            if used == module:
                continue
            if used not in rank:
                problems.append(f"{path.relative_to(src.parent)}:{number}: includes {used}/, which is no module")
            elif rank[used] > rank[module]:
                problems.append(f"{path.relative_to(src.parent)}:{number}: {module} includes {used}/, a module above it")
    for p in problems:
        print(p)
    print(f"layers: {len(LAYERS)} modules, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
