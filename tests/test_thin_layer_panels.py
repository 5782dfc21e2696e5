"""The cost-saving parts of the thin-layer sums (contactlib.kernels.thin_layer).

* The 64-point panels (five times as wide as the 20-point ones for the
  oscillation) against the 20-point panels alone at half their width (the
  quadrature before the change, refined): rigid and coated bases, rho and
  sigma up to 1200, each function to its scale (measured <= 2e-13).
* Panels up to 0.8 wide (64 nodes: 2.56) where the oscillation allows, against
  20-point panels of at most 0.125 (rho, sigma <= 60; measured <= 4e-14).
* The rule choice: 20 points up to ``span = 37.5``, 64 from 42 on.
* Both kinds in one pass: each equal bit for bit to its own pass, and the kept
  kind handed out only to a call with the same arguments and constants.
"""

from __future__ import annotations

import numpy as np
import pytest

from contactlib.kernels import layer, thin_layer

NU = 0.25
_sums = thin_layer._sums  # (the original, under monkeypatch)
BASES = ["bonded", "smooth", layer.Substrate(0.525, 0.3), layer.Substrate(0.01, 0.3),
         layer.Substrate(1e3, 0.3)]
rng = np.random.default_rng(7)
RHO = np.r_[0.0, 5.0, rng.uniform(0.0, 1200.0, 12), 999.0, 1200.0]
SIGMA = np.r_[0.5, 150.0, rng.uniform(0.0, 1200.0, 12), 1200.0]


@pytest.mark.parametrize("base", BASES)
@pytest.mark.parametrize("kind", ["pressure", "shear"])
def test_wide_panels_equal_the_refined_20_point_rule(monkeypatch, base, kind):
    """Measured <= 2e-13 of each function's scale (the 20-point rule itself: <= 2e-13)."""
    fine = layer.fine_panel(NU, base)
    assert thin_layer.nodes(2400.0, fine)[0].size < 0.67 * 28800  # 36% fewer than 20-point
    out = thin_layer.remainders(kind, RHO, SIGMA, NU, base)
    monkeypatch.setattr(thin_layer, "HIGH_WIDER", 0.1)  # never chosen: 20 points only
    monkeypatch.setattr(thin_layer, "PANEL_SPAN", thin_layer.PANEL_SPAN / 2)
    ref = thin_layer.remainders(kind, RHO, SIGMA, NU, base)
    scale = np.abs(ref).max(axis=(1, 2))[:, None, None]
    assert np.all(np.abs(out - ref) < 1e-12 * scale)


@pytest.mark.parametrize("base", BASES)
@pytest.mark.parametrize("top", [21.0, 60.0])
def test_wide_panels_at_small_spans(monkeypatch, base, top):
    """Panels to MAX_PANEL = 0.8 (64 nodes: 2.56) against 20-point ones of at most 0.125."""
    rho = np.r_[0.0, 0.7, 5.0, rng.uniform(0.0, top, 8), top]
    sigma = np.r_[0.3, 0.3 * top, rng.uniform(0.0, top, 8), top]
    out = thin_layer.remainders("pressure", rho, sigma, NU, base)
    out_s = thin_layer.remainders("shear", rho, sigma, NU, base)
    monkeypatch.setattr(thin_layer, "MAX_PANEL", 0.125)
    monkeypatch.setattr(thin_layer, "HIGH_WIDER", 0.1)  # 20 points only
    monkeypatch.setattr(thin_layer, "PANEL_SPAN", thin_layer.PANEL_SPAN / 2)
    for got, kind in ((out, "pressure"), (out_s, "shear")):
        ref = thin_layer.remainders(kind, rho, sigma, NU, base)
        scale = np.abs(ref).max(axis=(1, 2))[:, None, None]
        assert np.all(np.abs(got - ref) < 1e-12 * scale)  # measured <= 4e-14


