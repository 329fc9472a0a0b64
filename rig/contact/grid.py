"""Rectangular cell grid over a contact area, with the Hertz pressure averaged over each cell.

Dimensionless: lengths in units of a (half length along the contact line y), pressure in units
of p0. The grid has ny cells across 2a (y; n, more for narrow contacts: :func:`rows_across`) and nx
cells across 2b (x, rolling direction; :func:`cells_along_rolling`), plus
``GHOST_COLUMNS`` empty columns on each side of the contact, where the material that is about
to enter it (from x < -b, or from x > b when the rolling reverses) carries the displacement of
the field outside.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from rig import validate

SHAPES = ("ellipse", "line")
GHOST_COLUMNS = 2
_SUBSAMPLES = 8  # sub-cells per cell edge used to average the pressure over a cell
_RIM_SUBSAMPLES = 32  # the same for the cells the contact's rim cuts
# b/a below which a narrow contact gets more rows than n (up to 2n at half of it): :func:`rows_across`
NARROW_B_OVER_A = 0.15
# b/a above which a wide contact gets more rows than n (up to WIDE_ROWS n at 1.5 times it): :func:`rows_across`
WIDE_B_OVER_A = 20.0 / 3.0
WIDE_ROWS = 1.5
# largest cell aspect ratio hx/hy of a wide contact's grid: :func:`cells_along_rolling`
MAX_ASPECT = 2.5
_INSIDE = 1e-6  # p/p0 above which a cell's corner is inside (a corner on the rim, up to rounding, is not)


def pressure(shape: str, b_over_a: float, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Normal pressure p/p0 at points (x, y) [units of a].

    "ellipse": Hertz point contact, p = p0 sqrt(1 - (x/b)^2 - (y/a)^2).
    "line": finite line contact of length 2a, semi-elliptic across: p = p0 sqrt(1 - (x/b)^2), |y| <= a.
    """
    if shape == "ellipse":
        r2 = (x / b_over_a) ** 2 + y**2
    else:
        r2 = np.where(np.abs(y) <= 1.0, (x / b_over_a) ** 2, np.inf)
    return np.sqrt(np.clip(1.0 - r2, 0.0, None))


def leading_edge(shape: str, b_over_a: float, y: np.ndarray) -> np.ndarray:
    """x where material enters the contact (x = -b sqrt(1 - y^2) or -b) [a]; NaN outside |y| < 1."""
    with np.errstate(invalid="ignore"):
        if shape == "ellipse":
            return np.where(np.abs(y) < 1.0, -b_over_a * np.sqrt(1.0 - y**2), np.nan)
        return np.where(np.abs(y) <= 1.0, -b_over_a, np.nan)


def load_factor(shape: str) -> float:
    """F_N / (a b p0) of the exact pressure field: 2 pi/3 (ellipse) or pi (line)."""
    return 2.0 * np.pi / 3.0 if shape == "ellipse" else np.pi


def rows_across(n: int, b_over_a: float) -> int:
    """Cells across 2a (rows, along y) for the grid of nominal size n: n, or n NARROW_B_OVER_A/(b/a)
    for a contact narrower than NARROW_B_OVER_A, at most 2n.

    In full sliding the traction's direction turns round the spin pole within a distance ~b of it,
    across the rows as well as along them; rows of height 2a/n >> b do not see that turn. At b/a =
    0.1, alpha' = 0.1, pure spin, n = 32, nu_v is 0.0020 off its converged value 0.02600 with 32 rows x 32
    columns and 0.0009 with 48 x 32; the rows, not the columns, carry that error (refining y alone at nx = 32:
    nu_v 0.02045 / 0.02404 / 0.02560 / 0.02616 at 16 / 32 / 64 / 128 rows; x alone 0.02522 / 0.02404
    / 0.02380 / 0.02375). docs/contact-model.md, "Grid".

    A wide contact, b/a > WIDE_B_OVER_A, gets n (b/a)/WIDE_B_OVER_A rows, at most WIDE_ROWS n (b/a = 10:
    1.5 n). Near full stick the lateral traction is singular along the long sides (|y| -> a), and the
    spin moment nu_0, carried by that traction times x up to b, converges slowly in the rows: at b/a =
    10, alpha' = 325, pure spin, with cells of aspect 2.5, nu_0 = 0.36211 / 0.36327 / 0.36410 / 0.36492
    with 32 / 48 (4 n columns) / 48 / 64 rows (6 n and 8 n columns) at n = 32, against a converged value
    of 0.3655 (this grid on n = 16 / 32 / 64 extrapolated at the observed order 2.3; 0.3663 at first
    order; docs/accuracy-contact-sweep.md).
    """
    narrow = min(2.0, max(1.0, NARROW_B_OVER_A / b_over_a))
    wide = min(WIDE_ROWS, max(1.0, b_over_a / WIDE_B_OVER_A))
    return int(round(n * max(narrow, wide)))


