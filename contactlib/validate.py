"""Every input rule and every limit, written once.

The library entry points (:func:`contactlib.solve`, :func:`contactlib.sweep`,
:func:`contactlib.history`), the command line and the workflow's scenes all
check their input here. A bad value raises :class:`InputError`, a
:class:`ValueError` that carries the name of the argument (``exc.name``),
the requirement in words (``exc.requirement``) and the value, so that the
command line can name its option (``--slab-ratio``) and a scene its key
(``scenes.<name>.slab_ratio``) without reading the message text.

This module imports neither numpy nor the solvers, so the command line can
check its options before loading the numerics.

Examples
--------
>>> from contactlib import validate
>>> validate.nu(0.3)
0.3
>>> try:
...     validate.nu(0.7)
... except validate.InputError as exc:
...     print(exc.name, "|", exc)
nu | nu must be in (-1, 0.5], got 0.7
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from numbers import Integral, Real
from typing import Any, Callable, Iterable

__all__ = [
    "InputError", "GEOMETRIES", "METHODS", "Method", "METHOD_REGISTRY", "method_of",
    "DEFAULT_N", "MIN_N_DEFAULT_METHOD", "MAX_N",
    "EXTRAPOLATED_N_MULTIPLE", "SolverLimit", "SCENE_NAME_PATTERN", "scene_name",
    "RESULTS_DIR_PATTERN", "results_dir",
    "HISTORY_DEFAULT_N", "HISTORY_MIN_N", "HISTORY_MAX_N", "MAX_STEPS", "DEFAULT_MAX_ERROR",
    "PATH_DEFAULT_MAX_ERROR",
    "number", "integer", "flag", "callback", "choice", "geometry", "method", "nu",
    "slab_ratio", "stick_ratio", "stick_ratios", "paper_multiple", "friction", "n",
    "history_n", "steps", "load_path", "max_error", "tolerance", "requirement",
    "MIN_TOLERANCE", "MAX_TOLERANCE", "MIN_PLANNED_TOLERANCE", "planned_tolerance",
    "indenter_modulus", "indenter_nu", "indenter_material",
    "indenter_mapping", "BASES", "COATED_BASE", "SUBSTRATE_MODULUS_RANGE", "substrate",
    "LAYER_RATIO_MAX", "HISTORY_SPHERE_LAYER_RATIO_MAX", "HISTORY_CYLINDER_COATED_RATIO_MAX",
    "HISTORY_CYLINDER_SMOOTH_RATIO_MAX",
    "HISTORY_MESH_EXTENT", "base", "OUTPUTS",
    "DEFAULT_OUTPUTS", "SUBSURFACE_GRID", "subsurface_grid",
]

# ----------------------------------------------------------------------------- limits
GEOMETRIES: tuple[str, ...] = ("sphere", "cylinder")
"""Indenter shapes: a rigid sphere (rings) or a rigid cylinder (strips)."""

@dataclass(frozen=True)
class Method:
    """A self-similar method, registered once with what it takes and what it gives.

    The solvers and the drivers ask these fields instead of comparing names.

    Attributes
    ----------
    name : str
        The name ``solve(method=...)`` and ``--method`` take.
    default_n : int
        Elements across the half-contact when n is not given.
    min_n, n_multiple : int
        The smallest n and the multiple n must be of (1: any).
    nodal : bool
        Tractions at the nodes of a mesh graded at each stick ratio (ours); False:
        the paper's steps on a uniform mesh whose stick ratios are element edges.
    any_profile : bool
        Takes every power-law profile (False: its error model or scheme assumes the
        paraboloid).
    coated : bool
        Takes a coated body (base "elastic").
    planned : bool
        May be picked by a tolerance (:func:`contactlib.accuracy.plan`).
    own_estimate : bool
        Estimates its error from its own nested levels (the extrapolated method); else
        a nodal method is checked from the same case at n/2 and n/4.
    coulomb : {"resultant", "coefficient"}
        Coulomb's law on the slip zone's resultant forces, or with the coefficient as
        the paper prints it.
    relative_cost : float
        A planned method's time for a case, with its error estimate, over the default
        method's at the same n (:func:`contactlib.accuracy.relative_cost`).
    plan_safety : float
        A planned method's margin: the plan aims at tolerance / plan_safety
        (:func:`contactlib.accuracy.plan`).
    """

    name: str
    default_n: int
    min_n: int = 2
    n_multiple: int = 1
    nodal: bool = True
    any_profile: bool = False
    coated: bool = False
    planned: bool = False
    own_estimate: bool = False
    coulomb: str = "resultant"
    relative_cost: float = 1.0
    plan_safety: float = 2.0

    @property
    def estimates(self) -> bool:
        """Gives each case an error estimate and a ``resolved`` flag (the paper's
        schemes do not)."""
        return self.nodal

    @property
    def nested_estimate(self) -> bool:
        """Estimated from the same case on the nested meshes n/2 and n/4, solved by the
        caller (a nodal method without its own estimate)."""
        return self.nodal and not self.own_estimate


# convention: the default method's mesh is in sixteenths of the half-contact
MIN_N_DEFAULT_METHOD = 16
"""Fewest elements the default method accepts (its mesh is in sixteenths)."""

# exact: 8 x MIN_N_DEFAULT_METHOD, so that the n/8 level is a mesh of sixteenths nested in n
EXTRAPOLATED_N_MULTIPLE = 128
"""The extrapolated method's n: a multiple of this (its n/8 level is nested in n)."""

