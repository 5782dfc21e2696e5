"""The default method's estimate does not collapse where the nested levels agree by chance
(issue 42, item 9).

At n = 16 ... 31 the estimate compares two levels, n/2 and n, and no observed order can be
checked; where the error is not monotone in n they agree by chance. Cylinder, n = 16,
c/a = 0.05 ... 0.1: errors 0.8 ... 1.8e-3 against estimates 3e-5 ... 5e-4, reported
resolved at max_error = 1e-3. Truth: the extrapolated method at n = 256 (its own estimate
~1e-6, three orders below the errors checked). Scan: benchmarks/report_estimate_collapse.py.
"""

from __future__ import annotations

import pytest

import contactlib


@pytest.mark.parametrize("slab,c", [(0.0, 0.06), (0.0, 0.1), (0.05, 0.09)])
def test_two_level_estimate_covers_the_error_at_n16(slab, c):
    """Before: (0, 0.06) error 1.17e-3, estimate 6.6e-5; (0, 0.1) 1.78e-3 against 1.0e-4;
    (0.05, 0.09) 1.07e-3 against 9.7e-5, each resolved."""
    truth = contactlib.solve("cylinder", 0.3, stick_ratio=c, n=256, method="extrapolated",
                             slab_ratio=slab, energy=False)
    s = contactlib.solve("cylinder", 0.3, stick_ratio=c, n=16, slab_ratio=slab, energy=False)
    err = abs(s.friction_coefficient / truth.friction_coefficient - 1.0)
    assert truth.error_estimate < err / 100.0
    assert err <= s.error_estimate, (err, s.error_estimate)
    assert not (s.resolved and err > s.max_error)
    assert not s.resolved  # (error > max_error here)
    loose = contactlib.solve("cylinder", 0.3, stick_ratio=c, n=16, slab_ratio=slab,
                             energy=False, max_error=0.05)
    assert loose.resolved  # the flag follows the estimate, not the n
