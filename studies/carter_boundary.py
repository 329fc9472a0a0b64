"""Where the kinematic model's O(h) error comes from, in one dimension: not the stick/slip boundary.

The plane Carter problem (two elastically similar cylinders rolling with longitudinal creepage,
plane strain) has a closed-form solution and the singular features of the 3-D problem the kinematic
model solves (rig.contact.models.kinematic): a sqrt leading edge, a stick zone behind it and a
stick/slip boundary at which the reserve r - |q| (stick side) and the slip (slip side) both go like
the square root of the distance. This script discretises it as the 3-D model does - uniform cells,
cell loads by the Voronoi rule, exact cell integrals of the influence at the centres, the
second-order upwind difference of the displacement, the leading edge's two sub-cell corrections
(rig.contact.entry), the Coulomb law per cell by semi-smooth Newton - and measures the force error
against the closed form (docs/contact-convergence.md, "Where the rest of the error is"):

    python studies/carter_boundary.py orders [--w 0.5] [--profiled K] [--tilted] [--hertz] [--grids 16 32 ...]
    python studies/carter_boundary.py where [--w 0.5] [--profiled K] [--grids 64 128 ...]

orders: nu on each grid as the mean over eight sub-cell shifts of the cells, its error, the observed
order of successive doublings, the largest error and the spread over the shifts. where: the error
with the Newton solve's stick/slip partition against the exact partition, and the exact partition's
error split (exactly, through the adjoint) by the stick cells whose truncation error causes it.

What it shows (w = 0.5): today's discretisation (--profiled 1) converges at order 1.8 -> 1.1 on
n = 32 ... 2048 - asymptotically first order. The partition the solve finds, and the cell straddling
the boundary, contribute O(h^2); imposing the exact partition does not raise the order. The O(h) part
comes from the stick cells 3 ... 100 cells behind the leading edge: their traction grows like
sqrt(x - x_L), which uniform cells represent with an error (h^2 d^-1.5 in the slip at distance d) that
the stick zone's response (the adjoint, ~ d^-1/2 at the leading edge, ~ 0 at the stick/slip boundary)
sums to O(h). Giving the first K cells of the row the sqrt density the first cell already has
(--profiled K) removes it: K = 8 gives order 1.9-2.0 at w = 0.5 (n up to 1024), all cells (-1)
1.9-2.0 at every w tried (0.2, 0.5, 0.8, 0.95), for the mean, the largest error and the shift spread. Moving each other
cell's force to the centroid of p over it (--tilted, a dipole) does not help. Every cell with the density
of p, sqrt(1 - x^2), right at both edges (--hertz): order 1.9-2.0 at w = 0.5 with 30 % smaller errors,
and the thin slip layer at the trailing edge (w = 0.1, 0.2 a) near exact (mean error -4.0e-5/-5.0e-6/
-3.0e-7 at n = 16/32/64; every cell sqrt-profiled: -2.7e-4/-1.0e-4/-2.9e-5).

Dimensionless (lengths in a, traction in mu p0, slip in units in which the relative surface
displacement of a traction q is U(x) = -(1/pi) int ln|x - x'| q(x') dx', so dU/dx = -H[q], H the
finite Hilbert transform (1/pi) p.v. int q(x')/(x - x') dx': a point force pushes the surface along
itself, decaying like a log). Material flows in +x (leading edge x = -1, docs/contact-model.md), the
rigid slip is the creepage w > 0, and the slip is s = w + dU/dx (the 3-D model's s_c = s_g + the
transported displacement). Carter's solution for 0 < w < 1 (derivation in the docs section above):

    stick on [-1, 2c - 1], c = 1 - w:  q = -(sqrt(1 - x^2) - c sqrt(1 - ((x - x0)/c)^2)), x0 = c - 1
    slip on [2c - 1, 1]:               q = -sqrt(1 - x^2),  s = sqrt((x - x0)^2 - c^2)
    nu = int q / int p = -(1 - c^2)
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass

import numpy as np

GHOST = 2  # empty cells upstream of the first active one (the 3-D grid's ghost columns)
BACKWARD_2 = np.array([1.5, -2.0, 0.5])  # dU/dx from the cell and two upstream, times h
SHIFTS = np.arange(-0.5, 0.5, 0.125)  # sub-cell shifts of the grid, in cells
SLIP_SCALE = 0.5


def exact(w: float) -> tuple[float, float]:
    """(nu, x_b): Carter's force coefficient and stick/slip boundary for creepage w (0 < w < 1)."""
    c = 1.0 - w
    return -(1.0 - c * c), 2.0 * c - 1.0