# convention: the default method's plan margin (tolerance / 2; whether plans reach it:
# tests/test_extrapolated_method.py and tests/test_error_estimate.py, solves with tolerance=)
DEFAULT_PLAN_SAFETY = 2.0
# measured: benchmarks/bench_frontier.py part (d): the extrapolated method's time over the
# default method's at the same n, both with their estimates (stages.solve_cases, 5 cases
# c/a = 0.1 ... 0.9): 0.86, 0.92, 0.84 (sphere) and 0.80, 0.81, 0.78 (cylinder) at n = 128,
# 256, 512 on one machine, 0.87, 0.83, 0.97 and 0.82, 0.80, 0.84 on another. (It was 1.5,
# an early measurement, which planned the default method at n = 128 for 3e-4 where the
# extrapolated method's n = 128 is cheaper and 20 ... 50 times more accurate.)
EXTRAPOLATED_RELATIVE_COST = 0.9
# tested: tests/test_extrapolated_method.py (the plan's margin: its constant is the largest
# error measured over 30 cases, and 1.5 is enough: 6.5e-7 x 1.5 < 1e-6)
EXTRAPOLATED_PLAN_SAFETY = 1.5

METHOD_REGISTRY: dict[str, Method] = {m.name: m for m in (
    Method("default", 256, min_n=MIN_N_DEFAULT_METHOD, any_profile=True, coated=True,
           planned=True, plan_safety=DEFAULT_PLAN_SAFETY),
    Method("paper", 16, nodal=False),
    Method("paper-literal", 16, nodal=False, coulomb="coefficient"),
    Method("extrapolated", 256, min_n=EXTRAPOLATED_N_MULTIPLE,
           n_multiple=EXTRAPOLATED_N_MULTIPLE, planned=True, own_estimate=True,
           relative_cost=EXTRAPOLATED_RELATIVE_COST, plan_safety=EXTRAPOLATED_PLAN_SAFETY),
)}
"""Every self-similar method: ours, the paper's scheme, the paper's scheme as printed, and
ours on three nested meshes extrapolated in n (k to about 1e-6 at its default n)."""

DEFAULT_METHOD: str = "default"
"""The method ``solve`` and ``sweep`` use when neither a method nor a tolerance is given."""

METHODS: tuple[str, ...] = tuple(METHOD_REGISTRY)
"""The names of :data:`METHOD_REGISTRY`, in its order."""


def method_of(name: str) -> Method:
    """The registered :class:`Method` of a checked name (:func:`method`)."""
    return METHOD_REGISTRY[name]


def estimates(name: Any) -> bool:
    """Whether the method ``name`` (a dataset's ``method`` attribute) estimates its error,
    so that a case it did not resolve is a failure; False for a name not registered."""
    known = METHOD_REGISTRY.get(str(name))
    return known is not None and known.estimates

OUTPUTS: tuple[str, ...] = ("k_curve", "stresses", "displacements", "energy", "subsurface")
"""What a self-similar scene may ask for (``outputs``), in the order the stages run them."""

DEFAULT_OUTPUTS: tuple[str, ...] = ("k_curve", "stresses", "displacements", "energy")
"""The outputs of a scene that names none (``subsurface``, the costliest, only when asked)."""

# convention: default grid of the subsurface output (0 <= x, z <= 2, 101 points each)
SUBSURFACE_GRID: tuple[tuple[float, float, int], tuple[float, float, int]] = (
    (0.0, 2.0, 101), (0.0, 2.0, 101))
"""Default grid of the ``subsurface`` output: x = r/a (x/a) and z = depth/a as
``(start, stop, points)`` of equally spaced points."""

BASES: tuple[str, ...] = ("smooth", "bonded")
"""Rigid bases under a layer: frictionless (the paper's slab) or bonded."""

COATED_BASE = "elastic"
"""The base of a coated body: the layer bonded to an elastic half-space (half-plane)."""

