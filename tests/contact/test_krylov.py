"""The contact solver's GMRES (rig.contact.krylov) against a direct solve: right preconditioning,
restarts, the residual it reports, and the breakdown cases (zero right-hand side, exact subspace)."""

from __future__ import annotations

import numpy as np
import pytest

from rig.contact.krylov import gmres


def _system(n=200, seed=0):
    rng = np.random.default_rng(seed)
    a = np.eye(n) * 3.0 + rng.normal(size=(n, n)) / np.sqrt(n)  # nonsymmetric, well conditioned
    return a, rng.normal(size=n)


@pytest.mark.parametrize("restart", [5, 60])
@pytest.mark.parametrize("rtol", [1e-2, 1e-10])
def test_reaches_the_requested_true_residual_with_and_without_restarts(restart, rtol):
    a, b = _system()
    diagonal = np.diag(a).copy()
    x, products, converged = gmres(lambda v: a @ v, b, lambda v: v / diagonal, rtol=rtol, restart=restart)
    assert converged and products > 0
    assert np.linalg.norm(b - a @ x) <= 1.01 * rtol * np.linalg.norm(b)  # the Arnoldi residual is the true one
    if rtol == 1e-10:
        np.testing.assert_allclose(x, np.linalg.solve(a, b), rtol=1e-8, atol=1e-9)


def test_an_exact_preconditioner_converges_in_one_product():
    a, b = _system(50, seed=1)
    inverse = np.linalg.inv(a)
    x, products, converged = gmres(lambda v: a @ v, b, lambda v: inverse @ v, rtol=1e-12)
    assert converged and products == 1
    np.testing.assert_allclose(a @ x, b, atol=1e-10)


def test_zero_right_hand_side_is_zero_at_no_cost():
    a, _ = _system(20)
    x, products, converged = gmres(lambda v: a @ v, np.zeros(20), lambda v: v, rtol=1e-8)
    assert converged and products == 0 and not np.any(x)


def test_reports_failure_when_the_products_run_out():
    a, b = _system(300, seed=2)
    a += 40.0 * np.diag(np.linspace(-1, 1, 300))  # indefinite, spread spectrum: slow without a preconditioner
    x, products, converged = gmres(lambda v: a @ v, b, lambda v: v, rtol=1e-12, restart=10, maxiter=30)
    assert not converged and products == 30
    assert np.linalg.norm(b - a @ x) < np.linalg.norm(b)  # still a minimal-residual improvement
