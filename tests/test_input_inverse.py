"""The stick ratio a friction coefficient gives, at the ends of the inverse's range (issue 42,
item 9: "raw errors from below").

``solve(geometry, nu, friction=K)`` with K the project's own k at c/a = 0.99999 (the
inverse's ceiling, ``api.LARGEST_STICK_RATIO``) failed with scipy's raw "f(a) and f(b) must
have different signs": Brent's method solved the bracket's ends a second time from another
warm start, whose round-off could change the sign of k(c) - K. Now every stick ratio is solved
once, a friction within k's round-off of the ceiling gets the ceiling, and a friction beyond
the range solved is refused naming ``friction``, the n, the largest k solved and what to do.
"""

from __future__ import annotations

import dataclasses

import pytest

import contactlib
from contactlib import api, validate
from contactlib.cli import main

N = 64  # the inverse's range does not depend on n; n = 64 keeps each search under a second


@pytest.fixture(scope="module")
def k_ceiling() -> float:
    """The project's own k at c/a = 0.99999 (sphere, nu = 0.3, n = 64): 2.41466..."""
    sol = contactlib.solve("sphere", 0.3, stick_ratio=api.LARGEST_STICK_RATIO, n=N,
                           energy=False)
    assert sol.converged and sol.resolved
    return sol.friction_coefficient


@pytest.mark.parametrize("factor", [1.0, 1.0 + 5e-9, 1.0 - 1e-9])
def test_the_k_of_the_largest_stick_ratio_gives_it_back(k_ceiling, factor):
    sol = contactlib.solve("sphere", 0.3, friction=k_ceiling * factor, n=N, energy=False)
    assert sol.stick_ratio == pytest.approx(api.LARGEST_STICK_RATIO, abs=1e-12)
    assert sol.converged and sol.resolved
    assert sol.friction_coefficient == pytest.approx(k_ceiling * factor,
                                                     rel=2 * api.K_ROUNDOFF)


def test_a_k_just_below_the_ceiling_gives_a_stick_ratio_just_below_it(k_ceiling):
    k = k_ceiling * (1.0 - 1e-4)
    sol = contactlib.solve("sphere", 0.3, friction=k, n=N, energy=False)
    assert 0.99998 < sol.stick_ratio < api.LARGEST_STICK_RATIO
    assert sol.friction_coefficient == pytest.approx(k, rel=1e-5)


@pytest.mark.parametrize("factor", [1.0 + 1e-6, 1.5, 1e6])
def test_a_k_beyond_the_ceiling_is_refused_naming_the_range_solved(k_ceiling, factor):
    k = k_ceiling * factor
    with pytest.raises(validate.InputError) as err:
        contactlib.solve("sphere", 0.3, friction=k, n=N, energy=False)
    text = str(err.value)
    assert err.value.name == "friction" and text.startswith(f"friction {k!r} is too large")
    assert f"n = {N}" in text and "c/a = 0.99999" in text
    assert f"k = {k_ceiling:.10g}" in text  # the largest k solved, to round-off
    assert "stick ratio directly" in text and "\n" not in text


def test_friction_zero_is_hertz_and_a_tiny_friction_is_refused_below_the_floor():
    hertz = contactlib.solve("sphere", 0.3, friction=0.0, n=N, energy=False)
    assert hertz.stick_ratio == 0.0 and hertz.load_ratio == pytest.approx(1.0, abs=1e-3)
    with pytest.raises(validate.InputError, match=r"friction 1e-12 gives a stick zone below "
                       r"c/a = 1e-08, the smallest resolved \(k = [0-9.]+ there, at n = 64\)"):
        contactlib.solve("sphere", 0.3, friction=1e-12, n=N, energy=False)


def test_brent_never_solves_a_bracket_end_twice(k_ceiling, monkeypatch):
    """Round-off that depends on the warm start: each solve at the ceiling returns k a little
    above, then a little below, K. Solving the end again made scipy's raw sign error; the
    search now keeps the value the bracket was checked with."""
    real = api.solve_default
    calls: dict[float, int] = {}

    def flickering(geometry, c, n, **kwargs):
        d = real(geometry, c, n, **kwargs)
        if c == api.LARGEST_STICK_RATIO:
            calls[c] = calls.get(c, 0) + 1
            sign = 1.0 if calls[c] % 2 else -1.0
            d = dataclasses.replace(d, k=k_ceiling * (1.0 + sign * 1e-12))
        return d

    monkeypatch.setattr(api, "solve_default", flickering)
    c, d = api.stick_ratio_for_friction(api._validate_common("sphere", 0.3, N, "default",
                                                             0.0)[0], k_ceiling, N)
    assert calls == {api.LARGEST_STICK_RATIO: 1}
    assert c == pytest.approx(api.LARGEST_STICK_RATIO, abs=1e-12)


def test_the_command_line_answers_at_the_ceiling_and_refuses_beyond_it(k_ceiling, tmp_path,
                                                                      capsys):
    out = tmp_path / "x.nc"
    args = ["solve", "--geometry", "sphere", "--nu", "0.3", "--n", str(N)]
    assert main(args + ["--friction", repr(k_ceiling), "--output", str(out)]) == 0
    assert "0.99999" in capsys.readouterr().out and out.exists()
    out.unlink()
    code = main(args + ["--friction", "1e6", "--output", str(out)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and not out.exists()
    assert err.startswith("contactlib: error: --friction 1000000.0 is too large")
    assert "Traceback" not in err and "different signs" not in err


def test_no_partial_slip_solution_says_the_contact_probably_sticks_and_what_to_run():
    """A bonded layer, nu = 0.49, k = 0.5: the single-stick-zone solutions end (the slip
    reverses) with k = 0.35 < 0.5. The message says the contact probably sticks fully and
    points to the history solver, which shows it does (c/a = 1 at the top load)."""
    with pytest.raises(validate.InputError) as err:
        contactlib.solve("sphere", 0.49, friction=0.5, slab_ratio=2, base="bonded", n=N,
                         energy=False)
    text = str(err.value)
    assert err.value.name == "friction" and "no converged stick ratio found at n = 64" in text
    assert "the largest k found is 0.3" in text and "below 0.5" in text
    assert "probably sticks fully" in text and "contactlib history" in text
    assert "contactlib.history(" in text and "\n" not in text
    res = contactlib.history("sphere", 0.49, 0.5, [0, 1], 20, n=60, slab_ratio=2,
                             base="bonded", error_estimate=False)
    assert res.stick_ratio[-1] == 1.0