# limit: sphere and coated bodies to 1000 (tests/test_thin_layers.py, tests/test_thin_coatings.py,
# tests/test_thin_coatings_cylinder.py); the cylinder on a smooth base to 500, where every c/a =
# 0.05 ... 0.95 is resolved at n = 256 with an estimate covering the n = 1024 difference
# (benchmarks/report_thin_layers_cylinder_smooth.py; tests/test_thin_layers_cylinder_smooth.py)
LAYER_RATIO_MAX: dict[tuple[str, str], float] = {
    ("sphere", "smooth"): 1000.0, ("sphere", "bonded"): 1000.0, ("sphere", "elastic"): 1000.0,
    ("cylinder", "smooth"): 500.0, ("cylinder", "bonded"): 1000.0,
    ("cylinder", "elastic"): 1000.0,
}
"""Largest a/h (a_max/h in the history solver) per (geometry, base).

Sphere: the ring tables of :mod:`contactlib.kernels.layer` cover
max(r, s)/h <= 20; on a rigid base and on a coated body the transform-domain
sums of :mod:`contactlib.kernels.thin_layer` go on to 1000 (measured:
tests/test_thin_layers.py, tests/test_thin_coatings.py), in
:func:`contactlib.solve` and in :func:`contactlib.history` (whose mesh, sized
by a frictionless probe beyond a_max/h = 16.7, must stay within
:data:`HISTORY_SPHERE_LAYER_RATIO_MAX` h: tests/test_thin_layer_history.py).
Cylinder: where k at n = 256 is resolved to 1e-3 by its error estimate,
measured (docs/validation.md, "Layers"; on a smooth base to 500: beyond it, at 1000, the
estimate at n = 256 fell to 0.65 of the difference to n = 1024 and c/a <= 0.1 had none;
in history :data:`HISTORY_CYLINDER_SMOOTH_RATIO_MAX`); on a coated body 1000 with the
log-spaced far tables of :mod:`contactlib.kernels.strip` (|x +- s|/h <= 3072; measured:
tests/test_thin_coatings_cylinder.py), in history
:data:`HISTORY_CYLINDER_COATED_RATIO_MAX`.
"""

# limit: as measured in tests/test_coated_history_thin.py (benchmarks/report_coated_history_thin.py:
# E2/E1 = 0.1, 0.5, 10 at a_max/h = 50 ... 1000: the k = 0 contact within an element of the
# self-similar root, energy rest <= 2.6e-7, the n = 240 estimates against n = 480); a soft
# substrate is refused earlier, where its mesh would pass the 1200 h of the kernels
HISTORY_CYLINDER_COATED_RATIO_MAX = 1000.0
"""a_max/h of a coated cylinder in the history solver, as in ``solve``; beyond a_max/h = 20
the mesh is sized by a frictionless probe. A substrate softer than the coating grows the
contact (to 3.1 a_max at E2/E1 = 0.1) and is refused, naming ``slab_ratio``, where the mesh
over it would pass 1200 h (measured: a_max/h 310 passes and 320 is refused at E2/E1 = 0.1,
680 and 700 at 0.5)."""

# limit: as measured in tests/test_coated_history_thin.py (at 500: the k = 0 contact within an
# element of the self-similar root, the stick radius at P_max the self-similar c(k) within the
# estimate; at 100, 200, 500 in benchmarks/report_coated_history_thin.py), LAYER_RATIO_MAX's range
HISTORY_CYLINDER_SMOOTH_RATIO_MAX = 500.0
"""a_max/h of a cylinder on a smooth rigid base in the history solver, as in ``solve``; beyond
a_max/h = 20 the mesh is sized by a frictionless probe (the contact shrinks to 0.12 a_max at
500)."""

# limit: the probe-sized mesh stays within it (tests/test_thin_layer_history.py)
HISTORY_SPHERE_LAYER_RATIO_MAX = 1200.0
"""max(r, s)/h of the sphere's layer kernels in the history solver: the ring tables to
20, then the transform-domain sums (``kernels.layer.THIN_RATIO_MAX``)."""

# exact: history_solver.MESH_EXTENT, repeated (tests/test_model.py checks they agree)
HISTORY_MESH_EXTENT = 1.2
"""The history solver's mesh length over a_max (``history_solver.MESH_EXTENT``)."""

DEFAULT_N: dict[str, int] = {name: m.default_n for name, m in METHOD_REGISTRY.items()}
"""Default number of elements across the half-contact, per method."""

# limit: memory, about 3.3 GiB at n = 4096 (measured in tests/test_extremes.py)
MAX_N = 4096
"""Most elements of a self-similar solve (about 3.3 GiB at n = 4096)."""

# convention: the history's default mesh, elements of a_max/200
HISTORY_DEFAULT_N = 240
"""Default elements of the history solver over [0, 1.2 a_max] (size a_max / 200)."""

# convention: the history's default load steps a path segment (with HISTORY_DEFAULT_N: a
# cycle's work to a few 1e-3, docs/tolerance.md)
HISTORY_DEFAULT_STEPS = 200
"""Default load steps of a history, a path segment (or a load travel of P_max)."""

# convention: as the default method's fewest elements (MIN_N_DEFAULT_METHOD)
HISTORY_MIN_N = 16
# limit: the plan's largest n (tests/test_history_tolerance.py keeps planned runs within it;
# CHANGELOG, the history tolerance plan)
HISTORY_MAX_N = 2048
# limit: about 3 min a segment at the default n (CHANGELOG: runs are named within MAX_N and
# MAX_STEPS); tests/test_config_rules.py checks the refusal beyond
MAX_STEPS = 100_000
"""Most load steps per path segment (about 3 min a segment at the default n)."""

