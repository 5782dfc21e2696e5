"""The dataset conventions of contactlib.io, held against a stored description.

Every kind of dataset contactlib writes (a solve, a sweep, a workflow scene, a
loading history, a stack of histories, a convergence study) is built from a
small computation and described by its variable names, dimensions, dtypes and
attributes (``contactlib_version`` left out), in the order they are written,
which is what makes the files byte-reproducible. The description must equal
``tests/data/conventions.json``. A deliberate change of the interface (a new
variable, a reworded attribute) updates the stored file:

    CONTACTLIB_UPDATE_CONVENTIONS=1 python -m pytest tests/test_conventions.py

and the diff of that file shows the change for review. The numbers are not
compared here (the physics tests do that).
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import contactlib
from contactlib import convergence, io, pipeline
from contactlib.scene import parse_scene

STORED = Path(__file__).resolve().parent / "data" / "conventions.json"
UPDATE = os.environ.get("CONTACTLIB_UPDATE_CONVENTIONS") == "1"


def _plain(value: Any) -> Any:
    if isinstance(value, np.ndarray):
        return [_plain(v) for v in value.tolist()]
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _describe(ds) -> dict[str, Any]:
    """Names, dims, dtypes and attributes as lists of pairs: their order is compared too."""
    attrs = [[k, _plain(v)] for k, v in ds.attrs.items() if k != "contactlib_version"]
    attrs.append(["has_contactlib_version", "contactlib_version" in ds.attrs])
    variables = [[str(name), {"dims": list(var.dims), "dtype": str(var.dtype),
                              "attrs": [[k, _plain(v)] for k, v in var.attrs.items()]}]
                 for name, var in ds.variables.items()]
    return json.loads(json.dumps({"attrs": attrs, "variables": variables}))


def _datasets() -> dict[str, Any]:
    sweep = contactlib.sweep("sphere", 0.3, [0.0, 0.5, 1.0], n=16)
    slab = contactlib.sweep("cylinder", 0.3, [0.25, 0.5], n=8, method="paper", slab_ratio=0.05)
    scene = parse_scene("demo", {"geometry": "sphere", "nu": 0.3, "n": 16,
                                 "stick_ratios": [0.0, 0.5], "outputs": ["k_curve", "energy"]})
    parts = {p: pipeline.influence(scene.influence_spec(), p) for p in scene.parts}
    records = pipeline.solve(scene, parts["normal"], parts["shear"])
    scene_ds = pipeline.assemble(scene, records, checks=pipeline.check(records),
                                 work=pipeline.energy(scene, records))
    runs = [io.history_to_dataset(contactlib.history("sphere", 0.3, k, [0, 1, 0], 2, n=16))
            for k in (0.1, 0.2)]
    study = convergence.study("sphere", 0.3, "default", [16, 32, 64], [0.5])
    return {
        "solve": io.to_dataset(sweep[1]),
        "sweep": io.to_dataset(sweep),
        "sweep-cylinder-paper": io.to_dataset(slab),
        "scene": scene_ds,
        "history": runs[0],
        "history-stack": io.stack_histories(runs),
        "study": io.study_to_dataset(study, name="demo"),
    }


@pytest.fixture(scope="module")
def described() -> dict[str, Any]:
    return {name: _describe(ds) for name, ds in _datasets().items()}


def test_dataset_conventions_match_the_stored_description(described):
    if UPDATE:
        STORED.parent.mkdir(exist_ok=True)
        STORED.write_text(json.dumps(described, indent=1, ensure_ascii=False) + "\n",
                          encoding="utf-8")
    stored = json.loads(STORED.read_text(encoding="utf-8"))
    assert sorted(described) == sorted(stored)
    for name in stored:
        now, then = described[name], stored[name]
        assert [k for k, _ in now["attrs"]] == [k for k, _ in then["attrs"]], name
        assert now["attrs"] == then["attrs"], name
        assert [k for k, _ in now["variables"]] == [k for k, _ in then["variables"]], name
        for (var, a), (_, b) in zip(now["variables"], then["variables"]):
            assert a == b, f"{name}: {var}"


def test_every_variable_has_units_and_long_name(described):
    for name, d in described.items():
        for var, desc in d["variables"]:
            if var in ("quantity", "message"):  # labels, not quantities
                continue
            keys = [k for k, _ in desc["attrs"]]
            assert "units" in keys and "long_name" in keys, (name, var)
