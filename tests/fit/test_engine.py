"""The fit engine against closed-form weighted least squares (independent numbers: numpy lstsq)."""

from __future__ import annotations

import numpy as np
import pytest

from rig.fit.engine import DELTA_CHI2_95, fit
from rig.fit.parameters import FitParameter


class LinearModel:
    """y = sum_k theta_k basis_k(x): a stand-in ForwardModel whose WLS solution is closed-form."""

    def __init__(self, basis: np.ndarray, y: np.ndarray, u: np.ndarray, names=("a", "b")) -> None:
        self.basis = basis
        self.free = tuple(FitParameter(n, "1", -10.0, 10.0, 0.0, None, "test") for n in names)
        self.obs = type("Obs", (), dict(y=y, u=u, u_l=np.zeros(y.size), size=y.size, common_cov=None))()
        self.evaluations = 0

    def predict(self, theta, dl=0.0):
        self.evaluations += 1
        return self.basis @ np.asarray(theta, dtype=float)

    direct = predict


def _data(seed: int, basis_of=lambda x: np.column_stack([np.ones_like(x), x])):
    rng = np.random.default_rng(seed)
    x = np.linspace(0.0, 2.0, 12)
    u = 0.05 + 0.05 * x
    basis = basis_of(x)
    y = basis @ np.array([0.3, -0.7])[: basis.shape[1]] + u * rng.standard_normal(x.size)
    return basis, y, u


@pytest.mark.parametrize("seed", [1, 2])
def test_estimates_u_and_intervals_equal_closed_form_wls(seed):
    basis, y, u = _data(seed)
    w = 1.0 / u
    theta, *_ = np.linalg.lstsq(basis * w[:, None], y * w, rcond=None)
    cov = np.linalg.inv((basis * w[:, None] ** 2).T @ basis)
    result = fit(LinearModel(basis, y, u), [0.0, 0.0], polish="never")
    for k, e in enumerate(result.estimates):
        assert e.value == pytest.approx(theta[k], abs=1e-7)
        assert e.u == pytest.approx(np.sqrt(cov[k, k]), rel=1e-5)
        half = np.sqrt(DELTA_CHI2_95 * cov[k, k])  # quadratic chi2: profile interval = +-1.96 sigma
        assert e.lo95 == pytest.approx(theta[k] - half, abs=1e-3 * half)
        assert e.hi95 == pytest.approx(theta[k] + half, abs=1e-3 * half)
    expected = cov[0, 1] / np.sqrt(cov[0, 0] * cov[1, 1])
    assert result.correlation[0, 1] == pytest.approx(expected, abs=1e-5)
    assert result.chi2 == pytest.approx(np.sum(((y - basis @ theta) / u) ** 2), rel=1e-8)
    assert not result.warnings


def test_parameter_that_does_not_enter_is_flagged_flat():
    basis, y, u = _data(3, lambda x: np.column_stack([np.ones_like(x), 0.0 * x]))
    result = fit(LinearModel(basis, y, u), [0.0, 0.0], polish="never")
    assert any("b is not identifiable" in w and "flat" in w for w in result.warnings)
    b = result.estimate("b")
    assert b.open_lo and b.open_hi


def test_nearly_collinear_parameters_are_flagged():
    basis, y, u = _data(4, lambda x: np.column_stack([x, x * (1.0 + 0.01 * x)]))
    result = fit(LinearModel(basis, y, u), [0.0, 0.0], polish="never")
    assert abs(result.correlation[0, 1]) > 0.95
    assert any("not separately identifiable" in w for w in result.warnings)


def test_common_covariance_gives_closed_form_generalised_least_squares():
    basis, y, u = _data(5)
    common = 0.5 * np.outer(u, u)  # a fully correlated part (a calibration), inside the stated u
    model = LinearModel(basis, y, u)
    model.obs.common_cov = common
    v = common + np.diag(u**2 - np.diag(common))
    vinv = np.linalg.inv(v)
    cov = np.linalg.inv(basis.T @ vinv @ basis)
    theta = cov @ basis.T @ vinv @ y
    result = fit(model, [0.0, 0.0], polish="never")
    for k, e in enumerate(result.estimates):
        assert e.value == pytest.approx(theta[k], abs=1e-7)
        assert e.u == pytest.approx(np.sqrt(cov[k, k]), rel=1e-5)
    r = y - basis @ theta
    assert result.chi2 == pytest.approx(r @ vinv @ r, rel=1e-8)


def test_estimated_scatter_makes_chi2_equal_the_degrees_of_freedom():
    basis, y, u = _data(6)
    result = fit(LinearModel(basis, y, u / 5.0), [0.0, 0.0], polish="never", scatter=None)
    assert result.scatter > 0
    assert result.chi2 == pytest.approx(y.size - 2, rel=1e-2)
