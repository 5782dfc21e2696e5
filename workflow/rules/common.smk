# Validation, helpers and wildcard constraints shared by every rule.

import json
from pathlib import Path

import jsonschema
import yaml
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

import contactlib
from contactlib.scene import parse_scenes

SCHEMA = Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml"
VERSION = contactlib.__version__
PAPER_FIGURES = ("fig2", "fig3", "fig4", "fig5")
# loading-history figures (scenes of kind history) -> contactlib.history_figures
HISTORY_FIGURES = ("history_stick_radius", "history_stick_map", "history_loop", "history_energy")
FIGURES = PAPER_FIGURES + HISTORY_FIGURES
# outputs a figure draws from each of its scenes
FIGURE_NEEDS = {
    "fig2": ("k_curve",),
    "fig3": ("stresses",),
    "fig4": ("displacements",),
    "fig5": ("k_curve", "energy"),
}


def _validate_config(cfg):
    """Schema first (types and ranges), then the library's rules; one message per problem."""
    with open(SCHEMA) as fh:
        schema = yaml.safe_load(fh)
    errors = sorted(
        jsonschema.Draft202012Validator(schema).iter_errors(cfg), key=lambda e: list(e.absolute_path)
    )
    if errors:
        lines = []
        for e in errors:
            where = ".".join(str(p) for p in e.absolute_path) or "(top level)"
            if e.validator == "additionalProperties":
                message = e.message
            elif e.validator == "oneOf" and where.endswith("stick_ratios"):
                message = f"must be 'all' or a list of numbers in [0, 1], got {e.instance!r}"
            else:
                message = e.message
            lines.append(f"  {where}: {message}")
        raise WorkflowError("invalid configuration:\n" + "\n".join(lines))
    validate(cfg, str(SCHEMA))
    try:
        scenes = parse_scenes(cfg["scenes"])
    except ValueError as exc:
        raise WorkflowError(f"invalid configuration:\n  {exc}") from None
    for fig, names in (cfg.get("figures") or {}).items():
        if fig == "history_stick_map" and len(names) > 1:
            raise WorkflowError(
                f"invalid configuration:\n  figures.{fig}: one scene (the map of one "
                f"history), got {len(names)}"
            )
        for name in names:
            if name not in scenes:
                raise WorkflowError(
                    f"invalid configuration:\n  figures.{fig}: no scene named {name!r}"
                )
            want = "history" if fig in HISTORY_FIGURES else "self-similar"
            if scenes[name].kind != want:
                raise WorkflowError(
                    f"invalid configuration:\n  figures.{fig}: scene {name!r} is of kind "
                    f"{scenes[name].kind}; this figure draws scenes of kind {want}"
                )
            if want == "history":
                continue
            missing = [o for o in FIGURE_NEEDS[fig] if o not in scenes[name].outputs]
            if missing:
                raise WorkflowError(
                    f"invalid configuration:\n  figures.{fig}: scene {name!r} does not ask "
                    f"for {', '.join(missing)} (add it to scenes.{name}.outputs)"
                )
    return scenes


ALL_SCENES = _validate_config(config)
SCENES = {n: s for n, s in ALL_SCENES.items() if s.kind == "self-similar"}
HISTORIES = {n: s for n, s in ALL_SCENES.items() if s.kind == "history"}
CONVERGENCE = config.get("convergence") or {"stick_ratios": [], "studies": {}}
for _name, _st in CONVERGENCE["studies"].items():
    _ns = _st["n"]
    if any(b != 2 * a for a, b in zip(_ns, _ns[1:])):
        raise WorkflowError(
            f"invalid configuration:\n  convergence.studies.{_name}.n: each n must be twice "
            f"the previous, got {_ns}"
        )
    _ref = _st.get("reference")
    if _ref is not None and _ref not in CONVERGENCE["studies"]:
        raise WorkflowError(
            f"invalid configuration:\n  convergence.studies.{_name}.reference: no study "
            f"named {_ref!r}"
        )

# influence sets, shared by every scene with the same key; the parts any of them needs
INFLUENCE = {}
for _s in SCENES.values():
    _spec = INFLUENCE.setdefault(_s.influence_key, dict(_s.influence_spec(), parts=[]))
    _spec["parts"] = [p for p in ("normal", "shear") if p in _spec["parts"] or p in _s.parts]


wildcard_constraints:
    scene="|".join(sorted(SCENES)) or "NONE",
    hscene="|".join(sorted(HISTORIES)) or "NONE",
    key="[^/]+",
    study="|".join(sorted(CONVERGENCE["studies"])) or "NONE",


