"""Restarted GMRES with right preconditioning, lean enough for the contact solver's small systems.

scipy's ``gmres`` spends more time in its own bookkeeping than in the products when the system
has only a few thousand unknowns and converges in ~10 iterations (the contact solver's Newton
steps). Here the Arnoldi basis is one preallocated array, orthogonalised by classical Gram-Schmidt
applied twice (as stable as modified Gram-Schmidt [Giraud et al. 2005]) in a compiled loop, and the
least-squares problem is updated with Givens rotations (Saad & Schultz 1986). The preconditioned
basis vectors are kept (the flexible variant's storage, Saad 1993), so the solution costs no
further preconditioner application. The vector loops are numba's, single-threaded on purpose:
numpy's dot and matrix-vector products go to a threaded BLAS, whose threads cost more than they
save on vectors of 10^3-10^5 entries, and on a machine busy with other processes (two cores, a study
running beside) slowed a 128-cell solve six times (docs/contact-model.md, "Solver cost").
"""

from __future__ import annotations

from collections.abc import Callable

import numba
import numpy as np

Operator = Callable[[np.ndarray], np.ndarray]


@numba.njit(cache=True, nogil=True, fastmath=True)
def norm(x):
    """Euclidean norm of a 1-d array (single-threaded; module docstring)."""
    total = 0.0
    for k in range(x.size):
        total += x[k] * x[k]
    return np.sqrt(total)


@numba.njit(cache=True, nogil=True, fastmath=True)
def _orthogonalise(basis, j, w, column):
    """Classical Gram-Schmidt of w against basis[0..j], twice; adds the coefficients to column[0..j]
    and returns |w| afterwards."""
    n = w.size
    for _ in range(2):
        for i in range(j + 1):
            h = 0.0
            for k in range(n):
                h += basis[i, k] * w[k]
            column[i] += h
            for k in range(n):
                w[k] -= h * basis[i, k]
    return norm(w)


@numba.njit(cache=True, nogil=True, fastmath=True)
def _combine(coefficients, vectors, out):
    """out += sum_i coefficients[i] vectors[i]."""
    for i in range(coefficients.size):
        c = coefficients[i]
        for k in range(out.size):
            out[k] += c * vectors[i, k]


def gmres(matvec: Operator, b: np.ndarray, precondition: Operator, *, rtol: float, restart: int = 60,
          maxiter: int = 600) -> tuple[np.ndarray, int, bool]:
    """Solve A x = b with A = ``matvec`` and right preconditioner M = ``precondition`` (A M y = b,
    x = M y) until |b - A x| <= rtol |b|, or ``maxiter`` products in all.

    Returns (x, products of A, converged). The residual that is tested is the residual of A x = b
    (right preconditioning leaves it unscaled), as the Arnoldi relation gives it (no extra product)."""
    n = b.size
    x = np.zeros(n)
    beta = float(norm(b))
    target = rtol * beta
    if beta == 0.0:
        return x, 0, True
    residual = b
    products = 0
    basis = np.empty((restart + 1, n))
    preconditioned = np.empty((restart, n))
    hessenberg = np.zeros((restart + 1, restart))
    cs, sn = np.zeros(restart), np.zeros(restart)
    while True:
        basis[0] = residual / beta
        g = np.zeros(restart + 1)
        g[0] = beta
        j = 0
        while j < restart and products < maxiter:
            preconditioned[j] = precondition(basis[j])
            w = matvec(preconditioned[j])
            products += 1
            size = _orthogonalise(basis, j, w, hessenberg[:, j])
            hessenberg[j + 1, j] = size
            basis[j + 1] = w / size if size > 0.0 else 0.0
            for i in range(j):  # earlier rotations on the new column
                hi, hk = hessenberg[i, j], hessenberg[i + 1, j]
                hessenberg[i, j], hessenberg[i + 1, j] = cs[i] * hi + sn[i] * hk, -sn[i] * hi + cs[i] * hk
            radius = float(np.hypot(hessenberg[j, j], hessenberg[j + 1, j]))
            cs[j], sn[j] = hessenberg[j, j] / radius, hessenberg[j + 1, j] / radius
            hessenberg[j, j], hessenberg[j + 1, j] = radius, 0.0
            g[j], g[j + 1] = cs[j] * g[j], -sn[j] * g[j]
            j += 1
            if abs(g[j]) <= target:
                break
        _combine(_back_substitute(hessenberg[:j, :j], g[:j]), preconditioned, x)
        beta = abs(float(g[j]))
        if beta <= target or products >= maxiter:
            return x, products, beta <= target
        residual = np.zeros(n)  # b - A x, from the Arnoldi relation
        _combine(_rotate_back(g[j], cs[:j], sn[:j]), basis, residual)
        hessenberg[:] = 0.0


def _rotate_back(last: float, cs: np.ndarray, sn: np.ndarray) -> np.ndarray:
    """Coefficients in the Arnoldi basis of the residual whose rotated form is (0, ..., 0, last)."""
    e = np.zeros(cs.size + 1)
    e[-1] = last
    for i in range(cs.size - 1, -1, -1):
        e[i], e[i + 1] = cs[i] * e[i] - sn[i] * e[i + 1], sn[i] * e[i] + cs[i] * e[i + 1]
    return e


def _back_substitute(upper: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Solution of the upper-triangular system upper y = rhs."""
    y = np.zeros_like(rhs)
    for i in range(rhs.size - 1, -1, -1):
        y[i] = (rhs[i] - upper[i, i + 1:] @ y[i + 1:]) / upper[i, i]
    return y
