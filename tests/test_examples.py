"""Every script in examples/ runs, quickly, and prints what its docstring promises.

Each is run as a user would, ``python examples/NAME.py`` from the repository root, in a
fresh process; the test checks the exit status, a key line of the output and the time
(each example is meant to take a few seconds).
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"

# script -> a line fragment its output must contain (a number stated in the docs)
EXPECTED = {
    "steel_ball_on_glass.py": "contact radius a = 188.2 µm",
    "stick_ratio_sweep.py": "0.152483",
    "load_cycle.py": "all steps converged: True",
    "read_dataset.py": "c/a = 0.4: k = 0.210277",
    "friction_curve.py": "wrote friction_curve.png",
}
MAX_SECONDS = 30  # each takes 1-5 s alone; a loaded 2-core machine is slower


def test_every_example_is_listed():
    assert sorted(p.name for p in EXAMPLES.glob("*.py")) == sorted(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_example_runs(name: str, tmp_path: Path):
    start = time.perf_counter()
    out = subprocess.run([sys.executable, str(EXAMPLES / name)], cwd=tmp_path,
                         capture_output=True, text=True, timeout=120)
    elapsed = time.perf_counter() - start
    assert out.returncode == 0, out.stderr[-2000:]
    assert EXPECTED[name] in out.stdout, out.stdout[-2000:]
    assert elapsed < MAX_SECONDS, f"{name} took {elapsed:.1f} s"
    if name == "friction_curve.py":
        assert (tmp_path / "friction_curve.png").stat().st_size > 10_000


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_example_is_linked_from_the_docs(name: str):
    assert f"examples/{name}" in (ROOT / "docs" / "examples.md").read_text(encoding="utf-8")
