"""The slip layer between the circle's stick zone and its trailing edge: where its share of nu_v's
error sits, what in the slip cells' equations makes it, and what changes it
(docs/contact-convergence.md, "Fifth pass: the slip layer").

    python experiments/slip_layer.py map [--n 32] [--fine 256] [--variant V]   (n > 64 or --gmres: GMRES per part)
    python experiments/slip_layer.py nu [--grids 16 32 64 128] [--shifts 1] [--variant V] [--b 1] [--alpha 20.5]
    (BDF3_ROOM=K in the environment: active cells upstream a cell needs for the bdf3 variants, default 3)

Pure spin about the centre, Poisson 0.28; the circle at alpha' = 20.5 has the limit nu_v = 0.452144.
map (the circle): the adjoint split of experiments/contact_attribution.py (the reference: the same
variant on --fine cells) by region, then the slip cells downstream (x > 0) by physical distance to the
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

Variants (changes to the discrete law, monkeypatched here; rig/ is not edited; run from a copy of the
tree with the prototype's rig/contact/entry.py and cellwise.py, 9f2f2bd, to apply them to it):
  base          the law as rig/ has it;
  centroid      a row's last cell takes its rigid slip at the x-centroid of its load (its Voronoi share
                of the contact beyond the centre) instead of at its centre;
  centroidfull  the same, and its elastic slip moved there with the second difference of U;
  twopoint      the first two slip cells after a row's stick zone take the two-point difference
                (U_c - U_c-1)/h at x_c - h/2 (the BDF2 stencil there reaches into stick cells);
                the stick map is taken from the base solution and iterated to a fixed point;
  rimload       the contact in a rim cell goes to the nearest active cell of its own row, not to the
                nearest centre (which may be in the next row); rimtrail / rimlead: on one side only;
  trailing      a row's last TRAILING_CELLS cells: a 4-point stencil exact for (x_T - x)^1.5 as well;
  bdf3          cells with BDF3_ROOM active cells upstream: the third-order backward difference;
  bdf3slip      the same in the slip cells only (stick map iterated as in twopoint).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

import numpy as np
from scipy import ndimage

sys.path.insert(0, str(Path(__file__).resolve().parent))

import rig.contact.entry as entry  # noqa: E402
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
_base_weights = entry.transport_weights
_base_pressure = gridmod._cell_pressure
STICK_MAPS: dict = {}  # key(grid) -> (N,) stick map of the iterated variants (twopoint, bdf3slip)
TRAILING_CELLS = 3
BDF3_ROOM = int(os.environ.get("BDF3_ROOM", "3"))  # active cells upstream a cell needs for bdf3


def key(grid) -> tuple:
    """A grid's identity for STICK_MAPS (make_grid's cache is cleared between variants)."""
    return grid.shape, grid.b_over_a, grid.n, float(grid.x[0])


def last_cells(grid) -> np.ndarray:
    """(N,) True for each row's last active cell."""
    return ~grid.active.ravel()[grid.index + grid.ny]


def centroid_weights(grid, full=False):
    """Transport of main; a row's last cell's rigid slip at its load's x-centroid (full: its elastic
    slip too, moved there with the second difference of U)."""
    weights, x_slip = _base_weights(grid)
    x, y = grid.centres()
    last = last_cells(grid)
    h, b = grid.hx, grid.b_over_a
    # load of the last cell: its own cell plus the contact behind it up to x_T (row strip), p ~ sqrt
    s = (np.arange(64) + 0.5) / 64
    for c in np.flatnonzero(last):
        x_t = b * np.sqrt(max(1.0 - y[c] ** 2, 0.0))
        lo = x[c] - 0.5 * h
        xs = lo + (x_t - lo) * s
        p = gridmod.pressure(grid.shape, b, xs, np.full_like(xs, y[c]))
        if p.sum() > 0:
            shift = float((xs * p).sum() / p.sum()) - x[c]
            x_slip[c] += shift
            if full:
                weights[:, c] += shift / h**2 * np.array([1.0, -2.0, 1.0])
    return weights, x_slip


