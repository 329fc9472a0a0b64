"""Tensor-product cubic spline on a uniform grid, with first derivatives (used by the surrogate table).

Along each axis the interpolant is the **not-a-knot cubic spline** of the node values (C2,
fourth-order accurate, no end condition that forces a wrong curvature on a saturating curve;
an axis of 2 or 3 nodes gets the straight line or parabola through them).
Because 1-D spline interpolation is linear in the data, its node slopes are a fixed matrix D
times the node values; the tensor-product spline is then, cell by cell, the tensor-product cubic
Hermite polynomial of the node values and the slopes D_1, D_2, D_1 D_2, ... along every subset of
axes. We store those polynomials in the power basis of the local cell coordinate t in [0, 1]:
evaluation is a cell look-up (uniform axes: one division) and a 4 x 4 x ... contraction.

Pure numerics, no units: the caller says what the axes and the outputs are.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

# Power-basis coefficients (c0..c3) of the cubic Hermite polynomial from (f0, h f0', f1, h f1').
_HERMITE = np.array(
    [
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [-3.0, -2.0, 3.0, -1.0],
        [2.0, 1.0, -2.0, 1.0],
    ]
)
MIN_NODES = 2  # not-a-knot with 2 nodes is the straight line, with 3 the parabola through them


def slope_matrix(nodes: np.ndarray) -> np.ndarray:
    """D (n, n) with spline slopes at the nodes = D @ node values (not-a-knot cubic spline)."""
    from scipy.interpolate import CubicSpline  # here: scipy.interpolate costs ~0.4 s to import, a parent need not

    n = nodes.size
    return CubicSpline(nodes, np.eye(n), bc_type="not-a-knot").derivative()(nodes)


@dataclass(frozen=True, eq=False)
class TensorSpline:
    """Cubic spline over a uniform grid in d dimensions with m outputs.

    starts, steps: first node and spacing per axis; counts: nodes per axis; coefficients:
    shape (cells_1, ..., cells_d, m, 4, ..., 4), the power-basis coefficients of every cell.
    """

    starts: np.ndarray
    steps: np.ndarray
    counts: np.ndarray
    coefficients: np.ndarray

    @classmethod
    def fit(cls, axes: list[np.ndarray], values: np.ndarray) -> TensorSpline:
        """Spline through ``values`` (n_1, ..., n_d, m) on the uniform node vectors ``axes``."""
        coef = np.asarray(values, dtype=float)
        for k, nodes in enumerate(axes):
            h = float(nodes[1] - nodes[0])
            f = np.moveaxis(coef, k, 0)
            s = np.tensordot(slope_matrix(nodes), f, axes=(1, 0)) * h
            local = np.stack([f[:-1], s[:-1], f[1:], s[1:]], axis=-1)  # (cells, ..., 4)
            coef = np.moveaxis(local @ _HERMITE.T, 0, k)  # power coefficients c0..c3 along axis k
        d = len(axes)
        cells = coef.shape[:d]
        m = coef.shape[d]
        return cls(
            starts=np.array([float(a[0]) for a in axes]),
            steps=np.array([float(a[1] - a[0]) for a in axes]),
            counts=np.array([a.size for a in axes]),
            coefficients=np.ascontiguousarray(coef.reshape(int(np.prod(cells)), m, 4**d)),
        )

    @property
    def ndim(self) -> int:
        """Number of axes d."""
        return int(self.starts.size)

    def evaluate(self, points: np.ndarray) -> np.ndarray:
        """Values and all first-order mixed derivatives at points (d, N) inside the grid.

        Returns shape (N, m, 2**d), the last index in binary (axis 1 most significant): bit k
        set = differentiated once along axis k. For d = 3, [..., 0] is the value, [..., 4] the
        derivative along axis 1, [..., 5] the mixed derivative along axes 1 and 3. Points outside
        the grid are evaluated on the nearest edge cell's polynomial (the caller checks the domain).
        """
        d = self.ndim
        n = points.shape[1]
        u = (points - self.starts[:, None]) / self.steps[:, None]
        cell = np.clip(np.floor(u), 0, (self.counts - 2)[:, None]).astype(np.intp)
        t = u - cell
        t2 = t * t
        inv_h = (1.0 / self.steps)[:, None]
        basis = np.empty((d, n, 2, 4))  # [axis, point, derivative order, power]
        basis[:, :, 0, 0] = 1.0
        basis[:, :, 0, 1] = t
        basis[:, :, 0, 2] = t2
        basis[:, :, 0, 3] = t2 * t
        basis[:, :, 1, 0] = 0.0
        basis[:, :, 1, 1] = inv_h
        basis[:, :, 1, 2] = 2.0 * t * inv_h
        basis[:, :, 1, 3] = 3.0 * t2 * inv_h
        flat = cell[0]
        for k in range(1, d):
            flat = flat * (self.counts[k] - 1) + cell[k]
        block = self.coefficients[flat]  # (N, m, 4**d), axis 1 most significant
        m = block.shape[1]
        done = 1  # 2**(axes contracted so far); their derivative indices trail, last axis first
        for k in range(d - 1, -1, -1):
            # (N, m 4**k, 4, done) -> polynomial axis last -> contract with the basis (N, 4, 2)
            block = block.reshape(n, m * 4**k, 4, done).swapaxes(2, 3).reshape(n, m * 4**k * done, 4)
            block = block @ basis[k].swapaxes(1, 2)
            done *= 2
        # derivative indices are now ordered (axis d, ..., axis 1): reverse to (axis 1, ..., axis d)
        block = block.reshape((n, m) + (2,) * d).transpose((0, 1) + tuple(range(d + 1, 1, -1)))
        return block.reshape(n, m, done)

    def evaluate_one(self, point: tuple[float, ...]) -> np.ndarray:
        """As :meth:`evaluate` for one point given as d floats; returns (m, 2**d). Fast scalar path.

        Contracts the cell's coefficients one axis at a time (last axis first) with small matmuls.
        """
        flat, ts = self._locate(point)
        bases = np.array([((1.0, t, t * t, t * t * t), (0.0, ih, 2.0 * t * ih, 3.0 * t * t * ih))
                          for t, ih in zip(ts, self._inv_step)])  # (d, 2, 4)
        block = self.coefficients[flat]  # (m, 4**d), axis 1 most significant
        m = block.shape[0]
        done = 1  # 2**(axes already contracted)
        for k in range(len(point) - 1, -1, -1):
            # block: (m, 4**k, 4, done) -> contract the 4 with bases[k] (2, 4) -> (m, 4**k, 2, done)
            block = np.matmul(bases[k], block.reshape(m * 4**k, 4, done))
            done *= 2
        return block.reshape(m, done)

    def value_one(self, point: tuple[float, ...]) -> np.ndarray:
        """The values (m,) at one point given as d floats: :meth:`evaluate_one`'s first column without
        the derivatives, at half its cost (one small dot product per axis; the same polynomial summed
        in another order, so the two may differ in the last bit)."""
        flat, ts = self._locate(point)
        powers = np.array([(1.0, t, t * t, t * t * t) for t in ts])  # (d, 4)
        block = self.coefficients[flat]
        m = block.shape[0]
        for k in range(len(point) - 1, -1, -1):
            block = block.reshape(m * 4**k, 4).dot(powers[k])
        return block

    def _locate(self, point: tuple[float, ...]) -> tuple[int, list[float]]:
        """(flat index of the cell of ``point``, the local coordinate t in [0, 1] along each axis);
        outside the grid the nearest edge cell (t outside [0, 1])."""
        flat = 0
        ts = []
        for k, x in enumerate(point):
            u = (x - self._start[k]) * self._inv_step[k]
            i = min(max(int(u // 1.0), 0), self._last_cell[k])
            ts.append(u - i)
            flat = flat * (self._last_cell[k] + 1) + i
        return flat, ts

    def __post_init__(self) -> None:
        # plain-float copies for the scalar path (object is frozen: set through object.__setattr__)
        object.__setattr__(self, "_start", [float(s) for s in self.starts])
        object.__setattr__(self, "_inv_step", [1.0 / float(h) for h in self.steps])
        object.__setattr__(self, "_last_cell", [int(c) - 2 for c in self.counts])
