"""Where the kinematic model's discretisation error comes from: the grid studies of
docs/contact-convergence.md, one state at a time.

    python studies/contact_convergence.py sequence B ALPHA C L [--grids 16 24 32 48 64 128] [--shape line]
    python studies/contact_convergence.py shift SHAPE B ALPHA C L [--n 32]

B = b/a, ALPHA = alpha', (C, L) = rolling point (c/a, l/a); Poisson's ratio 0.28.
sequence: nu_v, nu_0 on a sequence of grids, with the observed orders of successive doublings.
shift: the cells moved along x by -1/2 ... 1/4 of a cell at one n: an answer that depends on where
the rim cuts the rows carries a first-order error.
The study that refined the cells along x (rolling) and along y separately needed grids that
rig.contact.grid does not build (a free number of cells along the rolling direction) and is not
kept here; docs/contact-convergence.md reports what it found.
"""

from __future__ import annotations

import argparse

import numpy as np

from rig.contact import grid as grid_module
from rig.contact.effects import ContactEffects
from rig.contact.integrate import coefficients
from rig.contact.kinematics import Creepage
from rig.contact.models import kinematic
from rig.contact.solve import solve

POISSON = 0.28


def _nu(b, alpha, c, l, n, shape="ellipse"):
    r = solve("kinematic", shape=shape, b_over_a=b, alpha=alpha, c_over_a=c, l_over_a=l, poisson=POISSON, n=n)
    return r.nu_v, r.nu_0, r.info["newton_iterations"], r.info["krylov_iterations"]


def sequence(args) -> None:
    values = {n: _nu(args.b, args.alpha, args.c, args.l, n, args.shape) for n in args.grids}
    for n, (v, o, newton, krylov) in values.items():
        print(f"n {n:4d}: nu_v {v:.6f} nu_0 {o:.6f}   ({newton} Newton, {krylov} products)")
    for k, name in enumerate(("nu_v", "nu_0")):
        orders = [np.log2((values[n][k] - values[2 * n][k]) / (values[2 * n][k] - values[4 * n][k]))
                  for n in args.grids if 4 * n in values]
        print(f"{name} observed orders (n, 2n, 4n from the smallest n): " + " ".join(f"{p:.2f}" for p in orders))


def shift(args) -> None:
    creepage = Creepage.from_rolling_point(args.alpha, args.c, args.l, POISSON)
    rows = []
    for offset in (-0.5, -0.25, 0.0, 0.25):
        grid = grid_module.make_grid(args.shape, args.b, args.n, offset)
        solution = kinematic.solve_grid(grid, POISSON, creepage, ContactEffects())
        x, y = grid.centres()
        result = coefficients(x, y, solution.q, grid.gather(grid.p), creepage)
        rows.append((result["nu_v"], result["nu_0"]))
        print(f"shift {offset:+.2f} cell: nu_v {rows[-1][0]:.6f} nu_0 {rows[-1][1]:.6f}")
    spread = np.ptp(np.array(rows), axis=0)
    print(f"spread: nu_v {spread[0]:.6f}, nu_0 {spread[1]:.6f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="study", required=True)
    for name in ("sequence", "shift"):
        p = sub.add_parser(name)
        if name == "shift":
            p.add_argument("shape", choices=grid_module.SHAPES)
        else:
            p.add_argument("--shape", choices=grid_module.SHAPES, default="ellipse")
        for field in ("b", "alpha", "c", "l"):
            p.add_argument(field, type=float)
        if name == "sequence":
            p.add_argument("--grids", type=int, nargs="+", default=[16, 24, 32, 48, 64, 128])
        else:
            p.add_argument("--n", type=int, default=32)
    args = parser.parse_args()
    {"sequence": sequence, "shift": shift}[args.study](args)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
