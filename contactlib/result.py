"""Result object shared by every method and geometry, and short ``repr`` of results.

Printing a result shows a few lines, in the style of scipy's
``OptimizeResult``: a title, the key scalars, and the arrays by name and
shape (never their contents), e.g.::

    Solution: sphere, nu = 0.3, method = default, n = 256
             stick_ratio: 0.5
    friction_coefficient: 0.152483 (estimated relative error 1.6e-05)
    ...
                  arrays: xi, pressure, shear, tangential_displacement (201,)
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .model.indenter import indenter

__all__ = ["Solution", "CaseRecord", "format_fields", "short_repr", "history_repr",
           "substrate_text"]


# ----------------------------------------------------------------------------- short repr
def _with_error(value: float, relative_error: float) -> str:
    """``value`` followed by its estimated relative error, when there is one (a zero has
    none: it is zero at any scale)."""
    if isinstance(relative_error, float) and math.isfinite(relative_error) and value != 0:
        return f"{_scalar(value)} (estimated relative error {relative_error:.1e})"
    return _scalar(value)


def _scalar(value: Any) -> str:
    """One value in a few characters: floats to 6 digits, arrays by shape."""
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value))
    if isinstance(value, (float, np.floating)):
        return "inf" if math.isinf(value) and value > 0 else f"{float(value):.6g}"
    if isinstance(value, np.ndarray):
        return f"array{value.shape} {value.dtype}"
    if isinstance(value, (tuple, list)):
        shown = ", ".join(_scalar(v) for v in list(value)[:6])
        more = f", ... ({len(value)} values)" if len(value) > 6 else ""
        return f"({shown}{more})" if isinstance(value, tuple) else f"[{shown}{more}]"
    if isinstance(value, dict):
        return "{" + ", ".join(map(str, value)) + "}" if value else "{}"
    if isinstance(value, str):
        return repr(value) if len(value) <= 100 else repr(value[:97] + "...")
    text = repr(value)
    if len(text) <= 100:
        return text
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return f"<{type(value).__name__}>"
    return text[:97] + "..."


def format_fields(title: str, items: Iterable[tuple[str, Any]]) -> str:
    """``title`` then one ``name: value`` line an item, names right-aligned.

    String values are shown as given; anything else through a compact
    formatter (floats to 6 significant digits, arrays by shape and dtype,
    long sequences shortened).
    """
    rows = [(name, value if isinstance(value, str) else _scalar(value))
            for name, value in items]
    width = max((len(name) for name, _ in rows), default=0)
    return "\n".join([title] + [f"{name:>{width}}{': ' if name else '  '}{value}"
                                for name, value in rows])


def _arrays_by_shape(obj: Any, names: Iterable[str]) -> list[tuple[str, str]]:
    """Lines ``name, name: shape`` grouping the arrays of ``obj`` by shape."""
    groups: dict[tuple, list[str]] = {}
    for name in names:
        value = getattr(obj, name, None)
        if value is not None:
            groups.setdefault(np.shape(value), []).append(name)
    return [("arrays" if i == 0 else "", f"{', '.join(group)} {shape}")
            for i, (shape, group) in enumerate(groups.items())]


def short_repr(obj: Any) -> str:
    """A few-line ``repr`` of any dataclass: scalars by value, arrays by shape."""
    fields = [f.name for f in dataclasses.fields(obj)]
    arrays = [n for n in fields if isinstance(getattr(obj, n), np.ndarray)]
    scalars = [(n, _scalar(getattr(obj, n))) for n in fields if n not in arrays]
    return format_fields(f"{type(obj).__name__}:", scalars + _arrays_by_shape(obj, arrays))


def _status(converged: Any, iterations: Any, residual: Any) -> str:
    it = int(iterations)
    return (f"{bool(converged)} ({it} iteration{'' if it == 1 else 's'}, "
            f"residual {float(residual):.3g})")


def _last(res: Any, name: str) -> float:
    """The last value of the per-step array ``name`` of ``res`` (NaN if it has none)."""
    values = np.asarray(getattr(res, name, ()), dtype=float)
    return float(values[-1]) if values.size else float("nan")


def history_repr(res: Any) -> str:
    """Short ``repr`` of a :class:`contactlib.history_api.HistoryResult`."""
    path = " -> ".join(f"{v:g}" for v in res.load_path[:8])
    if len(res.load_path) > 8:
        path += f" -> ... ({len(res.load_path)} levels)"
    head = (f"HistoryResult: {res.geometry}, nu = {res.nu:.10g}, k = {_scalar(res.friction)}, "
            f"n = {res.n}")
    if indenter(res.geometry).reports_layer(res.slab_ratio):
        head += f", a_max/h = {res.slab_ratio:g}"
    if res.slab_ratio > 0:
        head += f" ({getattr(res, 'base', 'smooth')} base{substrate_text(res)})"
    steps = int(np.size(res.load_ratio)) - 1
    done = int(np.count_nonzero(np.asarray(res.converged)[1:]))
    iters = np.asarray(res.iterations)

    def state(j: int) -> str:
        return (f"step {j}: load_ratio {_scalar(res.load_ratio[j])}, contact_radius "
                f"{_scalar(res.contact_radius[j])}, stick_ratio {_scalar(res.stick_ratio[j])}")

    items: list[tuple[str, Any]] = [
        ("load_path", f"{path} ({res.steps} steps a "
                      f"{'load travel of P_max' if getattr(res, 'segment_steps', ()) else 'segment'}"
                      f", {steps} in all)"),
        ("top load", state(int(np.argmax(res.load_ratio)))),
        ("end", state(steps)),
        ("frictional_work", "at the end (cumulative): " + _with_error(
            res.frictional_work[-1], _last(res, "work_error_estimate"))),
        ("converged", f"{done}/{steps} steps (at most {int(iters.max()) if iters.size else 0} "
                      f"iterations a step)"),
        ("message", res.message or "(none)"),
    ]
    names = ["xi", "xi_bounds", "segment", "load_ratio", "contact_radius", "stick_ratio",
             "indentation", "frictional_work", "converged", "iterations", "residual_norm",
             "state", "pressure", "shear", "tangential_displacement"]
    if getattr(res, "relaxation", ()):  # a viscoelastic body: its relaxation and energies
        items.insert(4, ("relaxation", f"{[list(p) for p in res.relaxation]} (g, tau); "
                                       f"duration {_scalar(res.time[-1])}"))
        items.insert(5, ("energy", f"external {_scalar(res.external_work[-1])} = stored "
                                   f"{_scalar(res.stored_energy[-1])} + viscous "
                                   f"{_scalar(res.viscous_work[-1])} + frictional (at the end)"))
        names += ["time", "external_work", "stored_energy", "viscous_work"]
    return format_fields(head, items + _arrays_by_shape(res, names))


def substrate_text(result: Any) -> str:
    """``": E2/E1 = 0.1, nu2 = 0.2"``: a coated body's substrate (``base = "elastic"``), or ""."""
    if getattr(result, "base", "smooth") != "elastic":
        return ""
    return (f": E2/E1 = {float(result.substrate_modulus):g}, "
            f"nu2 = {float(result.substrate_poisson_ratio):g}")


