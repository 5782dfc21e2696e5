"""contactlib: adhesion and partial slip of round bodies pressed normally together.

Rigid sphere on an elastic half-space, rigid cylinder on an elastic slab
(plane strain) with Coulomb friction: the self-similar loading problem with a
central stick zone, verified against exact limits.

The entry points below are loaded on first use, so that a process that needs
only part of the library (a workflow job drawing a figure, say) does not pay
for importing the solvers.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

__all__ = ["__version__", "solve", "sweep", "history", "fretting", "Solution",
           "physical_solve", "physical_history", "contact", "Contact"]

_LAZY = {"solve": "api", "sweep": "api", "history": "history_api",
         "fretting": "fretting_api", "Solution": "result",
         "physical_solve": "physical", "physical_history": "physical",
         "contact": "model", "Contact": "model"}

if TYPE_CHECKING:
    from .api import solve, sweep
    from .fretting_api import fretting
    from .history_api import history
    from .model import Contact, contact
    from .physical import physical_history, physical_solve
    from .result import Solution


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(f".{_LAZY[name]}", __name__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