# convention: the accuracy a result is asked by default (docs/accuracy.md)
DEFAULT_MAX_ERROR = 1e-3
"""Default accuracy asked of a result: a larger error estimate is not resolved."""

# convention: the accuracy a load path (history, fretting) is asked by default, what its
# default resolution delivers: a cycle's work to about 1.5e-3 at n = 240 and 200 steps a
# segment, the stick radius to 2.5e-3 a_max (docs/accuracy.md; 1e-3 needs about 4 n and
# 4 x steps, `history --tolerance 1e-3` plans it)
PATH_DEFAULT_MAX_ERROR = 1e-2
"""Default accuracy asked of a load path's steps (``history``, ``fretting``)."""

SCENE_NAME_PATTERN = r"^[A-Za-z0-9][A-Za-z0-9_-]*$"
"""A workflow scene's name (a file name and a Snakemake wildcard value): a letter or
digit, then letters, digits, ``-`` and ``_``."""

RESULTS_DIR_PATTERN = r"^[A-Za-z0-9_][A-Za-z0-9_./-]*$"
"""The workflow's ``results_dir`` (the folder of every output): a relative path that
starts with a letter, digit or ``_`` (so neither ``/`` nor ``..``)."""
# limit: as MIN_PLANNED_TOLERANCE (measured by benchmarks/report_log_extrapolation.py);
# tests/test_config_rules.py checks the schema's range
MIN_TOLERANCE = 1e-9
# convention: a coarser tolerance is no accuracy target (tests/test_config_rules.py checks the
# schema's range)
MAX_TOLERANCE = 0.1
"""Range of a scene's ``tolerance`` (relative error in k)."""

# limit: the extrapolated method's measured reach (benchmarks/report_log_extrapolation.py,
# benchmarks/report_estimate_coverage.py; see the docstring)
MIN_PLANNED_TOLERANCE = 1e-9
"""Smallest ``tolerance`` of solve/sweep (library and command line): the extrapolated
method's measured reach with five levels from n = 1024
(:data:`~contactlib.solvers.extrapolated_method.LOG_LEVEL_FROM_N`; nu = 0.4999999 against the
closed form, c/a = 0.003 ... 0.98: k to 4e-10 and better at n = 1024, its estimate 2.6e-10
... 1.3e-9). 1e-9 is planned where the estimate model meets it (c/a = 0.005 ... 0.98 at
n = 1024 ... 2048) and refused elsewhere (c/a nearer 0 and 1, where the noise bound of
:func:`~contactlib.solvers.extrapolated_method.log_noise` stays above it, and on layers)."""


class InputError(ValueError):
    """A bad input value.

    Parameters
    ----------
    name : str
        The argument's library name (``"nu"``, ``"slab_ratio"``); the command
        line shows it as ``--nu``, ``--slab-ratio``.
    requirement : str
        What a good value is, in words (``"in (-1, 0.5]"``).
    value : object
        The value given.
    message : str, optional
        The whole message, when ``"<name> must be <requirement>, got <value>"``
        does not fit (it always starts with the name).
    """

    def __init__(self, name: str, requirement: str, value: Any, message: str | None = None):
        self.name = name
        self.requirement = requirement
        self.value = value
        super().__init__(message or f"{name} must be {requirement}, got {value!r}")


class SolverLimit(ValueError):
    """Valid input that the solver cannot answer (not a bad value).

    Raised where every argument passes its rule but the method has no answer,
    e.g. a friction coefficient so large that the contact is most likely fully
    stuck (no self-similar slip annulus reaches it), one so small that the
    stick zone lies below the smallest one resolved, or a stick ratio beyond
    the coupled limit c*. The command line exits with status 3 for it (2 is
    bad input) and prints the commands that answer the case.

    Parameters
    ----------
    message : str
        Why, in physical terms, and what answers the case instead.
    remedies : sequence of (str, dict)
        The calls that answer it: a command (``"solve"``, ``"history"``) and
        the arguments that differ from the failed call, by library name
        (``{"stick_ratio": 1.0}``, ``{"friction": 0.5, "load_path": [0, 1]}``).
        Empty when none is known.
    """

    def __init__(self, message: str, remedies: Iterable[tuple[str, dict]] = ()):
        self.remedies = [(command, dict(args)) for command, args in remedies]
        super().__init__(message)


def shown(x: float) -> str:
    """A number as messages write it: ``%g`` without the exponent's padding (1e-9, not
    1e-09)."""
    text = f"{x:g}"
    mantissa, e, exponent = text.partition("e")
    return f"{mantissa}e{int(exponent)}" if e else text


def requirement(lo: float | None = None, hi: float | None = None, lo_open: bool = False,
                hi_open: bool = False) -> str:
    """An allowed range in words: ``in (-1, 0.5]``, ``>= 0``, ``< 1``."""
    if lo is not None and hi is not None:
        return f"in {'(' if lo_open else '['}{shown(lo)}, {shown(hi)}{')' if hi_open else ']'}"
    if lo is not None:
        return f"{'>' if lo_open else '>='} {shown(lo)}"
    if hi is not None:
        return f"{'<' if hi_open else '<='} {shown(hi)}"
    return "a number"


