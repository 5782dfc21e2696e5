"""Scenes: the named cases of a workflow configuration, validated and keyed.

A scene (``config/config.yaml``, under ``scenes:``) is of one of two kinds:

* ``self-similar`` (the default): a geometry, a material, a method and a
  resolution ``n`` *or* an accuracy target ``tolerance`` (relative error in
  k; the method and n are then picked from the measured convergence, see
  :mod:`contactlib.accuracy`), the stick ratios to solve and the outputs it
  needs -> a :class:`Scene`;
* ``history``: an incremental load path (:func:`contactlib.history`)
  for one or several friction coefficients -> a :class:`HistoryScene`;
* ``physical``: a load path of forces in physical units (radius, materials,
  forces; :func:`contactlib.physical.physical_history`) -> a
  :class:`PhysicalScene`.
 This module turns one scene's mapping into a :class:`Scene`,
validated with the library's own rules (the workflow's JSON schema then
checks what they let through; its enums and bounds are :mod:`contactlib.validate`'s),
and derives what the workflow needs from it:
which influence parts to build and under which shared key, which stages to
run, and a hash of the scene's configuration for provenance.

It imports neither Snakemake nor anything that touches the disk.

Examples
--------
>>> s = parse_scene("demo", {"geometry": "sphere", "nu": 0.3, "n": 32,
...                          "stick_ratios": [0.0, 0.5], "outputs": ["k_curve"]})
>>> s.parts, s.needs_samples, s.stages
(('normal', 'shear'), True, ('check',))
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import dataclass
from typing import Any, Mapping

from . import accuracy, validate
from .model import materials, profiles
from .model.geometry import Geometry
from .model.indenter import indenter
from .discretization.operators import parts_needed
from .result import short_repr
from .validate import DEFAULT_OUTPUTS, OUTPUTS

# No solver module (stages, and scipy with it) is imported here: the workflow imports
# this module in Snakemake's own process, which builds the DAG before any job starts.

__all__ = ["Scene", "HistoryScene", "PhysicalScene", "KINDS", "ConfigError", "parse_scene", "parse_named_scene",
           "parse_scenes",
           "config_hash", "material_pair_scenes", "scene_mapping"]

KINDS = ("self-similar", "history", "physical")
_KEYS = ("kind", "geometry", "nu", "method", "n", "tolerance", "max_error", "stick_ratios",
         "slab_ratio", "base", "outputs", "indenter", "body", "subsurface_grid", "profile",
         "exponent", "substrate_modulus", "substrate_nu")
_HISTORY_KEYS = ("kind", "geometry", "nu", "friction", "load_path", "steps", "n",
                 "slab_ratio", "base", "max_error", "indenter", "body", "relaxation",
                 "duration", "profile", "exponent", "tangential_path", "bulk_stress",
                 "substrate_modulus", "substrate_nu", "flat_ratio", "tangential_displacement")
# keys of a history scene that a fretting path (tangential_path) does not take: the
# fretting solvers cover the half-plane and the half-space, elastic bodies only
_NOT_FRETTING = ("slab_ratio", "base", "relaxation", "duration", "substrate_modulus",
                 "substrate_nu")
_PHYSICAL_KEYS = ("kind", "geometry", "radius", "length", "thickness", "base", "substrate",
                  "indenter", "body", "friction", "load_path", "steps", "n", "max_error",
                  "relaxation", "times")
_INDENTER_KEYS = {"indenter_modulus": "indenter.modulus_ratio", "indenter_nu": "indenter.nu"}


def config_hash(raw: Mapping[str, Any]) -> str:
    """A short SHA-256 of a scene's mapping (canonical JSON, sorted keys)."""
    text = json.dumps(raw, sort_keys=True, separators=(",", ":"), default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _base_spec(base: str) -> dict[str, str]:
    """``{"base": base}`` for a bonded base, {} for the default (keys and jobs stay as before)."""
    return {} if base == "smooth" else {"base": base}


def _profile_spec(profile: str, exponent: float | None,
                  flat_ratio: float | None = None) -> dict[str, Any]:
    """``profile`` (and ``exponent`` or ``flat_ratio``) keywords, {} for the paraboloid (keys
    and jobs as before)."""
    if profile == "paraboloid":
        return {}
    return {"profile": profile, **({} if exponent is None else {"exponent": exponent}),
            **({} if flat_ratio is None else {"flat_ratio": flat_ratio})}


def _scene_profile(raw: Mapping[str, Any],
                   bad: "_Problems") -> tuple[str, float | None, float | None]:
    """(name, exponent, flat_ratio) of a scene's ``profile``/``exponent``/``flat_ratio``
    keys, checked by :func:`contactlib.model.profiles.profile` (the spelling of ``--profile``,
    ``--exponent``, ``--flat-ratio``); exponent None unless ``power``, flat_ratio None
    unless ``rounded``. A problem is recorded under the key it concerns."""
    if not {"profile", "exponent", "flat_ratio"} & set(raw):
        return "paraboloid", None, None
    try:
        shape = profiles.profile(raw.get("profile", "paraboloid"), raw.get("exponent"),
                                 raw.get("flat_ratio"))
    except validate.InputError as exc:
        bad.add(exc.name, str(exc))
        return "paraboloid", None, None
    return (shape.name, shape.exponent if shape.name == "power" else None,
            shape.flat if shape.is_rounded else None)


def _ratio_digest(values: tuple[float, ...]) -> str:
    text = ",".join(repr(float(v)) for v in sorted(set(values)))
    return hashlib.sha256(text.encode()).hexdigest()[:10]


@dataclass(frozen=True, repr=False)
class Scene:
    """One validated scene.

    Attributes
    ----------
    name : str
    geometry : {"sphere", "cylinder"}
    nu : float
    method : {"default", "paper", "paper-literal", "extrapolated"}
    n : int
        Elements across the half-contact.
    stick_ratios : tuple of float
        c/a values, in the configured order (``all`` expanded to m/n).
    slab_ratio : float
        a/h of the layer (0 = half-space or half-plane).
    base : {"smooth", "bonded"}
        The layer's rigid base (key ``base``, default smooth).
    outputs : tuple of str
        Subset of ``k_curve``, ``stresses``, ``displacements``, ``energy``,
        ``subsurface`` (default: all but ``subsurface``).
    hash : str
        :func:`config_hash` of the scene's mapping as configured.
    tolerance : float or None
        Relative error in k the scene asked for (then ``method`` and ``n``
        were picked by :func:`contactlib.accuracy.plan`, and the solve
        checks the error a posteriori, refining n where needed).
    subsurface_grid : tuple
        ``((x0, x1, nx), (z0, z1, nz))`` of the ``subsurface`` output's grid (key
        ``subsurface_grid``, default :data:`contactlib.validate.SUBSURFACE_GRID`).
    """

    __repr__ = short_repr  # a few lines: long tuples shortened

    name: str
    geometry: str
    nu: float
    method: str
    n: int
    stick_ratios: tuple[float, ...]
    slab_ratio: float
    outputs: tuple[str, ...]
    hash: str
    tolerance: float | None = None
    max_error: float = validate.DEFAULT_MAX_ERROR
    kind: str = "self-similar"
    indenter_modulus: float = float("inf")
    indenter_nu: float | None = None
    base: str = "smooth"
    subsurface_grid: tuple = validate.SUBSURFACE_GRID
    profile: str = "paraboloid"
    exponent: float | None = None
    substrate_modulus: float = float("inf")
    substrate_nu: float | None = None

    @property
    def geometry_object(self) -> Geometry:
        return Geometry(self.geometry, self.nu, self.slab_ratio, self.indenter_modulus,
                        self.indenter_nu, self.base, self.substrate_modulus, self.substrate_nu,
                        profile=profiles.profile(self.profile, self.exponent))

    def _substrate_spec(self) -> dict[str, Any]:
        """A coated body's substrate keywords ({} on a rigid base: keys stay as before)."""
        if self.base != validate.COATED_BASE:
            return {}
        return {"substrate_modulus": self.substrate_modulus, "substrate_nu": self.substrate_nu}

    def solve_spec(self) -> dict[str, Any]:
        """The keywords beyond the influence set's that change a scene's numbers: the
        profile (the gap and the adherence condition); {} for the paraboloid."""
        return _profile_spec(self.profile, self.exponent)

    def _indenter_spec(self) -> dict[str, Any]:
        """The elastic indenter's keywords ({} for the rigid one, whose keys stay as before)."""
        if self.indenter_modulus == float("inf"):
            return {}
        return {"indenter_modulus": self.indenter_modulus, "indenter_nu": self.indenter_nu}

    @property
    def parts(self) -> tuple[str, ...]:
        """Influence parts needed: no shear matrices for a frictionless (or nu = 0.5) scene."""
        return parts_needed(self.geometry_object, self.stick_ratios)

    @property
    def influence_key(self) -> str:
        """Name of the influence set this scene uses, shared by every scene with equal key.

        The paper's rings do not depend on c/a; the default method's meshes
        do (a node at c), so its key carries a digest of the stick ratios.
        """
        key = f"{self.geometry}-nu{self.nu!r}-{self.method}-n{self.n}"
        if indenter(self.geometry).reports_layer(self.slab_ratio):
            key += f"-h{self.slab_ratio!r}"
        if self.slab_ratio > 0 and self.base != "smooth":
            key += f"-{self.base}"
        if self._indenter_spec():
            key += f"-E{self.indenter_modulus!r}-nu1{self.indenter_nu!r}"
        if self._substrate_spec():  # (the profile is not in the operators: shared)
            key += f"-E2_{self.substrate_modulus!r}-nu2_{self.substrate_nu!r}"
        if validate.method_of(self.method).nodal:  # a mesh per stick ratio
            key += "-c" + _ratio_digest(self.solved_ratios)
        return key

    @property
    def solved_ratios(self) -> tuple[float, ...]:
        """The stick ratios whose meshes are needed (nu = 0.5 reduces all to 0)."""
        if "shear" not in self.parts and self.geometry_object.decoupled:
            return (0.0,)
        return tuple(sorted(set(self.stick_ratios)))

    @property
    def needs_samples(self) -> bool:
        """Whether the solve stage must store slip/stick samples (checks or energy)."""
        return "k_curve" in self.outputs or "energy" in self.outputs

    @property
    def stages(self) -> tuple[str, ...]:
        """Post-processing stages beyond solve and assemble, in DAG order.

        The displacement profiles a scene may ask for are computed by the
        assemble stage itself (:func:`contactlib.pipeline.displacements`),
        not by a stage of their own.
        """
        out = []
        if "k_curve" in self.outputs:
            out.append("check")
        if "energy" in self.outputs:
            out.append("energy")
        return tuple(out)

    def influence_spec(self) -> dict[str, Any]:
        """What the influence stage needs (equal for every scene with the same key)."""
        return {"geometry": self.geometry, "nu": self.nu, "method": self.method, "n": self.n,
                "slab_ratio": self.slab_ratio, "stick_ratios": list(self.solved_ratios),
                **self._indenter_spec(), **_base_spec(self.base), **self._substrate_spec()}


class ConfigError(ValueError):
    """Every problem of a scene (or of all scenes), one line each.

    ``problems`` lists the lines, each starting with ``scenes.<name>.<key>:``;
    ``str()`` joins them with newlines.
    """

    def __init__(self, problems: list[str]) -> None:
        self.problems = list(problems)
        super().__init__("\n".join(self.problems))


class _Problems:
    """Collects ``scenes.<name>.<key>: message`` lines instead of stopping at the first."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.lines: list[str] = []

    def add(self, key: str, message: str) -> None:
        self.lines.append(f"scenes.{self.name}.{key}: {message}")

    def check(self, key: str, func, *args):
        """``func(*args)``, or None after recording its ValueError under ``key``."""
        try:
            return func(*args)
        except ValueError as exc:
            self.add(key, str(exc))
            return None

    def raise_any(self) -> None:
        if self.lines:
            raise ConfigError(self.lines)

    def keys(self, raw: Mapping[str, Any], allowed: tuple[str, ...],
             required: tuple[str, ...], kind: str) -> None:
        """Record every key of ``raw`` not ``allowed`` and every ``required`` one missing."""
        for key in sorted(str(k) for k in set(raw) - set(allowed)):
            self.add(key, f"unknown key for a {kind} scene (allowed: {', '.join(allowed)})")
        for key in required:
            if key not in raw:
                self.add(key, "is required")


def _scene_indenter(raw: Mapping[str, Any], nu: float | None,
                    bad: _Problems) -> tuple[float, float | None]:
    """(E1/E2, nu1) of a scene's ``indenter``/``body`` keys ((inf, None): rigid).

    A problem is recorded in ``bad`` under the key it concerns (named from the
    rule that failed, not from its text), and the rigid indenter returned.
    """
    if "indenter" not in raw and "body" not in raw:
        return math.inf, None
    try:
        return materials.scene_indenter(raw.get("indenter"), raw.get("body"), nu)
    except validate.InputError as exc:
        bad.add(_INDENTER_KEYS.get(exc.name, exc.name), str(exc))
        return math.inf, None


def parse_scene(name: str, raw: Mapping[str, Any]) -> "Scene | HistoryScene":
    """Validate one scene mapping with the library's rules.

    Every key is checked, and every problem is reported at once.

    Raises
    ------
    ConfigError
        A :class:`ValueError` with one line a problem, each naming the scene
        and the key, e.g. ``scenes.bad.nu: nu must be in (-1, 0.5], got 0.7``.
    """
    if not isinstance(raw, Mapping):
        raise ConfigError([f"scenes.{name}: must be a mapping, got {raw!r}"])
    kind = raw.get("kind", "self-similar")
    if kind not in KINDS:
        raise ConfigError([f"scenes.{name}.kind: must be one of {', '.join(KINDS)}, "
                           f"got {kind!r}"])
    if kind == "history":
        return _parse_history(name, raw)
    if kind == "physical":
        return _parse_physical(name, raw)

    bad = _Problems(name)
    for key in sorted(str(k) for k in set(raw) - set(_KEYS)):
        bad.add(key, f"unknown key (allowed: {', '.join(_KEYS)})")
    for key in ("geometry", "nu", "stick_ratios"):
        if key not in raw:
            bad.add(key, "is required")
    tolerance = None
    if "tolerance" in raw:
        both = [key for key in ("n", "method") if key in raw]
        for key in both:
            bad.add(key, "give either tolerance or n/method, not both (with a tolerance the "
                         "method and n are picked from the measured convergence)")
        tolerance = bad.check("tolerance", accuracy.check_tolerance, raw["tolerance"])
        if raw.get("stick_ratios") == "all":
            bad.add("stick_ratios", "'all' means m/n and needs a given n; with a tolerance "
                                    "list the stick ratios")
    max_error = bad.check("max_error", validate.max_error,
                          raw.get("max_error", validate.DEFAULT_MAX_ERROR))
    method = raw.get("method", validate.DEFAULT_METHOD)
    # each key on its own first, so that every bad key is named ...
    geometry = bad.check("geometry", validate.geometry, raw.get("geometry")) \
        if "geometry" in raw else None
    method = bad.check("method", validate.method, method)
    nu = bad.check("nu", validate.nu, raw.get("nu")) if "nu" in raw else None
    slab = bad.check("slab_ratio", validate.slab_ratio, raw.get("slab_ratio", 0.0))
    base = bad.check("base", validate.base, raw.get("base", "smooth"), True)
    substrate = (math.inf, None)
    if base is not None and geometry is not None and method is not None:
        try:
            substrate = validate.substrate(base, raw.get("substrate_modulus"),
                                           raw.get("substrate_nu"), geometry, method)
        except validate.InputError as exc:
            bad.add(exc.name, str(exc))
    if base == validate.COATED_BASE and "tolerance" in raw:
        bad.add("tolerance", "tolerance is not planned on a coated body (base 'elastic'): "
                             "give n (method 'default') instead")
    if not profiles.takes(raw.get("profile", "paraboloid"), "self-similar"):
        bad.add("profile", f"profile {raw['profile']!r} is for history only (kind: history): "
                           f"the punch's contact does not grow self-similarly")
        profile, exponent = "paraboloid", None
    else:
        profile, exponent, _ = _scene_profile(raw, bad)
    if profile != "paraboloid":
        if "tolerance" in raw:
            bad.add("tolerance", f"tolerance is planned for the paraboloid only; for the "
                                 f"{profile} profile give n (method 'default') instead")
        elif method is not None and not validate.method_of(method).any_profile:
            bad.add("method", f"method {method!r} is measured for the paraboloid only; use "
                              f"method 'default' for the {profile} profile")
    outputs = raw.get("outputs", list(DEFAULT_OUTPUTS))
    if not isinstance(outputs, (list, tuple)) or not outputs or \
            not all(isinstance(o, str) and o in OUTPUTS for o in outputs) or \
            len(set(outputs)) != len(outputs):
        bad.add("outputs", f"must be a non-empty list of distinct {', '.join(OUTPUTS)}, got "
                           f"{outputs!r}")
        outputs = []
    grid = bad.check("subsurface_grid", validate.subsurface_grid, raw.get("subsurface_grid", {}))
    if "subsurface" not in outputs and "subsurface_grid" in raw:
        bad.add("subsurface_grid", "given without subsurface in outputs")
    ind = _scene_indenter(raw, nu, bad)
    n = None
    if None not in (geometry, method, nu, slab, base):  # ... then what depends on several keys
        slab = bad.check("slab_ratio", validate.slab_ratio, slab, geometry, base)
        n = bad.check("n", validate.n, raw.get("n"), method)
    ratios = None
    if n is not None and "stick_ratios" in raw:
        ratios = bad.check("stick_ratios", validate.stick_ratios, raw["stick_ratios"], n)
        if ratios is not None and not validate.method_of(method).nodal:
            for c in ratios:
                if bad.check("stick_ratios", validate.paper_multiple, c, n,
                             "stick_ratios") is None:
                    break
    bad.raise_any()
    if tolerance is not None:
        method, n = accuracy.plan(Geometry(geometry, nu, slab, *ind, base), ratios, tolerance,
                                  methods=accuracy.PLANNED_METHODS)
    return Scene(name=name, geometry=geometry, nu=nu, method=method, n=n,
                 stick_ratios=tuple(ratios), slab_ratio=slab,
                 outputs=tuple(o for o in OUTPUTS if o in outputs), hash=config_hash(raw),
                 tolerance=tolerance, max_error=max_error, indenter_modulus=ind[0],
                 indenter_nu=ind[1], base=base, subsurface_grid=grid, profile=profile,
                 exponent=exponent, substrate_modulus=substrate[0], substrate_nu=substrate[1])


@dataclass(frozen=True, repr=False)
class HistoryScene:
    """One validated scene of kind ``history`` (see :func:`contactlib.history`).

    Attributes
    ----------
    name, geometry, nu, slab_ratio, hash
        As for :class:`Scene` (``slab_ratio`` is a_max/h).
    frictions : tuple of float
        Friction coefficients, one history each (stacked along
        ``friction_coefficient`` in the scene's dataset).
    load_path : tuple of float
        Load levels P/P_max, starting at 0.
    steps : int
        Steps per path segment.
    n : int
        Elements over [0, 1.2 a_max].
    max_error : float
        Accuracy a step must reach to be flagged resolved (default 1e-3).
    indenter_modulus : float
        E1/E2 of an elastic indenter (``inf``: rigid, the default), from the
        scene's ``indenter`` key (a mapping, or a material name with ``body``).
    indenter_nu : float or None
        Poisson's ratio of the indenter (None: rigid, or the body's).
    relaxation : tuple of (g, tau)
        A viscoelastic body's Prony terms (key ``relaxation: [[g, tau], ...]``);
        empty: elastic.
    durations : tuple of float
        Durations of the path segments (key ``duration``: the path's, split
        equally, or one a segment); required with a relaxation.
    profile, exponent : str, float or None
        The indenter's profile (keys ``profile``, ``exponent``; default the
        paraboloid), as ``contactlib history --profile --exponent`` takes it.
    flat_ratio : float or None
        b/a_max of ``profile: rounded`` (key ``flat_ratio``); None otherwise.
    tangential_path : tuple of float
        Q/(k P_max) at the points of ``load_path`` (key ``tangential_path``): a
        fretting path, run by :func:`contactlib.fretting` instead of
        :func:`contactlib.history` (one friction coefficient); empty: none.
    bulk_stress : tuple of float
        The body's bulk stress sigma/p0 at the same points (fretting only); empty: none.
    tangential_displacement : bool
        Key ``tangential_displacement: true`` (the sphere): ``tangential_path`` is the
        indenter's rigid shift s R/a_max^2 and Q the answer; default false.
    base, substrate_modulus, substrate_nu
        As for :class:`Scene`: ``base`` "elastic" is a coated body, the layer
        (a_max/h ``slab_ratio``) bonded to a substrate of E2/E1 ``substrate_modulus``.
    """

    __repr__ = short_repr  # a few lines: long tuples shortened

    name: str
    geometry: str
    nu: float
    frictions: tuple[float, ...]
    load_path: tuple[float, ...]
    steps: int
    n: int
    slab_ratio: float
    hash: str
    max_error: float = validate.PATH_DEFAULT_MAX_ERROR
    kind: str = "history"
    indenter_modulus: float = float("inf")
    indenter_nu: float | None = None
    relaxation: tuple[tuple[float, float], ...] = ()
    durations: tuple[float, ...] = ()
    base: str = "smooth"
    profile: str = "paraboloid"
    exponent: float | None = None
    tangential_path: tuple[float, ...] = ()
    bulk_stress: tuple[float, ...] = ()
    substrate_modulus: float = float("inf")
    substrate_nu: float | None = None
    flat_ratio: float | None = None
    tangential_displacement: bool = False

    @property
    def fretting(self) -> bool:
        """Whether the scene is a fretting path (run by :func:`contactlib.fretting`)."""
        return bool(self.tangential_path)

    def run_spec(self, index: int) -> dict[str, Any]:
        """Keyword arguments of :func:`contactlib.history` for friction ``index`` (of
        :func:`contactlib.fretting` for a fretting scene).

        The indenter's keywords appear only for an elastic indenter, so that a
        rigid scene's arguments (and its jobs' parameters) stay as they were;
        likewise the profile's only for another profile than the paraboloid.
        """
        if self.fretting:
            spec = {"geometry": self.geometry, "nu": self.nu, "friction": self.frictions[index],
                    "load_path": list(self.load_path),
                    "tangential_path": list(self.tangential_path), "steps": self.steps,
                    "n": self.n, "max_error": self.max_error}
            if self.bulk_stress:
                spec["bulk_stress"] = list(self.bulk_stress)
            if self.tangential_displacement:  # (a force-controlled scene's keywords unchanged)
                spec["tangential_displacement"] = True
            if self.indenter_modulus != float("inf"):
                spec.update(indenter_modulus=self.indenter_modulus,
                            indenter_nu=self.indenter_nu)
            return spec | _profile_spec(self.profile, self.exponent, self.flat_ratio)
        spec = {"geometry": self.geometry, "nu": self.nu, "friction": self.frictions[index],
                "load_path": list(self.load_path), "steps": self.steps, "n": self.n,
                "slab_ratio": self.slab_ratio, "max_error": self.max_error}
        if self.indenter_modulus != float("inf"):
            spec.update(indenter_modulus=self.indenter_modulus, indenter_nu=self.indenter_nu)
        if self.relaxation:  # a viscoelastic body (an elastic scene's keywords unchanged)
            spec.update(relaxation=[list(p) for p in self.relaxation],
                        duration=list(self.durations))
        spec.update(_base_spec(self.base))
        if self.base == validate.COATED_BASE:
            spec.update(substrate_modulus=self.substrate_modulus, substrate_nu=self.substrate_nu)
        return spec | _profile_spec(self.profile, self.exponent, self.flat_ratio)


def _fretting_paths(raw: Mapping[str, Any], ks: tuple[float, ...] | None, n: Any,
                    steps: int | None, bad: _Problems, nu: float | None = None,
                    ind: tuple[float, float | None] = (math.inf, None),
                    displacement: bool = False
                    ) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(tangential_path, bulk_stress) of a fretting scene, checked by
    :func:`contactlib.fretting_api.check_input` (the library's words, one line under the
    key its message names)."""
    from . import fretting_api  # (the solvers' imports: only for a fretting scene)

    for key in _NOT_FRETTING:
        if key in raw and not (key == "slab_ratio" and raw[key] == 0) \
                and not (key == "base" and raw[key] == "smooth"):
            bad.add(key, "not with tangential_path: a fretting path covers the half-plane "
                         "and the half-space (elastic bodies, slab_ratio 0) only")
    if ks is not None and len(ks) != 1:
        bad.add("friction", f"a fretting scene (tangential_path) takes one friction "
                            f"coefficient (tangential_path is Q/(k P_max)), got {list(ks)!r}")
        ks = None
    if ks is None or "load_path" not in raw or steps is None or "geometry" not in raw:
        return (), ()
    tang, sigma = raw["tangential_path"], raw.get("bulk_stress")
    if not profiles.takes(raw.get("profile", "paraboloid"), "fretting"):
        bad.add("profile", f"profile {raw['profile']!r} is not taken by a fretting scene "
                           f"(tangential_path): the fretting solvers cover the power laws and the "
                           f"rounded punch")
        return (), ()
    if raw["geometry"] == "sphere" and nu is None:
        return (), ()  # (nu's own problem is recorded; the sphere's check needs it)
    try:
        fretting_api.check_input(raw["geometry"], ks[0], raw["load_path"], tang, steps,
                                 n, sigma, raw.get("max_error", validate.PATH_DEFAULT_MAX_ERROR),
                                 nu=nu, indenter_modulus=ind[0], indenter_nu=ind[1],
                                 tangential_displacement=displacement)
    except ValueError as exc:
        text = str(exc)
        head, _, rest = text.partition(": ")
        if head in _HISTORY_KEYS:
            bad.add(head, rest)
        else:  # "fretting: geometry 'sphere' is not covered; ..."
            bad.add("geometry", text)
        return (), ()
    return (tuple(float(v) for v in tang),
            () if sigma is None else tuple(float(v) for v in sigma))


