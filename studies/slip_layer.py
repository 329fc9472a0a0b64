"""The slip layer between the circle's stick zone and its trailing edge: where its share of nu_v's
error sits, what in the slip cells' equations makes it, and what changes it
(docs/contact-convergence.md, the slip layer).

    python studies/slip_layer.py map [--n 32] [--fine 256]   (n > 64 or --gmres: GMRES per part)
    python studies/slip_layer.py nu [--grids 16 32 64 128] [--shifts 1] [--b 1] [--alpha 20.5]

Pure spin about the centre, Poisson 0.28; the circle at alpha' = 20.5 has the limit nu_v = 0.452144.
map (the circle): the adjoint split of studies/contact_attribution.py (the reference: the same
law on --fine cells) by region, then the slip cells downstream (x > 0) by physical distance to the
row's trailing edge x_T(y) (bands fixed in units of a: the +-2-cell classes of contact_attribution.py
hand cells from one class to the next as h falls, so their orders mislead), by distance to the stick
zone and by cells to the row's end; each band split into the residual's radial part and its direction
part, that into the averaging (the direction of the cell's mean traction t* against the fine slip's at
the centre) and the slip's truncation, and that into the BDF2 stencil's (on the fine displacement) and
the displacement's (the coarse cells' U of t* against the fine U at the same points).
nu: nu_v and nu_0 on a sequence of grids (means over ``shifts`` sub-cell shifts -1/2 + k/shifts), the
observed orders of nu_v from differences.

What it shows (main, n = 32/64/128, fine 8n): the slip cells at x > 0 carry 3.0e-4/1.06e-4/3.05e-5 of
nu_v's error, orders 1.5 then 1.8 (the +-2-cell class "beyond the boundary" gave 1.1 on 32/64), spread
over 0.05-0.5 a from x_T, the rows' last cell nearly nothing; its largest part is BDF2's truncation where
the slip's direction turns fast (on the axis the slip has a sqrt(x_T - x) term). The O(h) part is the
stick zone's (0.97/0.94). No local change to the rim or the last cells removes the layer's share;
third-order differences flip its sign instead.

The variants of the discrete law that were tried against this layer (a row's last cell at its load's
centroid, a two-point difference after the stick zone, rim loads kept in their row, a trailing-edge
stencil, third-order backward differences) needed changes inside rig.contact and are not kept here;
docs/contact-convergence.md reports what each did. This script runs the law as rig.contact has it.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
from scipy import ndimage

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rig.contact.grid as gridmod  # noqa: E402
from rig.contact.effects import ContactEffects  # noqa: E402
from rig.contact.influence import influence_operator  # noqa: E402
from rig.contact.integrate import coefficients  # noqa: E402
from rig.contact.kinematics import Creepage  # noqa: E402
from rig.contact.models import kinematic  # noqa: E402
from contact_attribution import adjoint_split, linearised, reference_on  # noqa: E402
from rig.contact.krylov import gmres  # noqa: E402

POISSON = 0.28
ALPHA = 20.5
LIMIT = 0.452144
B_OVER_A = 1.0
CREEPAGE = Creepage.from_rolling_point(ALPHA, 0.0, 0.0, POISSON)  # main() sets both from --b, --alpha
EFFECTS = ContactEffects()


def solve(grid):
    """The kinematic solution on a grid (rig.contact.models.kinematic as it is)."""
    return kinematic.solve_grid(grid, POISSON, CREEPAGE, EFFECTS)


def values(n: int, shift: float) -> tuple[float, float]:
    """(nu_v, nu_0) on the grid of size n moved by ``shift`` cells."""
    grid = gridmod.make_grid("ellipse", B_OVER_A, n, shift)
    solution = solve(grid)
    x, y = grid.centres()
    result = coefficients(x, y, solution.q, grid.gather(grid.p), CREEPAGE)
    return float(result["nu_v"]), float(result["nu_0"])


def sequence(args) -> None:
    shifts = [-0.5 + k / args.shifts for k in range(args.shifts)] if args.shifts > 1 else [0.0]
    rows = []
    for n in args.grids:
        v, v0 = np.mean([values(n, s) for s in shifts], axis=0)
        rows.append(v)
        error = f" error {v - LIMIT:+.3e}" if (B_OVER_A, ALPHA) == (1.0, 20.5) else ""
        print(f"b/a {B_OVER_A:g} alpha' {ALPHA:g} n {n:4d} shifts {len(shifts)}: nu_v {v:.7f}{error}"
              f" nu_0 {v0:.7f}", flush=True)
    d = np.diff(rows)
    orders = [np.log2(d[k] / d[k + 1]) if d[k] * d[k + 1] > 0 else np.nan for k in range(d.size - 1)]
    if orders:
        print(f"nu_v orders from differences: " + " ".join(f"{o:.2f}" for o in orders))


def attribution(args) -> None:
    grid = gridmod.make_grid("ellipse", B_OVER_A, args.n)
    solution = solve(grid)
    fine = gridmod.make_grid("ellipse", B_OVER_A, args.fine)
    fine_solution = solve(fine)  # the reference: the same law on the fine grid
    q_fine = fine_solution.q
    t_ref = reference_on(grid, fine, q_fine)
    load = grid.gather(grid.p).sum()
    disc = kinematic.Discretisation(grid, influence_operator(grid, POISSON), EFFECTS)
    if args.n <= 64 and not args.gmres:  # the adjoint, J formed densely
        share, phi, r_ref = adjoint_split(disc, CREEPAGE, solution.q, t_ref)
        estimate = share.sum()

        def share_of(r):
            return -float((phi * r).sum())
    else:  # one GMRES solve J d = R_part per part asked for: -g . d (g = d nu_v/dt)
        residual, linear = linearised(disc, CREEPAGE, solution.q)
        r_ref = residual(t_ref)[0]

        def share_of(r):
            d, _, converged = gmres(linear.jacobian, r.ravel(), linear.precondition, rtol=1e-9, restart=100,
                                    maxiter=5000)
            if not converged:
                raise RuntimeError("GMRES did not converge")
            return -float(d.reshape(2, -1)[1].sum() / load)
        estimate = share_of(r_ref)
    nu, nu_ref = solution.q[1].sum() / load, t_ref[1].sum() / load
    print(f"nu_v(n = {args.n}) {nu:.6f}, fine (n = {args.fine}) {nu_ref:.6f}: difference "
          f"{nu - nu_ref:+.3e}, adjoint {estimate:+.3e}")

    # the fine solution's slip and displacement, for the truncation's split
    fine_law = kinematic.Discretisation(fine, influence_operator(fine, POISSON), EFFECTS).law
    truth = (fine.scatter(fine_solution.s), fine_law.displacement(q_fine), disc.law.displacement(t_ref),
             disc.weights)
    s_ref = disc.rigid_slip(CREEPAGE) + disc.law.apply(t_ref)[1]  # the coarse slip at t*
    report(grid, solution, share_of, r_ref, t_ref, s_ref, fine, truth)


def bilinear(fine, field, x, y):
    """field (2, nxg, ny) on the fine grid's centres, bilinearly at points (x, y)."""
    fx, fy = (x - fine.x[0]) / fine.hx, (y - fine.y[0]) / fine.hy
    i = np.clip(np.floor(fx).astype(int), 0, fine.x.size - 2)
    j = np.clip(np.floor(fy).astype(int), 0, fine.ny - 2)
    a, b = fx - i, fy - j
    return (field[:, i, j] * (1 - a) * (1 - b) + field[:, i + 1, j] * a * (1 - b) + field[:, i, j + 1] * (1 - a) * b
            + field[:, i + 1, j + 1] * a * b)


