"""Scene-level stages of the workflow: arrays in, arrays (or a dataset) out.

Each function here is what one Snakemake rule runs (the scripts in
``workflow/scripts`` only read inputs and write outputs through
:mod:`contactlib.io`, which also holds the dataset conventions). The numerics
are those of :mod:`contactlib.stages`, which :func:`contactlib.solve` runs in
one process, so a scene's dataset holds the same numbers as ``contactlib
sweep`` with the same settings.

Examples
--------
>>> from contactlib.scene import parse_scene
>>> s = parse_scene("demo", {"geometry": "sphere", "nu": 0.3, "n": 32,
...                          "stick_ratios": [0.0, 0.5], "outputs": ["k_curve"]})
>>> parts = {p: influence(s.influence_spec(), p) for p in s.parts}
>>> records = solve(s, parts["normal"], parts["shear"])
>>> ds = assemble(s, records, checks=check(records))
>>> sorted(v for v in ds.data_vars if v in ("pressure", "frictional_work", "consistent"))
['consistent']
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Mapping, Sequence

import numpy as np

from .checks import FLAG_NAMES, VIOLATION_NAMES
from .result import CaseRecord
from .threads import blas_single_threaded

if TYPE_CHECKING:
    import xarray as xr

    from .scene import Scene

# The solver modules (stages and what it imports: scipy.linalg) are imported in
# the functions that need them, so that a workflow job running a light stage
# (check: numpy only) does not pay for them at start-up.

__all__ = ["influence", "solve", "check", "energy", "displacements", "assemble"]


@blas_single_threaded
def influence(spec: Mapping[str, Any], part: str) -> dict[str, np.ndarray]:
    """Influence matrices of one part for a :meth:`Scene.influence_spec`."""
    from . import stages
    from .model import contact

    geom = contact(spec["geometry"], float(spec["nu"]), float(spec["slab_ratio"]),
                   float(spec.get("indenter_modulus", "inf")), spec.get("indenter_nu"),
                   spec.get("base", "smooth"),
                   substrate_modulus=float(spec.get("substrate_modulus", "inf")),
                   substrate_nu=spec.get("substrate_nu"))
    return stages.influence(geom, spec["method"], int(spec["n"]), spec["stick_ratios"], part)


@blas_single_threaded
def solve(scene: Scene, normal: dict[str, np.ndarray] | None,
          shear: dict[str, np.ndarray] | None = None,
          progress: Callable[[int, int], None] | None = None) -> list[CaseRecord]:
    """Case records of every stick ratio of a scene (see :func:`stages.solve_cases`)."""
    from . import stages

    return stages.solve_cases(scene.geometry_object, scene.method, scene.n, scene.stick_ratios,
                              normal=normal, shear=shear, samples=scene.needs_samples,
                              tolerance=scene.tolerance, progress=progress,
                              max_error=scene.max_error)


def check(records: Sequence[CaseRecord]) -> dict[str, np.ndarray]:
    """Consistency flags and violation measures, one value a case.

    Elementwise comparisons of the records' samples, no BLAS or LAPACK call:
    not run under :func:`~contactlib.threads.single_blas_thread`, whose
    set-up imports scipy.linalg (0.25 s of the rule's 0.4 s of CPU time).
    """
    from .checks import record_flags  # (stages.check_case, without the solver's imports)

    flags = [record_flags(r) for r in records]
    out = {name: np.array([f[name] for f in flags], dtype=bool) for name in FLAG_NAMES}
    out.update({name: np.array([f[name] for f in flags], dtype=float) for name in VIOLATION_NAMES})
    return out


def energy(scene: Scene, records: Sequence[CaseRecord]) -> dict[str, np.ndarray]:
    """Frictional work of the loading half-cycle, one value a case (docs/conventions.md).

    A weighted sum over the records' slip samples (``energy.record_work``,
    what ``stages.work_case`` computes), no BLAS or LAPACK call: neither the
    solvers' imports nor :func:`~contactlib.threads.single_blas_thread`,
    whose set-up imports scipy.linalg (most of the rule's CPU time).
    """
    from .energy import record_work

    geom = scene.geometry_object
    return {"frictional_work": np.array([record_work(r, geom.work_factor, geom.work_weight_power)
                                         for r in records])}


@blas_single_threaded
def displacements(scene: Scene, records: Sequence[CaseRecord]) -> dict[str, np.ndarray]:
    """Tangential displacement u R/a^2 on the output grid, shape (cases, xi)."""
    from . import stages
    from .api import output_grid

    geom, xi = scene.geometry_object, output_grid()
    rows = [stages.profiles(geom, r, xi, stresses=False)["tangential_displacement"]
            for r in records]
    return {"xi": xi, "tangential_displacement": np.array(rows).reshape(len(records), xi.size)}


@blas_single_threaded
def assemble(scene: Scene, records: Sequence[CaseRecord], *,
             checks: Mapping[str, np.ndarray] | None = None,
             work: Mapping[str, np.ndarray] | None = None,
             profiles: Mapping[str, np.ndarray] | None = None) -> xr.Dataset:
    """The scene's dataset: docs/conventions.md variables for the outputs it asked for.

    Always: ``friction_coefficient``, ``load_ratio`` and the solver status.
    ``k_curve`` adds the consistency flags (needs ``checks``), ``stresses``
    the pressure and shear, ``displacements`` the tangential displacement
    (needs ``profiles``), ``energy`` the frictional work (needs ``work``),
    ``subsurface`` the stress field inside the body
    (:func:`contactlib.stresses.scene_subsurface`).
    Global attributes add ``scene`` and ``scene_config_hash`` (provenance).
    The conventions (names, CF attributes) are those of
    :func:`contactlib.io.scene_to_dataset`.
    """
    from . import stages
    from .api import output_grid
    from .io import scene_to_dataset

    geom, xi = scene.geometry_object, output_grid()
    want = set(scene.outputs)
    for name, given, needed in (("checks", checks, "k_curve"), ("work", work, "energy"),
                                ("profiles", profiles, "displacements")):
        if needed in want and given is None:
            raise ValueError(f"scene {scene.name!r} asks for {needed}: {name} must be given")
    if profiles is not None and not np.array_equal(profiles["xi"], xi):
        raise ValueError("profiles were computed on another output grid")
    sols = []
    for i, rec in enumerate(records):
        flags = None
        if checks is not None:
            flags = {name: checks[name][i] for name in FLAG_NAMES + VIOLATION_NAMES}
        prof = stages.profiles(geom, rec, xi, displacements=False) if "stresses" in want else {}
        if "displacements" in want:
            prof["tangential_displacement"] = profiles["tangential_displacement"][i]
        sols.append(stages.to_solution(
            geom, scene.method, scene.n, rec, xi, flags=flags,
            work=float(work["frictional_work"][i]) if "energy" in want else float("nan"),
            profile=prof))
        if geom.body.base == "elastic":  # a coated body: its substrate (as contactlib.solve)
            sols[-1].substrate_modulus = float(geom.body.substrate_modulus)
            sols[-1].substrate_poisson_ratio = float(geom.body.kernel_base.nu)
    violations = (None if "k_curve" not in want
                  else {name: checks[name] for name in VIOLATION_NAMES})
    tolerance = elements = estimate = None
    if scene.tolerance is not None:
        tolerance = scene.tolerance
        elements = np.array([int(r.elements) for r in records], dtype=np.int32)
        estimate = np.array([float(r.error_estimate) for r in records])
    ds = scene_to_dataset(sols, outputs=scene.outputs, scene=scene.name,
                          config_hash=scene.hash, violations=violations, elements=elements,
                          error_estimate=estimate, tolerance=tolerance)
    if "subsurface" in want:
        from .stresses import scene_subsurface
        ds = scene_subsurface(ds, scene, [{**stages.profiles(geom, rec, xi, displacements=False),
                                           **stages.nodal_tractions(geom, rec)}
                                          for rec in records], xi)
    return ds
