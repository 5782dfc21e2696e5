# Validation, helpers and wildcard constraints shared by every rule.

import json
import re
from pathlib import Path

import jsonschema
import yaml
from snakemake.exceptions import WorkflowError
from snakemake.utils import validate

import contactlib
from contactlib.scene import (material_pair_scenes, parse_named_scene, parse_scene,
                              viscoelastic_scenes)

SCHEMA = Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml"
VERSION = contactlib.__version__
PAPER_FIGURES = ("fig2", "fig3", "fig4", "fig5")
# loading-history figures (scenes of kind history) -> contactlib.plot.history
HISTORY_FIGURES = ("history_stick_radius", "history_stick_map", "history_loop", "history_energy")
FIGURES = PAPER_FIGURES + HISTORY_FIGURES
# outputs a figure draws from each of its scenes
FIGURE_NEEDS = {
    "fig2": ("k_curve",),
    "fig3": ("stresses",),
    "fig4": ("displacements",),
    "fig5": ("k_curve", "energy"),
}


def _schema_problems(cfg):
    """One ``(line, scene, keys)`` a schema violation (types and ranges), sorted by where
    it is: the scene it concerns (None: not a scene) and its keys (None: the whole scene)."""
    with open(SCHEMA) as fh:
        schema = yaml.safe_load(fh)
    errors = sorted(
        jsonschema.Draft202012Validator(schema).iter_errors(cfg), key=lambda e: list(e.absolute_path)
    )
    out = []
    for e in errors:
        path = list(e.absolute_path)
        scene, keys = None, None
        if len(path) >= 2 and path[0] == "scenes":
            scene = str(path[1])
            if len(path) >= 3:
                keys = {str(path[2])}
            elif e.validator in ("required", "additionalProperties"):
                keys = set(re.findall(r"'([^']*)'", e.message))
        elif path == ["scenes"] and "propertyNames" in e.schema_path:
            scene = str(e.instance)  # a bad scene name
        where = ".".join(str(p) for p in e.absolute_path) or "(top level)"
        if e.validator == "oneOf" and where.endswith("stick_ratios"):
            message = f"must be 'all' or a list of distinct numbers in [0, 1], got {e.instance!r}"
        elif e.validator == "oneOf" and where.endswith("friction"):
            message = f"must be a number >= 0 or a list of distinct ones, got {e.instance!r}"
        else:
            message = e.message
        out.append((f"{where}: {message}", scene, keys))
    return out


def _figure_problems(cfg, scenes, raw_scenes):
    """Figures naming missing scenes, scenes of the wrong kind or lacking an output."""
    lines = []
    for fig, names in (cfg.get("figures") or {}).items():
        if not isinstance(names, list) or fig not in FIGURES:
            continue  # the schema reports it
        if fig == "history_stick_map" and len(names) > 1:
            lines.append(f"figures.{fig}: one scene (the map of one history), got {len(names)}")
        for name in names:
            if name not in raw_scenes:
                lines.append(f"figures.{fig}: no scene named {name!r}")
                continue
            if name not in scenes:
                continue  # the scene's own problems are reported
            want = "history" if fig in HISTORY_FIGURES else "self-similar"
            if want == "history" and getattr(scenes[name], "fretting", False):
                lines.append(f"figures.{fig}: scene {name!r} is a fretting path "
                             f"(tangential_path); its own figure is figures/{name}.png")
                continue
            if scenes[name].kind != want:
                lines.append(f"figures.{fig}: scene {name!r} is of kind {scenes[name].kind}; "
                             f"this figure draws scenes of kind {want}")
                continue
            if want == "history":
                continue
            missing = [o for o in FIGURE_NEEDS[fig] if o not in scenes[name].outputs]
            if missing:
                lines.append(f"figures.{fig}: scene {name!r} does not ask for "
                             f"{', '.join(missing)} (add it to scenes.{name}.outputs)")
    return lines


# tables/<name>.csv and figures/<name>.png of the workflow's own targets: a physical or
# fretting scene, which writes its own under its name, must not take one of them
OWN_OUTPUT_NAMES = {"convergence", "fretting", "fretting-stick-map", "layers", "materials",
                    "viscoelastic", "key-numbers", "materials-key-numbers", "stresses",
                    "stresses-edge", "stresses-maps", "stresses-maxima", "stresses-tangential",
                    *FIGURES}


def _name_problems(scenes):
    """Physical and fretting scenes named like one of the workflow's own tables or figures."""
    return [f"scenes.{name}: the name is taken by the workflow's own figure or table "
            f"(figures/{name}.png, tables/{name}.csv); choose another"
            for name, s in scenes.items() if name in OWN_OUTPUT_NAMES
            and (s.kind == "physical" or getattr(s, "fretting", False))]


