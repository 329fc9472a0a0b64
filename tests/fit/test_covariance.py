"""The O(N) covariance of the shared errors (rig.fit.covariance) against the dense N x N algebra.

Independent numbers: numpy.linalg.solve on the dense matrix built element by element from its
definition (calibration: [dy/dS, dy/ds0] Sigma [..]^T; drift: q min(t_i, t_j) b_i b_j).
"""

from __future__ import annotations

import numpy as np
import pytest

from rig.fit import engine
from rig.fit.common_errors import CommonErrors
from rig.fit.covariance import RandomWalk, StructuredCovariance
from tests.fit.test_engine import LineWithNoisyX, noisy_line


def _dense(d, g, ages, loadings, rate):
    n = d.size
    v = np.diag(d) + (g @ g.T if g is not None else 0.0)
    for i in range(n):
        for j in range(n):
            v[i, j] += rate * min(ages[i], ages[j]) * loadings[i] * loadings[j]
    return v


@pytest.mark.parametrize("with_g, with_walk", [(True, True), (False, True), (True, False)])
def test_solve_and_whiten_equal_the_dense_algebra(with_g, with_walk):
    rng = np.random.default_rng(3)
    n = 40
    d = rng.uniform(0.2, 1.5, n) ** 2
    g = rng.normal(size=(n, 2)) if with_g else None
    ages = rng.choice([0.0, 1.0, 2.5, 2.5, 6.0, 11.0], n)  # ties and points read at age 0
    loadings = rng.normal(size=n)
    walk = RandomWalk(0.7, ages, loadings) if with_walk else None
    s = StructuredCovariance(d, g, walk)
    v = _dense(d, g, ages, loadings, 0.7 if with_walk else 0.0)
    r = rng.normal(size=n)
    many = rng.normal(size=(n, 3))
    assert s.solve(r) == pytest.approx(np.linalg.solve(v, r), rel=1e-10, abs=1e-12)
    assert s.solve(many) == pytest.approx(np.linalg.solve(v, many), rel=1e-10, abs=1e-12)
    w = s.whiten(many)
    assert w.T @ w == pytest.approx(many.T @ np.linalg.solve(v, many), rel=1e-10)
    assert s.diagonal() == pytest.approx(np.diag(v), rel=1e-12)


def test_a_million_points_need_no_n_by_n_matrix():
    """10^6 points: a dense V would take 8 TB; the structured form solves in O(N)."""
    n = 1_000_000
    rng = np.random.default_rng(4)
    s = StructuredCovariance(np.full(n, 1e-4), rng.normal(size=(n, 2)) * 1e-3,
                             RandomWalk(1e-8, np.sort(rng.uniform(0, 1000, n)), np.ones(n)))
    r = rng.normal(size=n) * 1e-2
    assert np.isfinite(s.whiten(r) @ s.whiten(r))


def _model_with_common_errors():
    x, y, u_x, u_y = noisy_line()
    model = LineWithNoisyX(x, y, np.full(x.size, u_y), np.full(x.size, u_x))
    ages = np.repeat(np.arange(1.0, 11.0), 4)
    slope = np.full(x.size, -0.02)
    model.obs.common = CommonErrors(1.0, 0.02, 0.01, -1e-5, slope, None, RandomWalk(4e-5, ages, slope / 0.02))
    return model


def test_the_fit_is_the_same_in_dense_and_structured_form(monkeypatch):
    """Calibration (sensitivity at the adjusted values) + drift + errors in x: the estimates,
    their u, the profile intervals and chi2 of the two forms agree to the solver's tolerance."""
    structured = engine.fit(_model_with_common_errors(), [0.0, 0.0], polish="never")
    monkeypatch.setattr(engine, "COVARIANCE_FORM", "dense")
    dense = engine.fit(_model_with_common_errors(), [0.0, 0.0], polish="never")
    assert structured.chi2 == pytest.approx(dense.chi2, rel=1e-7)
    for a, b in zip(structured.estimates, dense.estimates):
        assert a.value == pytest.approx(b.value, abs=1e-4 * b.u)  # the optimiser stops at xtol = 1e-8 of the range
        assert a.u == pytest.approx(b.u, rel=1e-6)
        assert (a.lo95, a.hi95) == pytest.approx((b.lo95, b.hi95), abs=1e-3 * b.u)
    assert structured.u_eff == pytest.approx(dense.u_eff, rel=1e-5)  # at the two (equal) optima