def exact_traction_integral(w: float, x: np.ndarray) -> np.ndarray:
    """int_{-1}^{x} q dx' of Carter's traction (x clipped to [-1, 1])."""
    c = 1.0 - w
    x0 = c - 1.0

    def ellipse(u):  # int_{-1}^{u} sqrt(1 - t^2) dt
        u = np.clip(u, -1.0, 1.0)
        return 0.5 * (u * np.sqrt(1.0 - u * u) + np.arcsin(u)) + np.pi / 4.0

    return -(ellipse(x) - c * c * ellipse((x - x0) / c))


def exact_load_integral(x: np.ndarray) -> np.ndarray:
    """int_0^x p dx' of p = sqrt(1 - x^2) (x clipped to [-1, 1])."""
    u = np.clip(x, -1.0, 1.0)
    return 0.5 * (u * np.sqrt(1.0 - u * u) + np.arcsin(u))


def load_moment_integral(x: np.ndarray) -> np.ndarray:
    """int x' p dx' of p = sqrt(1 - x^2), an antiderivative (x clipped to [-1, 1])."""
    return -((1.0 - np.clip(x, -1.0, 1.0) ** 2) ** 1.5) / 3.0


def log_integral(u: np.ndarray) -> np.ndarray:
    """Antiderivative of ln|u|: u ln|u| - u (0 at u = 0)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(u == 0.0, 0.0, u * np.log(np.abs(u)) - u)


def strip_influence(x: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """U at points x of a unit traction on [lo, hi]: -(1/pi) int_lo^hi ln|x - x'| dx' (broadcast)."""
    return -(log_integral(x - lo) - log_integral(x - hi)) / np.pi


@dataclass
class Grid1D:
    """Uniform cells of width h; the contact [-1, 1]; cells active where their centre is inside."""

    n: int
    shift: float

    def __post_init__(self):
        self.h = 2.0 / self.n
        k = np.arange(-GHOST - 1, self.n + GHOST + 1)
        x = -1.0 + self.h * (k + 0.5 + self.shift)
        inside = np.abs(x) < 1.0
        first = np.flatnonzero(inside)[0]
        last = np.flatnonzero(inside)[-1]
        self.x = x[first - GHOST:last + 1]  # two ghosts upstream, then the active cells
        self.m = last - first + 1  # active cells
        self.xa = self.x[GHOST:]
        # Voronoi loads: each active cell the part of [-1, 1] nearest to it, over h
        faces = np.concatenate([[-1.0], 0.5 * (self.xa[1:] + self.xa[:-1]), [1.0]])
        e = exact_load_integral(faces)
        self.p = np.diff(e) / self.h


def transport(g: Grid1D) -> np.ndarray:
    """T (m, m + GHOST): dU/dx at each active cell from U on [ghosts, active cells], as
    rig.contact.entry.transport_weights: the second-order backward difference; in the first cell the
    straddling step's outside part removed with the sqrt model; in the second the plain difference.
    (The rigid slip is a constant creepage: where it is taken does not matter.)"""
    m, h = g.m, g.h
    T = np.zeros((m, m + GHOST))
    for i in range(m):
        T[i, i:i + 3] = BACKWARD_2[::-1] / h  # columns: U two upstream, one upstream, own
    d = np.clip(-1.0 - (g.xa[0] - h), 0.0, h)
    r = d**1.5 / ((d + h) ** 1.5 - d**1.5)
    T[0, 0:3] = np.array([r, -(1.0 + r), 1.0]) / ((1.0 - r) * h)
    T[1, 1:4] = np.array([0.0, -1.0, 1.0]) / h
    return T


def sqrt_influence(x: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """U at points x of the traction sqrt(x' + 1) on [lo, hi] (lo >= -1), in closed form:
    -(1/pi) int_lo^hi ln|x - x'| sqrt(x' + 1) dx' = -(2/pi) [Q(v)] over v = sqrt(x' + 1), where Q is
    an antiderivative of v^2 ln|X - v^2|, X = x + 1."""
    X = x + 1.0

    def P(v, a):  # antiderivative of v^2 ln|v - a|
        with np.errstate(divide="ignore", invalid="ignore"):
            log = np.where(v == a, 0.0, np.log(np.abs(v - a)))
        return (v**3 - a**3) / 3.0 * log - v**3 / 9.0 - a * v**2 / 6.0 - a * a * v / 3.0

    def Q(v):
        a = np.sqrt(np.abs(X))
        with np.errstate(divide="ignore", invalid="ignore"):
            upstream = (v**3 / 3.0 * np.log(v * v + a * a)
                        - 2.0 / 3.0 * (v**3 / 3.0 - a * a * v + a**3 * np.arctan(v / np.where(a > 0, a, 1.0))))
        return np.where(X >= 0.0, P(v, a) + P(v, -a), upstream)

    return -(2.0 / np.pi) * (Q(np.sqrt(hi + 1.0)) - Q(np.sqrt(lo + 1.0)))


def hertz_influence(g: Grid1D, strips: int = 64) -> np.ndarray:
    """K (m + GHOST, m) with every active cell's force spread with the pressure's density sqrt(1 - x^2)
    over its share of the contact (the first cell from -1, the last to 1; rig.contact.entry's
    DENSITY = "hertz"), each cell in ``strips`` strips of uniform traction."""
    h = g.h
    lo = np.maximum(g.xa - h / 2, -1.0)
    hi = np.minimum(g.xa + h / 2, 1.0)
    lo[0], hi[-1] = -1.0, 1.0
    edges = lo[None, :] + (hi - lo)[None, :] * np.linspace(0.0, 1.0, strips + 1)[:, None]
    force = np.diff(exact_load_integral(edges), axis=0)
    force *= h / force.sum(axis=0)  # per unit traction of the cell
    return sum(strip_influence(g.x[:, None], edges[k][None, :], edges[k + 1][None, :])
               * (force[k] / (edges[k + 1] - edges[k]))[None, :] for k in range(strips))


def influence(g: Grid1D, profiled: int = 1, tilted: bool = False, hertz: bool = False) -> np.ndarray:
    """K (m + GHOST, m): U at every cell centre per unit traction of each active cell, uniform over
    the cell except:

    * the first ``profiled`` active cells (all if < 0) carry their force with the density ~ sqrt(x + 1) of
      a leading edge (the first cell over [-1, x_e + h/2], as rig.contact.entry, which profiles the
      first cell only);
    * tilted: every other cell's force sits at the centroid of p over the cell's share of the contact
      (the Voronoi rule of the loads), by moving the share (centroid - x_c)/h of it to the
      neighbouring cell (moment matching, as rig.contact.entry does for the first cell's profile);
    * hertz: every cell with the pressure's density (:func:`hertz_influence`; the others ignored).
    """
    if hertz:
        return hertz_influence(g)
    h = g.h
    K = strip_influence(g.x[:, None], (g.xa - h / 2)[None, :], (g.xa + h / 2)[None, :])
    if tilted:
        faces = np.concatenate([[-1.0], 0.5 * (g.xa[1:] + g.xa[:-1]), [1.0]])
        share = (np.diff(load_moment_integral(faces)) / np.diff(exact_load_integral(faces)) - g.xa) / h
        side = np.sign(share)
        nxt = strip_influence(g.x[:, None], (g.xa + side * h - h / 2)[None, :], (g.xa + side * h + h / 2)[None, :])
        K = (1.0 - np.abs(share))[None, :] * K + np.abs(share)[None, :] * nxt
    profiled = g.m if profiled < 0 else min(profiled, g.m)
    lo = np.maximum(g.xa[:profiled] - h / 2, -1.0)
    lo[0] = -1.0
    hi = g.xa[:profiled] + h / 2
    mass = (2.0 / 3.0) * ((hi + 1.0) ** 1.5 - (lo + 1.0) ** 1.5)  # int sqrt(x + 1) over the support
    K[:, :profiled] = sqrt_influence(g.x[:, None], lo[None, :], hi[None, :]) * (h / mass)[None, :]
    return K


@dataclass
class Model:
    """The discrete steady law s = w + A t on one grid, and its Coulomb solve."""

    g: Grid1D
    A: np.ndarray

    @classmethod
    def build(cls, n: int, shift: float, profiled: int = 1, tilted: bool = False, hertz: bool = False) -> "Model":
        g = Grid1D(n, shift)
        return cls(g, transport(g) @ influence(g, profiled, tilted, hertz))

    def solve(self, w: float, tol: float = 1e-12) -> np.ndarray:
        """Tractions t (m,) [mu p0] with the Coulomb law per cell: semi-smooth Newton on
        F(t) = t - clip(t - rho s(t), -r, r), with backtracking on |F|."""
        A, r = self.A, self.g.p
        rho = SLIP_SCALE / np.abs(np.diag(A))
        t = -r.copy()  # full sliding
        for _ in range(200):
            f, inside = self._residual(t, w, rho)
            if np.abs(f).max() < tol:
                return t
            J = np.where(inside[:, None], rho[:, None] * A, np.eye(r.size))
            delta = np.linalg.solve(J, -f)
            size, length = np.linalg.norm(f), 1.0
            while np.linalg.norm(self._residual(t + length * delta, w, rho)[0]) >= (1 - 1e-4 * length) * size and length > 1e-6:
                length *= 0.5
            t = t + length * delta
        raise RuntimeError("Newton did not converge")

    def _residual(self, t, w, rho):
        s = w + self.A @ t
        z = t - rho * s
        inside = np.abs(z) <= self.g.p
        return t - np.clip(z, -self.g.p, self.g.p), inside

    def nu(self, t: np.ndarray) -> float:
        return float(t.sum() / self.g.p.sum())


def nu_on(n: int, shift: float, w: float, **kw) -> tuple[float, Model, np.ndarray]:
    model = Model.build(n, shift, **kw)
    t = model.solve(w)
    return model.nu(t), model, t


def variant(args) -> dict:
    """The discretisation options chosen on the command line (Model.build's keywords)."""
    return dict(profiled=args.profiled, tilted=args.tilted, hertz=args.hertz)


def orders(args) -> None:
    nu_exact, x_b = exact(args.w)
    print(f"w = {args.w}: exact nu = {nu_exact:.8f}, stick/slip boundary at x = {x_b:.4f}")
    errors = []
    for n in args.grids:
        values = np.array([nu_on(n, s, args.w, **variant(args))[0] for s in SHIFTS])
        e = values - nu_exact
        errors.append(e.mean())
        order = "" if len(errors) < 2 else f"  order {np.log2(abs(errors[-2] / errors[-1])):.2f}"
        print(f"n {n:5d}: error mean {e.mean():+.3e}  max|e| {np.abs(e).max():.3e}  spread {np.ptp(e):.3e}{order}")


def where(args) -> None:
    """The error of nu (means over the shifts) for: the Newton solve; the exact stick/slip partition
    imposed (cells stick where their centre lies upstream of x_b), slip cells at their bound; the
    same with the slip cells at the exact traction's cell means (differs in the cell straddling x_b
    only); and that last error split by where the stick equations' truncation error sits. The split is
    exact (linear): with the partition and the slip cells fixed, the error e of the stick cells'
    tractions solves A_SS e = -R_S, R = w + A q_exact the residual of the exact cell means, so the
    force error is -phi . R_S with phi = A_SS^-T 1 / load (the adjoint: how nu answers a slip error
    in each stick cell)."""
    nu_exact, x_b = exact(args.w)
    bands = ("cells 0-2", "3-9", "10-99", "last 10", "other")
    print(f"w = {args.w}: errors of nu, mean over {SHIFTS.size} shifts; exact partition with the slip cells at the "
          "bound / at the exact means; the latter split by the stick cell (counted from the leading edge, or "
          "the last 10 before the boundary) whose truncation error causes it")
    print("    n       solve   exact/bound  exact/means" + "".join(f"{b:>11s}" for b in bands))
    for n in args.grids:
        rows = []
        for shift in SHIFTS:
            nu, model, _ = nu_on(n, shift, args.w, **variant(args))
            g, A = model.g, model.A
            faces = np.concatenate([[-1.0], 0.5 * (g.xa[1:] + g.xa[:-1]), [1.0]])
            q_exact = np.diff(exact_traction_integral(args.w, faces)) / g.h
            stick, slip = g.xa < x_b, g.xa >= x_b
            A_ss = A[np.ix_(stick, stick)]
            fixed = []
            for slip_traction in (-g.p, q_exact):
                t = np.where(stick, 0.0, slip_traction)
                t[stick] = np.linalg.solve(A_ss, -args.w - A[np.ix_(stick, slip)] @ t[slip])
                fixed.append(model.nu(t) - nu_exact)
            R = (args.w + A @ q_exact)[stick]
            share = -np.linalg.solve(A_ss.T, np.ones(R.size)) / g.p.sum() * R
            k = np.arange(R.size)
            last = R.size - 1 - k < 10
            masks = [~last & (k < 3), ~last & (k >= 3) & (k < 10), ~last & (k >= 10) & (k < 100), last]
            masks.append(~np.logical_or.reduce(masks))
            rows.append([nu - nu_exact] + fixed + [share[m].sum() for m in masks])
        r = np.mean(rows, axis=0)
        print(f"{n:5d}  " + "".join(f"{v:+12.3e}" for v in r[:3]) + "".join(f"{v:+11.2e}" for v in r[3:]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    o = sub.add_parser("orders")
    o.add_argument("--w", type=float, default=0.5)
    o.add_argument("--grids", type=int, nargs="+", default=[16, 32, 64, 128, 256, 512])
    o.set_defaults(run=orders)
    wh = sub.add_parser("where")
    wh.add_argument("--w", type=float, default=0.5)
    wh.add_argument("--grids", type=int, nargs="+", default=[64, 128, 256, 512, 1024])
    wh.set_defaults(run=where)
    for p in (o, wh):
        p.add_argument("--profiled", type=int, default=1,
                       help="cells from the leading edge whose traction has the sqrt density (1: today's 3-D model; -1: all)")
        p.add_argument("--hertz", action="store_true", help="every cell's force with the density of p (sqrt(1 - x^2))")
        p.add_argument("--tilted", action="store_true", help="the other cells' forces at the centroid of p over the cell")
    args = parser.parse_args()
    args.run(args)


if __name__ == "__main__":
    main()
