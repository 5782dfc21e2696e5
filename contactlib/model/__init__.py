"""The problem model: *what* is pressed into *what*, and how.

One concern a module: ``profiles.py`` (the gap and its frictionless closed forms),
``indenter.py`` (the sphere's rings, the cylinder's strips), ``body.py`` (elastic and
viscoelastic bodies, layers and coatings), ``materials.py`` (named materials),
``theory.py`` (Hertz and the uncoupled closed form), ``load_paths.py`` (load shapes),
``geometry.py`` (a thin ``Contact`` kept for old callers) and ``problem.py`` (the
``Contact``: the two bodies, the profile and the interface, validated once).

``Contact``, ``contact`` and ``accepts_model`` are re-exported here and loaded on first
use, so that importing ``contactlib.model.profiles`` alone does not load the kernels.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__all__ = ["Contact", "contact", "accepts_model"]

if TYPE_CHECKING:
    from .problem import Contact, accepts_model, contact


def __getattr__(name: str) -> Any:
    if name in __all__:
        value = getattr(importlib.import_module(".problem", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