def _convergence_problems(cfg):
    lines = []
    studies = (cfg.get("convergence") or {}).get("studies")
    if not isinstance(studies, dict):
        return lines
    for name, st in studies.items():
        ns = st.get("n") if isinstance(st, dict) else None
        if isinstance(ns, list) and any(b != 2 * a for a, b in zip(ns, ns[1:])):
            lines.append(f"convergence.studies.{name}.n: each n must be twice the previous, "
                         f"got {ns}")
        ref = st.get("reference") if isinstance(st, dict) else None
        if ref is not None and ref not in studies:
            lines.append(f"convergence.studies.{name}.reference: no study named {ref!r}")
    return lines


def _validate_config(cfg):
    """Every problem of the configuration at once, one line each, or the parsed scenes.

    Each scene by the library's rules first (contactlib.scene.parse_named_scene,
    the words of ``contactlib check-config``), then the schema (types and
    ranges) for what the library let through, the figures' scene lists and
    the convergence studies; all of it is gathered before one error is raised.
    """
    raw_scenes = cfg.get("scenes") if isinstance(cfg.get("scenes"), dict) else {}
    scenes, lines, said = {}, [], {}  # said: the keys the library named, by scene
    for name, raw in raw_scenes.items():
        name = str(name)
        try:
            scenes[name] = parse_named_scene(name, raw)
        except ValueError as exc:  # ConfigError: one line a bad key
            for line in getattr(exc, "problems", [str(exc)]):
                head, prefix = line.split(":", 1)[0], f"scenes.{name}."
                key = head[len(prefix):].split(".")[0] if head.startswith(prefix) else None
                said.setdefault(name, set()).add(key)
                lines.append(line)
    try:  # the library's rule, as check-config says it
        contactlib.validate.results_dir(cfg.get("results_dir", "results"))
        said_dir = False
    except ValueError as exc:
        lines.append(f"results_dir: {exc}")
        said_dir = True
    for line, scene, keys in _schema_problems(cfg):  # one report a problem: the library's
        if said_dir and line.startswith("results_dir:"):
            continue
        if scene is not None:
            if scene in said and (keys is None or None in said[scene] or keys & said[scene]):
                continue
            scenes.pop(scene, None)
        lines.append(line)
    lines.sort(key=lambda line: line.split(":", 1)[0].split(".")[:2])  # grouped by scene
    lines += _name_problems(scenes)
    lines += _figure_problems(cfg, scenes, raw_scenes)
    lines += _convergence_problems(cfg)
    if lines:
        raise WorkflowError("invalid configuration:\n" + "\n".join(f"  {l}" for l in lines))
    validate(cfg, str(SCHEMA))  # fills the schema's defaults
    return scenes


def material_scenes(cfg, taken):
    """The `materials` target's scenes (contactlib.scene.material_pair_scenes): per pair
    [indenter, body] a self-similar scene mat-<indenter>-on-<body> and a history scene
    mat-<indenter>-on-<body>-cycle.

    Returns {name: scene} and {self-similar name: (history name, "indenter on body")}
    in the configured order; every problem of the section is raised at once."""
    section = cfg.get("materials")
    if not isinstance(section, dict):
        return {}, {}
    try:
        raws = material_pair_scenes(section)
    except ValueError as exc:
        raise WorkflowError(f"invalid configuration:\n  materials.pairs: {exc}") from None
    scenes, lines = {}, []
    for name, raw in raws.items():
        if name in taken:
            lines.append(f"materials.pairs: scene name {name!r} is taken")
            continue
        try:
            scenes[name] = parse_scene(name, raw)
        except ValueError as exc:
            lines += [f"materials: {line}" for line in getattr(exc, "problems", [str(exc)])]
    if lines:
        raise WorkflowError("invalid configuration:\n" + "\n".join(f"  {l}" for l in lines))
    pairs = {name: (f"{name}-cycle", f"{raw['indenter']} on {raw['body']}".replace("_", " "))
             for name, raw in raws.items() if raw.get("kind") != "history"}
    return scenes, pairs


def visco_scenes(cfg, taken):
    """The `viscoelastic` target's history scenes (contactlib.scene.viscoelastic_scenes):
    one cycle a duration, visco-T<duration>; every problem of the section at once."""
    section = cfg.get("viscoelastic")
    if not isinstance(section, dict):
        return {}
    scenes, lines = {}, []
    for name, raw in viscoelastic_scenes(section).items():
        if name in taken:
            lines.append(f"viscoelastic.durations: scene name {name!r} is taken")
            continue
        try:
            scenes[name] = parse_scene(name, raw)
        except ValueError as exc:
            lines += [f"viscoelastic: {line}" for line in getattr(exc, "problems", [str(exc)])]
    if lines:
        raise WorkflowError("invalid configuration:\n" + "\n".join(f"  {l}" for l in lines))
    return scenes


