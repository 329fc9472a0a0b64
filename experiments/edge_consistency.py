"""The kinematic model's slip operator against a closed form, and what the leading edge's share of
its error does to nu_v (docs/contact-convergence.md, "Sixth study: the operator against Johnson's
closed form").

    python experiments/edge_consistency.py operator [--grids 16 32 64 128 256]
    python experiments/edge_consistency.py calibrated [--cells 3] [--grids 16 24 32 48 64 128] [--b 1] [--alpha 20.5]
    python experiments/edge_consistency.py stencil [--cells 0] [--grids 16 24 32 48 64 128]

operator: the circle (b/a = 1), Poisson 0.28. The traction t = (p, 0) and (0, p) with the Hertz shape
p = p0 sqrt(1 - r^2) has a displacement that is a quadratic in x and y inside the contact (Johnson's
closed form, rig.contact.hertz.hertz_traction_slip). The model's elastic slip dU/dx
(rig.contact.models.kinematic: the FFT influence product, the entry profile and the transport weights
together) is compared with the exact derivative at the points the transport takes it
(Discretisation.x_slip): in the interior (r < 0.5), and cell by cell from each row's leading edge (rows |y| < 0.7).

calibrated: nu_v and nu_0 of pure spin when the first ``--cells`` slip cells of each row get a local
correction, -e_k t_first / p_first per traction component, that makes the operator exact on the two
Hertz-shaped fields above (e_k: the slip error of cell k of the row under them). Monkeypatched here (rig/
is not edited); the circle only (the closed form is the circle's).

stencil: the same idea one degree higher (Galin: a Hertz-weighted linear traction p {1, x, y} e_b has a
quadratic slip inside): each cell's slip gets a correction from its own traction and that of its upstream
and its cross-row neighbour (towards y = 0), solved per cell to be exact on the six fields, whose exact
slips are quadratics fitted on the interior of an n = 128 grid; every cell (--cells 0) or the first and
last --cells cells of each row. Circle, pure spin.
"""

from __future__ import annotations

import argparse

import numpy as np
import scipy.sparse as sparse

import rig.contact.entry as entry
import rig.contact.models.kinematic as kinematic
from rig.contact.effects import ContactEffects
from rig.contact.grid import make_grid
from rig.contact.hertz import hertz_traction_slip
from rig.contact.influence import influence_operator
from rig.contact.solve import solve
from rig.errors import ConvergenceError

POISSON = 0.28
ROWS_NEAR_AXIS = 0.7  # |y| [a] of the rows whose leading-edge cells are reported
INTERIOR = 0.5  # r [a] of the cells called interior


def slip_under(grid, law, density, direction):
    """The law's elastic slip (2, N) [p0/G] under the traction p density e_direction (density (N,) [1])."""
    t = np.zeros((2, grid.index.size))
    t[direction] = grid.gather(grid.p) * density
    return law.apply(t)[1]


def operator_errors(grid, disc, poisson, component):
    """The model's elastic slip minus the exact one (2, N) for the Hertz-shaped traction along ``component``."""
    _, y = grid.centres()
    return slip_under(grid, disc.law, 1.0, component) - hertz_traction_slip(disc.x_slip, y, poisson, component)


def cells_from_edge(grid, k):
    """Active-cell indices (E,) of the k-th cell of each row from its leading edge (-1 where the row is shorter)."""
    position = np.full(grid.p.size, -1)
    position[grid.index] = np.arange(grid.index.size)
    return position[grid.index[np.flatnonzero(entry.entering(grid))] + k * grid.ny]


def operator_study(grids) -> None:
    print("Hertz-shaped traction (p, 0) on the circle: the model's dU_x/dx minus the exact one [p0/G]")
    print("n | interior max | mean error of cell k = 0 ... 5 from the leading edge (rows |y| < 0.7) | per-row sum of k = 0 ... 7, x h [p0 a/G]")
    for n in grids:
        grid = make_grid("ellipse", 1.0, n)
        disc = kinematic.Discretisation(grid, influence_operator(grid, POISSON), ContactEffects())
        error = operator_errors(grid, disc, POISSON, 0)[0]
        x, y = grid.centres()
        interior = np.abs(error[np.hypot(x, y) < INTERIOR]).max()
        first = cells_from_edge(grid, 0)
        rows = np.abs(y[first]) < ROWS_NEAR_AXIS
        per_cell = np.array([error[cells_from_edge(grid, k)[rows]] for k in range(8)])
        print(f"{n:4d} | {interior:.2e} | " + " ".join(f"{v:+.1e}" for v in per_cell[:6].mean(axis=1))
              + f" | {per_cell.sum(axis=0).mean() * grid.hx:+.2e}")


def with_correction(correction):
    """An entry_profile that adds correction(grid, poisson, disc) (2N, 2N) to the local slip, disc the
    uncorrected Discretisation of the grid (whose errors the correction is made from; any other the
    correction makes is uncorrected too)."""
    plain = entry.entry_profile

    def profile(grid, poisson):
        base = plain(grid, poisson)
        kinematic.entry_profile = plain  # every Discretisation the correction makes is uncorrected
        try:
            disc = kinematic.Discretisation(grid, influence_operator(grid, poisson), ContactEffects())
            local = correction(grid, poisson, disc)
        finally:
            kinematic.entry_profile = profile
        return entry.EntryProfile(base.cells, base.full, base.neighbour, base.neighbour_active, base.share,
                                  (base.local + local).tocsr())

    return profile