def cells_along_rolling(n: int, b_over_a: float) -> int:
    """Cells across 2b (columns, along x) for the grid of nominal size n: n to 2n, square cells for
    1 <= b/a <= 2, and for a wide contact at least enough that a cell is at most MAX_ASPECT times as
    long as it is high (b/a = 10: 6 n columns with 1.5 n rows).

    The upwind scheme's error scales with the cell size relative to the contact's extent in the
    rolling direction, so 2b never gets fewer cells than 2a; from b/a = 2 the cells stretch along x
    instead of multiplying, up to the aspect ratio MAX_ASPECT. Longer cells cost accuracy where the
    field turns within a distance ~a along x: round the spin pole in full sliding and at the
    lateral edges near full stick. At b/a = 10 with 2 n columns (aspect 5) nu_v at alpha' = 0.1, C =
    (0.5, 0.5) a moved by 0.003 between n = 16, 24, 32, 64 (0.07895 / 0.07362 / 0.07683 / 0.07537,
    converged 0.07575); with 4 n columns (aspect 2.5 with n rows) 0.07541 at n = 32, and nu_0 at
    alpha' = 325, pure spin, 0.36211 against 0.36002 (docs/accuracy-contact-sweep.md).
    """
    along = n * min(max(b_over_a, 1.0), 2.0)
    limited = b_over_a * rows_across(n, b_over_a) / MAX_ASPECT
    return int(round(max(along, limited)))


@dataclass(frozen=True, eq=False)
class Grid:
    """Cells of an (nx + 2 GHOST_COLUMNS) x ny rectangle; index [i, j], i along x, j along y.

    n: the nominal size it was made for (make_grid's n; ny = rows_across(n, b/a), nx =
    cells_along_rolling(n, b/a)).
    x, y: cell-centre coordinates [a]; hx, hy: cell sizes [a]; active: cells whose centre lies
    inside the contact (so that the cells' union has the contact's area to O(h^2)); p: p/p0
    averaged over the cell (0 outside the active cells); flattened order = C order of [i, j].
    """

    shape: str
    b_over_a: float
    n: int
    nx: int
    ny: int
    hx: float
    hy: float
    x: np.ndarray
    y: np.ndarray
    p: np.ndarray
    active: np.ndarray

    @property
    def full_shape(self) -> tuple[int, int]:
        return self.p.shape

    @property
    def cell_area(self) -> float:
        return self.hx * self.hy

    @cached_property
    def index(self) -> np.ndarray:
        """Flat indices (into the full rectangle) of the active cells (computed once: the solvers
        scatter and gather with them in every product)."""
        return np.flatnonzero(self.active.ravel())

    def centres(self) -> tuple[np.ndarray, np.ndarray]:
        """(x, y) of the active cells [a]."""
        xx, yy = np.meshgrid(self.x, self.y, indexing="ij")
        return xx[self.active], yy[self.active]

    def scatter(self, values: np.ndarray) -> np.ndarray:
        """Place per-active-cell values (..., N) into zero-filled full arrays (..., nxg, ny)."""
        out = np.zeros(values.shape[:-1] + (self.p.size,), dtype=values.dtype)
        out[..., self.index] = values
        return out.reshape(values.shape[:-1] + self.p.shape)

    def gather(self, full: np.ndarray) -> np.ndarray:
        """Inverse of :meth:`scatter`: the active cells of full arrays (..., nxg, ny) -> (..., N)."""
        return full.reshape(full.shape[:-2] + (-1,))[..., self.index]


@lru_cache(maxsize=64)
def make_grid(shape: str, b_over_a: float, n: int, shift: float = 0.0) -> Grid:
    """Grid of nominal size n over the contact of the given shape and b/a (cached): n cells across
    2a (more when the contact is narrow, :func:`rows_across`), n to 2n across 2b.

    shift: the cells moved along x by this fraction of a cell, -1/2 ... 1/2 (0: the outer faces
    of the cells at x = -b and b); the answers must not depend on it (tests)."""
    validate.choice("shape", shape, SHAPES)
    b = validate.number("b_over_a", b_over_a, 0.0, lo_open=True)
    n = validate.integer("n", n, 4, 4096)
    shift = validate.number("shift", shift, -0.5, 0.5)
    nx, ny = cells_along_rolling(n, b), rows_across(n, b)
    hx, hy = 2.0 * b / nx, 2.0 / ny
    x = -b + hx * (np.arange(nx + 2 * GHOST_COLUMNS) - GHOST_COLUMNS + 0.5 + shift)
    y = hy * (np.arange(ny) + 0.5 - 0.5 * ny)  # exactly antisymmetric: mirrored problems see mirrored cells
    inside = pressure(shape, b, x[:, None], y[None, :]) > 0.0
    inside[:GHOST_COLUMNS] = False
    inside[-GHOST_COLUMNS:] = False
    return Grid(shape, b, n, nx, ny, hx, hy, x, y, _cell_pressure(shape, b, x, y, hx, hy, inside), inside)


