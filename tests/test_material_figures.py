"""The `materials` target: contactlib.plot.materials, the pair scenes and the workflow DAG."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

import contactlib
from conftest import job_counts, make_workdir, needs_snakemake
from contactlib.io import history_to_dataset, stack_histories, to_dataset, write_figure
from contactlib.model.materials import pair
from contactlib.plot import style_path
from contactlib.plot.materials import cycle_work, fig_material_pairs, pair_label
from contactlib.scene import HistoryScene, Scene, material_pair_scenes, parse_scene, \
    scene_mapping

PAIRS = [("steel", "aluminium"), ("aluminium", "steel"), ("steel", "steel")]
SECTION = {"pairs": [list(p) for p in PAIRS], "n": 16, "stick_ratios": [0.0, 0.3, 0.6, 1.0],
           "friction": [0.02, 0.05], "load_path": [0, 1, 0], "steps": 4}


@pytest.fixture(scope="module")
def data() -> tuple[list[xr.Dataset], list[xr.Dataset]]:
    """Small sweeps (n = 32) and histories (n = 40, 4 steps a segment) of three pairs.

    (At n = 16 steel on aluminium, c/a = 0.3, breaks stick admissibility by 1.2e-4, a
    coarse-mesh effect gone at n = 32, and is then not resolved.)
    """
    sims, hists = [], []
    for ind, body in PAIRS:
        ratio, nu1, nu2 = pair(ind, body)
        kw = dict(indenter_modulus=ratio, indenter_nu=nu1)
        sims.append(to_dataset(contactlib.sweep("sphere", nu2, SECTION["stick_ratios"], n=32,
                                                max_error=0.05,
                                                **kw)))
        hists.append(stack_histories([history_to_dataset(contactlib.history(
            "sphere", nu2, k, [0, 1, 0], 4, n=40, **kw)) for k in SECTION["friction"]]))
    return sims, hists


# ----------------------------------------------------------------------------- figure
def test_figure_builds_with_beta_in_every_label(data, tmp_path):
    sims, hists = data
    names = [f"{a} on {b}" for a, b in PAIRS]
    fig = fig_material_pairs(sims, hists, labels=names)
    texts = [t.get_text() for ax in fig.axes if ax.get_legend()
             for t in ax.get_legend().get_texts()]
    assert texts == ["steel on aluminium (β = +0.117)", "aluminium on steel (β = -0.117)",
                     "steel on steel (β = 0)"]
    ax_k, ax_w = fig.axes[0], fig.axes[2]  # each column: plot panel, then legend holder
    assert ax_k.get_xlabel() == "stick ratio c/a" and ax_w.get_yscale() == "log"
    # beta = 0 has no positive work: named in the note, not drawn on the log axis
    assert any("steel on steel (β = 0): no positive work" in t.get_text() for t in ax_w.texts)
    write_figure(fig, tmp_path / "m.png", style=style_path())
    assert (tmp_path / "m.png").stat().st_size > 10_000


def test_mirror_pairs_draw_the_same_k_and_work(data):
    sims, hists = data
    np.testing.assert_allclose(sims[0]["friction_coefficient"], sims[1]["friction_coefficient"],
                               rtol=1e-6)
    assert sims[0].attrs["dundurs_beta"] == pytest.approx(-sims[1].attrs["dundurs_beta"])
    w0, w1 = cycle_work(hists[0])[1], cycle_work(hists[1])[1]
    np.testing.assert_allclose(w0, w1, rtol=1e-6)
    assert (w0 > 0).all()


def test_cycle_work_is_the_whole_path_for_a_single_cycle(data):
    k, work, ok = cycle_work(data[1][0])
    np.testing.assert_array_equal(k, SECTION["friction"])
    full = data[1][0]["frictional_work"].values
    np.testing.assert_allclose(work, full[:, -1] - full[:, 0])
    assert ok.all()
    fretting = history_to_dataset(contactlib.history("sphere", 0.3, 0.1, [0, 1, 0.5, 1, 0.5],
                                                     3, n=40, indenter_modulus=2.0))
    kf, wf, _ = cycle_work(fretting)  # the last two segments: 0.5 -> 1 -> 0.5
    w = fretting["frictional_work"].values
    assert kf.tolist() == [0.1] and wf[0] == pytest.approx(w[-1] - w[6])


def test_figure_refuses_bad_input(data):
    sims, hists = data
    with pytest.raises(ValueError, match="3 self-similar datasets but 2 histories"):
        fig_material_pairs(sims, hists[:2])
    with pytest.raises(ValueError, match="2 labels for 3 pairs"):
        fig_material_pairs(sims, hists, labels=["a", "b"])
    rigid = sims[0].copy()
    rigid.attrs = {k: v for k, v in rigid.attrs.items() if k != "dundurs_beta"}
    with pytest.raises(ValueError, match="'x' lacks the attribute 'dundurs_beta'"):
        pair_label(rigid, "x")
    loading = history_to_dataset(contactlib.history("sphere", 0.3, 0.1, [0, 1], 3, n=40))
    with pytest.raises(ValueError, match="does not end in one loading and one unloading"):
        cycle_work(loading)


# ----------------------------------------------------------------------------- scenes
def test_material_pair_scenes_parse_and_are_found_by_name():
    raws = material_pair_scenes(SECTION)
    assert list(raws) == ["mat-steel-on-aluminium", "mat-steel-on-aluminium-cycle",
                          "mat-aluminium-on-steel", "mat-aluminium-on-steel-cycle",
                          "mat-steel-on-steel", "mat-steel-on-steel-cycle"]
    ss = parse_scene("mat-steel-on-aluminium", raws["mat-steel-on-aluminium"])
    hs = parse_scene("mat-steel-on-aluminium-cycle", raws["mat-steel-on-aluminium-cycle"])
    assert isinstance(ss, Scene) and isinstance(hs, HistoryScene)
    assert ss.nu == hs.nu == 0.33 and ss.indenter_modulus == hs.indenter_modulus == 3.0
    assert hs.run_spec(0)["indenter_nu"] == 0.3
    config = {"scenes": {"own": {"geometry": "sphere"}}, "materials": SECTION}
    assert scene_mapping(config, "own") == {"geometry": "sphere"}
    assert scene_mapping(config, "mat-steel-on-steel-cycle")["kind"] == "history"
    with pytest.raises(KeyError):
        scene_mapping(config, "nothing")
    with pytest.raises(ValueError, match="indenter"):
        material_pair_scenes(dict(SECTION, pairs=[["unobtainium", "steel"]]))


# ----------------------------------------------------------------------------- workflow
@needs_snakemake
@pytest.mark.slow  # two dry runs; the scene and figure functions are tested fast above
@pytest.mark.workflow
def test_materials_target_is_separate_from_the_main_job(tmp_path):
    wd = make_workdir(tmp_path)
    main = job_counts(wd)
    assert "materials_figure" not in main and "materials" not in main
    counts = job_counts(wd, "materials")
    pairs = 6  # config/config.yaml
    assert counts["materials_figure"] == counts["materials"] == 1
    assert counts["solve"] == counts["history_run"] == pairs
    assert "energy" not in counts and "key_numbers" not in counts
    assert counts["materials_key_numbers"] == 1  # the pairs' own key-numbers table


# ----------------------------------------------------------------------------- key numbers
def test_key_numbers_of_material_scenes_name_the_indenter(data):
    """The material scenes' rows carry E1/E2, nu1 and beta (the report's body cell too);
    a table of rigid scenes keeps exactly the main job's columns."""
    from contactlib.summary import COLUMNS, INDENTER_COLUMNS, key_numbers, report_rows

    sims, hists = data
    rows = key_numbers(list(sims) + list(hists))
    assert all(tuple(r) == COLUMNS + INDENTER_COLUMNS for r in rows)
    runs = len(SECTION["friction"])  # a history row a run (long format)
    assert len(rows) == len(sims) + runs * len(hists)
    for i, ((ind, body), row) in enumerate(zip(PAIRS, rows)):
        ratio, nu1, nu2 = pair(ind, body)
        hrows = rows[len(sims) + runs * i:len(sims) + runs * (i + 1)]
        assert [r["history k"] for r in hrows] == SECTION["friction"]
        for r in (row, *hrows):
            assert r["indenter E1/E2"] == pytest.approx(ratio, rel=1e-12)
            assert r["indenter nu"] == nu1 and r["nu"] == nu2
        beta = contactlib.solve("sphere", nu2, stick_ratio=0.0, n=16, indenter_modulus=ratio,
                                indenter_nu=nu1).dundurs_beta
        assert row["dundurs beta"] == pytest.approx(beta, rel=1e-12, abs=1e-15)
        assert row["k at c/a = 0.25"] != row["k at c/a = 0.25"]  # not in the scene: NaN
    assert rows[0]["dundurs beta"] > 0 > rows[1]["dundurs beta"]
    cells = [r["body"] for r in report_rows(rows)]
    assert "β = +" in cells[0] and "β = -" in cells[1] and "E1/E2 = 3" in cells[0]
    rigid = key_numbers([to_dataset(contactlib.sweep("sphere", 0.3, [0.0, 0.5], n=16,
                                                     max_error=0.05))])
    assert tuple(rigid[0]) == COLUMNS and "β" not in report_rows(rigid)[0]["body"]