def _is_bool(value: Any) -> bool:
    """Python and numpy booleans (numpy is not imported here; ``numpy.bool`` from 2.0)."""
    return isinstance(value, bool) or (type(value).__name__ in ("bool_", "bool")
                                       and type(value).__module__ == "numpy")


def is_sequence(value: Any) -> bool:
    """Whether ``value`` is a sequence of items (not a string, not a 0-d array)."""
    return not isinstance(value, (str, bytes)) and hasattr(value, "__iter__") and \
        getattr(value, "ndim", None) != 0


def _scalar(value: Any) -> Any:
    """A 0-d numpy array as the scalar it holds (``np.array(0.3)`` is 0.3); else as given."""
    if type(value).__name__ == "ndarray" and getattr(value, "ndim", None) == 0:
        return value.item() if value.dtype.kind in "biuf" else value
    return value


# ----------------------------------------------------------------------------- generic rules
def number(name: str, value: Any, lo: float | None = None, hi: float | None = None,
           lo_open: bool = False, hi_open: bool = False) -> float:
    """A finite real number in the given range (booleans and strings refused)."""
    req = requirement(lo, hi, lo_open, hi_open)
    value = _scalar(value)
    if _is_bool(value) or not isinstance(value, Real):
        raise InputError(name, f"a number {req}" if req != "a number" else req, value)
    try:
        v = float(value)
    except OverflowError:  # an int beyond the float range
        v = math.inf
    if not math.isfinite(v):
        raise InputError(name, f"finite ({req})" if req != "a number" else "finite", value)
    if (lo is not None and (v < lo or (lo_open and v == lo))) or \
            (hi is not None and (v > hi or (hi_open and v == hi))):
        raise InputError(name, req, value)
    return v


def integer(name: str, value: Any, lo: int, hi: int | None = None) -> int:
    """An integer in [lo, hi] (an integral float such as ``64.0`` is accepted)."""
    req = f"an integer >= {lo}" if hi is None else f"an integer in [{lo}, {hi}]"
    value = _scalar(value)
    if _is_bool(value) or not isinstance(value, (Integral, Real)):
        raise InputError(name, req, value)
    if not isinstance(value, Integral):
        if not (math.isfinite(float(value)) and float(value).is_integer()):
            raise InputError(name, req, value)
    v = int(value)
    if v < lo or (hi is not None and v > hi):
        raise InputError(name, req, value)
    return v


def flag(name: str, value: Any) -> bool:
    """A real boolean (``True``/``False``, numpy bools too); never a truthy string."""
    value = _scalar(value)
    if _is_bool(value):
        return bool(value)
    raise InputError(name, "True or False", value)


def callback(name: str, value: Any) -> Callable | None:
    """None or a callable (checked before any work)."""
    if value is not None and not callable(value):
        raise InputError(name, "callable or None", value)
    return value


def choice(name: str, value: Any, allowed: Iterable[str]) -> str:
    """One of the allowed names."""
    allowed = tuple(allowed)
    if not isinstance(value, str) or value not in allowed:
        raise InputError(name, f"one of {', '.join(allowed)}", value)
    return value


# ----------------------------------------------------------------------------- the problem
def geometry(value: Any) -> str:
    """``"sphere"`` or ``"cylinder"``."""
    return choice("geometry", value, GEOMETRIES)


def method(value: Any) -> str:
    """``"default"``, ``"paper"``, ``"paper-literal"`` or ``"extrapolated"``."""
    return choice("method", value, METHODS)


def scene_name(value: Any) -> str:
    """A workflow scene's name (:data:`SCENE_NAME_PATTERN`)."""
    import re

    if not isinstance(value, str) or not re.match(SCENE_NAME_PATTERN, value):
        raise InputError("scene name", "a letter or digit followed by letters, digits, '-' "
                         "and '_' (it names files and jobs)", value)
    return value


def results_dir(value: Any) -> str:
    """The workflow's output folder (:data:`RESULTS_DIR_PATTERN`)."""
    import re

    if not isinstance(value, str) or not re.match(RESULTS_DIR_PATTERN, value):
        raise InputError("results_dir", "a relative path starting with a letter, digit or "
                         "'_', of letters, digits, '_', '.', '/' and '-'", value)
    return value


def nu(value: Any) -> float:
    """Poisson's ratio of the body, in (-1, 0.5]."""
    return number("nu", value, -1.0, 0.5, lo_open=True)


def base(value: Any, coated: bool = False) -> str:
    """The rigid base under a layer: ``"smooth"`` or ``"bonded"``; with ``coated``
    also ``"elastic"`` (:data:`COATED_BASE`, checked by :func:`substrate`)."""
    if value == COATED_BASE and not coated:
        raise InputError("base", f"one of {', '.join(BASES)} here", value,
                         f"base {value!r} (a coated body) is not available here (solve, "
                         "sweep, history and their physical forms take it)")
    return choice("base", value, BASES + ((COATED_BASE,) if coated else ()))