def first_cells_correction(cells: int):
    """The calibrated correction of the first ``cells`` cells of each row (module docstring)."""

    def correction(grid, poisson, disc):
        size = grid.index.size
        first = cells_from_edge(grid, 0)
        p_first = grid.gather(grid.p)[first]
        rows, columns, values = [], [], []
        for b in (0, 1):
            error = operator_errors(grid, disc, poisson, b)
            for k in range(cells):
                target = cells_from_edge(grid, k)
                ok = target >= 0
                for a in (0, 1):
                    rows.append(a * size + target[ok])
                    columns.append(b * size + first[ok])
                    values.append(-error[a, target[ok]] / p_first[ok])
        return sparse.csr_matrix((np.concatenate(values), (np.concatenate(rows), np.concatenate(columns))),
                                 shape=(2 * size, 2 * size))

    return correction


def field_slips(grid, law):
    """{(phi, b): elastic slip (2, N)} of the traction p phi e_b, phi in 1, x, y."""
    x, y = grid.centres()
    return {(name, b): slip_under(grid, law, phi, b) for name, phi in (("1", 1.0), ("x", x), ("y", y)) for b in (0, 1)}


def quadratics(x, y):
    return np.stack([np.ones_like(x), x, y, x * x, x * y, y * y], axis=-1)


def stencil_correction(rim_cells: int):
    """The linear-exact stencil correction (module docstring) of every cell, or of the first and last
    ``rim_cells`` of each row."""

    def correction(grid, poisson, disc):
        fine = make_grid("ellipse", 1.0, 128)
        fine_disc = kinematic.Discretisation(fine, influence_operator(fine, poisson), ContactEffects())
        _, y_fine = fine.centres()
        inside = fine_disc.x_slip**2 + y_fine**2 < INTERIOR**2
        basis = quadratics(fine_disc.x_slip[inside], y_fine[inside])
        exact = {key: [np.linalg.lstsq(basis, slip[a][inside], rcond=None)[0] for a in (0, 1)]
                 for key, slip in field_slips(fine, fine_disc.law).items()}
        x, y = grid.centres()
        here = quadratics(disc.x_slip, y)
        error = {key: [slip[a] - here @ exact[key][a] for a in (0, 1)]
                 for key, slip in field_slips(grid, disc.law).items()}
        p, size, ny = grid.gather(grid.p), grid.index.size, grid.ny
        position = np.full(grid.p.size, -1)
        position[grid.index] = np.arange(size)
        upstream = position[grid.index - ny]
        across = position[grid.index + np.where(y > 0, -1, 1)]
        chosen = np.ones(size, dtype=bool)
        if rim_cells:
            from_lead = np.cumsum(grid.active, axis=0)
            from_trail = np.cumsum(grid.active[::-1], axis=0)[::-1]
            chosen = (grid.active & ((from_lead <= rim_cells) | (from_trail <= rim_cells))).ravel()[grid.index]
        rows, columns, values = [], [], []
        for c in np.flatnonzero(chosen & (upstream >= 0) & (across >= 0)):
            cells = np.array([c, upstream[c], across[c]])
            moments = np.array([p[cells], p[cells] * x[cells], p[cells] * y[cells]])
            for a in (0, 1):
                for b in (0, 1):
                    weights = np.linalg.solve(moments, -np.array([error[name, b][a][c] for name in ("1", "x", "y")]))
                    rows += [a * size + c] * 3
                    columns += list(b * size + cells)
                    values += list(weights)
        return sparse.csr_matrix((values, (rows, columns)), shape=(2 * size, 2 * size))

    return correction


def corrected_study(args) -> None:
    if args.study == "stencil":
        kinematic.entry_profile = with_correction(stencil_correction(args.cells))
        print(f"pure spin, circle, alpha' = {args.alpha}, linear-exact stencil on "
              + (f"the first and last {args.cells} cells of each row" if args.cells else "every cell"))
    else:
        if args.cells:
            kinematic.entry_profile = with_correction(first_cells_correction(args.cells))
        print(f"pure spin, b/a = {args.b}, alpha' = {args.alpha}, first {args.cells} cells of each row calibrated")
    for n in args.grids:
        try:
            r = solve("kinematic", shape="ellipse", b_over_a=args.b, alpha=args.alpha, c_over_a=0.0, l_over_a=0.0,
                      poisson=POISSON, n=n)
        except ConvergenceError as error:
            print(f"n {n:4d}  {error}", flush=True)
            continue
        print(f"n {n:4d}  nu_v {r.nu_v:.7f}  nu_0 {r.nu_0:.7f}  Newton {r.info['newton_iterations']}", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("study", choices=("operator", "calibrated", "stencil"))
    parser.add_argument("--grids", type=int, nargs="+")
    parser.add_argument("--cells", type=int, help="cells of each row corrected (calibrated: default 3, 0: none; "
                        "stencil: default 0, every cell)")
    parser.add_argument("--b", type=float, default=1.0, help="calibrated: b/a (the correction is exact for 1 only)")
    parser.add_argument("--alpha", type=float, default=20.5)
    args = parser.parse_args()
    if args.study == "operator":
        operator_study(args.grids or [16, 32, 64, 128, 256])
    else:
        args.grids = args.grids or [16, 24, 32, 48, 64, 128]
        if args.cells is None:
            args.cells = 3 if args.study == "calibrated" else 0
        if args.study == "stencil":
            args.b = 1.0
        corrected_study(args)


if __name__ == "__main__":
    main()
