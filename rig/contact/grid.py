"""Rectangular cell grid over a contact area, with the Hertz pressure averaged over each cell.

Dimensionless: lengths in units of a (half length along the contact line y), pressure in units
of p0. The grid has n cells across 2a (y) and nx cells across 2b (x, rolling direction), plus
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
_SUBSAMPLES = 8  # sub-points per cell edge used to average the pressure over a cell


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


def cells_along_rolling(n: int, b_over_a: float) -> int:
    """Cells across 2b for n cells across 2a: n to 2n, square cells for 1 <= b/a <= 2.

    The upwind scheme's error scales with the cell size relative to the contact's extent in the
    rolling direction, so 2b never gets fewer cells than 2a; beyond b/a = 2 the cells stretch
    along x instead of multiplying.
    """
    return int(round(n * min(max(b_over_a, 1.0), 2.0)))


@dataclass(frozen=True, eq=False)
class Grid:
    """Cells of an (nx + 2 GHOST_COLUMNS) x ny rectangle; index [i, j], i along x, j along y.

    x, y: cell-centre coordinates [a]; hx, hy: cell sizes [a]; active: cells whose centre lies
    inside the contact (so that the cells' union has the contact's area to O(h^2)); p: p/p0
    averaged over the cell (0 outside the active cells); flattened order = C order of [i, j].
    """

    shape: str
    b_over_a: float
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
def make_grid(shape: str, b_over_a: float, n: int) -> Grid:
    """Grid with n cells across 2a over the contact of the given shape and b/a (cached)."""
    validate.choice("shape", shape, SHAPES)
    b = validate.number("b_over_a", b_over_a, 0.0, lo_open=True)
    n = validate.integer("n", n, 4, 4096)
    nx = cells_along_rolling(n, b)
    hx, hy = 2.0 * b / nx, 2.0 / n
    x = -b + hx * (np.arange(nx + 2 * GHOST_COLUMNS) - GHOST_COLUMNS + 0.5)
    y = -1.0 + hy * (np.arange(n) + 0.5)
    s = (np.arange(_SUBSAMPLES) + 0.5) / _SUBSAMPLES - 0.5
    xs = x[:, None, None, None] + hx * s[None, None, :, None]
    ys = y[None, :, None, None] + hy * s[None, None, None, :]
    inside = pressure(shape, b, x[:, None], y[None, :]) > 0.0
    inside[:GHOST_COLUMNS] = False
    inside[-GHOST_COLUMNS:] = False
    p = np.where(inside, pressure(shape, b, xs, ys).mean(axis=(2, 3)), 0.0)
    return Grid(shape, b, nx, n, hx, hy, x, y, p, inside)
