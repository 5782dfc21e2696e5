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
