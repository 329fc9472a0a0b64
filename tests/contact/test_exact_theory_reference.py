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
to its own n = 64 values, and nu_v is linear in alpha' (docs/contact-convergence.md)."""


def test_default_grid_matches_exact_theory_from_alpha_3(solved):
    """Issue 9, acceptance 3. Measured at n = 32: max |d nu_v| 0.0026 (alpha' = 10.2), max
    |d nu_0| 0.0028 (alpha' = 25.7)."""
    alpha, nu_v, nu_0, default, _ = solved
    upper = alpha >= CONVERGED_FROM
    d_v = np.array([r.nu_v for r in default]) - nu_v
    d_0 = np.array([r.nu_0 for r in default]) - nu_0
    assert np.max(np.abs(d_v[upper])) <= 0.003, d_v[upper]
    assert np.max(np.abs(d_0[upper])) <= 0.004, d_0[upper]


def test_below_alpha_3_the_default_grid_is_converged_and_nu_0_agrees(solved):
    """Below alpha' = 3: n = 32 within 1.2e-3 of n = 64 (measured: nu_v 1.0e-3 at alpha' = 2.6, where
    n = 128 moves it by another 2.5e-4, second order; nu_0 2.5e-4), and nu_0, which the reference
    resolves there, within 1e-3 of it (measured 5e-4). nu_v stays 0.001-0.005 below the reference,
    whose nu_v/alpha' grows towards 0.25 as alpha' -> 0 while ours is linear."""
    alpha, _, nu_0, default, fine = solved
    lower = alpha < CONVERGED_FROM
    coarse = [r for r, low in zip(default, lower) if low]
    for name in ("nu_v", "nu_0"):
        gap = np.array([getattr(c, name) - getattr(f, name) for c, f in zip(coarse, fine)])
        assert np.max(np.abs(gap)) <= 1.2e-3, (name, gap)
    assert np.max(np.abs(np.array([r.nu_0 for r in coarse]) - nu_0[lower])) <= 1e-3


def _contact_limits():
    """alpha' -> ((nu_v, u), (nu_0, u)): CONTACT's own values extrapolated to zero element size
    (tests/contact/data/contact_fortran_pure_spin.toml, 10 ... 160 elements; benchmarks/contact_fortran.py)."""
    import tomllib

    sidecar = tomllib.loads((DATA.parent / "contact_fortran_pure_spin.toml").read_text())["extrapolation"]
    alphas = {"a3": 3.0, "a10_2313": 10.2313, "a20_5": 20.5, "a102_313": 102.313}
    return {alpha: tuple((sidecar[f"{key}_{q}"]["limit"], sidecar[f"{key}_{q}"]["uncertainty"]) for q in ("nu_v", "nu_0"))
            for key, alpha in alphas.items()}


@pytest.mark.parametrize("alpha, limits", sorted(_contact_limits().items()))
def test_default_grid_is_within_the_issue_goal_of_converged_exact_theory(alpha, limits):
    """Issue 9's accuracy goal, |d nu_v| <= 0.002 and |d nu_0| <= 0.004 at the default grid, against
    CONTACT's converged limits (not its 80-element values: at alpha' = 20.5 those are 0.0008 and 0.003
    off its own limit, which is where 'the exact answer 0.4528, 0.2643' came from). Measured at n = 32:
    max |d nu_v| 0.0014 (alpha' = 20.5), max |d nu_0| 0.0006 (alpha' = 20.5)."""
    (nu_v, _), (nu_0, _) = limits
    r = solve("kinematic", shape="ellipse", b_over_a=1.0, c_over_a=0.0, l_over_a=0.0, poisson=0.28, alpha=alpha)
    assert abs(r.nu_v - nu_v) <= 0.002, f"nu_v {r.nu_v:.4f} vs converged exact {nu_v} at alpha' = {alpha}"
    assert abs(r.nu_0 - nu_0) <= 0.004, f"nu_0 {r.nu_0:.4f} vs converged exact {nu_0} at alpha' = {alpha}"