ALL_SCENES = _validate_config(config)
# where every output goes: the config's results_dir (default results), so that a study
# of your own (--configfile) does not overwrite the paper's figures and datasets
RESULTS = "{}/".format(Path(str(config.get("results_dir", "results"))).as_posix())
# the `materials` target's scenes: built by the same rules, not part of `all`
MATERIAL_SCENES, MATERIAL_PAIRS = material_scenes(config, ALL_SCENES)
# the `viscoelastic` target's scenes (history scenes), not part of `all` either
VISCO_SCENES = visco_scenes(config, {**ALL_SCENES, **MATERIAL_SCENES})
SCENES = {n: s for n, s in {**ALL_SCENES, **MATERIAL_SCENES}.items() if s.kind == "self-similar"}
HISTORIES = {n: s for n, s in {**ALL_SCENES, **MATERIAL_SCENES, **VISCO_SCENES}.items()
             if s.kind == "history" and not s.fretting}
# history scenes with a tangential path: contactlib.fretting, a dataset, table and figure
FRETTING = {n: s for n, s in ALL_SCENES.items() if s.kind == "history" and s.fretting}
# scenes in physical units (radius, materials, forces): a dataset, a table and a figure in SI
PHYSICAL = {n: s for n, s in ALL_SCENES.items() if s.kind == "physical"}
CONVERGENCE = config.get("convergence") or {"stick_ratios": [], "studies": {}}

# influence sets, shared by every scene with the same key; the parts any of them needs
INFLUENCE = {}
for _s in SCENES.values():
    _spec = INFLUENCE.setdefault(_s.influence_key, dict(_s.influence_spec(), parts=[]))
    _spec["parts"] = [p for p in ("normal", "shear") if p in _spec["parts"] or p in _s.parts]


wildcard_constraints:
    scene="|".join(sorted(SCENES)) or "NONE",
    hscene="|".join(sorted(HISTORIES)) or "NONE",
    pscene="|".join(sorted(PHYSICAL)) or "NONE",
    fscene="|".join(sorted(FRETTING)) or "NONE",
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
        **s.solve_spec(),  # a profile's keys (none for the paraboloid: params as before)
        **{k: v for k, v in s.influence_spec().items() if k.startswith("substrate")},
    }


def physical_params(wildcards):
    """A physical scene's call (contactlib.physical.physical_history, SI) plus provenance."""
    s = PHYSICAL[wildcards.pscene]
    return {"run": s.run_spec(), "scene": s.name, "hash": s.hash}


def fretting_params(wildcards):
    """A fretting scene's call (contactlib.fretting, its one friction coefficient) plus
    provenance."""
    s = FRETTING[wildcards.fscene]
    return {"run": s.run_spec(0), "scene": s.name, "hash": s.hash}


def history_params(wildcards):
    """A history scene's runs (the library call's arguments, one a k) plus provenance."""
    s = HISTORIES[wildcards.hscene]
    return {"runs": [s.run_spec(i) for i in range(len(s.frictions))], "scene": s.name,
            "hash": s.hash}


def _cores():
    """--cores, or None where it is not set (a cluster run with --jobs only)."""
    try:
        return workflow.cores
    except WorkflowError:
        return None


