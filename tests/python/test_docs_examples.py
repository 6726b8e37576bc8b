"""The example scripts of docs/python.md run (with short durations), and the
page shows them as they are in docs/examples/."""
import os
import subprocess
import sys

import pytest

import spiral
from conftest import DEEPWATER, SOURCE_DIR

EXAMPLES = SOURCE_DIR / "docs" / "examples"


@pytest.mark.parametrize("script", ["quickstart.py", "pretension_sweep.py"])
def test_the_page_shows_the_script(script):
    page = (SOURCE_DIR / "docs" / "python.md").read_text()
    assert (EXAMPLES / script).read_text().strip() in page


def run_example(script, *args, cwd):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], cwd=cwd, env=os.environ.copy(),
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_quickstart_runs(tmp_path):
    out = run_example("quickstart.py", DEEPWATER, 1200, cwd=tmp_path)  # the MPM fits want 20 min
    assert "tightest zone" in out and "optimization:" in out
    variant = spiral.load(tmp_path / "variant.yaml")
    assert variant.lines["L3"].segments[1].length == spiral.load(DEEPWATER).lines["L3"].segments[1].length + 2.0


def test_pretension_sweep_runs(tmp_path):
    out = run_example("pretension_sweep.py", DEEPWATER, "lc1-survival-collinear-0deg", 3, "sweep.png", cwd=tmp_path)
    assert len(out.splitlines()) == 3
    assert (tmp_path / "sweep.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
