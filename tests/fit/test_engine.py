"""The fit engine against closed-form weighted least squares (independent numbers: numpy lstsq)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import least_squares

from rig.fit import engine
from rig.fit.common_errors import CommonErrors
from rig.fit.engine import DELTA_CHI2_95, fit
from rig.fit.parameters import FitParameter


class LinearModel:
    """y = sum_k theta_k basis_k(x): a stand-in ForwardModel whose WLS solution is closed-form."""

    def __init__(self, basis: np.ndarray, y: np.ndarray, u: np.ndarray, names=("a", "b")) -> None:
        self.basis = basis
        self.free = tuple(FitParameter(n, "1", -10.0, 10.0, 0.0, None, "test") for n in names)
        self.obs = type("Obs", (), dict(y=y, u=u, u_independent=u, u_l=np.zeros(y.size), size=y.size, common=None))()
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


def test_the_profile_is_computed_near_the_interval_only():
    """A quadratic chi2 rises 4 > 3.84 at 2u: each crossing is bracketed by the first step out, so no
    profile value lies beyond 2u of the estimate, though the range reaches 10 / u ~ 200-500 u away
    (each value far out costs a stand fit's node tables there)."""
    basis, y, u = _data(1)
    result = fit(LinearModel(basis, y, u), [0.0, 0.0], polish="never")
    for e in result.estimates:
        visited = result.profiles[e.name][:, 0]
        assert np.all(np.abs(visited - e.value) <= 2 * e.u * (1 + 1e-9)), (e.name, visited)
        assert e.lo95 < e.value < e.hi95 and not (e.open_lo or e.open_hi)


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
    common = 0.5 * np.outer(u, u)  # a fully correlated part (here one that does not depend on y), inside u
    model = LinearModel(basis, y, u)
    model.obs.common = CommonErrors(None, 0.0, 0.0, 0.0, np.zeros(y.size), common)
    model.obs.u_independent = np.sqrt(u**2 - np.diag(common))
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


class LineWithNoisyX(LinearModel):
    """y = a + b x with x itself measured (u_x): the forward model's dl shifts every x."""

    def __init__(self, x: np.ndarray, y: np.ndarray, u: np.ndarray, u_x: np.ndarray) -> None:
        super().__init__(np.column_stack([np.ones_like(x), x]), y, u)
        self.x = x
        self.obs.u_l = u_x

    def predict(self, theta, dl=0.0):
        self.evaluations += 1
        return theta[0] + theta[1] * (self.x + dl)


def noisy_line():
    """(x, y, u_x, u_y): 40 points of y = 0.3 - 0.7 x with errors in x (0.15) and y (0.05), seeded."""
    rng = np.random.default_rng(7)
    x_true = np.linspace(0.0, 2.0, 40)
    u_x, u_y = 0.15, 0.05
    x = x_true + u_x * rng.standard_normal(x_true.size)
    y = 0.3 - 0.7 * x_true + u_y * rng.standard_normal(x_true.size)
    return x, y, u_x, u_y


def deming_line(x, y, u_x, u_y):
    """(intercept, slope) of Deming's regression with the error variance ratio u_y^2/u_x^2 (closed form)."""
    ratio = u_y**2 / u_x**2
    sxx, syy, sxy = np.var(x), np.var(y), np.cov(x, y, bias=True)[0, 1]
    slope = (syy - ratio * sxx + np.sqrt((syy - ratio * sxx) ** 2 + 4 * ratio * sxy**2)) / (2 * sxy)
    return y.mean() - slope * x.mean(), slope


def test_errors_in_the_regressor_give_demings_line_not_an_attenuated_slope():
    """Errors in l/a: the engine's chi2 with df/dl at theta is orthogonal distance regression,
    which for a straight line with constant u_x, u_y has Deming's closed form (independent number).
    With df/dl held fixed during the minimisation (the engine before) the weights are constant and
    the slope is the ordinary least-squares one, attenuated towards 0 (here by 4 %)."""
    x, y, u_x, u_y = noisy_line()
    result = fit(LineWithNoisyX(x, y, np.full(x.size, u_y), np.full(x.size, u_x)), [0.0, 0.0], polish="never",
                 profile=False)
    intercept, slope = deming_line(x, y, u_x, u_y)
    ols = np.polyfit(x, y, 1)[0]
    assert abs(ols - slope) > 0.02  # the two answers differ by far more than the tolerance below
    assert result.estimate("b").value == pytest.approx(slope, abs=1e-6)
    assert result.estimate("a").value == pytest.approx(intercept, abs=1e-6)


def test_a_run_out_of_evaluations_goes_on_once_from_where_it_stopped(monkeypatch):
    """The first attempt is cut to 3 evaluations (status 0: budget used up while descending); the
    retry starts from its end point with RETRY_NFEV_PER_PARAMETER per parameter and reaches the
    closed-form WLS answer. A retry that runs out too is a named FitConvergenceError."""
    basis, y, u = _data(8)
    w = 1.0 / u
    theta, *_ = np.linalg.lstsq(basis * w[:, None], y * w, rcond=None)
    calls = []

    def cut_first(fun, x0, **kwargs):
        if not calls:
            kwargs["max_nfev"] = 3
        calls.append((np.array(x0), kwargs["max_nfev"]))
        res = least_squares(fun, x0, **kwargs)
        calls[-1] += (res.status, res.x)
        return res

    monkeypatch.setattr(engine, "least_squares", cut_first)
    result = fit(LinearModel(basis, y, u), [0.0, 0.0], polish="never", profile=False)
    (start_1, budget_1, status_1, end_1), (start_2, budget_2, _, _) = calls[:2]
    assert (budget_1, status_1) == (3, 0) and budget_2 == engine.RETRY_NFEV_PER_PARAMETER * 2
    assert np.array_equal(start_2, end_1) and not np.array_equal(end_1, start_1)
    assert [e.value for e in result.estimates] == pytest.approx(theta, abs=1e-7)

    calls.clear()
    monkeypatch.setattr(engine, "RETRY_NFEV_PER_PARAMETER", 1)  # the retry runs out as well
    with pytest.raises(engine.FitConvergenceError, match="fit line did not converge"):
        fit(LinearModel(basis, y, u), [0.0, 0.0], polish="never", profile=False, label="line")