def _parse_history(name: str, raw: Mapping[str, Any]) -> HistoryScene:
    bad = _Problems(name)
    bad.keys(raw, _HISTORY_KEYS, ("geometry", "nu", "friction", "load_path"), "history")
    ks = None
    if "friction" in raw:
        friction = raw["friction"]
        values = list(friction) if isinstance(friction, (list, tuple)) else [friction]
        if not values:
            bad.add("friction", "must not be empty")
        else:
            ks = bad.check("friction", lambda: tuple(validate.friction(k) for k in values))
            if ks is not None and len(set(ks)) != len(ks):
                bad.add("friction", f"repeats a value: {values!r}")
    path = bad.check("load_path", validate.load_path, raw["load_path"]) \
        if "load_path" in raw else None
    fretting = "tangential_path" in raw
    if "steps" in raw:
        steps = bad.check("steps", validate.steps, raw["steps"])
    else:  # the library's default (a fretting path's is the cylinder's: scenes take no other)
        from .fretting_api import DEFAULT_STEPS as fretting_steps

        steps = fretting_steps if fretting else validate.HISTORY_DEFAULT_STEPS
    if "bulk_stress" in raw and not fretting:
        bad.add("bulk_stress", "needs tangential_path (a fretting path)")
    displacement = raw.get("tangential_displacement", False)
    if not isinstance(displacement, bool):
        bad.add("tangential_displacement", f"true or false, got {displacement!r}")
        displacement = False
    elif displacement and not fretting:
        bad.add("tangential_displacement", "needs tangential_path (the shift at the points "
                                           "of load_path)")
    if fretting:  # the fretting solver's own n (a multiple of 4) and default
        from .fretting_api import DEFAULT_N as fretting_n

        n = raw.get("n", fretting_n)
    else:
        n = bad.check("n", validate.history_n, raw.get("n"))
    geometry = bad.check("geometry", validate.geometry, raw["geometry"]) \
        if "geometry" in raw else None
    nu = bad.check("nu", validate.nu, raw["nu"]) if "nu" in raw else None
    base = bad.check("base", validate.base, raw.get("base", "smooth"), True)
    slab = bad.check("slab_ratio", validate.slab_ratio, raw.get("slab_ratio", 0.0), geometry,
                     base or "smooth", validate.HISTORY_MESH_EXTENT)
    substrate = (math.inf, None)
    if base is not None and geometry is not None and not fretting:
        try:
            substrate = validate.substrate(base, raw.get("substrate_modulus"),
                                           raw.get("substrate_nu"), geometry)
        except validate.InputError as exc:
            bad.add(exc.name, str(exc))
    max_error = bad.check("max_error", validate.max_error,
                          raw.get("max_error", validate.PATH_DEFAULT_MAX_ERROR))
    ind = _scene_indenter(raw, nu, bad)
    prony = bad.check("relaxation", validate.relaxation, raw.get("relaxation"))
    durations = bad.check("duration", validate.duration, raw.get("duration"),
                          len(path) - 1 if path else 1, bool(prony)) if prony is not None else ()
    if prony and ind[0] != float("inf"):
        bad.add("relaxation", "needs a rigid indenter")
    if prony and base == validate.COATED_BASE:  # (contactlib.history's words)
        bad.add("relaxation", "relaxation is not available on a coated body (base 'elastic'): "
                              "the substrate's kernels are elastic only; use a rigid base or "
                              "an elastic layer")
    profile, exponent, flat_ratio = _scene_profile(raw, bad)
    tang, sigma = (_fretting_paths(raw, ks, n, steps, bad, nu, ind, displacement)
                   if fretting else ((), ()))
    bad.raise_any()
    return HistoryScene(name=name, geometry=geometry, nu=nu, frictions=ks,
                        load_path=path, steps=steps, n=n, slab_ratio=slab,
                        hash=config_hash(raw), max_error=max_error, indenter_modulus=ind[0],
                        indenter_nu=ind[1], relaxation=prony, durations=durations,
                        base=base, profile=profile, exponent=exponent, tangential_path=tang,
                        bulk_stress=sigma, substrate_modulus=substrate[0],
                        substrate_nu=substrate[1], flat_ratio=flat_ratio,
                        tangential_displacement=displacement)


