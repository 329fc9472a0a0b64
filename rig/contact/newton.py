"""Semi-smooth Newton-Krylov for the Coulomb law on a grid: F(t) = q - P_r(q - rho s) = 0.

q (interface traction) and s (slip) are affine in the unknown tractions t (rig.contact.elastic_law);
P_r projects each cell's 2-vector on the disc |.| <= r_c (the traction bound, eqs. 13-14). F = 0 is
the Coulomb law: a cell sticks (s = 0, |q| <= r) or slides with q = -r s/|s|; rho > 0 (per cell)
scales the slip and changes the path, not the answer. Each step solves J delta = -F by GMRES
(rig.contact.krylov) with the law's preconditioner to a relative residual eta (the forcing term),
and a backtracking line search on |F|_2 globalises. Without surface inertia (q = t) every iterate is
projected on the feasible set |t_c| <= r_c, which holds the solution: the projection on a convex set
is non-expansive, so it never moves an iterate away from the solution, and a traction the linear
step pushed past its bound no longer decides that cell's stick/slip guess at the next step.
"""

from __future__ import annotations

import numpy as np

from rig.contact.krylov import gmres, norm
from rig.errors import ConvergenceError

TOLERANCE = 1e-6  # max |F| relative to the largest traction bound: nu to ~1e-7 (tractions are O(1) in mu p0)
# a cell sticks where |q| stays below its bound by more than the tolerance can blur
STICK_MARGIN = 10 * TOLERANCE
# Newton steps before giving up: MAX_STEPS, or as many as a row has cells (step_limit). Most solves take
# 2-9. Near full stick a row can hold a stretch of cells stuck at their bound with the stick front entering
# it from upstream, and each Newton step moves that front by about one cell (the sliding cell at the front
# pins the traction level of the cells behind it) with |F| falling all the way: b/a = 10, alpha' = 325,
# C = (-1, 1) a took 75 steps on the default grid (192 x 48 cells) and 275 on n = 64 (388 x 96 cells;
# 37 and 181 with the projected iterates), so a fixed cap fails on fine grids what converges.
MAX_STEPS = 150


def step_limit(cells_along_row: int) -> int:
    """Newton steps allowed on a grid with this many cells along the rolling direction [1]."""
    return max(MAX_STEPS, int(cells_along_row))


def project(z: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Projection of each 2-vector z_c on the disc |.| <= r_c; returns (P(z), |z|, inside mask)."""
    norm = np.hypot(z[0], z[1])
    inside = norm <= r
    scale = np.where(inside, 1.0, r / np.where(norm > 0.0, norm, 1.0))
    return z * scale, norm, inside


def solve(law, s0: np.ndarray, r: np.ndarray, rho, t0: np.ndarray) -> tuple[np.ndarray, int, int]:
    """Tractions t (2, N) [mu p0] with F(t) = 0 for the law (q, s - s0) = law.apply(t), from t0;
    returns (t, Newton steps, Krylov products)."""
    n = r.size
    scale = max(float(np.max(r)), 1e-300)
    tol = TOLERANCE * scale

    def evaluate(t):
        q, a = law.apply(t)
        z = q - rho * (s0 + a)
        pz, zn, inside = project(z, r)
        return q - pz, z, zn, inside

    feasible = (lambda t: project(t, r)[0]) if law.traction_is_interface else (lambda t: t)
    limit = step_limit(law.grid.full_shape[0])
    t = feasible(t0)
    f, z, zn, inside = evaluate(t)
    krylov = 0
    for step in range(limit + 1):
        largest = float(np.abs(f).max())
        if largest <= tol:
            return t, step, krylov
        if step == limit:
            break
        safe = np.where(zn > 0.0, zn, 1.0)
        linear = law.linearise(z / safe, np.where(inside, 1.0, r / safe), inside, rho)
        # forcing: the linear residual asked of GMRES, relative; quadratic (|F|) once Newton converges,
        # never tighter than needed to reach the tolerance in this step
        forcing = min(0.1, max(largest / scale, 0.5 * tol / largest))
        delta, products, _ = gmres(linear.jacobian, -f.ravel(), linear.precondition, rtol=forcing)
        krylov += products
        delta = delta.reshape(2, n)
        # backtracking on |F|_2, the merit whose decrease the Newton direction guarantees (the largest
        # |F_c| often rises for a full step while the whole residual falls)
        size = norm(f.ravel())
        length = 1.0
        while True:
            candidate = feasible(t + length * delta)
            trial = evaluate(candidate)
            if norm(trial[0].ravel()) < (1.0 - 1e-4 * length) * size or length < 1e-4:
                break
            length *= 0.5
        t = candidate
        f, z, zn, inside = trial
    raise ConvergenceError(
        f"contact solve did not converge in {limit} Newton iterations: residual "
        f"{largest / scale:.2e} of the traction bound (tolerance {TOLERANCE:.0e})"
    )
