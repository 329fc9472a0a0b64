"""Restarted GMRES with right preconditioning, lean enough for the contact solver's small systems.

scipy's ``gmres`` spends more time in its own bookkeeping than in the products when the system
has only a few thousand unknowns and converges in ~10 iterations (the contact solver's Newton
steps): here the Arnoldi basis is one preallocated array, orthogonalised block-wise (classical
Gram-Schmidt, applied twice, which is as stable as modified Gram-Schmidt [Giraud et al. 2005]),
and the least-squares problem is updated with Givens rotations (Saad & Schultz 1986).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

Operator = Callable[[np.ndarray], np.ndarray]


def gmres(matvec: Operator, b: np.ndarray, precondition: Operator, *, rtol: float, restart: int = 60,
          maxiter: int = 600) -> tuple[np.ndarray, int, bool]:
    """Solve A x = b with A = ``matvec`` and right preconditioner M = ``precondition`` (A M y = b,
    x = M y) until |b - A x| <= rtol |b|, or ``maxiter`` products in all.

    Returns (x, products of A, converged). The residual that is tested is the residual of A x = b
    (right preconditioning leaves it unscaled), as the Arnoldi relation gives it (no extra product)."""
    n = b.size
    x = np.zeros(n)
    beta = float(np.linalg.norm(b))
    target = rtol * beta
    if beta == 0.0:
        return x, 0, True
    residual = b
    products = 0
    basis = np.empty((restart + 1, n))
    hessenberg = np.zeros((restart + 1, restart))
    cs, sn = np.zeros(restart), np.zeros(restart)
    while True:
        basis[0] = residual / beta
        g = np.zeros(restart + 1)
        g[0] = beta
        j = 0
        while j < restart and products < maxiter:
            w = matvec(precondition(basis[j]))
            products += 1
            for _ in range(2):  # classical Gram-Schmidt, twice
                h = basis[: j + 1] @ w
                w -= h @ basis[: j + 1]
                hessenberg[: j + 1, j] += h
            hessenberg[j + 1, j] = float(np.linalg.norm(w))
            basis[j + 1] = w / hessenberg[j + 1, j] if hessenberg[j + 1, j] > 0.0 else 0.0
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
        x += precondition(_back_substitute(hessenberg[:j, :j], g[:j]) @ basis[:j])
        beta = abs(float(g[j]))
        if beta <= target or products >= maxiter:
            return x, products, beta <= target
        residual = _rotate_back(g[j], cs[:j], sn[:j]) @ basis[: j + 1]  # b - A x, from the Arnoldi relation
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
