"""Observed order of convergence under grid refinement (first-order upwind scheme)."""

import numpy as np

from rig.contact.solve import solve
from tests.contact.test_linear_limit import grid_creep_coefficients


def observed_order(values):
    """p from three solutions at h, h/2, h/4: (f_h - f_h/2)/(f_h/2 - f_h/4) = 2^p."""
    f1, f2, f3 = values
    return np.log2((f1 - f2) / (f2 - f3))


def test_spin_coefficient_of_a_line_contact_converges_at_first_order():
    """The line contact's cells fit its boundary exactly, so the scheme's own order shows cleanly
    (an ellipse adds a staircase error that makes refinement sequences non-monotone)."""
    c23 = [grid_creep_coefficients("line", 1.0, 0.25, n)[2] for n in (16, 32, 64)]
    order = observed_order(c23)
    assert 0.85 < order < 1.2, f"observed order {order:.2f}, expected ~1 (upwind differences, eq. 10)"


def test_partial_slip_characteristic_converges_at_first_order():
    values = [
        solve("kinematic", shape="line", b_over_a=1.0, alpha=20.0, c_over_a=0.0, l_over_a=0.0, poisson=0.28, n=n).nu_v
        for n in (16, 32, 64)
    ]
    order = observed_order(values)
    assert 0.7 < order < 1.4, f"observed order {order:.2f} of nu_v at alpha' = 20"