@dataclass(frozen=True, repr=False, eq=False)
class CaseRecord:
    """One solved self-similar case as the stages hand it on (units E* = a = R = 1).

    Made by :func:`contactlib.stages.case_record` from a discrete solution
    (default or paper method), completed by the error estimates of
    :func:`contactlib.stages.solve_cases`, turned into a :class:`Solution` by
    :func:`contactlib.stages.to_solution`. The workflow carries it between
    its rules as ``.npz`` (:func:`contactlib.io.write_records`,
    :func:`contactlib.io.read_records`; one array ``"<i>/<field>"`` a field,
    fields that are None left out). Frozen: a stage that adds to a record
    returns a new one (:func:`dataclasses.replace`). Compared by identity
    (its arrays have no single truth value).

    Attributes
    ----------
    kind : str
        The solver family that made it: ``"default"`` (nodal, piecewise-linear
        tractions) or ``"paper"`` (the paper's rings or strips, step tractions).
    stick_ratio : float
        c/a of the case (for nu = 0.5 the one asked for; the mesh then has c = 0).
    nodes : ndarray, shape (N + 1,)
        Element nodes r/a (x/a), 0 ... 1.
    stick_index : int
        M with ``nodes[M]`` = c of the mesh.
    p : ndarray
        Pressure in units of E* a/R: nodal values (default, N + 1) or one a
        ring (paper, N).
    traction : ndarray
        The shear coefficient, same layout as ``p``: q = shape(xi) traction,
        shape = r/a for rings, 1 for strips (units of E* a/R).
    k : float
        Friction coefficient (>= 0; ``inf`` at full adhesion).
    delta : float
        Indentation in units of a^2/R (NaN for the paper's scheme, which has
        no delta).
    converged : bool
    residual_norm : float
        Relative residual of the last Newton step.
    iterations : int
    message : str
        Notes joined by "; " (empty when there is nothing to say).
    load : float
        Total load in units of E* a^3/R (sphere) or E* a^2/R per unit length
        (cylinder).
    round_off : float
        Last relative Newton step when Newton stopped on the round-off floor
        (0 otherwise).
    nodal_u, nodal_du : ndarray or None
        u (units a^2/R) and du/dx (units a/R) at the nodes, from the solve's
        own operators (default method only).
    slip_x, slip_w, slip_q, slip_s : ndarray or None
        The slip-zone samples of the checks and the work: points xi, their
        quadrature weights, the shear q (units E* a/R) and the slip rate
        s = 2u - xi du/dxi (units a^2/R); None when samples were not asked for.
    stick_q, stick_p : ndarray or None
        Shear and pressure at stick-zone points (element midpoints, and the
        nodes for continuous tractions), units E* a/R.
    elements : int or None
        The n a tolerance reached (None without a tolerance).
    error_estimate, load_error_estimate, work_error_estimate : float
        Estimated relative errors of k, the load and the work (NaN when not
        estimated).
    resolved : bool
        Converged, and ``error_estimate`` at most ``max_error``.
    max_error : float
        The accuracy asked for (NaN when not estimated).
    """

    __repr__ = short_repr

    kind: str
    stick_ratio: float
    nodes: np.ndarray
    stick_index: int
    p: np.ndarray
    traction: np.ndarray
    k: float
    delta: float
    converged: bool
    residual_norm: float
    iterations: int
    message: str
    load: float
    round_off: float = 0.0
    nodal_u: np.ndarray | None = None
    nodal_du: np.ndarray | None = None
    slip_x: np.ndarray | None = None
    slip_w: np.ndarray | None = None
    slip_q: np.ndarray | None = None
    slip_s: np.ndarray | None = None
    stick_q: np.ndarray | None = None
    stick_p: np.ndarray | None = None
    elements: int | None = None
    error_estimate: float = float("nan")
    load_error_estimate: float = float("nan")
    work_error_estimate: float = float("nan")
    resolved: bool = False
    max_error: float = float("nan")


