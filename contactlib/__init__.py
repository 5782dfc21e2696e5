"""contactlib: adhesion and partial slip of round bodies pressed normally together.

Rigid sphere on an elastic half-space, rigid cylinder on an elastic slab
(plane strain) with Coulomb friction: the self-similar loading problem with a
central stick zone, verified against exact limits.
"""

__version__ = "0.1.0"

from .api import solve, sweep  # noqa: E402
from .history_api import history  # noqa: E402
from .result import Solution  # noqa: E402

__all__ = ["__version__", "solve", "sweep", "history", "Solution"]
