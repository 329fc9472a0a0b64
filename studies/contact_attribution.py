"""Which cells' equations make the kinematic model's error at one state: an adjoint attribution.

    python studies/contact_attribution.py [--n 32] [--fine 256] [--b 1] [--alpha 20.5] [--map]

Pure spin about the centre. The solution on a fine grid (nf = 8 n cells across 2a: its error is
4-14x smaller), summed over the coarse cells (rim cells that are outside the coarse contact give
their force to the nearest coarse cell), stands in for the exact tractions t*. Put into the coarse
equations F(t) = q - P_r(q - rho s) (rig.contact.newton) it leaves a residual R = F(t*), the
discretisation's truncation error; with J the semi-smooth Jacobian at the coarse solution t_n,
t_n - t* ~ -J^-1 R, so

    nu_v(n) - nu_v(t*) ~ -phi . R,   phi = J^-T d nu_v/dt   (the adjoint: how nu_v answers a residual)

which splits the error exactly (to first order) over the cells whose equations cause it. J is formed
column by column from its products (2N of them: n <= 64). Classes: the stick/slip boundary (cells
within 2 cells of a cell in the other state), the rest of the stick zone with every row's first
two cells (the leading edge's near field: the stick zone starts at the leading edge here), and the
rest of the slip zone. The finer classes near the leading edge are not reported: their residuals
there are O(h^0.5) and their shares large and of both signs (docs/contact-convergence.md, "Where the rest
of the error is"). The +-2-cell classes hand cells from one class to the next as h falls, so orders
taken from them mislead; studies/slip_layer.py splits by physical place (the fifth pass).
"""

from __future__ import annotations

import argparse

import numpy as np
from scipy import ndimage

from rig.contact.effects import ContactEffects
from rig.contact.grid import make_grid
from rig.contact.influence import influence_operator
from rig.contact.kinematics import Creepage
from rig.contact.models import kinematic
from rig.contact.newton import project

POISSON = 0.28


def reference_on(coarse, fine, q_fine) -> np.ndarray:
    """The fine tractions (2, Nf) summed over each coarse cell, per coarse cell area (2, N)."""
    ratio = (coarse.hx * coarse.hy) / (fine.hx * fine.hy)
    i = np.floor((fine.x - coarse.x[0]) / coarse.hx + 0.5).astype(int)
    j = np.floor((fine.y - coarse.y[0]) / coarse.hy + 0.5).astype(int)
    field = np.zeros((2,) + coarse.full_shape)
    for m in range(2):
        np.add.at(field[m], (i[:, None], j[None, :]), fine.scatter(q_fine)[m] / ratio)
    ai, aj = np.nonzero(coarse.active)
    for oi, oj in zip(*np.nonzero((np.abs(field).sum(axis=0) > 0) & ~coarse.active)):
        k = np.argmin((coarse.x[ai] - coarse.x[oi]) ** 2 + (coarse.y[aj] - coarse.y[oj]) ** 2)
        field[:, ai[k], aj[k]] += field[:, oi, oj]
    return coarse.gather(field)


def linearised(disc, creepage, q):
    """(residual, J): t -> (F(t), z, |z|, inside) of the discretisation ``disc``'s equations
    (rig.contact.models.kinematic.Discretisation) and their Jacobian at tractions q (2, N) [mu p0]."""
    grid = disc.grid
    s_g, rho, bound = disc.rigid_slip(creepage), disc.slip_scale(), grid.gather(grid.p)

    def residual(t):
        q, elastic = disc.law.apply(t)
        z = q - rho * (s_g + elastic)
        pz, zn, inside = project(z, bound)
        return q - pz, z, zn, inside

    _, z, zn, inside = residual(q)
    safe = np.where(zn > 0.0, zn, 1.0)
    return residual, disc.law.linearise(z / safe, np.where(inside, 1.0, bound / safe), inside, rho)


