"""The kinematic model against Kalker's exact theory (CONTACT, an independent program).

Reference: tests/contact/data/exact_pure_spin_circle.csv (+ .toml): pure spin of a circular Hertz
contact, nu = 0.28, nu_v and nu_0 versus alpha' (issue 5, acceptance 2, at the model level; the
`rig compare` path is tested in tests/compare).
"""

from pathlib import Path

import numpy as np
import pytest

from rig.contact.solve import solve

DATA = Path(__file__).parent / "data" / "exact_pure_spin_circle.csv"


def _reference():
    rows = [line.split(",") for line in DATA.read_text().splitlines()[2:] if line.strip()]
    values = np.array([[float(v) for v in row] for row in rows])
    return values[:, 0], values[:, 1], values[:, 3]


@pytest.fixture(scope="module")
def solved():
    """(alpha', reference nu_v, reference nu_0, ours at the default grid, ours at n = 64 below alpha' = 3)."""
    alpha, nu_v, nu_0 = _reference()
    common = dict(shape="ellipse", b_over_a=1.0, c_over_a=0.0, l_over_a=0.0, poisson=0.28)
    default = [solve("kinematic", alpha=a, **common) for a in alpha]
    fine = [solve("kinematic", alpha=a, n=64, **common) for a in alpha[alpha < CONVERGED_FROM]]
    return alpha, nu_v, nu_0, default, fine


CONVERGED_FROM = 3.0
"""Below this alpha' the reference (80 cells) is not converged itself (issue 9): there ours is held
to its own n = 64 values, and nu_v is linear in alpha' (docs/contact-model.md, convergence study)."""


def test_default_grid_matches_exact_theory_from_alpha_3(solved):
    """Issue 9, acceptance 3. Measured at n = 32: max |d nu_v| 0.0025 (alpha' = 40.7), max
    |d nu_0| 0.0032 (alpha' = 25.7)."""
    alpha, nu_v, nu_0, default, _ = solved
    upper = alpha >= CONVERGED_FROM
    d_v = np.array([r.nu_v for r in default]) - nu_v
    d_0 = np.array([r.nu_0 for r in default]) - nu_0
    assert np.max(np.abs(d_v[upper])) <= 0.003, d_v[upper]
    assert np.max(np.abs(d_0[upper])) <= 0.004, d_0[upper]


def test_below_alpha_3_the_default_grid_is_converged_and_nu_0_agrees(solved):
    """Below alpha' = 3: n = 32 within 1e-3 of n = 64 (measured 5e-4), and nu_0, which the
    reference resolves there, within 1e-3 of it (measured 2e-4). nu_v stays 0.001-0.005 below the
    reference, whose nu_v/alpha' grows towards 0.25 as alpha' -> 0 while ours is linear."""
    alpha, _, nu_0, default, fine = solved
    lower = alpha < CONVERGED_FROM
    coarse = [r for r, low in zip(default, lower) if low]
    for name in ("nu_v", "nu_0"):
        gap = np.array([getattr(c, name) - getattr(f, name) for c, f in zip(coarse, fine)])
        assert np.max(np.abs(gap)) <= 1e-3, (name, gap)
    assert np.max(np.abs(np.array([r.nu_0 for r in coarse]) - nu_0[lower])) <= 1e-3