# limit: the remainder tables against their quadrature and the limits of tests/test_coatings.py
# (docs/models.md)
SUBSTRATE_MODULUS_RANGE: tuple[float, float] = (1e-2, 1e6)
"""Verified range of ``substrate_modulus`` E2/E1 of a coated body (the layer's
remainder tables against their quadrature, and the limits of
``tests/test_coatings.py``; docs/models.md)."""


def substrate(base_name: str, modulus: Any, nu2: Any, geometry_name: str,
              method_name: str = "default") -> tuple[float, float | None]:
    """The elastic substrate of a coated body: ``(E2/E1, nu2)`` (nu2 None: the layer's).

    ``base_name`` (already checked) is :data:`COATED_BASE` for a coated body;
    any other base refuses a substrate (``modulus`` must be None or inf and
    ``nu2`` None), and then ``(inf, None)`` is returned. A coated body is a
    sphere or cylinder under the default method, with E2/E1 in
    :data:`SUBSTRATE_MODULUS_RANGE`.
    """
    modulus = _scalar(modulus)
    given = modulus is not None and not (isinstance(modulus, Real) and not _is_bool(modulus)
                                         and modulus == math.inf)
    if base_name != COATED_BASE:
        if given:
            raise InputError("substrate_modulus", "unset without base='elastic'", modulus,
                             f"substrate_modulus needs base='elastic' (a coated body), not "
                             f"base={base_name!r}, got {modulus!r}")
        if nu2 is not None:
            raise InputError("substrate_nu", "unset without base='elastic'", nu2,
                             f"substrate_nu needs base='elastic' (a coated body), not "
                             f"base={base_name!r}, got {nu2!r}")
        return math.inf, None
    if not method_of(method_name).coated:
        raise InputError("method", "'default' on a coated body", method_name,
                         f"method {method_name!r} is not available on a coated body "
                         "(base 'elastic'): use method 'default'")
    if modulus is None:
        raise InputError("substrate_modulus", "given with base='elastic'", modulus,
                         "substrate_modulus (E2/E1 of the substrate over the layer) is required "
                         "with base='elastic'")
    lo, hi = SUBSTRATE_MODULUS_RANGE
    m = number("substrate_modulus", modulus, lo, hi)
    return m, (None if nu2 is None else number("substrate_nu", nu2, -1.0, 0.5, lo_open=True))


def slab_ratio(value: Any, geometry_name: str | None = None, base_name: str = "smooth",
               extent: float = 1.0) -> float:
    """a/h of the layer, finite and >= 0 (0: half-space or half-plane).

    ``geometry_name`` and ``base_name`` (already checked) bound it by
    :data:`LAYER_RATIO_MAX` (a coated body: 1000 for both geometries; in history the
    sphere's :data:`HISTORY_SPHERE_LAYER_RATIO_MAX` and the coated cylinder's
    :data:`HISTORY_CYLINDER_COATED_RATIO_MAX`);
    ``extent`` is the farthest point of the mesh in
    units of the length scale (the history solver's 1.2 a_max), which
    divides the sphere's bound (its kernels are bounded in r/h, not a/h).
    """
    v = number("slab_ratio", value, 0.0, None)
    if geometry_name is None:
        return v
    hi = LAYER_RATIO_MAX[(geometry_name, base_name)]
    if geometry_name == "sphere" and extent != 1.0:
        hi = min(hi, HISTORY_SPHERE_LAYER_RATIO_MAX / extent)
    if geometry_name == "cylinder" and base_name == COATED_BASE and extent != 1.0:
        hi = min(hi, HISTORY_CYLINDER_COATED_RATIO_MAX)
    if geometry_name == "cylinder" and base_name == "smooth" and extent != 1.0:
        hi = min(hi, HISTORY_CYLINDER_SMOOTH_RATIO_MAX)
    if v > hi:
        raise InputError("slab_ratio", f"<= {hi:g} for a {geometry_name} on a {base_name} "
                         "base (the supported range, as measured: docs/validation.md, "
                         "'Layers')", value)
    return v


def indenter_modulus(value: Any) -> float:
    """E1/E2, Young's modulus of the indenter over the body's, in (0, inf]; inf is rigid."""
    value = _scalar(value)
    if isinstance(value, Real) and not _is_bool(value) and value == math.inf:
        return math.inf
    return number("indenter_modulus", value, 0.0, None, lo_open=True)


def indenter_nu(value: Any) -> float:
    """Poisson's ratio nu1 of the indenter, in (-1, 0.5]."""
    return number("indenter_nu", value, -1.0, 0.5, lo_open=True)


def indenter_material(modulus: Any = math.inf, poisson: Any = None) -> tuple[float, float | None]:
    """(E1/E2, nu1) of the indenter; nu1 None takes the body's.

    A Poisson's ratio needs an elastic indenter: ``indenter_nu`` with the
    rigid default modulus (inf) is refused, naming the value.
    """
    ratio = indenter_modulus(modulus)
    if poisson is None:
        return ratio, None
    nu1 = indenter_nu(poisson)
    if ratio == math.inf:
        raise InputError("indenter_nu", "given with a finite indenter_modulus", poisson,
                         f"indenter_nu = {poisson!r} needs an elastic indenter: give its "
                         "modulus ratio E1/E2 too (the default, inf, is rigid)")
    return ratio, nu1


