"""The repository stands alone: no tracked file points outside it, every doc link resolves.

* No tracked file, this one included, names the team's folder outside the
  repository, its paper or its design note: a clone has neither, so a reader
  must find everything under the clone.
* Every relative link in ``README.md`` and ``docs/*.md`` (Markdown links
  ``[text](target)``) names a file or folder that exists in the repository,
  none climbs out of it, and an ``#anchor`` into a Markdown page names one of
  its headings (GitHub's rule: lower case, punctuation dropped, spaces to
  hyphens).
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
# spelled in parts, so that this file passes its own check
_OUTSIDE = "sha" + "red"
_FORBIDDEN = ("../" + _OUTSIDE, _OUTSIDE + "/paper", "des" + "ign.md")
_LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
_EXTERNAL = ("http://", "https://", "mailto:")


def _tracked_files() -> list[Path]:
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout")
    out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True)
    return [ROOT / name for name in out.stdout.decode().split("\0") if name]


def _doc_pages() -> list[Path]:
    return [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]


def test_no_tracked_file_points_outside_the_repository():
    offenders = []
    for path in _tracked_files():
        if not path.is_file():
            continue
        try:
            text = path.read_text(encoding="utf-8").lower()
        except UnicodeDecodeError:
            continue  # binary
        for word in _FORBIDDEN:
            for lineno, line in enumerate(text.splitlines(), 1):
                if word in line:
                    offenders.append(f"{path.relative_to(ROOT)}:{lineno}: {word}")
    assert not offenders, "references outside the repository:\n" + "\n".join(offenders)


def test_docs_exist():
    pages = {p.name for p in _doc_pages()}
    for name in ("index.md", "theory.md", "conventions.md", "methods.md", "validation.md",
                 "workflow.md", "cluster.md", "accuracy.md", "getting-started.md", "examples.md"):
        assert name in pages, f"docs/{name} is missing"
    assert (ROOT / "docs" / "reference" / "api.md").is_file(), "docs/reference/api.md is missing"


def _anchors(page: Path) -> set[str]:
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    heads = re.findall(r"^#{1,6}\s+(.*?)\s*$", text, flags=re.M)
    return {re.sub(r"[^\w\- ]", "", h.lower()).replace(" ", "-") for h in heads}


def test_anchor_rule_matches_github():
    assert re.sub(r"[^\w\- ]", "", "The speed–accuracy trade".lower()).replace(" ", "-") \
        == "the-speedaccuracy-trade"


def _links(page: Path) -> list[str]:
    text = page.read_text(encoding="utf-8")
    text = re.sub(r"```.*?```", "", text, flags=re.S)  # links are not taken from code blocks
    text = re.sub(r"`[^`\n]*`", "", text)
    return _LINK.findall(text)


def test_link_pattern_finds_relative_links():
    fake = "See [the docs](docs/index.md#top), ![img](x.png) and [web](https://example.org)."
    assert _LINK.findall(fake) == ["docs/index.md#top", "https://example.org"]


@pytest.mark.parametrize("page", _doc_pages(), ids=lambda p: str(p.relative_to(ROOT)))
def test_relative_links_resolve(page: Path):
    assert page.is_file(), f"{page.relative_to(ROOT)} is missing"
    broken = []
    for target in _links(page):
        if target.startswith(_EXTERNAL):
            continue
        rel, _, anchor = target.partition("#")
        dest = (page.parent / rel).resolve() if rel else page
        if not dest.is_relative_to(ROOT) or not dest.exists():
            broken.append(target)
        elif anchor and dest.suffix == ".md" and anchor not in _anchors(dest):
            broken.append(target)
    assert not broken, f"{page.relative_to(ROOT)}: broken links {broken}"