def trailing_weights(grid, cells=TRAILING_CELLS):
    """Transport of main with a fourth weight (k = 3); a row's last ``cells`` cells take dU/dx from the
    4-point stencil (c, c-1, c-2, c-3) exact for 1, x, x^2 and (x_T - x)^1.5 (the trailing edge's sqrt
    slip; x_T(y) the trailing edge of the row), instead of BDF2."""
    weights, x_slip = _base_weights(grid)
    weights = np.vstack([weights, np.zeros((1, weights.shape[1]))])
    x, y = grid.centres()
    h = grid.hx
    before = grid.gather((np.cumsum(grid.active[::-1], axis=0)[::-1] - 1)[None])[0]
    room = grid.gather((np.cumsum(grid.active, axis=0) - 1)[None])[0]  # active cells upstream
    k = np.arange(4) * h
    for c in np.flatnonzero((before < cells) & (room >= 3)):
        x_t = grid.b_over_a * np.sqrt(max(1.0 - y[c] ** 2, 0.0))
        d = x_t - (x[c] - k)
        if d[0] <= 0.0:
            continue
        a = np.stack([np.ones(4), -k, k**2, d**1.5])
        rhs = np.array([0.0, 1.0, 0.0, -1.5 * np.sqrt(d[0])])
        weights[:, c] = np.linalg.solve(a, rhs)
    return weights, x_slip


def bdf3_weights(grid, slip_only=False):
    """Transport of main with a fourth weight (k = 3); cells with BDF3_ROOM (>= 3) active cells upstream
    take the third-order backward difference (11 U_c - 18 U_c-1 + 9 U_c-2 - 2 U_c-3)/(6 h), all of them
    or (slip_only) the slip cells of the stick map in STICK_MAPS."""
    weights, x_slip = _base_weights(grid)
    weights = np.vstack([weights, np.zeros((1, weights.shape[1]))])
    room = grid.gather((np.cumsum(grid.active, axis=0) - 1)[None])[0]
    chosen = room >= BDF3_ROOM
    if slip_only:
        stick = STICK_MAPS.get(key(grid))
        chosen &= np.zeros_like(chosen) if stick is None else ~stick
    weights[:, chosen] = np.array([11.0, -18.0, 9.0, -2.0])[:, None] / (6.0 * grid.hx)
    return weights, x_slip


def twopoint_weights(grid):
    """Transport of main; the first two slip cells after a row's stick zone: two-point difference."""
    weights, x_slip = _base_weights(grid)
    stick = STICK_MAPS.get(key(grid))
    if stick is None:
        return weights, x_slip
    full = grid.scatter(stick.astype(float)[None, :])[0] > 0.5
    up1 = np.roll(full, 1, axis=0)
    up2 = np.roll(full, 2, axis=0)
    first_slip = grid.gather((~full & up1 & grid.active)[None])[0]
    second_slip = grid.gather((~full & ~up1 & up2 & grid.active)[None])[0]
    chosen = (first_slip | second_slip) & ~entry.entering(grid)
    weights[:, chosen] = np.array([1.0, -1.0, 0.0])[:, None] / grid.hx
    x_slip[chosen] -= 0.5 * grid.hx
    return weights, x_slip


def rimload_pressure(shape, b, x, y, hx, hy, active, side=0):
    """As main, but the contact in a rim cell goes to the nearest active cell of its own row (not to the
    nearest centre, which may be in the next row); side > 0: only on the trailing side (x > 0), < 0:
    only on the leading side."""
    p = _base_pressure(shape, b, x, y, hx, hy, active)
    if side:
        keep = p.copy()
    interior = np.logical_and.reduce([gridmod.pressure(shape, b, x[:, None] + sx * hx / 2, y[None, :] + sy * hy / 2)
                                      > gridmod._INSIDE for sx in (-1, 1) for sy in (-1, 1)])
    m = 64
    s = (np.arange(m) + 0.5) / m - 0.5
    out = np.where(interior, p, 0.0)
    for j in range(y.size):
        cols = np.flatnonzero(active[:, j])
        if cols.size == 0:
            continue
        ys = y[j] + hy * s
        for i in range(x.size):
            if interior[i, j]:
                continue
            xs = x[i] + hx * s
            load = gridmod.pressure(shape, b, xs[:, None], ys[None, :]).mean()
            if load == 0.0:
                continue
            target = i if active[i, j] else cols[np.argmin(np.abs(cols - i))]
            out[target, j] += load
    if side:  # main's loads on the other side; the Voronoi shares that crossed x = 0 are none (rim cells only)
        other = (x[:, None] > 0) != (side > 0)
        out = np.where(other, keep, out)
    return out