def adjoint_split(disc, creepage, q, t_ref) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The shares (N,) of nu_v's error -phi . R by cell (x and y equations summed), the adjoint phi
    (2, N) and the residual R (2, N) of the reference tractions t_ref (2, N) [mu p0] in the equations of
    the discretisation ``disc``, J taken at its solution q (J formed densely: n <= 64)."""
    residual, linear = linearised(disc, creepage, q)
    size = q.size
    unit = np.zeros(size)
    jacobian = np.empty((size, size))
    for k in range(size):
        unit[k] = 1.0
        jacobian[:, k] = linear.jacobian(unit)
        unit[k] = 0.0
    gradient = np.zeros(size)
    gradient[size // 2:] = 1.0 / disc.grid.gather(disc.grid.p).sum()  # nu_v = sum q_y / sum p
    phi = np.linalg.solve(jacobian.T, gradient)
    r_ref = residual(t_ref)[0]
    share = -phi * r_ref.ravel()
    return share[: size // 2] + share[size // 2:], phi.reshape(2, -1), r_ref


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n", type=int, default=32)
    parser.add_argument("--fine", type=int, default=256)
    parser.add_argument("--b", type=float, default=1.0)
    parser.add_argument("--alpha", type=float, default=20.5)
    parser.add_argument("--map", action="store_true", help="the slip zone's shares binned in x and y")
    args = parser.parse_args()
    creepage = Creepage.from_rolling_point(args.alpha, 0.0, 0.0, POISSON)
    effects = ContactEffects()
    grid, fine = make_grid("ellipse", args.b, args.n), make_grid("ellipse", args.b, args.fine)
    solution = kinematic.solve_grid(grid, POISSON, creepage, effects)
    t_ref = reference_on(grid, fine, kinematic.solve_grid(fine, POISSON, creepage, effects).q)
    load = grid.gather(grid.p).sum()

    disc = kinematic.Discretisation(grid, influence_operator(grid, POISSON), effects)
    share = grid.scatter(adjoint_split(disc, creepage, solution.q, t_ref)[0][None, :])[0]
    nu, nu_ref = solution.q[1].sum() / load, t_ref[1].sum() / load
    print(f"b/a {args.b}, alpha' {args.alpha}: nu_v(n = {args.n}) {nu:.6f}, fine (n = {args.fine}) on the coarse "
          f"cells {nu_ref:.6f}: difference {nu - nu_ref:+.3e}, adjoint estimate {share.sum():+.3e}")

    active = grid.active
    stick = (grid.scatter(solution.stick.astype(float)[None, :])[0] > 0.5) & active
    slip = active & ~stick
    near = np.ones((5, 5), dtype=bool)
    boundary = (stick & ndimage.binary_dilation(slip, near)) | (slip & ndimage.binary_dilation(stick, near))
    first_two = active & (np.cumsum(active, axis=0) <= 2)
    classes = {
        "stick/slip boundary (+-2 cells)": boundary & ~first_two,
        "stick zone and the rows' first two cells": (stick | first_two) & ~(boundary & ~first_two),
        "slip zone beyond the boundary": slip & ~boundary & ~first_two,
    }
    for name, mask in classes.items():
        print(f"  {name:42s} {mask.sum():5d} cells  {share[mask].sum():+.3e}")
    if args.map:
        xs, ys = np.meshgrid(grid.x, grid.y, indexing="ij")
        edges = np.linspace(-1.0, 1.0, 9)
        print("slip zone beyond the boundary, shares x 1e6 binned: rows y (top down), columns x (-1 ... 1)")
        for j in range(8, 0, -1):
            cells = [share[classes["slip zone beyond the boundary"] & (xs >= edges[i]) & (xs < edges[i + 1])
                           & (ys >= edges[j - 1]) & (ys < edges[j])].sum() * 1e6 for i in range(8)]
            print(f"  y {edges[j - 1]:+.2f}..{edges[j]:+.2f} " + " ".join(f"{c:+7.1f}" for c in cells))


if __name__ == "__main__":
    main()
