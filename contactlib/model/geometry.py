"""``Geometry``: the model built from the public names (kept for compatibility).

``Geometry(name, nu, slab_ratio)`` is a :class:`~contactlib.model.Contact`
(a rigid indenter on an elastic body) that also keeps the three names it was
made from as fields. New code builds the model with
:func:`contactlib.model.contact`; what differs between the sphere and the
cylinder is in :mod:`contactlib.model.indenter`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .body import ElasticBody
from .indenter import Indenter, indenter
from . import Contact

__all__ = ["Geometry"]


@dataclass(frozen=True)
class Geometry(Contact):
    """A sphere or cylinder on an elastic body (units E* = a = R = 1, E* composite).

    Parameters
    ----------
    name : {"sphere", "cylinder"}
    nu : float
        Poisson's ratio of the body.
    slab_ratio : float
        a/h of the slab under the cylinder (0: half-plane).
    indenter_modulus : float
        E1/E2 of the indenter over the body (``inf``: rigid, the default).
    indenter_nu : float, optional
        Poisson's ratio of the indenter (None: the body's).
    base : {"smooth", "bonded", "elastic"}
        The layer's base (default smooth; irrelevant at slab_ratio 0).
    substrate_modulus, substrate_nu : float
        E2/E1 and Poisson's ratio of the elastic substrate (``base="elastic"``;
        see :class:`~contactlib.model.body.ElasticBody`).
    """

    indenter: Indenter = field(init=False, repr=False, compare=False)
    body: ElasticBody = field(init=False, repr=False, compare=False)
    name: str
    nu: float
    slab_ratio: float = 0.0
    indenter_modulus: float = math.inf
    indenter_nu: float | None = None
    base: str = "smooth"
    substrate_modulus: float = math.inf
    substrate_nu: float | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "indenter",
                           indenter(self.name, self.indenter_modulus, self.indenter_nu))
        object.__setattr__(self, "body", ElasticBody(self.nu, self.slab_ratio, self.base,
                                                   self.substrate_modulus, self.substrate_nu))

    @property
    def thickness(self) -> float:
        """Layer thickness h/a (``inf``: half-space or half-plane)."""
        return self.body.thickness
