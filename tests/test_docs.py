"""The front page and the documentation pages are for users, and the site builds.

* README.md is a front page: at most about 120 lines (130 allowed), with the two
  Quickstart commands that CI runs verbatim.
* README.md and every page under docs/ state results, not history: no commit hash, no
  load average, no dated diary entry (history goes to CHANGELOG.md).
* Every page under docs/ is in the site's navigation (mkdocs.yml), and the site builds
  with warnings as errors where mkdocs is installed (``pip install -e '.[docs]'``;
  ``.ci/run`` builds it in a separate step).
"""

from __future__ import annotations

import importlib.util
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
README = ROOT / "README.md"
QUICKSTART = ("python -m pip install -e . && snakemake --cores 2",
              "python -m pip install -e '.[test]' && python -m pytest -q")

# a 7-40 digit hex word with at least one letter and one digit: a commit hash
_HASH = re.compile(r"(?<![\w.])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}(?![\w.])")
_DIARY = re.compile(r"load average|\b20\d\d-\d\d-\d\d\b|\bsession\b|tried and (?:reverted|dropped)"
                    r"|\bin /tmp\b", re.I)


def _pages() -> list[Path]:
    return [README, *sorted((ROOT / "docs").rglob("*.md"))]


def test_readme_is_a_front_page():
    lines = README.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 130, f"README.md has {len(lines)} lines"
    for command in QUICKSTART:
        assert command in lines, f"the Quickstart command {command!r} is not in README.md"


def test_hash_pattern():
    assert _HASH.findall("see 7e7dca5 and 26183a0f, not 1234567, 2.3e-10 or deadbeefs")\
        == ["7e7dca5", "26183a0f"]


@pytest.mark.parametrize("page", _pages(), ids=lambda p: str(p.relative_to(ROOT)))
def test_page_states_results_not_history(page: Path):
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    found = []
    for lineno, line in enumerate(text.splitlines(), 1):
        found += [f"{lineno}: commit hash {h}" for h in _HASH.findall(line)]
        found += [f"{lineno}: {m.group()!r}" for m in _DIARY.finditer(line)]
    assert not found, f"{page.relative_to(ROOT)} (history belongs in CHANGELOG.md):\n" \
        + "\n".join(found)


def test_every_page_is_in_the_navigation():
    config = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    nav = set(re.findall(r":\s*([\w/.-]+\.md)\s*$", config, flags=re.M))
    pages = {p.relative_to(ROOT / "docs").as_posix() for p in (ROOT / "docs").rglob("*.md")}
    assert pages - nav == set(), f"pages missing from the nav of mkdocs.yml: {pages - nav}"
    assert nav - pages == set(), f"nav entries without a page: {nav - pages}"


@pytest.mark.skipif(importlib.util.find_spec("mkdocs") is None
                    or importlib.util.find_spec("mkdocstrings") is None,
                    reason="the docs extra is not installed (pip install -e '.[docs]')")
def test_site_builds_strictly(tmp_path: Path):
    mkdocs = shutil.which("mkdocs")
    cmd = [mkdocs] if mkdocs else [sys.executable, "-m", "mkdocs"]
    out = subprocess.run([*cmd, "build", "--strict", "--site-dir", str(tmp_path / "site")],
                         cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-3000:]


def test_site_hooks():
    """mkdocs_hooks.py: Sphinx roles, reST tables and the stars of E* in docstrings."""
    import doctest

    spec = importlib.util.spec_from_file_location("mkdocs_hooks", ROOT / "mkdocs_hooks.py")
    hooks = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(hooks)
    assert doctest.testmod(hooks).failed == 0
    html = ('<p>see :func:<code>~contactlib.api.solve</code></p>\n'
            '<p>==  ==\na   b\n==  ==</p>')
    assert hooks.on_page_content(html) == ('<p>see <code>solve</code></p>\n'
                                           '<pre class="rst-table"><code>==  ==\na   b\n==  ==</code></pre>')