@dataclass(frozen=True, repr=False)
class PhysicalScene:
    """One validated scene of kind ``physical``: a path of forces in SI.

    Attributes
    ----------
    name, geometry, hash
        As for :class:`Scene`.
    spec : dict
        Keyword arguments of :func:`contactlib.physical.physical_history`, in SI
        (radius, length, thickness in m; forces in N, a shape's frequency in Hz,
        times and relaxation times in s; materials by name or as [E in Pa, nu]).
    """

    __repr__ = short_repr

    name: str
    geometry: str
    spec: dict
    hash: str
    kind: str = "physical"

    def run_spec(self) -> dict[str, Any]:
        """Keyword arguments of :func:`contactlib.physical.physical_history` (a copy)."""
        return json.loads(json.dumps(self.spec))


def _parse_physical(name: str, raw: Mapping[str, Any]) -> PhysicalScene:
    """A ``physical`` scene: the keys of :func:`contactlib.physical.physical_history`, each
    checked by the physical door's own rules (units, materials, the force path)."""
    from .model import load_paths
    from . import physical

    bad = _Problems(name)
    for key in ("profile", "exponent"):
        if key in raw:
            bad.add(key, "physical scenes take the paraboloid only (contactlib.physical_history "
                         "has no profile yet); a history scene takes a cone or a power law")
    bad.keys({k: v for k, v in raw.items() if k not in ("profile", "exponent")},
             _PHYSICAL_KEYS, ("geometry", "radius", "body", "friction", "load_path"),
             "physical")
    geometry = bad.check("geometry", validate.geometry, raw["geometry"]) \
        if "geometry" in raw else None
    spec: dict[str, Any] = {"geometry": geometry}
    if "radius" in raw:
        spec["radius"] = bad.check("radius", physical.parse_quantity, raw["radius"], "length",
                                   "radius")
    for key in ("length", "thickness"):
        if key in raw:
            spec[key] = bad.check(key, physical.parse_quantity, raw[key], "length", key)
    if geometry == "cylinder" and "length" not in raw:
        bad.add("length", "is required for a cylinder (the force is over its length)")
    if geometry == "sphere" and "length" in raw:
        bad.add("length", "is for a cylinder only")
    for key, role in (("indenter", "indenter"), ("body", "body")):
        if key in raw:
            mat = bad.check(key, physical.material, raw[key], role)
            if mat is not None:  # JSON-able: the table's name, or [E in Pa, nu]
                spec[key] = mat.name if mat.name not in ("E,nu",) else [mat.E, mat.nu]
    spec["base"] = bad.check("base", validate.base, raw.get("base", "smooth"), True)
    if "substrate" in raw:  # a coated body: the layer (body, thickness) on this material
        mat = bad.check("substrate", physical.material, raw["substrate"], "substrate")
        if mat is not None:
            spec["substrate"] = mat.name if mat.name not in ("E,nu",) else [mat.E, mat.nu]
    if "friction" in raw:
        spec["friction"] = bad.check("friction", validate.friction, raw["friction"])
    if "load_path" in raw:
        path = raw["load_path"]
        if load_paths.is_shaped(path):
            if bad.check("load_path", physical.force_shape, dict(path)) is not None:
                spec["load_path"] = dict(path)
        else:
            forces = bad.check("load_path", physical.parse_force_path, path)
            spec["load_path"] = list(forces) if forces is not None else None
    spec["steps"] = bad.check("steps", validate.steps,
                              raw.get("steps", physical.DEFAULT_HISTORY_STEPS))
    if raw.get("n") is not None:
        spec["n"] = bad.check("n", validate.history_n, raw["n"])
    spec["max_error"] = bad.check("max_error", validate.max_error,
                                  raw.get("max_error", validate.PATH_DEFAULT_MAX_ERROR))
    if "relaxation" in raw:
        items = raw["relaxation"]
        if not isinstance(items, (list, tuple)) or not all(
                isinstance(p, (list, tuple)) and len(p) == 2 for p in items):
            bad.add("relaxation", f"must be a list of pairs [g, tau] (tau in s or with a "
                                  f"unit), got {items!r}")
        else:
            taus = [bad.check("relaxation", physical.parse_quantity, tau, "time",
                              "relaxation") for _, tau in items]
            pairs = [[g, t] for (g, _), t in zip(items, taus)]
            if None not in taus and bad.check("relaxation", validate.relaxation, pairs):
                spec["relaxation"] = pairs
    if "times" in raw:
        times = raw["times"]
        def when(t: Any) -> float:
            return physical.parse_quantity(t, "time", "times", positive=False)

        ok = isinstance(times, (list, tuple)) and all(
            bad.check("times", when, t) is not None for t in times)
        if not isinstance(times, (list, tuple)):
            bad.add("times", f"must be a list of times (s or with a unit), got {times!r}")
        spec["times"] = [when(t) for t in times] if ok else None
    bad.raise_any()
    spec = {k: v for k, v in spec.items() if v is not None}
    if spec["base"] == "smooth":
        spec.pop("base")
    try:  # what depends on several keys (a relaxation and its times, a path's times)
        physical.check_history(**spec)
    except ValueError as exc:
        key = getattr(exc, "name", None)
        raise ConfigError([f"scenes.{name}.{key}: {exc}" if key else
                           f"scenes.{name}: {exc}"]) from None
    return PhysicalScene(name=name, geometry=geometry, spec=spec, hash=config_hash(raw))