class _OnAccess:
    """A dataclass field that may be given as a zero-argument callable: called once, on first
    access, and its value kept (what costs kernel work is computed when it is read, never for
    a caller who does not read it). Required like a plain field (no default)."""

    def __set_name__(self, owner: type, name: str) -> None:
        self._slot = "_" + name + "_value"

    def __get__(self, obj: Any, objtype: type | None = None) -> Any:
        if obj is None:  # no default: the dataclass keeps the field required
            raise AttributeError(self._slot)
        value = obj.__dict__[self._slot]
        if callable(value):
            value = value()
            obj.__dict__[self._slot] = value
        return value

    def __set__(self, obj: Any, value: Any) -> None:
        obj.__dict__[self._slot] = value


@dataclass(repr=False)
class Solution:
    """One solved partial-slip case, in the scalings of docs/conventions.md.

    All profile arrays live on ``xi`` (r/a or x/a, 0...1).

    Attributes
    ----------
    geometry : str
        ``"sphere"`` or ``"cylinder"``.
    nu : float
        Poisson's ratio of the elastic body.
    method : str
        Discretization (``"default"``, ``"paper"``, ...).
    n : int
        Number of elements (rings or strips) across the half-contact.
    slab_ratio : float
        a/h of the layer (0 = half-space or half-plane).
    stick_ratio : float
        c/a, 0 (frictionless) ... 1 (full adhesion).
    friction_coefficient : float
        k; ``inf`` at full adhesion.
    xi : ndarray
        Output abscissae r/a.
    pressure : ndarray
        p / p0 with p0 the Hertz peak pressure at the same contact radius.
    shear : ndarray
        q / p0, traction on the elastic body, positive away from the axis.
    tangential_displacement : ndarray
        u R / a^2, positive away from the axis. It needs the kernels at every ``xi`` (about
        as much work as the rest of a case's post-processing), so :func:`~contactlib.solve`
        and :func:`~contactlib.sweep` compute it when it is first read, once.
    load_ratio : float
        P / P_Hertz(a).
    frictional_work : float
        Loading half-cycle work, V R^2/(E* a^5) (sphere) or V R^2/(E* a^4)
        per unit length (cylinder, both sides of the axis). NaN when not
        requested.
    slip_direction_ok, stick_admissible, consistent : bool
        Consistency flags (see :mod:`contactlib.checks`).
    converged : bool
    residual_norm : float
    iterations : int
    message : str
        Human-readable note (e.g. why a case is degenerate).
    indenter_modulus_ratio : float
        E1/E2 of the indenter over the body (``inf``: rigid).
    indenter_poisson_ratio : float
        nu1 of the indenter (the body's nu for a rigid one, where it plays no role).
    dundurs_beta : float
        Dundurs' beta of the pair (> 0: slip inward, q = k p; < 0: outward, q = -k p).
    base : str
        The layer's rigid base, "smooth" or "bonded", or "elastic" (a coated
        body) (irrelevant at a/h = 0).
    profile : str
        The indenter's profile: "paraboloid" (Hertz, the default), "cone" or "power"
        (:mod:`contactlib.model.profiles`).
    exponent : float
        Its exponent d, h ~ r^d (2 for the paraboloid, 1 for the cone).
    substrate_modulus, substrate_poisson_ratio : float
        E2/E1 and nu2 of a coated body's substrate (``base = "elastic"``; inf and
        NaN otherwise).
    model : contactlib.model.Contact or None
        The problem model that was solved (indenter, profile, body, layer, base):
        ask it rather than rebuilding it from the fields above, which copy it for
        the datasets. None for a solution rebuilt from a dataset or a record file.
    error_estimate : float
        Estimated relative error of ``friction_coefficient`` (embedded
        solves on the nested meshes n/4 and n/2; 0 where k is exact).
    load_error_estimate, work_error_estimate : float
        The same for ``load_ratio`` and ``frictional_work`` (NaN when not
        estimated).
    resolved : bool
        Converged, ``error_estimate`` at most ``max_error``, and (default
        and extrapolated methods, when the checks ran) consistent; a case
        that is not resolved is not to be used as a good number.
    max_error : float
        The accuracy asked for (relative error of k).
    extra : dict
        ``stick_violation``, ``slip_violation`` (:mod:`contactlib.checks`) and
        ``indentation`` (delta in units of a^2/R); for the default and extrapolated
        methods also the solve's own piecewise-linear tractions, ``nodes`` (r/a or x/a)
        with ``nodal_pressure`` and ``nodal_shear`` (p/p0, q/p0), which
        :func:`contactlib.stresses.subsurface_stresses` integrates.

    Examples
    --------
    >>> from contactlib import solve
    >>> sol = solve("cylinder", 0.3, stick_ratio=0.5, n=64)
    >>> print(repr(sol).splitlines()[0])
    Solution: cylinder, nu = 0.3, method = default, n = 64, a/h = 0
    >>> float(sol.xi[0]), float(sol.xi[-1]), float(sol.pressure[-1])  # smooth edge: p(a) = 0
    (0.0, 1.0, 0.0)
    >>> float(sol.shear[0]), float(sol.tangential_displacement[0])  # nothing moves on the axis
    (0.0, 0.0)
    """

    geometry: str
    nu: float
    method: str
    n: int
    slab_ratio: float
    stick_ratio: float
    friction_coefficient: float
    xi: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    tangential_displacement: np.ndarray = _OnAccess()  # type: ignore[assignment]
    load_ratio: float
    frictional_work: float = float("nan")
    slip_direction_ok: bool = True
    stick_admissible: bool = True
    consistent: bool = True
    converged: bool = True
    residual_norm: float = 0.0
    iterations: int = 0
    message: str = ""
    error_estimate: float = float("nan")
    load_error_estimate: float = float("nan")
    work_error_estimate: float = float("nan")
    resolved: bool = False
    max_error: float = float("nan")
    extra: dict = field(default_factory=dict)
    indenter_modulus_ratio: float = float("inf")
    indenter_poisson_ratio: float = float("nan")
    dundurs_beta: float = float("nan")
    base: str = "smooth"
    profile: str = "paraboloid"
    exponent: float = 2.0
    substrate_modulus: float = float("inf")
    substrate_poisson_ratio: float = float("nan")
    model: Any = field(default=None, repr=False, compare=False)

    def __repr__(self) -> str:
        head = f"Solution: {self.geometry}, nu = {self.nu:.10g}, method = {self.method}, n = {self.n}"
        if indenter(self.geometry).reports_layer(self.slab_ratio):
            head += f", a/h = {self.slab_ratio:g}"
        if self.slab_ratio > 0:
            head += f" ({self.base} base{substrate_text(self)})"
        if self.profile != "paraboloid":
            head += f", profile = {self.profile} (d = {self.exponent:g})"
        if self.indenter_modulus_ratio != float("inf"):
            head += (f", E1/E2 = {self.indenter_modulus_ratio:g}, nu1 = "
                     f"{self.indenter_poisson_ratio:g}, beta = {self.dundurs_beta:.4g}")
        items: list[tuple[str, Any]] = [
            ("stick_ratio", self.stick_ratio),
            ("friction_coefficient", _with_error(self.friction_coefficient, self.error_estimate)),
            ("load_ratio", _with_error(self.load_ratio, self.load_error_estimate)),
            ("frictional_work", _with_error(self.frictional_work, self.work_error_estimate)),
            ("resolved", f"{bool(self.resolved)} (max_error {_scalar(self.max_error)})"),
            ("converged", _status(self.converged, self.iterations, self.residual_norm)),
            ("consistent", f"{bool(self.consistent)} (slip_direction_ok "
                           f"{bool(self.slip_direction_ok)}, stick_admissible "
                           f"{bool(self.stick_admissible)})"),
            ("message", self.message or "(none)"),
        ]
        if self.extra:
            items.append(("extra", self.extra))
        return format_fields(head, items + _arrays_by_shape(
            self, ("xi", "pressure", "shear", "tangential_displacement")))