def use(variant: str) -> None:
    weights = {"centroid": centroid_weights, "twopoint": twopoint_weights, "trailing": trailing_weights,
               "bdf3": bdf3_weights, "bdf3slip": lambda grid: bdf3_weights(grid, slip_only=True),
               "centroidfull": lambda grid: centroid_weights(grid, full=True)}.get(variant, _base_weights)
    kinematic.transport_weights = weights
    # the first cells' local correction (rig.contact.entry) takes three weights: a cell it reaches that
    # has a fourth (bdf3 with BDF3_ROOM <= 6 under the prototype) loses that one there
    entry.transport_weights = lambda grid: (lambda w, xs: (w[:3], xs))(*weights(grid))
    entry.entry_profile.cache_clear()
    pressures = {"rimload": rimload_pressure,
                 "rimtrail": lambda *a: rimload_pressure(*a, side=1), "rimlead": lambda *a: rimload_pressure(*a, side=-1)}
    gridmod._cell_pressure = pressures.get(variant, _base_pressure)
    gridmod.make_grid.cache_clear()


def solve(grid, variant: str):
    """The kinematic solution on a grid; twopoint and bdf3slip iterate their stick map to a fixed point."""
    iterated = variant in ("twopoint", "bdf3slip")
    use("base" if iterated else variant)
    solution = kinematic.solve_grid(grid, POISSON, CREEPAGE, EFFECTS)
    if not iterated:
        return solution
    use(variant)
    for _ in range(10):
        STICK_MAPS[key(grid)] = solution.stick
        entry.entry_profile.cache_clear()
        solution = kinematic.solve_grid(grid, POISSON, CREEPAGE, EFFECTS)
        if np.array_equal(solution.stick, STICK_MAPS[key(grid)]):
            break
    return solution


def values(n: int, shift: float, variant: str) -> tuple[float, float]:
    """(nu_v, nu_0) on the grid of size n moved by ``shift`` cells."""
    use(variant)
    grid = gridmod.make_grid("ellipse", B_OVER_A, n, shift)
    solution = solve(grid, variant)
    x, y = grid.centres()
    result = coefficients(x, y, solution.q, grid.gather(grid.p), CREEPAGE)
    return float(result["nu_v"]), float(result["nu_0"])


def sequence(args) -> None:
    shifts = [-0.5 + k / args.shifts for k in range(args.shifts)] if args.shifts > 1 else [0.0]
    rows = []
    for n in args.grids:
        v, v0 = np.mean([values(n, s, args.variant) for s in shifts], axis=0)
        rows.append(v)
        error = f" error {v - LIMIT:+.3e}" if (B_OVER_A, ALPHA) == (1.0, 20.5) else ""
        print(f"{args.variant:9s} b/a {B_OVER_A:g} alpha' {ALPHA:g} n {n:4d} shifts {len(shifts)}: nu_v {v:.7f}{error}"
              f" nu_0 {v0:.7f}", flush=True)
    d = np.diff(rows)
    orders = [np.log2(d[k] / d[k + 1]) if d[k] * d[k + 1] > 0 else np.nan for k in range(d.size - 1)]
    if orders:
        print(f"{args.variant:9s} nu_v orders from differences: " + " ".join(f"{o:.2f}" for o in orders))


def attribution(args) -> None:
    use(args.variant)
    grid = gridmod.make_grid("ellipse", B_OVER_A, args.n)
    solution = solve(grid, args.variant)
    fine = gridmod.make_grid("ellipse", B_OVER_A, args.fine)
    fine_solution = solve(fine, args.variant)  # the reference: the same variant on the fine grid
    q_fine = fine_solution.q
    use(args.variant)
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
    print(f"{args.variant}: nu_v(n = {args.n}) {nu:.6f}, fine (n = {args.fine}) {nu_ref:.6f}: difference "
          f"{nu - nu_ref:+.3e}, adjoint {estimate:+.3e}")

    truth = None
    if args.variant == "base":  # the fine solution's slip and displacement, for the truncation's split
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
    parser.add_argument("--variant", default="base", choices=("base", "centroid", "centroidfull", "twopoint", "rimload", "rimtrail", "rimlead", "trailing", "bdf3", "bdf3slip"))
    args = parser.parse_args()
    global B_OVER_A, ALPHA, CREEPAGE
    B_OVER_A, ALPHA = args.b, args.alpha
    CREEPAGE = Creepage.from_rolling_point(ALPHA, 0.0, 0.0, POISSON)
    (attribution if args.study == "map" else sequence)(args)


if __name__ == "__main__":
    main()