def parse_named_scene(name: Any, raw: Mapping[str, Any]) -> "Scene | HistoryScene":
    """:func:`parse_scene` after checking the name (:func:`contactlib.validate.scene_name`):
    the rules of ``contactlib check-config`` and of the workflow, one scene.

    Raises
    ------
    ConfigError
        ``scenes.<name>: scene name must be ...`` for a bad name, else as
        :func:`parse_scene`.
    """
    name = str(name)  # a YAML key 123 names scene "123"
    try:
        validate.scene_name(name)
    except ValueError as exc:
        raise ConfigError([f"scenes.{name}: {exc}"]) from None
    return parse_scene(name, raw)


def parse_scenes(scenes: Mapping[str, Mapping[str, Any]]) -> dict[str, "Scene | HistoryScene"]:
    """Validate every scene of a configuration (see :func:`parse_scene`).

    Raises
    ------
    ConfigError
        Listing the problems of every bad scene at once.
    """
    if not isinstance(scenes, Mapping) or not scenes:
        raise ConfigError(["scenes: must be a non-empty mapping of scene names to scenes"])
    out: dict[str, Scene | HistoryScene] = {}
    problems: list[str] = []
    for name, raw in scenes.items():
        try:
            out[str(name)] = parse_named_scene(name, raw)
        except ConfigError as exc:
            problems += exc.problems
    if problems:
        raise ConfigError(problems)
    return out