def _cell_pressure(shape, b, x, y, hx, hy, active) -> np.ndarray:
    """p/p0 of each active cell: the load of the part of the contact nearer to its centre than to
    any other active centre, over the cell area (0 elsewhere). Inside, that part is the cell; at
    the rim it also takes the contact within the inactive cells next to it, so the cells carry the
    whole load (dropping it, as a centre rule alone does, loses 0.1-0.6 % of F_N at the rim,
    O(h^1.5) and of either sign with n). Interior cells average 8 x 8 sub-cells, cells the rim
    reaches 32 x 32, each sub-cell with its exact mean across x (_mean_across): with midpoint samples
    the total load was off by up to 2e-4 at n = 8 (the sqrt edge, and p concave), now <= 1e-4 for the
    ellipse and exact for the line contact."""
    mean = _sub_points(shape, b, x[:, None], y[None, :], hx, hy, _SUBSAMPLES)[2].mean(axis=(2, 3))
    interior = np.logical_and.reduce([pressure(shape, b, x[:, None] + sx * hx / 2, y[None, :] + sy * hy / 2) > _INSIDE
                                      for sx in (-1, 1) for sy in (-1, 1)])
    p = np.where(interior, mean, 0.0)
    # the rim's cells: every cell the contact reaches into (its point nearest the centre is inside), not
    # only those whose 8 x 8 sub-points see load: a sliver thinner than a sub-point spacing lost its load
    near_x = np.clip(0.0, x[:, None] - hx / 2, x[:, None] + hx / 2)
    near_y = np.clip(0.0, y[None, :] - hy / 2, y[None, :] + hy / 2)
    i, j = np.nonzero(~interior & ((pressure(shape, b, near_x, near_y) > 0.0) | active))
    xs, ys, ps = _sub_points(shape, b, x[i], y[j], hx, hy, _RIM_SUBSAMPLES)
    loaded = ps > 0.0
    centres = np.column_stack([c[active] for c in np.meshgrid(x, y, indexing="ij")])
    # the two nearest centres; a sub-point as near to both (the lattice makes ties) goes half to each,
    # which keeps the loads as symmetric as the contact (negative spin is solved as the mirror image)
    from scipy.spatial import cKDTree  # here: scipy.spatial (and scipy.sparse) cost ~0.5 s to import

    distance, nearest = cKDTree(centres).query(np.column_stack([xs[loaded], ys[loaded]]), k=2)
    half = 0.5 * (distance[:, 1] - distance[:, 0] <= 1e-9 * (hx + hy))
    weights = ps[loaded] / _RIM_SUBSAMPLES**2
    for k, share in ((0, 1.0 - half), (1, half)):
        p[active] += np.bincount(nearest[:, k], weights=weights * share, minlength=centres.shape[0])
    return p


def _sub_points(shape, b, x, y, hx, hy, m):
    """(x, y, p/p0) of m x m sub-cells of the cells centred at (x, y) (broadcast; arrays (..., m, m)):
    their centres and the exact mean of p/p0 across each sub-cell's width at its centre line."""
    s = (np.arange(m) + 0.5) / m - 0.5
    xs, ys = np.broadcast_arrays(x[..., None, None] + hx * s[:, None], y[..., None, None] + hy * s[None, :])
    return xs, ys, _mean_across(shape, b, xs - 0.5 * hx / m, xs + 0.5 * hx / m, ys)


def _mean_across(shape, b, x0, x1, y):
    """Mean of p/p0 over [x0, x1] at y, exact: p = sqrt(c^2 - (x/b)^2) with c^2 = 1 - y^2 (ellipse) or
    1 for |y| <= 1 (line), whose primitive is b (u sqrt(c^2 - u^2) + c^2 asin(u/c))/2, u = x/b clipped
    to [-c, c]. The sqrt edge inside a sub-cell is what a midpoint sample gets wrong (O(h^1.5))."""
    c2 = np.clip(1.0 - y**2, 0.0, None) if shape == "ellipse" else np.where(np.abs(y) <= 1.0, 1.0, 0.0)
    c = np.sqrt(c2)
    safe = np.where(c > 0.0, c, 1.0)

    def primitive(x):
        u = np.clip(x / b, -c, c)
        return 0.5 * b * (u * np.sqrt(np.clip(c2 - u**2, 0.0, None)) + c2 * np.arcsin(np.clip(u / safe, -1.0, 1.0)))

    return (primitive(x1) - primitive(x0)) / (x1 - x0)