def indenter_mapping(value: Any) -> tuple[float, float | None]:
    """A scene's ``indenter: {modulus_ratio: R, nu: NU1}`` as (E1/E2, nu1); nu optional."""
    req = "a mapping {modulus_ratio: E1/E2, nu: NU1} or a material name"
    if not hasattr(value, "keys") or set(value) - {"modulus_ratio", "nu"} or \
            "modulus_ratio" not in value:
        raise InputError("indenter", req, value)
    return indenter_material(value["modulus_ratio"], value.get("nu"))


def stick_ratio(value: Any, name: str = "stick_ratio") -> float:
    """A stick ratio c/a in [0, 1]."""
    return number(name, value, 0.0, 1.0)


def stick_ratios(values: Any, n: int, labels: list[str] | None = None) -> list[float]:
    """``"all"`` (m/n for m = 1 ... n-1) or a non-empty list of distinct c/a in [0, 1].

    ``labels`` (the values as the user typed them) name a repeated value.
    """
    req = "'all' or a list of distinct numbers in [0, 1]"
    if isinstance(values, str):
        if values != "all":
            raise InputError("stick_ratios", req, values)
        return [m / n for m in range(1, n)]
    try:
        items = list(values)
    except TypeError:
        raise InputError("stick_ratios", req, values) from None
    if not items:
        raise InputError("stick_ratios", req, values, "stick_ratios must not be empty")
    ratios = [stick_ratio(v, "stick_ratios") for v in items]
    shown = [repr(v) for v in items] if labels is None else [repr(t) for t in labels]
    seen: dict[float, int] = {}
    for i, c in enumerate(ratios):
        if c in seen:
            j = seen[c]
            raise InputError("stick_ratios", req, values,
                             f"stick_ratios must not repeat a value: {shown[i]} at position "
                             f"{i} repeats {shown[j]} at position {j} (c/a = {c:g}); each c/a "
                             f"is one row of the dataset")
        seen[c] = i
    return ratios


def paper_multiple(c: float, n: int, name: str = "stick_ratio") -> int:
    """m with c = m/n: the paper's scheme puts c/a on its element edges."""
    m = int(round(c * n))
    if abs(m - c * n) > 1e-9 * n:
        raise InputError(name, f"a multiple of 1/n = 1/{n} for the paper method", c)
    return m


def friction(value: Any) -> float:
    """Friction coefficient k >= 0; ``inf`` (full adhesion) is allowed."""
    value = _scalar(value)
    if isinstance(value, Real) and not _is_bool(value) and value == math.inf:
        return math.inf
    return number("friction", value, 0.0, None)


def n(value: Any, method_name: str) -> int:
    """Elements of a self-similar solve (None: the method's default)."""
    if value is None:
        return DEFAULT_N[method_name]
    spec = method_of(method_name)
    lo = spec.min_n
    v = integer("n", value, 2, MAX_N)
    if spec.n_multiple > 1 and (v < spec.n_multiple or v % spec.n_multiple):
        raise InputError("n", f"a multiple of {spec.n_multiple} in "
                         f"[{spec.n_multiple}, {MAX_N}] for the {method_name} method "
                         "(n/8, n/4, n/2 nested in n)", value)
    if v < lo:
        raise InputError("n", f"an integer in [{lo}, {MAX_N}]", value,
                         f"n must be at least {lo} for the default method, got {value!r}")
    return v


def history_n(value: Any) -> int:
    """Elements of the history solver over [0, 1.2 a_max] (None: the default)."""
    if value is None:
        return HISTORY_DEFAULT_N
    return integer("n", value, HISTORY_MIN_N, HISTORY_MAX_N)


def steps(value: Any) -> int:
    """Load steps per path segment, in [1, MAX_STEPS]."""
    return integer("steps", value, 1, MAX_STEPS)


def load_path(values: Any) -> tuple[float, ...]:
    """Load levels P/P_max in [0, 1], at least two, starting at 0."""
    req = "a sequence of at least two load levels in [0, 1] starting at 0"
    if not is_sequence(values):
        raise InputError("load_path", req, values)
    items = list(values)
    if not items:
        raise InputError("load_path", req, values, "load_path must not be empty")
    levels = tuple(number("load_path", v, 0.0, 1.0) for v in items)
    if len(levels) < 2:
        raise InputError("load_path", req, values,
                         f"load_path needs at least two levels (a start and an end), "
                         f"got {items!r}")
    if levels[0] != 0.0:
        raise InputError("load_path", req, values,
                         f"load_path must start at 0 (the body starts unloaded), "
                         f"got {items[0]!r}")
    if max(levels) == 0.0:
        raise InputError("load_path", req, values,
                         f"load_path never rises above 0 (no contact to follow), got "
                         f"{list(levels)!r}")
    return levels