def material_pair_scenes(section: Mapping[str, Any]) -> dict[str, dict[str, Any]]:
    """The scene mappings of a configuration's ``materials`` section, in its order.

    Each pair ``[indenter, body]`` (material names of ``contactlib/data/materials.yaml``)
    gives a self-similar scene ``mat-<indenter>-on-<body>`` (``k_curve``) and a
    history scene ``mat-<indenter>-on-<body>-cycle`` (underscores of the names
    read as hyphens); the body's Poisson ratio is the material's.

    Raises
    ------
    contactlib.validate.InputError
        If a name is not in the table of materials.

    Examples
    --------
    >>> raw = material_pair_scenes({"pairs": [["steel", "aluminium"]], "n": 32,
    ...     "stick_ratios": [0.5], "friction": [0.1], "load_path": [0, 1, 0], "steps": 4})
    >>> list(raw), raw["mat-steel-on-aluminium"]["nu"]
    (['mat-steel-on-aluminium', 'mat-steel-on-aluminium-cycle'], 0.33)
    """
    out: dict[str, dict[str, Any]] = {}
    for ind, body in section["pairs"]:
        nu = materials.pair(ind, body)[2]
        name = f"mat-{ind}-on-{body}".replace("_", "-")
        common = {"geometry": section.get("geometry", "sphere"), "nu": nu, "indenter": ind,
                  "body": body}
        out[name] = dict(common, n=section.get("n", 256), stick_ratios=section["stick_ratios"],
                         outputs=["k_curve"])
        out[f"{name}-cycle"] = dict(common, kind="history", friction=section["friction"],
                                    load_path=section["load_path"], steps=section["steps"])
    return out


