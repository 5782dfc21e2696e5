"""Named engineering materials for elastic indenters (``contactlib/data/materials.yaml``).

The table lists Young's modulus E (GPa) and Poisson's ratio nu of common
materials, each with its source. A computation needs only the pair: the
modulus ratio E1/E2 of the indenter over the body and the two Poisson
ratios (:func:`pair`); the composite modulus and Dundurs' beta follow
(:class:`contactlib.model.Contact`).

The table is package data (``contactlib/data/materials.yaml``, read with
:mod:`importlib.resources`, so it travels with an installed wheel); the
repository's ``config/materials.yaml`` is a link to it.

Examples
--------
>>> from contactlib.model.materials import pair
>>> ratio, nu1, nu2 = pair("steel", "aluminium")
>>> round(ratio, 4), nu1, nu2
(3.0, 0.3, 0.33)
"""

from __future__ import annotations

from functools import lru_cache
from importlib import resources
from typing import Any

from .. import validate

__all__ = ["MATERIALS_FILE", "materials", "pair", "scene_indenter"]

MATERIALS_FILE = resources.files("contactlib") / "data" / "materials.yaml"
"""The table of materials: package data (an :mod:`importlib.resources` traversable)."""


@lru_cache(maxsize=None)
def materials() -> dict[str, dict[str, Any]]:
    """Name -> {"E": GPa, "nu": float, "source": [...], ...} from :data:`MATERIALS_FILE`."""
    import yaml  # the workflow's dependency; loaded only when a material is named

    table = yaml.safe_load(MATERIALS_FILE.read_text(encoding="utf-8"))["materials"]
    for name, entry in table.items():  # the table obeys the same rules as any input
        validate.number(f"materials.{name}.E", entry["E"], 0.0, None, lo_open=True)
        validate.nu(entry["nu"])
        if not entry.get("source"):
            raise ValueError(f"materials.{name} has no source")
    return table


def pair(indenter: Any, body: Any) -> tuple[float, float, float]:
    """(E1/E2, nu1, nu2) of an indenter material pressed into a body material.

    Raises
    ------
    validate.InputError
        Naming ``indenter`` or ``body`` when the name is not in the table.
    """
    table = materials()
    for key, value in (("indenter", indenter), ("body", body)):
        if not isinstance(value, str) or value not in table:
            raise validate.InputError(key, f"one of {', '.join(table)}", value)
    e1, e2 = table[indenter], table[body]
    return float(e1["E"]) / float(e2["E"]), float(e1["nu"]), float(e2["nu"])


def scene_indenter(value: Any, body: Any, nu: float | None) -> tuple[float, float | None]:
    """(E1/E2, nu1) of a scene's ``indenter`` key: a mapping, or a material name.

    A material name needs the scene's ``body`` material (E2), whose Poisson
    ratio must be the scene's ``nu``. Errors name the key (``indenter``,
    ``body`` or ``nu``).
    """
    if not isinstance(value, str):
        if body is not None:
            raise validate.InputError("body", "given only with a material name as indenter",
                                      body)
        return validate.indenter_mapping(value)
    if body is None:
        raise validate.InputError("body", "a material name", body,
                                  f"body is required with indenter = {value!r} (E1/E2 needs "
                                  "the body's material)")
    ratio, nu1, nu2 = pair(value, body)
    if nu is not None and nu != nu2:
        raise validate.InputError("nu", f"{nu2!r} ({body})", nu,
                                  f"nu = {nu!r} differs from {body}'s {nu2!r} "
                                  f"({MATERIALS_FILE.name})")
    return ratio, nu1
