"""Tuned constants live beside the measurement that fixed them (issue 36).

Every module-level constant of ``contactlib/`` whose value is a numeric literal (or
arithmetic on numeric literals, like ``1 << 17`` or ``2.0**-53``), or a tuple, list, set or
dict of them, is named UPPER_CASE (an optional leading underscore) and carries, in the
contiguous comment lines directly above it or in a trailing comment on its first line,
exactly one tag (the convention of docs/architecture.md):

* ``# measured: benchmarks/<file>.py ...``: a tuned trade of speed against accuracy, which
  that script re-measures;
* ``# tested: tests/<file>.py ...``: a tolerance or threshold whose effect that test checks;
* ``# exact: ...``: a mathematical or physical value, or one derived from others;
* ``# convention: ...``: a unit, default or interface choice, not tuned;
* ``# limit: ...``: a validated input range, naming where it was measured (a benchmark, a
  test or a CHANGELOG entry).

Read from the source (``ast`` for the constants, ``tokenize`` for the comments).
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from pathlib import Path

import pytest

import contactlib

PACKAGE = Path(contactlib.__file__).resolve().parent
ROOT = PACKAGE.parent
TAGS = ("measured", "tested", "exact", "convention", "limit")
_TAG = re.compile(r"#\s*(" + "|".join(TAGS) + r"):(.*)")
_NAME = re.compile(r"_?[A-Z][A-Z0-9_]*")
_PATH = re.compile(r"\b((?:benchmarks|tests)/[\w./-]*?\.py)\b")
# modules whose owners are tagging them; the set only shrinks (stresses.py, stress_study.py
# and stresses_grid.py are done; stresses_tangential.py has no numeric constant)
PENDING: set[str] = set()  # every module is tagged
MODULES = sorted(p.relative_to(ROOT).as_posix() for p in PACKAGE.rglob("*.py"))


def _numeric(node: ast.AST) -> bool:
    """A numeric literal, or arithmetic on numeric literals (no names, no calls)."""
    if isinstance(node, ast.Constant):
        return isinstance(node.value, (int, float, complex)) and not isinstance(node.value, bool)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
        return _numeric(node.operand)
    if isinstance(node, ast.BinOp):
        return _numeric(node.left) and _numeric(node.right)
    return False


def _numeric_value(node: ast.AST) -> bool:
    """A numeric literal, or a (nested) tuple, list, set or dict of numeric literals."""
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return bool(node.elts) and all(_numeric_value(e) for e in node.elts)
    if isinstance(node, ast.Dict):
        return bool(node.values) and all(_numeric_value(v) for v in node.values)
    return _numeric(node)


def _statements(body: list[ast.stmt]):
    """Module-level statements, those inside module-level if/try/with blocks included."""
    for node in body:
        yield node
        if isinstance(node, (ast.If, ast.With)):
            yield from _statements(node.body)
            yield from _statements(getattr(node, "orelse", []))
        elif isinstance(node, ast.Try):
            for block in (node.body, node.orelse, node.finalbody):
                yield from _statements(block)
            for handler in node.handlers:
                yield from _statements(handler.body)


def constants(source: str) -> list[tuple[str, int]]:
    """(name, line) of every module-level numeric constant of ``source``."""
    found = []
    for node in _statements(ast.parse(source).body):
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target, value = node.targets[0], node.value
        elif isinstance(node, ast.AnnAssign) and node.value is not None:
            target, value = node.target, node.value
        else:
            continue
        if (isinstance(target, ast.Name) and _NAME.fullmatch(target.id)
                and _numeric_value(value)):
            found.append((target.id, node.lineno))
    return found


def _comments(source: str) -> tuple[dict[int, str], set[int]]:
    """Comments by line, and the lines that hold nothing but a comment."""
    comments, alone = {}, set()
    code_lines = set()
    for tok in tokenize.generate_tokens(io.StringIO(source).readline):
        if tok.type == tokenize.COMMENT:
            comments[tok.start[0]] = tok.string
        elif tok.type not in (tokenize.NL, tokenize.NEWLINE, tokenize.INDENT,
                              tokenize.DEDENT, tokenize.ENCODING, tokenize.ENDMARKER):
            for line in range(tok.start[0], tok.end[0] + 1):
                code_lines.add(line)
    alone = {line for line in comments if line not in code_lines}
    return comments, alone


def problems(path: str, source: str | None = None) -> list[str]:
    """'file:line NAME: what is wrong' for every constant whose tag is missing or bad."""
    if source is None:
        source = (ROOT / path).read_text(encoding="utf-8")
    comments, alone = _comments(source)
    found = []
    for name, line in constants(source):
        block = []  # the contiguous comment lines directly above, top first
        above = line - 1
        while above in alone:
            block.insert(0, comments[above])
            above -= 1
        if line in comments:
            block.append(comments[line])
        tags = [(i, m) for i, c in enumerate(block) if (m := _TAG.match(c.strip()))]
        where = f"{path}:{line} {name}"
        if not tags:
            found.append(f"{where}: no tag ({', '.join(t + ':' for t in TAGS)}) "
                         f"in the comment lines directly above or at the end of its line")
            continue
        if len(tags) > 1:
            found.append(f"{where}: {len(tags)} tags, exactly one expected")
            continue
        i, match = tags[0]
        tag, text = match.group(1), match.group(2).strip()
        # the tag's text goes on in the comment lines below it (not a trailing comment)
        more = [c.lstrip("#").strip() for c in block[i + 1:len(block) - (line in comments)]]
        full = " ".join([text, *more])
        if not text:
            found.append(f"{where}: '{tag}:' says nothing")
        elif tag == "measured" and not text.startswith("benchmarks/"):
            found.append(f"{where}: 'measured:' must name benchmarks/<file>.py first")
        elif tag == "tested" and not text.startswith("tests/"):
            found.append(f"{where}: 'tested:' must name tests/<file>.py first")
        elif tag == "limit" and not (_PATH.search(full) or "CHANGELOG" in full):
            found.append(f"{where}: 'limit:' must say where the range was measured "
                         f"(benchmarks/..., tests/... or CHANGELOG)")
        for ref in _PATH.findall(full):
            if not (ROOT / ref).is_file():
                found.append(f"{where}: '{tag}:' names {ref}, which does not exist")
    return found


def test_the_scanner_finds_constants_and_reads_tags():
    source = ("import numpy as np\n"
              "A = 1  # convention: a trailing tag\n"
              "# an explanation\n"
              "# exact: the tag may follow it\n"
              "_B: float = 2.0**-53\n"
              "C = (0.5, (1, 2))\n"
              "\n"
              "# measured: benchmarks/no_such_file.py\n"
              "D = {'x': 1.0}\n"
              "# tested: tests/test_constants.py\n"
              "E = -3\n"
              "F = ('a', 1)\n"
              "G = 4.0 / np.pi\n"
              "H = True\n"
              "lower = 1\n"
              "# limit: nowhere\n"
              "I = 5\n"
              "def f():\n"
              "    J = 1\n")
    assert [n for n, _ in constants(source)] == ["A", "_B", "C", "D", "E", "I"]
    found = problems("x.py", source)
    assert len(found) == 3, found
    assert found[0].startswith("x.py:6 C: no tag")
    assert found[1].startswith("x.py:9 D:") and "no_such_file.py" in found[1]
    assert found[2].startswith("x.py:17 I:") and "limit:" in found[2]


@pytest.mark.parametrize("path", [m for m in MODULES if m not in PENDING])
def test_numeric_constants_name_their_measurement(path):
    found = problems(path)
    assert not found, "\n".join(found)


@pytest.mark.parametrize("path", sorted(PENDING))
def test_pending_modules_are_not_yet_annotated(path):
    if not (ROOT / path).is_file():
        pytest.skip(f"{path} is not written yet")
    if not constants((ROOT / path).read_text(encoding="utf-8")):
        pytest.skip(f"{path} has no numeric constants (yet)")
    # fails once an owner has tagged every constant: then take the module out of PENDING
    assert problems(path), (f"{path} is fully annotated: remove it from PENDING in "
                            f"tests/test_constants.py")