def scene_mapping(config: Mapping[str, Any], name: str) -> Mapping[str, Any]:
    """A scene's mapping by name: from ``scenes``, else from the ``materials`` section.

    Raises
    ------
    KeyError
        If no scene of that name is configured.
    """
    scenes = config.get("scenes") or {}
    if name in scenes:
        return scenes[name]
    section = config.get("materials")
    if isinstance(section, Mapping):
        found = material_pair_scenes(section)
        if name in found:
            return found[name]
    raise KeyError(name)


__all__ += ["viscoelastic_scenes"]


def viscoelastic_scenes(section: Mapping[str, Any]) -> dict[str, dict[str, Any]]:
    """The history scenes of a configuration's ``viscoelastic`` section, one a cycle duration.

    The section gives ``geometry`` (default sphere), ``nu``, ``friction`` (a
    list), ``relaxation`` ([[g, tau], ...]), ``durations`` (of the cycle, in
    the unit of tau), ``load_path`` (default [0, 1, 0]), ``steps`` and ``n``
    (optional). Scene ``visco-T<duration>`` is the cycle of that duration.

    Examples
    --------
    >>> raw = viscoelastic_scenes({"nu": 0.3, "friction": [0.1], "relaxation": [[0.5, 1.0]],
    ...                            "durations": [0.01, 1], "steps": 50})
    >>> list(raw), raw["visco-T1"]["duration"]
    (['visco-T0.01', 'visco-T1'], 1.0)
    """
    out: dict[str, dict[str, Any]] = {}
    for duration in section["durations"]:
        raw = {"kind": "history", "geometry": section.get("geometry", "sphere"),
               "nu": section["nu"], "friction": section["friction"],
               "load_path": section.get("load_path", [0, 1, 0]), "steps": section["steps"],
               "relaxation": section["relaxation"], "duration": float(duration)}
        if "n" in section:
            raw["n"] = section["n"]
        out[f"visco-T{float(duration):g}"] = raw
    return out

