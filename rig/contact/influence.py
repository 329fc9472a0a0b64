"""Love/Cerruti surface displacements of tangential traction, eq. (6), integrated exactly per cell.

Relative tangential displacement u = u1 - u2 of the two surfaces under a traction q on body 1
(and -q on body 2), Kalker's combined modulus 2/G = 1/G1 + 1/G2 (Equations §1.4, table 1.8 #5-6):

    u_x = 1/(pi G) int [ ((1-nu)/R + nu X^2/R^3) q_x + nu X Y/R^3 q_y ] dS'
    u_y = 1/(pi G) int [ nu X Y/R^3 q_x + ((1-nu)/R + nu Y^2/R^3) q_y ] dS'

with X = x - x', Y = y - y', R = |(X, Y)|. Each source cell carries a uniform traction; the
integral over the cell is exact (corner sums of closed-form primitives), so neighbours and the
cell itself are treated alike and no point-force kernel appears (Equations §1.9 step 2).
Dimensionless: lengths in a, traction in mu p0, displacement in mu p0 a / G.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import fft

from rig.contact import cellwise
from rig.contact.grid import Grid


def _x_asinh_y_over_x(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """x * asinh(y/|x|), continuous (-> 0) at x = 0."""
    ax = np.abs(x)
    safe = np.where(ax > 0.0, ax, 1.0)
    return np.where(ax > 0.0, x * np.arcsinh(y / safe), 0.0)


def _corner_sum(prim, x1: np.ndarray, x2: np.ndarray, y1: np.ndarray, y2: np.ndarray) -> np.ndarray:
    """int_{x1}^{x2} int_{y1}^{y2} f dX dY from a primitive with d2F/dXdY = f."""
    return prim(x2, y2) - prim(x1, y2) - prim(x2, y1) + prim(x1, y1)


def cell_integrals(X: np.ndarray, Y: np.ndarray, hx: float, hy: float) -> tuple[np.ndarray, ...]:
    """Integrals of 1/R, X^2/R^3, Y^2/R^3, XY/R^3 over a source cell of size hx x hy.

    (X, Y) is the field point relative to the source-cell centre. Primitives (Equations §1.9):
    1/R: X asinh(Y/|X|) + Y asinh(X/|Y|); X^2/R^3: Y asinh(X/|Y|); Y^2/R^3: X asinh(Y/|X|); XY/R^3: -R.
    """
    x1, x2 = X - hx / 2, X + hx / 2
    y1, y2 = Y - hy / 2, Y + hy / 2
    i_xx = _corner_sum(lambda u, v: _x_asinh_y_over_x(v, u), x1, x2, y1, y2)
    i_yy = _corner_sum(lambda u, v: _x_asinh_y_over_x(u, v), x1, x2, y1, y2)
    i_xy = _corner_sum(lambda u, v: -np.hypot(u, v), x1, x2, y1, y2)
    return i_xx + i_yy, i_xx, i_yy, i_xy


def cell_kernels(X: np.ndarray, Y: np.ndarray, hx: float, hy: float, poisson: float) -> tuple[np.ndarray, ...]:
    """Influence (K_xx, K_xy, K_yy) of a unit uniform traction on one cell, eq. (6) with 1/pi."""
    i1, i_xx, i_yy, i_xy = cell_integrals(X, Y, hx, hy)
    nu = poisson
    return ((1 - nu) * i1 + nu * i_xx) / np.pi, nu * i_xy / np.pi, ((1 - nu) * i1 + nu * i_yy) / np.pi


def self_displacement(h: float, poisson: float) -> float:
    """Displacement at the centre of a square cell of side h under its own unit traction.

    = 2 h (2 - nu) asinh(1)/pi, eq. (19) in these units (Kalker's combined G).
    """
    return 2.0 * h * (2.0 - poisson) * np.arcsinh(1.0) / np.pi


@dataclass(frozen=True, eq=False)
class InfluenceOperator:
    """Displacements on the full grid rectangle from tractions on it, by FFT convolution.

    ``apply(q)`` takes q of shape (2, nxg, ny) and returns u of the same shape. ``self_term``
    and ``upstream_term`` are the (xx, yy) influences of a cell on itself and on the cell one
    step upstream (used to scale and precondition the solver).

    The products' transforms run one axis at a time, so that the padding's zero rows are never
    transformed, and on one thread: up to n = 128 a second thread cost more than it saved even with
    the second core idle (docs/contact-model.md, "Solver cost", fourth pass).
    """

    grid_shape: tuple[int, int]
    pad_shape: tuple[int, int]
    kernels_hat: np.ndarray  # (3, px, py//2+1): xx, xy, yy
    inverse_shape: tuple[int, int]  # periodic grid of the approximate inverse (about 1.25 x the grid)
    inverse_hat: np.ndarray  # (3, ix, iy//2+1): the 2x2 inverse of the kernels' symbol on it
    riesz_hat: np.ndarray  # (px, py//2+1): cell integral of 1/(2 pi R), symbol ~ 1/|k|
    self_term: np.ndarray  # (2,) xx, yy
    upstream_term: np.ndarray  # (2,) xx, yy
    poisson: float  # Poisson's ratio of the kernels [1]

    def _spectrum(self, field: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
        """rfft2 of field (2, nxg, ny) zero-padded to ``shape``, one axis at a time: the real transforms
        along the rows run over the grid's nxg rows only, not over the padding's zero rows."""
        rows = fft.rfft(field, n=shape[1], axis=2)
        return fft.fft(rows, n=shape[0], axis=1, overwrite_x=True)

    def _field(self, spectrum: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
        """irfft2 of spectrum on ``shape``, cut to the grid (2, nxg, ny): the rows' real transforms
        only over the grid's rows (overwrites spectrum)."""
        mx, my = self.grid_shape
        rows = fft.ifft(spectrum, axis=1, overwrite_x=True)[:, :mx]
        return fft.irfft(rows, n=shape[1], axis=2)[:, :, :my]

    def _convolve(self, field: np.ndarray, symbol: np.ndarray, shape: tuple[int, int]) -> np.ndarray:
        spectrum = self._spectrum(field, shape)
        cellwise.symbol_product(symbol, spectrum, spectrum)
        return self._field(spectrum, shape)

    def apply(self, q: np.ndarray) -> np.ndarray:
        """Displacement u (2, nxg, ny) [mu p0 a/G] of tractions q (2, nxg, ny) [mu p0]."""
        return self._convolve(q, self.kernels_hat, self.pad_shape)

    def apply_riesz(self, f: np.ndarray) -> np.ndarray:
        """(1/(2 pi)) int f(x')/|x - x'| dA' of a cell-wise constant field f (2, nxg, ny) [units a]."""
        spectrum = self._spectrum(f, self.pad_shape)
        spectrum *= self.riesz_hat
        return self._field(spectrum, self.pad_shape)

    def apply_inverse(self, u: np.ndarray) -> np.ndarray:
        """Circulant inverse of :meth:`apply` on a periodic grid a quarter larger than the grid: an
        approximate inverse used to precondition the solver. The inverse's kernel (symbol ~ |k|)
        decays like 1/r^3, so its periodic images a quarter grid away hardly matter, and the
        transforms cost less than half of the zero-padded ones (same Krylov counts, measured)."""
        return self._convolve(u, self.inverse_hat, self.inverse_shape)


def _circular_offsets(shape: tuple[int, int], hx: float, hy: float) -> tuple[np.ndarray, np.ndarray]:
    """(X, Y) [a] of the cells of a periodic grid of ``shape`` as offsets from cell (0, 0):
    0 .. p//2 and -(p - p//2 - 1) .. -1 cells along each axis."""
    offsets = [np.where(np.arange(p) < p // 2 + 1, np.arange(p), np.arange(p) - p) * h for p, h in zip(shape, (hx, hy))]
    return np.meshgrid(*offsets, indexing="ij")


def _kernel_symbols(shape: tuple[int, int], hx: float, hy: float, poisson: float) -> np.ndarray:
    """rfft2 (3, px, py//2+1) of the cell kernels (xx, xy, yy) on a periodic grid of ``shape``."""
    X, Y = _circular_offsets(shape, hx, hy)
    return fft.rfft2(np.stack(cell_kernels(X, Y, hx, hy, poisson)), axes=(1, 2), workers=-1)


def _even_fast_length(target: int) -> int:
    """The smallest even length >= target that scipy's FFT factors into small primes. Chosen when the
    products ran on two threads, where odd lengths split badly ((525, 256) took 3.4 ms a transform
    pair, (520, 256) 2.4 ms and (540, 256) 2.1 ms; b/a = 10, n = 128); kept because the
    preconditioner's periodic grid, and so the solver's path, depends on it."""
    length = fft.next_fast_len(target)
    while length % 2:
        length = fft.next_fast_len(length + 1)
    return length


@lru_cache(maxsize=32)
def _operator(mx: int, my: int, hx: float, hy: float, poisson: float) -> InfluenceOperator:
    pad = _even_fast_length(2 * mx), _even_fast_length(2 * my)  # zero padding: linear convolution
    kernels_hat = _kernel_symbols(pad, hx, hy, poisson)
    X, Y = _circular_offsets(pad, hx, hy)
    riesz_hat = fft.rfft2(cell_integrals(X, Y, hx, hy)[0] / (2.0 * np.pi), workers=-1)
    inverse_shape = _even_fast_length(-(-5 * mx // 4)), _even_fast_length(-(-5 * my // 4))
    kxx, kxy, kyy = _kernel_symbols(inverse_shape, hx, hy, poisson)
    det = kxx * kyy - kxy * kxy
    inverse_hat = np.stack([kyy / det, -kxy / det, kxx / det])
    k0 = cell_kernels(np.array(0.0), np.array(0.0), hx, hy, poisson)
    k1 = cell_kernels(np.array(-hx), np.array(0.0), hx, hy, poisson)
    return InfluenceOperator(
        (mx, my), pad, kernels_hat, inverse_shape, inverse_hat, riesz_hat, np.array([k0[0], k0[2]]),
        np.array([k1[0], k1[2]]), poisson,
    )


def influence_operator(grid: Grid, poisson: float) -> InfluenceOperator:
    """The (cached) FFT influence operator of a grid for Poisson's ratio ``poisson``."""
    mx, my = grid.full_shape
    return _operator(mx, my, grid.hx, grid.hy, float(poisson))