# ----------------------------------------------------------------------------- helpers
def scene_of(wildcards):
    return SCENES[wildcards.scene]


def scene_params(wildcards):
    """Everything about a scene a rule's result depends on (so a change reruns it)."""
    s = SCENES[wildcards.scene]
    return {
        "name": s.name,
        "geometry": s.geometry,
        "nu": s.nu,
        "method": s.method,
        "n": s.n,
        "slab_ratio": s.slab_ratio,
        "stick_ratios": list(s.stick_ratios),
        "outputs": list(s.outputs),
        "tolerance": s.tolerance,
        "hash": s.hash,
    }


def history_params(wildcards):
    """A history scene's runs (the library call's arguments, one a k) plus provenance."""
    s = HISTORIES[wildcards.hscene]
    return {"runs": [s.run_spec(i) for i in range(len(s.frictions))], "scene": s.name,
            "hash": s.hash}


def history_threads(wildcards):
    """One worker process a friction coefficient (Snakemake caps it at --cores)."""
    return len(HISTORIES[wildcards.hscene].frictions)


def influence_files(wildcards):
    """The folder of the scene's influence set (its <part>.npz files)."""
    return {"influence": f"results/influence/{SCENES[wildcards.scene].influence_key}"}


def stage_files(wildcards):
    """The post-processing results a scene's dataset is assembled from."""
    s = SCENES[wildcards.scene]
    files = {"solutions": f"results/solutions/{s.name}.npz"}
    folders = {"check": "checks", "energy": "energy", "displacements": "profiles"}
    for stage in s.stages:
        files[stage] = f"results/{folders[stage]}/{s.name}.npz"
    return files


def figure_scenes(fig):
    return list((config.get("figures") or {}).get(fig) or [])


def all_targets():
    out = [f"results/datasets/{name}.nc" for name in ALL_SCENES]
    for fig in FIGURES:
        if figure_scenes(fig):
            out += [f"results/figures/{fig}.png", f"results/figures/{fig}.pdf"]
    if SCENES:  # the key-numbers table sums up the self-similar scenes
        out += ["results/tables/key-numbers.csv", "results/tables/key-numbers.html"]
    return out


def study_reference(wildcards):
    ref = CONVERGENCE["studies"][wildcards.study].get("reference")
    return {"reference": f"results/convergence/{ref}.nc"} if ref else {}


def operator_mb(n, count=1):
    """Memory of `count` dense operators (3 x (n+1)^2 float64) in MB."""
    return count * 24 * (n + 1) ** 2 / 1e6


def influence_spec(wildcards):
    return INFLUENCE[wildcards.key]


def mem_influence(wildcards, attempt):
    spec = INFLUENCE[wildcards.key]
    count = len(spec["stick_ratios"]) if spec["method"] == "default" else 1
    return int(600 + 3 * operator_mb(spec["n"], count)) * attempt


def mem_solve(wildcards, attempt):
    """The influence set it loads (every mesh, both parts) plus the per-case work."""
    s = SCENES[wildcards.scene]
    meshes = len(s.solved_ratios) if s.method == "default" else 1
    return int(500 + operator_mb(s.n, 2 * meshes) + 12 * operator_mb(s.n)) * attempt


def runtime_solve(wildcards, attempt):
    """Minutes: ~1 s a case at n = 256, growing like n^2 (kernels) to n^3 (LU).

    A tolerance scene may double n once or twice after its a-posteriori check.
    """
    s = SCENES[wildcards.scene]
    per_case = max(1.0, (s.n / 256) ** 2.5) * (8 if s.tolerance is not None else 1)
    return int(5 + len(s.stick_ratios) * per_case / 60 * 4) * attempt


def mem_history(wildcards, threads, attempt):
    """Per worker: dense operators over the history mesh (a few n x n) plus the per-step arrays."""
    s = HISTORIES[wildcards.hscene]
    steps = s.steps * (len(s.load_path) - 1) + 1
    return int(500 + threads * (10 * 8 * s.n**2 / 1e6 + 6 * 8 * steps * s.n / 1e6)) * attempt


def runtime_history(wildcards, threads, attempt):
    """Minutes: ~2 ms a step at n = 240, growing like n^2 ... n^3; the runs share the workers."""
    s = HISTORIES[wildcards.hscene]
    steps = s.steps * (len(s.load_path) - 1) * -(-len(s.frictions) // threads)
    return int(5 + steps * 0.002 * max(1.0, (s.n / 240) ** 3) / 60 * 4) * attempt