def max_error(value: Any) -> float:
    """The accuracy asked of a result, in (0, 1) (a relative error)."""
    return number("max_error", value, 0.0, 1.0, lo_open=True, hi_open=True)


def tolerance(value: Any) -> float:
    """A relative tolerance on k, in [MIN_TOLERANCE, MAX_TOLERANCE]."""
    return number("tolerance", value, MIN_TOLERANCE, MAX_TOLERANCE)


def planned_tolerance(value: Any) -> float:
    """The ``tolerance`` of solve/sweep: a relative error of k in [1e-9, 0.1]."""
    return number("tolerance", value, MIN_PLANNED_TOLERANCE, MAX_TOLERANCE)


# ----------------------------------------------------------------------------- viscoelastic body
__all__ += ["relaxation", "duration", "is_sequence"]


def relaxation(values: Any) -> tuple[tuple[float, float], ...]:
    """A Prony series ``[[g_1, tau_1], ...]`` of the body's relaxation (empty: elastic).

    E(t)/E(0) = 1 - sum g_i (1 - exp(-t/tau_i)) with every g_i > 0,
    sum g_i < 1 (a solid: E(inf) > 0) and every tau_i > 0 and finite.
    None or an empty sequence is the elastic body.
    """
    req = "a list of pairs [g, tau] with g > 0, tau > 0 and sum of g < 1"
    if values is None:
        return ()
    if not is_sequence(values):
        raise InputError("relaxation", req, values)
    pairs = []
    for item in values:
        if not is_sequence(item) or len(list(item)) != 2:
            raise InputError("relaxation", req, values,
                             f"relaxation must be {req}, got the malformed pair {item!r}")
        g, tau = list(item)
        g = number("relaxation", g, 0.0, 1.0, lo_open=True, hi_open=True)
        tau = number("relaxation", tau, 0.0, None, lo_open=True)
        pairs.append((g, tau))
    if sum(g for g, _ in pairs) >= 1.0:
        raise InputError("relaxation", req, values,
                         f"relaxation must have a sum of g below 1 (E(inf) > 0), got "
                         f"{sum(g for g, _ in pairs):g} from {values!r}")
    return tuple(pairs)


def duration(value: Any, segments: int, relaxed: bool) -> tuple[float, ...]:
    """Durations of the ``segments`` path segments (same unit as the relaxation times).

    ``value`` is the duration of the whole path (split equally) or a
    sequence of one positive duration a segment. It is required, finite and
    positive with a relaxation (``relaxed``), and refused without one.
    Returns () for an elastic body.
    """
    if not relaxed:
        if value is not None:
            raise InputError("duration", "given with a relaxation", value,
                             f"duration = {value!r} needs a relaxation (an elastic body "
                             "has no time scale)")
        return ()
    if value is None:
        raise InputError("duration", "given (> 0) with a relaxation", value,
                         "duration is required with a relaxation (the path's duration, "
                         "in the unit of tau)")
    if not is_sequence(value):
        total = number("duration", value, 0.0, None, lo_open=True)
        return tuple(total / segments for _ in range(segments))
    items = list(value)
    if len(items) != segments:
        raise InputError("duration", f"one number or {segments} (one a segment)", value,
                         f"duration must give one number or one a path segment "
                         f"({segments}), got {len(items)}: {value!r}")
    return tuple(number("duration", v, 0.0, None, lo_open=True) for v in items)


def subsurface_grid(value: Any) -> tuple[tuple[float, float, int], tuple[float, float, int]]:
    """A ``subsurface`` grid: ``{"x": [start, stop, points], "z": [start, stop, points]}``.

    Both axes in units of a; z (depth) from >= 0, x may start below 0 (cylinder); stop >
    start; 2 ... 1001 points. A missing axis takes :data:`SUBSURFACE_GRID`'s.

    Returns
    -------
    tuple
        ``((x0, x1, nx), (z0, z1, nz))``.

    Raises
    ------
    InputError
        Naming the axis and what a good value is.
    """
    req = ("a mapping with x and/or z, each [start, stop, points] (start < stop, z start "
           ">= 0, 2 ... 1001 points)")
    if not isinstance(value, Mapping) or not set(value) <= {"x", "z"}:
        raise InputError("subsurface_grid", req, value)
    out = []
    for axis, default in zip(("x", "z"), SUBSURFACE_GRID):
        spec = value.get(axis, default)
        if not is_sequence(spec) or len(spec) != 3:
            raise InputError(f"subsurface_grid.{axis}", "[start, stop, points]", spec)
        lo = number(f"subsurface_grid.{axis} start", spec[0], 0.0 if axis == "z" else None)
        hi = number(f"subsurface_grid.{axis} stop", spec[1])
        if not hi > lo:
            raise InputError(f"subsurface_grid.{axis}", "[start, stop, points] with stop > "
                             "start", spec)
        out.append((lo, hi, integer(f"subsurface_grid.{axis} points", spec[2], 2, 1001)))
    return out[0], out[1]

