"""Koziarski's kinematic law of friction (seed 000, eqs. 7-20) on a grid, solved as one coupled system.

Discrete steady rolling (seed notes 1.5, 1.9), dimensionless (lengths in a, traction in mu p0,
displacement in mu p0 a/G, slip in mu p0 v/G, G = Kalker's combined shear modulus):

    s_c = s_g,c + (U_c - U_up(c)) / hx + s_pl,c                 eqs. (8), (10), (13)
    U   = K t,   s_pl = (Psi - 1) v_el q / (mu p)   (local)      eqs. (6), (20), (25)
    q   = t + Gamma Lambda^-1 D2 U    (surface inertia)          eq. (15), model choice
    |q_c| <= r_c, and q_c = -r_c s_c/|s_c| where s_c != 0      eqs. (13), (14)

t is the traction the half-space feels (q = t without inertia). The paper's law (14),
q = -mu p w/max(|w|, v0), is exactly this Coulomb condition once the element's own slip
v0 = Psi v_el (eqs. 20, 25) is split off the total slip (the plastic part (Psi - 1) v_el is a
slip velocity with no grid length in it, rig.contact.effects.plastic_slip); solving the coupled
problem for every element at once *is* the kinematic law. The element-by-element marching that
the paper advertises ("no iterative steps") diverges under grid refinement (seed notes 1.9 step 6;
tests/contact/test_marching_diverges.py shows it), so it is not offered.

Solver: semi-smooth Newton on F(t) = q - P_r(q - rho s) (P_r: projection on the disc of radius
r per cell), GMRES on the exact generalised Jacobian with FFT influence products, right-
preconditioned by (restricted circulant inverse of K) o (exact upwind solve of the local law);
FASTSIM gives the start, a backtracking line search on |F|_2 globalises. Static friction (mu0/mu > 1)
adds an outer loop over the stick/slip memory of each material point along its row: it starts
with every point holding mu0 p and moves a point to mu p once its material has slipped one cell
upstream; a point never moves back within one solve, so the loop ends after at most N passes
(the stick/slip law with memory is hysteretic and need not have one fixed point otherwise).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sparse
from scipy.linalg import lapack

from rig.contact.effects import ContactEffects
from rig.contact.grid import Grid, leading_edge, make_grid
from rig.contact.influence import InfluenceOperator, influence_operator
from rig.contact.kalker import creep_coefficients
from rig.contact.kinematics import Creepage
from rig.contact.krylov import gmres as krylov_gmres
from rig.contact.models import fastsim
from rig.errors import ConvergenceError

NEWTON_TOL = 1e-7  # max |F| relative to the largest traction bound: nu to ~1e-8 (tractions are O(1) in mu p0)
# a cell sticks where |q| stays below its bound by more than Newton's tolerance can blur
STICK_MARGIN = 10 * NEWTON_TOL
MAX_NEWTON = 50
FULL_STICK_PRODUCTS = 5000  # GMRES products the linear full-stick solve may take
MAX_MEMORY_PASSES = 50
BACKWARD_2 = (1.5, -2.0, 0.5)  # dU/dx at a cell from it and two cells upstream, times h
# grids with at least this many cells across 2a start Newton from the solution on half as many
# (nested iteration; coarser ones from FASTSIM)
NESTED_START_N = 64
BAND_BELOW, BAND_ABOVE = 5, 1  # bandwidths of the preconditioner's local law in line order


@dataclass(frozen=True)
class GridSolution:
    """Traction q (2, N) [mu p0], slip s (2, N) [mu p0 v/G, zero where stuck], stick (N,), counts."""

    q: np.ndarray
    s: np.ndarray
    stick: np.ndarray
    newton_iterations: int
    krylov_iterations: int
    memory_passes: int


def project(z: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Projection of each 2-vector z_c on the disc |.| <= r_c; returns (P(z), |z|, inside mask)."""
    norm = np.hypot(z[0], z[1])
    inside = norm <= r
    scale = np.where(inside, 1.0, r / np.where(norm > 0.0, norm, 1.0))
    return z * scale, norm, inside


