"""Koziarski's kinematic law of friction ([Koziarski], eqs. 7-20) on a grid, solved as one coupled system.

Discrete steady rolling (Equations §1.5, 1.9), dimensionless (lengths in a, traction in mu p0,
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
the paper advertises ("no iterative steps") diverges under grid refinement (Equations §1.9 step 6;
tests/contact/test_marching_diverges.py shows it), so it is not offered.

Solver: semi-smooth Newton on F(t) = q - P_r(q - rho s) (P_r: projection on the disc of radius
r per cell; rig.contact.newton), GMRES on the exact generalised Jacobian with FFT influence products,
right-preconditioned by an exact upwind solve of the local law whose displacement-controlled share
goes through the circulant inverse of K (rig.contact.elastic_law); FASTSIM gives the start, a
backtracking line search on |F|_2 globalises. Static friction (mu0/mu > 1)
adds an outer loop over the stick/slip memory of each material point along its row: it starts
with every point holding mu0 p and moves a point to mu p once its material has slipped one cell
upstream; a point never moves back within one solve, so the loop ends after at most N passes
(the stick/slip law with memory is hysteretic and need not have one fixed point otherwise).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig.contact import newton
from rig.contact.effects import ContactEffects
from rig.contact.elastic_law import ElasticLaw
from rig.contact.entry import entry_profile, transport_weights
from rig.contact.grid import Grid, make_grid
from rig.contact.influence import InfluenceOperator, influence_operator
from rig.contact.kalker import creep_coefficients
from rig.contact.kinematics import Creepage
from rig.contact.krylov import gmres
from rig.contact.models import fastsim
from rig.contact.newton import STICK_MARGIN, project
from rig.errors import ConvergenceError

MAX_MEMORY_PASSES = 50
FULL_STICK_PRODUCTS = 5000  # GMRES products the linear full-stick solve may take
# grids with at least this many cells across 2a start Newton from the solution on half as many
# (nested iteration; coarser ones from FASTSIM)
NESTED_START_N = 64
# rho = SLIP_SCALE / (a cell's slip per unit of its own traction): with 1, on fine grids the stick zone
# of a row grew by one cell per Newton step (16 steps at n = 128, pure spin, alpha' = 20.5); with 0.5,
# 4 (docs/contact-model.md, "Solver cost")
SLIP_SCALE = 0.5


@dataclass(frozen=True)
class GridSolution:
    """Traction q (2, N) [mu p0], slip s (2, N) [mu p0 v/G, zero where stuck], stick (N,), counts."""

    q: np.ndarray
    s: np.ndarray
    stick: np.ndarray
    newton_iterations: int
    krylov_iterations: int
    memory_passes: int


class Discretisation:
    """The discrete steady law on one grid: its transport weights, where the rigid slip is taken,
    and the affine law (q, s - s_g)(t) they make (``law``, rig.contact.elastic_law.ElasticLaw).

    Transport (eqs. 8, 10), the slip at each cell centre x_c (step h along the rolling direction):

        s_c = s_g(x_c) + (3 U_c - 4 U_c-1 + U_c-2)/(2 h)            (second-order backward difference)

    except in the first two cells of each row, next to the leading edge x_L; and the first cell's
    traction is spread over [x_L, x_c + h/2] with the density sqrt(x - x_L) a traction has at a
    leading edge, not uniformly over the cell (rig.contact.entry). Every row's entry sets the
    traction level of the whole row (in stick, the material carries it downstream), so the model must
    know where x_L lies inside the first cell: without that, nu moved at first order with the edge's
    sub-cell position, erratically with n [R, our construction; docs/contact-convergence.md,
    "The rim and the leading edge"].
    """

    def __init__(self, grid: Grid, op: InfluenceOperator, effects: ContactEffects) -> None:
        self.grid = grid
        self.weights, self.x_slip = transport_weights(grid)
        self.plastic_rate = effects.plastic_rate(op.poisson)
        self.law = ElasticLaw(grid, op, self.weights, self.plastic_rate, effects.surface_inertia,
                              entry_profile(grid, op.poisson))

    def rigid_slip(self, creepage: Creepage) -> np.ndarray:
        """s_g (2, N) [mu p0 v/G] where the transport takes it: the cell centre, or for the first two
        cells of a row the point their slip refers to (rig.contact.entry.transport_weights)."""
        _, y = self.grid.centres()
        return creepage.field(self.x_slip, y)

    def slip_scale(self) -> np.ndarray:
        """rho (N,) [1]: SLIP_SCALE times the inverse of ds_c/dt_c, a cell's slip per unit of its own
        traction. rho weighs slip against traction in the projection z = q - rho s, i.e. in how Newton
        guesses which cells stick; any positive value gives the same answer, not the same path."""
        op = self.law.op
        k0, k1 = op.self_term[0], op.upstream_term[0]
        return SLIP_SCALE / (self.weights[0] * (k0 - k1) + self.plastic_rate)


def solve_grid(grid: Grid, poisson: float, creepage: Creepage, effects: ContactEffects) -> GridSolution:
    """Solve the discrete kinematic law of friction for one steady rolling state."""
    op = influence_operator(grid, poisson)
    disc = Discretisation(grid, op, effects)
    s_g = disc.rigid_slip(creepage)
    p = effects.traction_bound(grid.gather(grid.p))  # mu(p) p/(mu0 p0); p itself unless mu depends on p
    n_cells = p.size
    rho = disc.slip_scale()

    static = effects.static_friction
    sticking_upstream = np.ones(n_cells, dtype=bool)
    r = p if static is None else static.bound(p, sticking_upstream)
    t = _start(grid, poisson, creepage, effects, r)
    total_newton = total_krylov = 0
    for memory_pass in range(1, MAX_MEMORY_PASSES + 1):
        t, n_newton, n_krylov = newton.solve(disc.law, s_g, r, rho, t)
        total_newton += n_newton
        total_krylov += n_krylov
        q, elastic = disc.law.apply(t)
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
    # every cell inside the disc: J v = rho (ds/dt) v, the slip's linear part scaled by rho
    stick = disc.law.linearise(np.zeros((2, n)), np.ones(n), np.ones(n, dtype=bool), rho)
    t, _, converged = gmres(stick.jacobian, -(rho * s_g).ravel(), stick.precondition, rtol=rtol, restart=100,
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
    if grid.n < NESTED_START_N:
        return _fastsim_start(grid, poisson, creepage, r)
    coarse = make_grid(grid.shape, grid.b_over_a, grid.n // 2)
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


