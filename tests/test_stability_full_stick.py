"""Near full stick at strong coupling: the largest stick ratio c* < 1 of one slip zone.

Where the coupling is strong (nu <= 0 on the half-space or half-plane), k(c/a)
of the single-stick-zone self-similar solution grows without bound as c/a
approaches a limit c* below 1 (sphere: 0.952 at nu = -0.99, 0.99901 at
nu = 0; half-plane 0.8495 at nu = -0.99); past c* the root comes back
through k = inf with slip outward and tensile pressure at the stick edge, so
no friction coefficient gives c/a > c* (docs/accuracy.md, "Near full stick").
The reason is the full-stick solution itself: its pressure turns tensile
near the edge, where the tractions oscillate like rho^(1/2 + i eps),
eps = ln(3 - 4 nu)/(2 pi), rho the distance to the edge.

The truths used: refinement in n; the oscillation index eps (closed form);
the incremental history solver, which does not assume self-similarity.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from contactlib import history, solve
from contactlib.cli import main
from contactlib.solvers.default_method import solve_default
from contactlib.model import contact
from contactlib.validate import SolverLimit


def _tensile_and_sign_change(geometry: str, nu: float, n: int) -> tuple[float, float]:
    """Full stick (c/a = 1): 1 - r where p first turns negative (from the axis), and 1 - r
    where the shear then first changes sign."""
    d = solve_default(contact(geometry, nu), 1.0, n)
    r, p = d.mesh.nodes[:-1], d.p[:-1]
    q = d.shear(r)
    ip = int(np.nonzero(p < 0)[0][0])
    flip = np.nonzero(np.sign(q) != np.sign(q[ip]))[0]
    iq = int(flip[flip > ip][0])
    return float(1.0 - r[ip]), float(1.0 - r[iq])


@pytest.mark.parametrize("geometry", ["sphere", "cylinder"])
def test_full_stick_pressure_turns_tensile_at_the_oscillating_edge(geometry):
    """The full-stick pressure is tensile near the edge at nu = -0.99, stable under
    refinement, and the shear changes sign a factor exp(pi/(2 eps)) closer to the edge
    (the phase of p + iq advances by pi/2), eps = ln(3 - 4 nu)/(2 pi)."""
    nu = -0.99
    rp128, _ = _tensile_and_sign_change(geometry, nu, 128)
    rp, rq = _tensile_and_sign_change(geometry, nu, 256)
    assert abs(rp128 / rp - 1.0) < 0.1  # measured 0.0198, 0.0209 (sphere); 0.0665 (cylinder)
    eps = math.log(3.0 - 4.0 * nu) / (2.0 * math.pi)
    ratio = (rp / rq) / math.exp(math.pi / (2.0 * eps))  # measured 0.94 (sphere), 1.07
    assert 1 / 1.5 < ratio < 1.5  # the sign change of q lies on a geometric mesh
    # at nu = 0.3 the oscillation is slow (eps = 0.094): no tensile node down to 1.5e-5 a
    d = solve_default(contact(geometry, 0.3), 1.0, 256)
    assert np.all(d.p[:-1] >= 0.0)


def test_k_grows_without_bound_below_full_stick():
    """Sphere, nu = -0.99: 1/k falls to zero at c* = 0.952 (< 1); k converges under
    refinement inside c*, and past c* the solve is refused with the reason."""
    model = contact("sphere", -0.99)
    ks = {c: solve_default(model, c, 128).k for c in (0.93, 0.94, 0.95)}
    assert all(np.isfinite(k) and k > 0 for k in ks.values())
    inv = np.array([1.0 / ks[c] for c in (0.93, 0.94, 0.95)])
    assert inv[0] > inv[1] > inv[2] > 0.0  # 0.214, 0.129, 0.023
    c_star = 0.95 + inv[2] * 0.01 / (inv[1] - inv[2])  # linear in c: a bound above c*
    assert 0.95 < c_star < 0.96
    k256 = solve_default(model, 0.94, 256).k
    assert abs(k256 / ks[0.94] - 1.0) < 5e-3  # 7.7316 at both n
    sol = solve("sphere", -0.99, stick_ratio=0.96, n=128, energy=False)
    assert not sol.converged and not sol.resolved and math.isnan(sol.friction_coefficient)
    assert "beyond the largest stick ratio" in sol.message and "tensile" in sol.message


def test_tiny_friction_is_refused_with_the_stick_ratio_it_would_give(tmp_path, capsys):
    """k = 1e-3 at nu = -0.99 gives c/a ~ 1e-470 (k ~ A/ln(4a/c)): below any resolved stick
    zone; the library says so (a solver limit, not bad input), and the command line exits
    3 with the reason and the command that answers it (friction 0: Hertz), no file."""
    with pytest.raises(SolverLimit, match="smallest resolved"):
        solve("sphere", -0.99, friction=1e-3, n=64, energy=False)
    out = tmp_path / "x.nc"
    code = main(["solve", "--geometry", "cylinder", "--nu", "0", "--friction", "1e-6",
                 "--n", "64", "--output", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 3 and len(err) == 2 and "friction" in err[0] and not out.exists()
    assert err[1] == ("contactlib: answer it with: contactlib solve --geometry cylinder --nu 0 "
                      f"--n 64 --friction 0 --output {out}")


@pytest.mark.slow  # two inverse searches (about 30 s)
def test_inverse_near_the_largest_stick_ratio():
    """k = 10 and 1e4 at nu = -0.99 (sphere): stick ratios below c* (the inverse used to
    refuse both as 'full adhesion'); the forward solve at the returned c/a gives k back,
    and k = 1e4, where k is hypersensitive to c/a, is flagged."""
    sol = solve("sphere", -0.99, friction=10.0, n=128, energy=False)
    assert 0.94 < sol.stick_ratio < 0.95 and sol.converged and sol.consistent
    back = solve_default(contact("sphere", -0.99), sol.stick_ratio, 256).k
    assert abs(back / 10.0 - 1.0) < 3.0 * sol.error_estimate + 1e-4
    big = solve("sphere", -0.99, friction=1e4, n=128, energy=False)
    assert 0.951 < big.stick_ratio < 0.9523 and not big.resolved


@pytest.mark.slow  # the history runs take about 10 s
def test_history_solver_reaches_the_same_stick_ratio():
    """Monotonic loading by the incremental history solver (no self-similarity assumed),
    nu = -0.99, k = 2: its stick ratio at the top load agrees with the default method's
    inverse within two of its elements, at n = 240 and 480, and every step converges
    with one inward slip zone outside one stick zone."""
    c_default = solve("sphere", -0.99, friction=2.0, n=128, energy=False).stick_ratio
    for n in (240, 480):
        res = history("sphere", -0.99, 2.0, [0, 1], 100, n=n, error_estimate=False)
        assert res.converged.all()
        assert abs(res.stick_ratio[-1] - c_default) < 2 * 1.2 / n  # 0.8816, 0.8805 vs 0.880
        state = res.state[-1][res.state[-1] > 0]
        first_slip = int(np.argmax(state != 1))
        assert np.all(state[:first_slip] == 1) and np.all(state[first_slip:] == 2)


def test_large_friction_beyond_the_resolved_stick_zone_is_refused():
    """nu = 0.3, k = 10: the stick zone would leave 1 - c/a ~ exp(-pi k / beta) (uncoupled),
    far below 1 - 1e-5, the largest resolved; refused, not a flagged c/a = 1 - 7.6e-7."""
    with pytest.raises(ValueError, match="too large"):
        solve("sphere", 0.3, friction=10.0, n=64, energy=False)


@pytest.mark.slow  # two solves near full stick and one inverse search (about 15 s)
def test_friction_of_the_largest_resolved_stick_ratio_is_accepted():
    """The project's own k at c/a = 1 - 1e-5 (the inverse's ceiling), given back as the
    friction, returns that stick ratio, resolved: not a refusal as 'too large' because a
    warm-started Newton there lands 4e-10 relative away, nor a raw scipy sign error."""
    k = solve("cylinder", 0.3, stick_ratio=0.99999, energy=False)
    assert k.resolved
    back = solve("cylinder", 0.3, friction=k.friction_coefficient, energy=False)
    assert back.resolved and abs(back.stick_ratio - 0.99999) < 1e-9
    assert abs(back.friction_coefficient / k.friction_coefficient - 1.0) < k.error_estimate
