"""mkdocs hooks of the documentation site (mkdocs.yml, ``hooks:``).

The docstrings are numpydoc, written for Sphinx as well as for ``help()``:

* cross-references use Sphinx roles (``:func:`contactlib.solve```), which Markdown
  renders as the literal role name before the code span: the role is dropped and, as
  Sphinx does, ``~package.module.name`` shortened to ``name``;
* a few module docstrings hold reStructuredText simple tables (rows between lines of
  ``=====  =====``), which Markdown runs together into one paragraph: such a paragraph
  is shown preformatted, as ``help()`` shows it.
"""

from __future__ import annotations

import re
from typing import Any

_ROLE = re.compile(r":(?:py:)?(?:func|class|meth|mod|attr|data|obj|exc|const):(?=<code>)")
_TILDE = re.compile(r"<code>~(?:[\w]+\.)*([\w]+)</code>")
_RST_TABLE = re.compile(r"<p>(=+(?:  +=+)+\n.*?\n=+(?:  +=+)+)</p>", re.S)


def on_page_content(html: str, **kwargs: Any) -> str:
    html = _RST_TABLE.sub(r'<pre class="rst-table"><code>\1</code></pre>', html)
    return _TILDE.sub(r"<code>\1</code>", _ROLE.sub("", html))


# --- griffe extension (mkdocs.yml: handlers.python.options.extensions) ----------------------

_STAR = re.compile(r"(?<=[\w)\]])(?<!\\)\*(?![A-Za-z0-9*])")
# *emphasis*, as reST and Markdown both write it: a star before a word, one after it
_EMPHASIS = re.compile(r"(?<![\w*\\])\*(?=[^\s*])[^*\n]*?(?<=[^\s*\\])\*(?![\w*])")


def _escape_outside_emphasis(text: str) -> str:
    pieces, end = [], 0
    for match in _EMPHASIS.finditer(text):
        pieces += [_STAR.sub(r"\\*", text[end:match.start()]), match.group()]
        end = match.end()
    return "".join([*pieces, _STAR.sub(r"\\*", text[end:])])


def escape_stars(text: str) -> str:
    """Escape the stars of names such as E* and c* in a docstring, outside code.

    Markdown reads ``E* ... E*`` as emphasis and drops both stars. A star right after a
    letter, digit or bracket and not before a letter or digit is escaped, except in
    *emphasis*, code spans, doctest blocks, reST literal blocks (``::``) and indented
    blocks after a blank line, where Markdown shows text as it is.

    >>> escape_stars("1/E* = (1 - nu^2)/E1, scaled by E* a^5; `E*` and **kw")
    '1/E\\\\* = (1 - nu^2)/E1, scaled by E\\\\* a^5; `E*` and **kw'
    >>> escape_stars("the *measured* error at c*, E*_i")
    'the *measured* error at c\\\\*, E\\\\*_i'
    >>> escape_stars("a span ``x = E*\\ny / E*`` ends; E*\\n\\n    1/E* = code")
    'a span ``x = E*\\ny / E*`` ends; E\\\\*\\n\\n    1/E* = code'
    """
    out: list[str] = []
    doctest = block = literal = code = False
    previous_blank = True
    for line in text.split("\n"):
        stripped = line.strip()
        indented = line.startswith("    ")
        if stripped.startswith(">>>"):
            doctest = True
        elif not stripped:
            doctest = False
        if indented and previous_blank and not code:
            block = True  # an indented code block starts after a blank line
        elif stripped and not indented:
            block = False
        if literal and stripped and not line.startswith(" "):
            literal = False
        if (doctest or block or literal) and stripped:
            out.append(line)
        else:
            parts = re.split(r"(`+)", line)
            for index, part in enumerate(parts):
                if part.startswith("`"):
                    code = not code
                elif not code:
                    parts[index] = _escape_outside_emphasis(part)
            out.append("".join(parts))
        if stripped.endswith("::"):
            literal = True
        previous_blank = not stripped
    return "\n".join(out)


try:
    import griffe
except ImportError:  # the hooks above do not need it
    griffe = None

if griffe is not None:
    class EscapeStars(griffe.Extension):
        """Apply :func:`escape_stars` to every docstring griffe loads."""

        def on_object(self, *, obj: Any, **kwargs: Any) -> None:
            if obj.docstring is not None:
                obj.docstring.value = escape_stars(obj.docstring.value)