def test_rule_choice():
    """20 points up to span 37.5 (panels of min(0.8, 30/span)); from 42 on 64 points."""
    g, w = np.polynomial.legendre.leggauss(20)
    for span in (10.0, 37.5):
        width = min(thin_layer.MAX_PANEL, thin_layer.PANEL_SPAN / span)
        edges = np.linspace(0.0, thin_layer.T_MAX, int(np.ceil(thin_layer.T_MAX / width)) + 1)
        lo, hi = edges[:-1, None], edges[1:, None]
        t, wt = thin_layer.nodes(span)
        assert np.array_equal(t, (0.5 * (hi - lo) * g + 0.5 * (lo + hi)).ravel())
        assert np.array_equal(wt, (0.5 * (hi - lo) * w).ravel())
    for span in (42.0, 60.0, 2000.0):  # 64 nodes on panels of min(2.56, 150/span)
        t, wt = thin_layer.nodes(span)
        width = min(thin_layer.MAX_PANEL * 64 / 20,
                    thin_layer.HIGH_WIDER * thin_layer.PANEL_SPAN / span)
        assert t.size == 64 * int(np.ceil(thin_layer.T_MAX / width))
        assert abs(wt.sum() - thin_layer.T_MAX) < 1e-12


@pytest.mark.parametrize("base", ["bonded", layer.Substrate(0.525, 0.3)])
def test_both_kinds_in_one_pass_equal_their_own_passes(monkeypatch, base):
    edges = np.r_[0.0, np.cumsum(np.geomspace(0.5, 9.0, 60))]  # to ~200 h
    g, gw = np.polynomial.legendre.leggauss(6)  # a Gauss rule on each element
    half, mid = 0.5 * np.diff(edges)[:, None], 0.5 * (edges[1:] + edges[:-1])[:, None]
    s, w = (mid + half * g).ravel(), (half * gw).ravel()
    owner = np.repeat(np.arange(edges.size - 1), 6)
    rho = np.r_[edges[::3], 37.3]
    both = thin_layer._sums(("pressure", "shear"), rho, s, NU, base, w, owner)
    for kind in ("pressure", "shear"):
        own = thin_layer._sums((kind,), rho, s, NU, base, w, owner)[kind]
        assert np.array_equal(both[kind], own)
    # the operators' order: pressure computes both, shear gets the kept sums
    calls = []
    monkeypatch.setattr(thin_layer, "_sums", lambda kinds, *args: calls.append(kinds)
                        or _sums(kinds, *args))
    with thin_layer.both_kinds():
        assert np.array_equal(thin_layer.remainders("pressure", rho, s, NU, base, w, owner),
                              both["pressure"])
        assert np.array_equal(thin_layer.remainders("shear", rho, s, NU, base, w, owner),
                              both["shear"])
        assert calls == [("pressure", "shear")]
        # kept only for the same arguments and constants
        thin_layer.remainders("pressure", rho, s, NU, base, w, owner)
        other = thin_layer.remainders("shear", rho[:-1], s, NU, base, w, owner)
        assert other.shape == (3, rho.size - 1, edges.size - 1)
        scale = np.abs(both["shear"]).max()
        assert np.abs(other - both["shear"][:, :-1]).max() < 1e-13 * scale
        thin_layer.remainders("pressure", rho, s, NU, base, w, owner)
        monkeypatch.setattr(thin_layer, "PANEL_SPAN", thin_layer.PANEL_SPAN / 2)
        finer = thin_layer.remainders("shear", rho, s, NU, base, w, owner)
        assert not np.array_equal(finer, both["shear"])
        assert np.array_equal(finer, _sums(("shear",), rho, s, NU, base, w, owner)["shear"])
    # outside: one kind a call, nothing kept
    del calls[:]
    thin_layer.remainders("pressure", rho, s, NU, base, w, owner)
    thin_layer.remainders("shear", rho, s, NU, base, w, owner)
    assert calls == [("pressure",), ("shear",)]


def test_operators_ask_for_both_kinds(monkeypatch):
    """A coated sphere's operators at a/h = 100: one pass for both parts, each as alone."""
    from contactlib import model as contact_model
    from contactlib.discretization import operators

    calls = []
    monkeypatch.setattr(thin_layer, "_sums", lambda kinds, *args: calls.append(kinds)
                        or _sums(kinds, *args))
    geometry = contact_model.contact("sphere", NU, slab_ratio=100.0, base="elastic",
                                     substrate_modulus=0.525, substrate_nu=0.3)
    nodes = np.linspace(0.0, 1.0, 33)
    p, q = operators.operators(geometry, nodes, nodes)
    assert calls == [("pressure", "shear")]
    assert np.array_equal(p, operators.operator_part(geometry, nodes, nodes, "normal"))
    assert np.array_equal(q, operators.operator_part(geometry, nodes, nodes, "shear"))
    assert calls[1:] == [("pressure",), ("shear",)]