def side_threads(wanted):
    """Threads of a job that can run beside others: `wanted`, but at most half of --cores.

    Snakemake starts a job only when its threads are free, so a job asking for
    every core waits until all running jobs end (and then keeps cores idle while
    its own serial part, the imports, runs). With --cores 2 these jobs take one
    core each and run beside the chain of the self-similar scenes; only the last
    job (figures_paper) takes both.

    Only where the jobs run on this machine: a cluster job (and Snakemake
    running it on its node) gets `wanted`. Call it when jobs are made (in a
    `threads:` function), when the executor is known.
    """
    cores = _cores()
    if cores is None or not workflow.local_exec or workflow.remote_exec:
        return wanted
    return max(1, min(wanted, cores // 2))


def figure_threads(family, n):
    """n worker processes; the history family's at most half of --cores (side_threads)."""
    return n if family == "paper" else (lambda wildcards: side_threads(n))


# Job priorities: the length of the chain of jobs still to come after a job (quiet
# 2-core machine, seconds: influence 3.4 + solve 2.1 + assemble (with the profiles) 2 +
# figures 3.3 + table 1 for a default scene; a history run 1 - 5, its dataset 1,
# the history figures 5), so that the long chains start first and the short jobs
# fill the cores beside them; without this the scheduler (which prefers big
# inputs among equal priorities) left a default scene's solve for last, and the
# main job ended on one core.
PRIORITY = {
    "influence": 3, "history_run": 3, "physical_run": 3,
    "solve": 2, "figures_history": 2,
    "check": 1, "energy": 1, "assemble": 1,
    "figures_paper": 0, "key_numbers": 0,
}


def history_threads(wildcards):
    """One worker process a friction coefficient, at most half of --cores (side_threads)."""
    return side_threads(len(HISTORIES[wildcards.hscene].frictions))


def influence_files(wildcards):
    """The folder of the scene's influence set (its <part>.npz files)."""
    return {"influence": f"{RESULTS}influence/{SCENES[wildcards.scene].influence_key}"}


def stage_files(wildcards):
    """The post-processing results a scene's dataset is assembled from."""
    s = SCENES[wildcards.scene]
    files = {"solutions": f"{RESULTS}solutions/{s.name}.npz"}
    folders = {"check": "checks", "energy": "energy"}
    for stage in s.stages:
        files[stage] = f"{RESULTS}{folders[stage]}/{s.name}.npz"
    return files


def figure_scenes(fig):
    return list((config.get("figures") or {}).get(fig) or [])


# the title a figure is listed under in the report (its caption holds the rest)
FIGURE_TITLES = {
    "fig2": "Fig. 2: friction coefficient k against stick ratio c/a",
    "fig3": "Fig. 3: pressure and shear across the contact",
    "fig4": "Fig. 4: tangential surface displacement",
    "fig5": "Fig. 5: frictional work of a loading half-cycle",
    "history_stick_radius": "History: stick-zone radius along the load path",
    "history_stick_map": "History: stick/slip map over the path",
    "history_loop": "History: displacement loop under load-unload",
    "history_energy": "History: energy dissipated per load cycle",
}


# the figures the config asks for (those given scenes), by family
FIGURE_FAMILIES = {
    family: [fig for fig in figs if figure_scenes(fig)]
    for family, figs in (("paper", PAPER_FIGURES), ("history", HISTORY_FIGURES))
}
FIGURE_FAMILIES = {family: figs for family, figs in FIGURE_FAMILIES.items() if figs}


def figure_inputs(figs):
    """The datasets of every scene the figures draw, each once."""
    return sorted({f"{RESULTS}datasets/{s}.nc" for fig in figs for s in figure_scenes(fig)})


def figure_outputs(figs):
    """<fig>_png (in the report, with the figure's caption and title) and <fig>_pdf."""
    out = {}
    for fig in figs:
        out[f"{fig}_png"] = report(
            f"{RESULTS}figures/{fig}.png",
            caption=f"../report/{fig}.rst",
            category="Figures",
            labels={"figure": FIGURE_TITLES.get(fig, fig), "file": f"{fig}.png"},
        )
        out[f"{fig}_pdf"] = f"{RESULTS}figures/{fig}.pdf"
    return out


def all_targets():
    out = [f"{RESULTS}datasets/{name}.nc" for name in ALL_SCENES]
    for name in [*PHYSICAL, *FRETTING]:  # a physical or fretting scene's table and figure
        out += [f"{RESULTS}tables/{name}.csv", f"{RESULTS}figures/{name}.png",
                f"{RESULTS}figures/{name}.pdf"]
    for fig in FIGURES:
        if figure_scenes(fig):
            out += [f"{RESULTS}figures/{fig}.png", f"{RESULTS}figures/{fig}.pdf"]
    if ALL_SCENES:  # the key-numbers table sums up every scene
        out += [f"{RESULTS}tables/key-numbers.csv", f"{RESULTS}tables/key-numbers.html"]
    return out


def study_reference(wildcards):
    ref = CONVERGENCE["studies"][wildcards.study].get("reference")
    return {"reference": f"{RESULTS}convergence/{ref}.nc"} if ref else {}


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


def cancel_rate_limiter_timer():
    """Cancel the timer Snakemake's job-rate limiter leaves armed (onsuccess, onerror).

    The limiter (--max-jobs-per-timespan, default 100/1s) arms a non-daemon
    timer of up to 1 s after each round of job selection, and the interpreter
    waits for it before exiting: every run ended about 1 s after its last job
    (1.25 s measured between "Elapsed time" and the exit). When the handlers
    run, the scheduler has returned, so the timer has nothing left to wake.
    """
    import threading

    for thread in threading.enumerate():
        if isinstance(thread, threading.Timer):
            thread.cancel()
