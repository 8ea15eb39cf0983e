"""What the Python module's tests share. CTest runs them (python/CMakeLists.txt)
with PYTHONPATH set to the module's folder, IMPOSSIBLE_BINARY to the CLI and
IMPOSSIBLE_SOURCE_DIR to the repository."""
import os
import pathlib
import subprocess

SOURCE_DIR = pathlib.Path(os.environ.get("IMPOSSIBLE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("IMPOSSIBLE_BINARY", str(SOURCE_DIR / "build" / "impossible"))
LAYOUTS = sorted((SOURCE_DIR / "layouts").glob("*.json"))


def cli(*args, cwd=None, check=True):
    """Runs the CLI; returns (stdout, stderr) as text."""
    done = subprocess.run([BINARY, *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=120)
    if check and done.returncode != 0:
        raise AssertionError(f"impossible {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr}")
    return done.stdout, done.stderr
