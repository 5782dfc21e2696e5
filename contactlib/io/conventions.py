"""The dataset conventions: names, units, attributes and the netCDF encoding.

What a variable is called, its CF ``units`` and ``long_name``, the flags'
``flag_values``, the global attributes every dataset shares (``Conventions``,
``contactlib_version``, a layer's ``slab_ratio`` and ``base``, the workflow's
provenance) and how a variable is encoded in a netCDF file. The conversions
(:mod:`contactlib.io.datasets`, :mod:`contactlib.io.fretting`,
:mod:`contactlib.io.physical`) and the writer (:mod:`contactlib.io.files`)
take these from here; this module imports nothing of contactlib (but its
version, when :func:`version` runs).

Examples
--------
>>> cf_attrs("wall time of one solve", "s")
{'units': 's', 'long_name': 'wall time of one solve'}
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # xarray is imported where a dataset is made or read (start-up time)
    import xarray as xr

__all__ = ["CONVENTIONS", "COMPRESSION", "BOOL_FLAGS", "PROFILE_ATTRS", "POINT_FLOAT_ATTRS",
           "POINT_BOOL_ATTRS", "PROVENANCE", "work_comment", "layer_attrs", "version",
           "cf_attrs", "set_provenance", "netcdf_encoding"]


# ----------------------------------------------------------------------------- conventions
CONVENTIONS = "CF-1.10"
COMPRESSION: dict[str, Any] = {"zlib": True, "complevel": 4, "shuffle": True}

BOOL_FLAGS: dict[str, Any] = {
    "flag_values": np.array([0, 1], dtype=np.int8),
    "flag_meanings": "false true",
}

# name -> (long_name, comment); every variable here is dimensionless (units "1").
PROFILE_ATTRS: dict[str, tuple[str, str]] = {
    "pressure": (
        "contact pressure over Hertz peak pressure",
        "p / p0, p0 = Hertz peak pressure at the same contact radius; "
        "positive in compression",
    ),
    "shear": (
        "shear traction over Hertz peak pressure",
        "q / p0, traction on the elastic body, positive away from the axis",
    ),
    "tangential_displacement": (
        "scaled tangential surface displacement",
        "u R / a**2, surface displacement, positive away from the axis",
    ),
}

def work_comment(ind: Any) -> str:
    """The scaling of ``frictional_work`` for an indenter (rings or strips)."""
    per_length = (", V per unit length over the whole contact (both sides of the axis)"
                  if ind.plane_strain else "")
    return (f"V R**2 / (E* a**{ind.work_exponent}){per_length}; loading 0 -> a; "
            f"NaN when not computed")

POINT_FLOAT_ATTRS: dict[str, tuple[str, str]] = {
    "friction_coefficient": (
        "coefficient of friction",
        "k; inf at full adhesion (stick_ratio = 1), 0 when frictionless",
    ),
    "load_ratio": (
        "normal load over Hertz load",
        "P / P_Hertz(a) at the same contact radius",
    ),
    "frictional_work": ("scaled frictional work of the loading half-cycle", ""),
    "residual_norm": ("norm of the final solver residual", "solver status"),
    "error_estimate": (
        "estimated relative error of friction_coefficient",
        "from the same case on the nested meshes n/4 and n/2 (Richardson with the observed "
        "order in [1, 2]; the larger difference where they do not converge cleanly); 0 "
        "where k is exact",
    ),
    "load_error_estimate": ("estimated relative error of load_ratio", "as error_estimate"),
    "work_error_estimate": (
        "estimated relative error of frictional_work",
        "as error_estimate; NaN when the work is not computed",
    ),
}

POINT_BOOL_ATTRS: dict[str, tuple[str, str]] = {
    "slip_direction_ok": (
        "slip opposes shear at every slip point",
        "consistency flag",
    ),
    "stick_admissible": (
        "abs(q) <= k p at every stick point",
        "consistency flag",
    ),
    "consistent": (
        "slip direction and stick admissibility both hold",
        "consistency flag",
    ),
    "converged": ("solver converged", "solver status; failed cases are kept"),
    "resolved": (
        "converged with error_estimate at most max_error",
        "a case that is not resolved is not a good number (see message)",
    ),
}



def layer_attrs(ind: Any, result: Any) -> dict[str, Any]:
    """The layer's global attributes: ``slab_ratio`` (a/h, or a_max/h in a history) and ``base``.

    ``slab_ratio`` where the indenter reports it (always for the cylinder, on
    a layer for the sphere: a sphere on the half-space keeps its attributes);
    ``base`` = "bonded" on a layer bonded to its base. Without ``base`` a
    layer is on a smooth base: the default, and the paper's slab, whose
    files keep the attributes they had before bases existed. A coated body
    (``base`` = "elastic") adds ``substrate_modulus`` (E2/E1) and
    ``substrate_poisson_ratio``.
    """
    slab = float(result.slab_ratio)
    base = str(getattr(result, "base", "smooth"))
    attrs: dict[str, Any] = {}
    if ind.reports_layer(slab):
        attrs["slab_ratio"] = slab
    if slab > 0 and base != "smooth":
        attrs["base"] = base
    if slab > 0 and base == "elastic":
        attrs["substrate_modulus"] = float(result.substrate_modulus)
        attrs["substrate_poisson_ratio"] = float(result.substrate_poisson_ratio)
    return attrs


def version() -> str:
    """The contactlib version written into every dataset (``contactlib_version``).

    Returns
    -------
    str
        ``contactlib.__version__``, the single source of the version (also
        read by ``pyproject.toml`` and ``contactlib --version``).

    Examples
    --------
    >>> import contactlib
    >>> version() == contactlib.__version__
    True
    """
    from contactlib import __version__

    return str(__version__)


def cf_attrs(long_name: str, units: str = "1", comment: str = "",
             **extra: Any) -> dict[str, Any]:
    """CF attributes of one variable: ``units``, ``long_name``, then ``comment`` and extras.

    Parameters
    ----------
    long_name : str
        CF ``long_name``.
    units : str
        CF ``units``; ``"1"`` (dimensionless, the default) for every scaled
        quantity of docs/conventions.md.
    comment : str
        Scaling, sign or provenance; left out when empty.
    **extra
        Further attributes (e.g. ``flag_values``, ``bounds``).

    Returns
    -------
    dict
        In this order, so that files are byte-reproducible.

    Examples
    --------
    >>> cf_attrs("wall time of one solve", "s")
    {'units': 's', 'long_name': 'wall time of one solve'}
    """
    attrs: dict[str, Any] = {"units": units, "long_name": long_name}
    if comment:
        attrs["comment"] = comment
    attrs.update(extra)
    return attrs


PROVENANCE = "scene_config_hash"  # the workflow's own datasets: read_dataset needs their check


def set_provenance(ds: xr.Dataset, scene: str, config_hash: str,
                   outputs: Sequence[str] | None = None) -> xr.Dataset:
    """Add the workflow's provenance attributes to ``ds`` (in place) and return it.

    Parameters
    ----------
    ds : xarray.Dataset
    scene : str
        The scene's name (attribute ``scene``).
    config_hash : str
        Hash of the scene's settings (attribute ``scene_config_hash``).
    outputs : sequence of str, optional
        The outputs the scene asked for (attribute ``outputs``, space separated).

    Returns
    -------
    xarray.Dataset
        ``ds``.
    """
    ds.attrs["scene"] = scene
    ds.attrs[PROVENANCE] = config_hash
    if outputs is not None:
        ds.attrs["outputs"] = " ".join(outputs)
    return ds


def netcdf_encoding(ds: xr.Dataset) -> dict[str, dict[str, Any]]:
    """Per-variable netCDF encoding: no fill on coordinates, zlib on data."""
    encoding: dict[str, dict[str, Any]] = {}
    for name in ds.coords:
        encoding[str(name)] = {"_FillValue": None}
    for name, var in ds.data_vars.items():
        if var.dtype.kind in "biuf" and var.ndim > 0:
            encoding[str(name)] = dict(COMPRESSION)
    return encoding