def report(grid, solution, share_of, r_ref, t_ref, s_ref, fine, truth) -> None:
    """The shares by region: the classes of contact_attribution.py, then the slip zone downstream
    (x > 0) by the cell's distance to its row's trailing edge, x_T(y) - x [a], each split into the
    residual's radial part (|t*| against the bound p) and its tangential part (the direction), the latter
    into the averaging (the direction of the cell's mean traction t* against the fine slip's direction at
    the centre) and the slip's truncation (the coarse slip at t* against the fine solution's slip at the
    centre), the truncation once more into the stencil's (the coarse transport on the fine displacement
    at x_c, x_c - h, x_c - 2h against the fine slip's dU/dx at x_c) and the displacement's (the coarse
    cells' U of t* against the fine U at the same points); then by distance to the stick zone and by
    cells to the row's end (k_T). share_of(r): nu_v's error due to a part r (2, N) of the residual."""
    x, y = grid.centres()
    full = grid.scatter(solution.stick.astype(float)[None, :])[0] > 0.5
    active = grid.active
    slip_full = active & ~full
    near = np.ones((5, 5), dtype=bool)
    boundary = grid.gather(((full & ndimage.binary_dilation(slip_full, near))
                            | (slip_full & ndimage.binary_dilation(full, near)))[None])[0]
    first_two = grid.gather((active & (np.cumsum(active, axis=0) <= 2))[None])[0]
    slip = ~solution.stick
    regions = {
        "rows' first two cells": first_two,
        "stick/slip boundary (+-2 cells)": boundary & ~first_two,
        "rest of the stick zone": solution.stick & ~boundary & ~first_two,
        "rest of the slip zone, x < 0": slip & ~boundary & ~first_two & (x < 0),
        "rest of the slip zone, x > 0": slip & ~boundary & ~first_two & (x >= 0),
        "all slip cells x > 0 (boundary incl.)": slip & (x >= 0),
    }
    for name, mask in regions.items():
        print(f"  {name:40s} {mask.sum():5d} cells {share_of(r_ref * mask):+.3e}", flush=True)
    radial = t_ref / np.hypot(*t_ref)
    tangent = np.stack([-radial[1], radial[0]])
    r_tangent = tangent * (r_ref * tangent).sum(0)
    angle = lambda v: np.arctan2(v[1], v[0])  # noqa: E731
    wrap = lambda a: (a + np.pi) % (2 * np.pi) - np.pi  # noqa: E731
    if truth is not None:
        fine_slip, u_fine, u_coarse, weights = truth
        s_true = bilinear(fine, fine_slip, x, y)
        averaging = wrap(angle(t_ref) - angle(-s_true))
        truncation = wrap(angle(-s_true) - angle(-s_ref))
        total = averaging + truncation
        part = np.where(total != 0.0, averaging / np.where(total != 0.0, total, 1.0), 0.0)
        ix, iy = np.divmod(grid.index, grid.ny)
        stencil_u = sum(w * bilinear(fine, u_fine, x - k * grid.hx, y) for k, w in enumerate(weights))
        coarse_u = sum(w * u_coarse[:, ix - k, iy] for k, w in enumerate(weights))
        normal = np.stack([-s_true[1], s_true[0]]) / np.hypot(*s_true).clip(1e-300)
        slope = s_ref - (coarse_u - stencil_u)  # the coarse slip with the fine U's samples in the stencil
        e_stencil = ((slope - s_true) * normal).sum(0)
        e_all = ((s_ref - s_true) * normal).sum(0)
        part_stencil = np.where(e_all != 0.0, e_stencil / np.where(e_all != 0.0, e_all, 1.0), 0.0)
    distance = grid.b_over_a * np.sqrt(np.clip(1.0 - y**2, 0.0, None)) - x
    k_t = grid.gather((np.cumsum(active[::-1], axis=0)[::-1] - 1)[None])[0]
    print("  slip cells x > 0 by x_T - x [a]: share = radial + tangential (= averaging + truncation"
          " [= stencil + displacement]) x 1e6")
    for lo, hi in ((0, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.3), (0.3, 0.5), (0.5, 2.0)):
        m = slip & (x >= 0) & (distance >= lo) & (distance < hi)
        whole, direction = share_of(r_ref * m), share_of(r_tangent * m)
        split = ""
        if truth is not None:
            a = share_of(r_tangent * m * part)
            b = share_of(r_tangent * m * (1 - part) * part_stencil)
            split = f" (= {a * 1e6:+7.1f} {(direction - a) * 1e6:+7.1f} [= {b * 1e6:+7.1f} {(direction - a - b) * 1e6:+7.1f}])"
        print(f"    [{lo:.2f}, {hi:.2f}) {m.sum():5d} cells {whole * 1e6:+7.1f} = {(whole - direction) * 1e6:+7.1f}"
              f" {direction * 1e6:+7.1f}{split}", flush=True)
    gap = ndimage.distance_transform_edt(~full, sampling=(grid.hx, grid.hy))  # to the nearest stick cell [a]
    gap = grid.gather(gap[None])[0]
    print("  slip cells x > 0 by distance to the stick zone [a] x 1e6: " + " ".join(
        f"[{lo:.3f}, {hi:.3f}) {share_of(r_ref * (slip & (x >= 0) & (gap >= lo) & (gap < hi))) * 1e6:+.1f}"
        for lo, hi in ((0, 0.13), (0.13, 0.26), (0.26, 0.5), (0.5, 9))))
    print("  slip cells x > 0 by k_T (cells to the row's last; 0 = last) x 1e6: " + " ".join(
        f"{share_of(r_ref * (slip & (x >= 0) & (k_t == k))) * 1e6:+.1f}" for k in range(8))
        + f" | >= 8: {share_of(r_ref * (slip & (x >= 0) & (k_t >= 8))) * 1e6:+.1f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=("map", "nu"))
    parser.add_argument("--n", type=int, default=32)
    parser.add_argument("--fine", type=int, default=256)
    parser.add_argument("--b", type=float, default=1.0, help="b/a (nu only)")
    parser.add_argument("--alpha", type=float, default=20.5, help="alpha' (nu only)")
    parser.add_argument("--grids", type=int, nargs="+", default=[16, 32, 64, 128])
    parser.add_argument("--shifts", type=int, default=1)
    parser.add_argument("--gmres", action="store_true", help="map: GMRES per part also for n <= 64")
    args = parser.parse_args()
    global B_OVER_A, ALPHA, CREEPAGE
    B_OVER_A, ALPHA = args.b, args.alpha
    CREEPAGE = Creepage.from_rolling_point(ALPHA, 0.0, 0.0, POISSON)
    (attribution if args.study == "map" else sequence)(args)


if __name__ == "__main__":
    main()
