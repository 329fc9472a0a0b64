"""The affine part of a grid contact model and its linearisation for the Newton-Krylov solver.

A grid model states its unknowns, the tractions t (2, N) of the contact's cells [mu p0], through
two affine maps (dimensionless: lengths in a, slip in mu p0 v/G or, for a rolling step, slip
displacement in mu p0 a/G; rig.contact.models.kinematic):

    U = K t                                       half-space displacement, eq. (6) (rig.contact.influence)
    q = t  (+ Gamma Lambda^-1 D2 U)               traction on the interface (+ surface inertia, eq. 15)
    s = s0 + sum_k c_k,c U(k cells upstream) + g q     slip: transport (eqs. 8, 10) + plastic slip (eq. 25)

with c_k,c the transport weights of cell c (the steady model's second-order difference along the
rolling direction, k = 0, 1, 2; one unit weight for a transient step) and g the plastic slip rate.
The Coulomb law |q| <= r, q = -r s/|s| where s != 0 (eqs. 13-14) is then solved by
rig.contact.newton, which needs products with the Jacobian of F(t) = q - P_r(q - rho s) and a
preconditioner; :class:`Linearisation` provides both for one Newton step.

Jacobian: with P' the derivative of the projection at z = q - rho s (I inside the disc,
(r/|z|)(I - z z^T/|z|^2) outside) and no surface inertia,

    J v = (I - P' + rho g P') v + rho P' sum_k c_k (K v)(k upstream),

evaluated by one FFT product with K and a loop over the cells (rig.contact.cellwise).
Preconditioner [R, our construction]. J mixes two kinds of rows: where a cell sticks, or slides
slowly (P' near I), it asks for a displacement (the transported K v), an operator of order zero that
the circulant inverse of K undoes; where a cell slides fast (P' near 0, or radially: P' has no
radial part), it fixes the traction itself. So M^-1 v is formed in the displacement-like unknown
w = k0 t (k0 the self term of K): first L w = v, J with K replaced by k0 in the local terms,

    (L w)_c = [(I - P'_c)/k0 + rho_c P'_c (c_0,c + g/k0)] w_c + rho_c P'_c sum_k>0 c_k,c w_(k upstream),

solved exactly cell by cell from the leading edge downstream (a band solve along each row); then
the traction takes the displacement-controlled share through the inverse of K and the rest locally,

    M^-1 v = P' Kc^-1 (P' w) + (I - P') w/k0,

with Kc^-1 the circulant inverse of K (rig.contact.influence.InfluenceOperator.apply_inverse).
Before the second term (everything through Kc^-1, as in Vollebregt's FFT preconditioner) a
sliding cell's traction answered a displacement, an operator of order +1, and GMRES needed 2-7
times more products in partial slip (docs/contact-model.md, "Solver cost").
With surface inertia the Jacobian products take the general path through :meth:`ElasticLaw.apply`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from rig.contact import cellwise
from rig.contact.effects.surface_inertia import SurfaceInertia
from rig.contact.entry import EntryProfile
from rig.contact.grid import Grid
from rig.contact.influence import InfluenceOperator


@dataclass(frozen=True, eq=False)
class ElasticLaw:
    """The affine maps t -> (q, s - s0) of a grid model (module docstring).

    transport (K, N): weight [1/a, or 1 for a rolling step] of the displacement at each cell (k = 0)
    and k cells upstream; plastic_rate g: plastic slip per unit traction [1]; inertia: surface
    inertia (eq. 15) or None (off); entry: the first cells' traction profile at the leading edge
    (the steady model's, rig.contact.entry) or None (uniform cells).
    """

    grid: Grid
    op: InfluenceOperator
    transport: np.ndarray
    plastic_rate: float = 0.0
    inertia: SurfaceInertia | None = None
    entry: EntryProfile | None = None

    @cached_property
    def cells(self) -> tuple[np.ndarray, np.ndarray]:
        """(ix, iy): the cells' indices on the grid rectangle."""
        ix, iy = np.divmod(self.grid.index, self.grid.ny)
        return ix, iy

    @cached_property
    def upstream(self) -> np.ndarray:
        """(K - 1, N): cell-list index of the cell k = 1 .. K - 1 steps upstream, -1 outside the contact."""
        position = -np.ones(self.grid.p.size, dtype=np.int64)
        position[self.grid.index] = np.arange(self.grid.index.size)
        steps = np.arange(1, self.transport.shape[0])[:, None]
        return position[self.grid.index[None, :] - steps * self.grid.ny]

    @property
    def traction_is_interface(self) -> bool:
        """True when q = t (no surface inertia, or an inertia number of 0): the bound |q| <= r then
        bounds the unknowns themselves."""
        return self.inertia is None or self.inertia.number == 0.0

    def displacement(self, t: np.ndarray) -> np.ndarray:
        """U (2, nx, ny) [mu p0 a/G] on the grid rectangle of tractions t (2, N) [mu p0] at the cells
        (the first cells' moment-matched share moved when there is an entry profile)."""
        field = self.grid.scatter(t)
        if self.entry is not None:
            self.entry.spread(field, t)
        return self.op.apply(field)

    def apply(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The linear part of the law at tractions t (2, N): (q, s - s0), both (2, N)."""
        u = self.displacement(t)
        q = t if self.inertia is None else t + self.inertia.layer_force(u.reshape(2, -1), self.grid, self.op)
        slip = np.empty_like(t)
        ix, iy = self.cells
        cellwise.transported(u, ix, iy, self.transport, slip)
        if self.entry is not None:
            slip += self.entry.slip(t)
        if self.plastic_rate:
            slip += self.plastic_rate * q
        return q, slip

    def linearise(self, zhat: np.ndarray, ratio: np.ndarray, inside: np.ndarray, rho: np.ndarray | float) -> Linearisation:
        """The Jacobian and preconditioner at projection data (zhat (2, N) unit z, ratio (N,) r/|z|,
        inside (N,) |z| <= r) for the slip scale rho (N,) or a number."""
        return Linearisation(self, zhat, ratio, inside, rho)


class Linearisation:
    """J and M^-1 of one Newton step (module docstring) as functions of flat (2N,) vectors; the
    per-cell symmetric matrices are stored as (xx, xy, yy) rows (3, N)."""

    def __init__(self, law: ElasticLaw, zhat: np.ndarray, ratio: np.ndarray, inside: np.ndarray, rho) -> None:
        self.law = law
        n = zhat.shape[1]
        self.rho = rho = np.broadcast_to(np.asarray(rho, dtype=float), (n,))
        # P' of the projection: (xx, xy, yy)
        self.projection = np.stack([
            np.where(inside, 1.0, ratio * (1.0 - zhat[0] ** 2)),
            np.where(inside, 0.0, -ratio * zhat[0] * zhat[1]),
            np.where(inside, 1.0, ratio * (1.0 - zhat[1] ** 2)),
        ])
        identity = np.array([1.0, 0.0, 1.0])[:, None]
        g = law.plastic_rate
        self.local = identity - (1.0 - rho * g) * self.projection  # I - P' + rho g P'
        self.slip_gain = rho * self.projection  # rho P'
        k0 = law.op.self_term[0]
        diagonal = (identity - self.projection) / k0 + self.slip_gain * (law.transport[0] + g / k0)
        det = diagonal[0] * diagonal[2] - diagonal[1] ** 2
        self.diagonal_inverse = np.stack([diagonal[2], -diagonal[1], diagonal[0]]) / det
        grid = law.grid
        self.w = np.empty((2, n))
        self.t = np.empty((2, n))
        self.out = np.empty((2, n))
        self.field = np.zeros((2,) + grid.full_shape)  # only the cells are ever written: zero elsewhere

    def jacobian(self, v: np.ndarray) -> np.ndarray:
        """J v for a flat (2N,) v."""
        law, op = self.law, self.law.op
        v = v.reshape(2, -1)
        ix, iy = law.cells
        if law.inertia is not None:  # the general path: q depends on U too
            dq, da = law.apply(v)
            return (dq - _symmetric_product(self.projection, dq - self.rho * da)).ravel()
        cellwise.place(v, ix, iy, self.field)
        if law.entry is not None:
            law.entry.spread(self.field, v)
        u = op.apply(self.field)
        if law.entry is not None:
            law.entry.clear(self.field)
        cellwise.linearised_law(u, ix, iy, law.transport, v, self.local, self.slip_gain, self.out)
        if law.entry is not None:
            local = law.entry.local
            cellwise.add_local_slip(local.indptr, local.indices, local.data, v, self.slip_gain, self.out)
        return self.out.ravel().copy()

    def precondition(self, v: np.ndarray) -> np.ndarray:
        """M^-1 v for a flat (2N,) v."""
        law, op = self.law, self.law.op
        ix, iy = law.cells
        cellwise.upwind_solve(v.reshape(2, -1), self.diagonal_inverse, self.slip_gain, law.upstream,
                              law.transport[1:], self.projection, ix, iy, self.w, self.field)
        cellwise.blend(op.apply_inverse(self.field), ix, iy, self.projection, self.w, 1.0 / op.self_term[0], self.t)
        return self.t.ravel().copy()


def _symmetric_product(matrix: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Per-cell product of symmetric 2x2 matrices (3, N) (xx, xy, yy) with vectors v (2, N)."""
    return np.stack([matrix[0] * v[0] + matrix[1] * v[1], matrix[1] * v[0] + matrix[2] * v[1]])