class Discretisation:
    """The linear parts of the discrete model on one grid: U(t), q(t, U), s(q, U).

    Transport (eqs. 8, 10), the slip at each cell centre x_c (step h along the rolling direction):

        s_c = s_g(x_c) + (3 U_c - 4 U_c-1 + U_c-2)/(2 h)            (second-order backward difference)

    except in the first cell of each row, which the leading edge x_L cuts off from its upstream
    neighbour (x_c-1 < x_L < x_c). There the mean slip S1 over the step [x_c-1, x_c] straddles the
    edge: its part outside the contact is the free surface's slip, which grows like
    sqrt(x_L - x) from the edge (the traction there is bounded by mu p ~ sqrt(distance)). The
    step before, [x_c-2, x_c-1], lies wholly outside with mean slip S0, so the outside part of S1
    is r S0, r = d^1.5/((d + h)^1.5 - d^1.5), d = x_L - x_c-1, and the slip of the material in
    the contact is s_c = (S1 - r S0)/(1 - r). Every row's entry condition sets the traction level
    of the whole row (in stick, the material carries it downstream), so it must be accurate: the
    backward difference across the edge alone (which lets material stick outside the contact)
    makes nu_v first order with a sign that depends on where the edge cuts each row [R, our
    construction; docs/contact-model.md, "Convergence study"].
    """

    def __init__(self, grid: Grid, op: InfluenceOperator, effects: ContactEffects) -> None:
        self.grid = grid
        self.op = op
        self.idx = grid.index
        self.upstream = (self.idx - grid.ny, self.idx - 2 * grid.ny)
        self.weights, self.x_slip = _transport(grid)
        cells = np.arange(self.idx.size)
        self.transport = sparse.csr_matrix(  # (N, full cells): the weights at each cell and upstream
            (self.weights.ravel(), (np.tile(cells, 3), np.concatenate([self.idx, *self.upstream]))),
            shape=(self.idx.size, grid.p.size),
        )
        self.plastic = effects.plastic_slip
        self.inertia = effects.surface_inertia
        self.plastic_rate = 0.0 if self.plastic is None else self.plastic.rate(op.poisson)

    def rigid_slip(self, creepage: Creepage) -> np.ndarray:
        """s_g (2, N) [mu p0 v/G] where the transport takes it: the cell centre, or for the first
        cell of a row the point its edge-corrected slip refers to (class docstring)."""
        _, y = self.grid.centres()
        return creepage.field(self.x_slip, y)

    def displacement(self, t: np.ndarray) -> np.ndarray:
        """Half-space displacement on the full rectangle, flattened to (2, cells)."""
        return self.op.apply(self.grid.scatter(t)).reshape(2, -1)

    def interface_traction(self, t: np.ndarray, u_full: np.ndarray) -> np.ndarray:
        if self.inertia is None:
            return t
        return t + self.inertia.layer_force(u_full, self.grid, self.op)

    def apply(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The linear part of the steady law: (q(t), elastic slip(t)); s = s_g + the latter."""
        u = self.displacement(t)
        q = self.interface_traction(t, u)
        return q, self.elastic_slip(q, u)

    def elastic_slip(self, q: np.ndarray, u_full: np.ndarray) -> np.ndarray:
        """Change of the displacement a material point carries over its step per unit step
        (eqs. 8, 10; class docstring), plus the plastic self slip of eq. (25) when it is on."""
        slip = (self.transport @ u_full.T).T
        if self.plastic is not None:
            slip += self.plastic.slip(q, self.op.poisson)
        return slip

    def slip_scale(self) -> np.ndarray:
        """rho (N,): about the inverse of ds_c/dt_c, a cell's slip per unit of its own traction [1]
        (it scales the projection of the Newton residual; any positive value gives the same answer)."""
        k0, k1 = self.op.self_term[0], self.op.upstream_term[0]
        return 1.0 / (self.weights[0] * (k0 - k1) + self.plastic_rate)


def _transport(grid: Grid) -> tuple[np.ndarray, np.ndarray]:
    """Weights (3, N) [1/a] of U at each active cell and at the cells one and two steps upstream,
    and the x [a] at which the rigid slip is taken (Discretisation's transport, class docstring)."""
    x, y = grid.centres()
    h = grid.hx
    entering = ~grid.active.ravel()[grid.index - grid.ny]
    weights = np.empty((3, x.size))
    weights[:] = np.array(BACKWARD_2)[:, None] / h
    x_slip = x.copy()
    xe = x[entering]
    d = np.clip(leading_edge(grid.shape, grid.b_over_a, y[entering]) - (xe - h), 0.0, h)
    r = d**1.5 / ((d + h) ** 1.5 - d**1.5)  # outside share of the straddling step's slip over S0
    inside = (1.0 - r) * h
    weights[0, entering] = 1.0 / inside
    weights[1, entering] = -(1.0 + r) / inside
    weights[2, entering] = r / inside
    x_slip[entering] = ((xe - 0.5 * h) - r * (xe - 1.5 * h)) / (1.0 - r)
    return weights, x_slip


class _Preconditioner:
    """M^-1 = Kc^-1 o L^-1: L is the Jacobian with K replaced by K_self, which only couples a
    cell to its upstream neighbours (solved exactly: a band LU in line order), and Kc^-1 the
    circulant inverse of the influence operator restricted to the contact (Vollebregt's FFT
    preconditioner idea)."""

    def __init__(self, disc: Discretisation, rho, *, upwind: bool = True) -> None:
        """rho: Discretisation.slip_scale (N,) or a number; upwind: the steady law couples a cell
        to its upstream neighbours (the transport); the transient law of one rolling step does
        not (the carried displacement is known)."""
        grid = disc.grid
        n = disc.idx.size
        self.n = n
        self.disc = disc
        k0 = disc.op.self_term[0]
        self.radial = 1.0 / k0
        # L in the displacement-like unknown w = K_self t: slip = rho (D w + plastic rate w / k0)
        self.links = []
        if upwind:
            position = -np.ones(grid.p.size, dtype=int)
            position[disc.idx] = np.arange(n)
            for up, weight in zip(disc.upstream, disc.weights[1:]):
                upstream = position[up]
                has = np.flatnonzero(upstream >= 0)
                self.links.append((has, upstream[has], (rho * weight)[has]))
            self.tangential = rho * (disc.weights[0] + disc.plastic_rate / k0)
        else:
            self.tangential = rho
        # unknowns ordered line by line along the rolling direction (row j, then column i), the two
        # components of a cell side by side: L couples an unknown only to the same cell and to the
        # two cells upstream in its line, so it is a band matrix (5 below the diagonal, 1 above)
        # and its LU factor costs O(N) (LAPACK's banded solver)
        column, row = np.divmod(disc.idx, grid.ny)
        rank = np.empty(n, dtype=int)
        rank[np.lexsort((column, row))] = np.arange(n)
        self.permutation = np.concatenate([2 * rank, 2 * rank + 1])  # (component, cell) -> line order
        self.inverse_permutation = np.argsort(self.permutation)

    def factor(self, zhat: np.ndarray, ratio: np.ndarray, inside: np.ndarray):
        """M^-1 for the Newton step at projection data (zhat, ratio, inside): a function of v (2N,)."""
        n = self.n
        pxx = np.where(inside, 1.0, ratio * (1.0 - zhat[0] ** 2))
        pxy = np.where(inside, 0.0, -ratio * zhat[0] * zhat[1])
        pyy = np.where(inside, 1.0, ratio * (1.0 - zhat[1] ** 2))
        k, c = self.radial, self.tangential
        cells = np.arange(n)
        rows = [cells, cells, cells + n, cells + n]
        cols = [cells, cells + n, cells, cells + n]
        vals = [(1 - pxx) * k + pxx * c, pxy * (c - k), pxy * (c - k), (1 - pyy) * k + pyy * c]
        for has, up, coefficient in self.links:
            rows += [has, has, has + n, has + n]
            cols += [up, up + n, up, up + n]
            vals += [pxx[has] * coefficient, pxy[has] * coefficient, pxy[has] * coefficient, pyy[has] * coefficient]
        perm = self.permutation
        i, j = perm[np.concatenate(rows)], perm[np.concatenate(cols)]
        band = np.zeros((2 * BAND_BELOW + BAND_ABOVE + 1, 2 * n))
        band[BAND_BELOW + BAND_ABOVE + i - j, j] = np.concatenate(vals)
        lu, pivots, info = lapack.dgbtrf(band, BAND_BELOW, BAND_ABOVE)
        if info != 0:
            raise ConvergenceError(f"preconditioner factor is singular (LAPACK dgbtrf info {info})")
        grid = self.disc.grid
        op = self.disc.op
        inverse = self.inverse_permutation

        def apply(v):
            w = lapack.dgbtrs(lu, BAND_BELOW, BAND_ABOVE, v[inverse], pivots)[0][perm].reshape(2, n)
            return grid.gather(op.apply_inverse(grid.scatter(w))).ravel()

        return apply


def solve_grid(grid: Grid, poisson: float, creepage: Creepage, effects: ContactEffects) -> GridSolution:
    """Solve the discrete kinematic law of friction for one steady rolling state."""
    op = influence_operator(grid, poisson)
    disc = Discretisation(grid, op, effects)
    s_g = disc.rigid_slip(creepage)
    p = effects.traction_bound(grid.gather(grid.p))  # mu(p) p/(mu0 p0); p itself unless mu depends on p
    n_cells = p.size
    rho = disc.slip_scale()
    precond = _Preconditioner(disc, rho)

    static = effects.static_friction
    sticking_upstream = np.ones(n_cells, dtype=bool)
    r = p if static is None else static.bound(p, sticking_upstream)
    t = _start(grid, poisson, creepage, effects, r)
    total_newton = total_krylov = 0
    for memory_pass in range(1, MAX_MEMORY_PASSES + 1):
        t, n_newton, n_krylov = _newton(disc.apply, s_g, precond, r, rho, t)
        total_newton += n_newton
        total_krylov += n_krylov
        q, elastic = disc.apply(t)
        s = s_g + elastic
        stick = np.hypot(q[0], q[1]) < r * (1.0 - STICK_MARGIN)
        if static is None:
            break
        new_upstream = sticking_upstream & static.upstream_state(stick, grid)
        if np.array_equal(new_upstream, sticking_upstream):
            break
        sticking_upstream = new_upstream
        r = static.bound(p, sticking_upstream)
    else:
        raise ConvergenceError(
            f"stick/slip memory (static friction mu0/mu = {static.ratio}) did not settle in "
            f"{MAX_MEMORY_PASSES} passes: the stick/slip partition keeps changing"
        )
    # Newton leaves |q| up to its tolerance above the bound in sliding cells: the bound is exact
    return GridSolution(project(q, r)[0], np.where(stick, 0.0, s), stick, total_newton, total_krylov, memory_pass)


def solve_full_stick(grid: Grid, poisson: float, creepage: Creepage, effects: ContactEffects, rtol: float = 1e-12) -> np.ndarray:
    """Tractions (2, N) [mu p0] if every element adheres (no traction bound): s = 0 everywhere.

    This is linear theory on the grid (alpha' -> inf, or unlimited friction); used to compute
    creepage coefficients (rig.contact.linear_tables) and to check the linear limit.
    """
    op = influence_operator(grid, poisson)
    disc = Discretisation(grid, op, effects)
    n = grid.index.size
    s_g = disc.rigid_slip(creepage)
    rho = disc.slip_scale()
    inside = np.ones(n, dtype=bool)
    preconditioner = _Preconditioner(disc, rho).factor(np.zeros((2, n)), np.ones(n), inside)

    def operator(v):
        return disc.apply(v.reshape(2, n))[1].ravel()

    t, _, converged = krylov_gmres(operator, -s_g.ravel(), preconditioner, rtol=rtol, restart=100,
                                   maxiter=FULL_STICK_PRODUCTS)
    if not converged:
        raise ConvergenceError(f"full-stick linear solve did not reach rtol {rtol:g} in {FULL_STICK_PRODUCTS} "
                               "GMRES iterations")
    return t.reshape(2, n)


def _start(grid: Grid, poisson: float, creepage: Creepage, effects: ContactEffects, r: np.ndarray) -> np.ndarray:
    """Newton's start (2, N) [mu p0]: on fine grids the solution on the grid with half as many
    cells, carried to the fine cells (each takes the traction of the coarse cell it lies in,
    limited to its own bound), so that Newton mostly refines the stick/slip pattern; on coarser
    grids FASTSIM. The start changes the cost, not the answer. (Measured with the first-order
    transport, pure spin, alpha' = 20.5, n = 128: 5 Newton steps instead of 24; with today's
    transport the same state takes 18.)"""
    if grid.ny < NESTED_START_N:
        return _fastsim_start(grid, poisson, creepage, r)
    coarse = make_grid(grid.shape, grid.b_over_a, grid.ny // 2)
    t_coarse = coarse.scatter(solve_grid(coarse, poisson, creepage, effects).q)
    xc, yc = grid.centres()
    i = np.clip(np.floor((xc - coarse.x[0]) / coarse.hx + 0.5).astype(int), 0, coarse.x.size - 1)
    j = np.clip(np.floor((yc - coarse.y[0]) / coarse.hy + 0.5).astype(int), 0, coarse.ny - 1)
    t = t_coarse[:, i, j]
    return project(t, r)[0]


def _fastsim_start(grid: Grid, poisson: float, creepage: Creepage, r: np.ndarray) -> np.ndarray:
    """FASTSIM tractions with the ellipse's flexibilities: a start that already has the
    right stick/slip pattern, so Newton needs few steps (a guess only; any start converges)."""
    b = float(np.clip(grid.b_over_a, 0.1, 10.0))
    flex = fastsim.flexibility("ellipse", b, creep_coefficients("ellipse", b, poisson), creepage)
    return grid.gather(fastsim.march(grid, fastsim.slip_increments(grid, creepage), grid.scatter(r), flex))


def _newton(apply, s0: np.ndarray, precond: _Preconditioner, r: np.ndarray, rho: float, t0: np.ndarray):
    """Semi-smooth Newton-Krylov for F(t) = q - P_r(q - rho s) = 0 of an affine law
    (q, s - s0) = apply(t); returns (t, Newton iterations, Krylov iterations)."""
    n = r.size
    scale = max(float(np.max(r)), 1e-300)
    tol = NEWTON_TOL * scale

    def evaluate(t):
        q, a = apply(t)
        z = q - rho * (s0 + a)
        pz, zn, inside = project(z, r)
        return q - pz, z, zn, inside

    t = t0
    f, z, zn, inside = evaluate(t)
    krylov = 0
    for iteration in range(MAX_NEWTON + 1):
        largest = float(np.abs(f).max())
        if largest <= tol:
            return t, iteration, krylov
        if iteration == MAX_NEWTON:
            break
        safe = np.where(zn > 0.0, zn, 1.0)
        zhat = z / safe
        ratio = np.where(inside, 1.0, r / safe)

        def jacobian(v, zhat=zhat, ratio=ratio, inside=inside):
            dq, da = apply(v.reshape(2, n))
            dz = dq - rho * da
            radial = zhat[0] * dz[0] + zhat[1] * dz[1]
            dp = np.where(inside, dz, ratio * (dz - zhat * radial))
            return (dq - dp).ravel()

        forcing = min(0.1, max(largest / scale, 0.1 * tol / largest))
        delta, products, _ = krylov_gmres(jacobian, -f.ravel(), precond.factor(zhat, ratio, inside), rtol=forcing)
        krylov += products
        delta = delta.reshape(2, n)
        # backtracking on |F|_2, the merit whose decrease the Newton direction guarantees (the largest
        # |F_c| often rises for a full step while the whole residual falls)
        norm = float(np.linalg.norm(f))
        step = 1.0
        while True:
            trial = evaluate(t + step * delta)
            if float(np.linalg.norm(trial[0])) < (1.0 - 1e-4 * step) * norm or step < 1e-4:
                break
            step *= 0.5
        t = t + step * delta
        f, z, zn, inside = trial
    raise ConvergenceError(
        f"kinematic contact solve did not converge in {MAX_NEWTON} Newton iterations: residual "
        f"{largest / scale:.2e} of the traction bound (tolerance {NEWTON_TOL:.0e})"
    )
