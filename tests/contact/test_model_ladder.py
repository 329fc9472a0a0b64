"""The models agree where their theories meet (issue 2, acceptance 3 and 4)."""

import numpy as np
import pytest

from rig.contact.solve import solve, solve_creepage

CASES = [("ellipse", 1.0, 0.0, 0.0), ("ellipse", 2.0, 0.4, 0.5), ("line", 1.0, 0.4, 0.5), ("line", 0.5, 0.0, 1.0)]


def _solve(model, shape, b, c, l, alpha, n=32):
    return solve(model, shape=shape, b_over_a=b, alpha=alpha, c_over_a=c, l_over_a=l, poisson=0.28, n=n)


@pytest.mark.parametrize("shape, b, c, l", CASES)
def test_kinematic_tends_to_its_own_rigid_limit_as_alpha_goes_to_zero(shape, b, c, l):
    limit = _solve("kinematic", shape, b, c, l, 0.0)
    small = _solve("kinematic", shape, b, c, l, 1e-3)
    assert (small.nu_T, small.nu_v, small.nu_0) == pytest.approx((limit.nu_T, limit.nu_v, limit.nu_0), abs=2e-3)
    rigid = _solve("rigid", shape, b, c, l, 0.0)
    assert (limit.nu_T, limit.nu_v, limit.nu_0) == pytest.approx((rigid.nu_T, rigid.nu_v, rigid.nu_0), abs=0.01)


@pytest.mark.parametrize("shape, b", [("ellipse", 1.0), ("ellipse", 2.0), ("ellipse", 0.5), ("line", 1.0), ("line", 0.5)])
@pytest.mark.parametrize("creepage", ["xi", "eta", "phi"])
def test_fastsim_is_linear_theory_at_small_pure_creepage(shape, b, creepage):
    """Kalker's three flexibilities make FASTSIM's full-stick forces exact for each pure creepage
    (combined creepages: tests/contact/test_fastsim.py)."""
    unit = {"xi": (1e-6, 0.0, 0.0), "eta": (0.0, 1e-6, 0.0), "phi": (0.0, 0.0, 1e-6)}[creepage]
    xi, eta, phi = unit
    common = dict(shape=shape, b_over_a=b, xi=xi, eta=eta, phi=phi, poisson=0.28, n=32)
    fast = solve_creepage("fastsim", **common)
    lin = solve_creepage("linear", **common)
    assert fast.stick_fraction == 1.0
    for name in ("nu_T", "nu_v"):
        assert getattr(fast, name) * 1e6 == pytest.approx(getattr(lin, name) * 1e6, rel=0.01, abs=1e-6), name


@pytest.mark.parametrize("shape, b, c, l", CASES)
def test_fastsim_is_rigid_sliding_at_large_creepage(shape, b, c, l):
    fast = _solve("fastsim", shape, b, c, l, 1e-4)
    rigid = _solve("rigid", shape, b, c, l, 0.0)
    assert (fast.nu_T, fast.nu_v, fast.nu_0) == pytest.approx((rigid.nu_T, rigid.nu_v, rigid.nu_0), abs=0.01)


def test_adhesion_grows_and_pivoting_loss_falls_with_alpha():
    alphas = [0.3, 3.0, 30.0, 300.0]
    results = [_solve("kinematic", "ellipse", 1.0, 0.0, 0.0, a) for a in alphas]
    stick = [r.stick_fraction for r in results]
    loss = [r.nu_0 for r in results]
    assert np.all(np.diff(stick) >= 0) and stick[-1] > 0.9, stick
    assert np.all(np.diff(loss) < 0), loss


def test_longitudinal_force_of_pure_spin_rises_to_one_maximum_then_decays():
    """Equations §1.10(c): nu_v (c = l = 0) rises from 0 to a single maximum near alpha' 3-30, then ~1/alpha'."""
    alphas = np.geomspace(0.1, 1000.0, 13)
    nu_v = np.array([_solve("kinematic", "ellipse", 1.0, 0.0, 0.0, a, n=24).nu_v for a in alphas])
    peak = int(np.argmax(nu_v))
    assert 3.0 <= alphas[peak] <= 30.0 and 0.3 <= nu_v[peak] <= 0.7
    assert np.all(np.diff(nu_v[: peak + 1]) > 0) and np.all(np.diff(nu_v[peak:]) < 0)
