"""``Geometry``: the model built from the public names (kept for compatibility).

``Geometry(name, nu, slab_ratio)`` is a :class:`~contactlib.model.Contact`
(a rigid indenter on an elastic body) that also keeps the three names it was
made from as fields. New code builds the model with
:func:`contactlib.model.contact`; what differs between the sphere and the
cylinder is in :mod:`contactlib.indenter`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .body import ElasticBody
from .indenter import Indenter, indenter
from .model import Contact

__all__ = ["Geometry"]


@dataclass(frozen=True)
class Geometry(Contact):
    """A rigid sphere or cylinder on an elastic body (units E* = a = R = 1).

    Parameters
    ----------
    name : {"sphere", "cylinder"}
    nu : float
        Poisson's ratio.
    slab_ratio : float
        a/h of the slab under the cylinder (0: half-plane).
    """

    indenter: Indenter = field(init=False, repr=False, compare=False)
    body: ElasticBody = field(init=False, repr=False, compare=False)
    name: str
    nu: float
    slab_ratio: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "indenter", indenter(self.name))
        object.__setattr__(self, "body", ElasticBody(self.nu, self.slab_ratio))

    @property
    def thickness(self) -> float:
        """Slab thickness h/a (``inf``: half-plane)."""
        return self.body.thickness
