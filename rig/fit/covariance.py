"""A covariance of N points held in O(N) memory: independent part, a few shared errors, a random walk.

    V = D + G G^T + B M B,    D = diag(d),  G (N, m) with m small,  M_ij = q min(t_i, t_j),  B = diag(b)

D: each point's own variance; G: shared errors of a few standard-normal sources (a calibration's
sensitivity and offset: G = [dy/dS, dy/ds0] Sigma^(1/2)); the random walk: a zero drifting since
t = 0 with variance rate q, read by point i at age t_i with loading b_i (rig.fit.common_errors).
N x N is never formed. Every shared error is a latent variable s = (z, eta): z the walk's level at
each distinct age (K of them), eta the m sources; with s's prior precision R^T R (R z the walk's
increments over their standard deviations, R eta = eta) and U = [B E, G] (E: point -> its age),

    r^T V^-1 r = min_s  |D^-1/2 (r - U s)|^2 + |R s|^2        (Woodbury's identity as least squares)

at s^ = P^-1 U^T D^-1 r with the capacitance P = R^T R + U^T D^-1 U: tridiagonal in z (the walk
is Markov) bordered by m rows, solved by a banded Cholesky and a Schur complement of size m, in
O(N + K m^2) time. :meth:`whiten` returns the stacked vector [D^-1/2 (r - U s^), R s^] (length
N + K + m), linear in r with squared norm r^T V^-1 r, so it serves as whitened residuals of a
least-squares fit exactly as L^-1 r does for V = L L^T.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import solveh_banded


@dataclass(frozen=True)
class RandomWalk:
    """A zero that walks from 0 at t = 0: cov = rate min(t_i, t_j) b_i b_j.

    rate: q [units of y^2 per s, after the loading]; ages: t_i [s] >= 0; loadings: b_i [1]."""

    rate: float
    ages: np.ndarray
    loadings: np.ndarray

    def variance(self) -> np.ndarray:
        return self.rate * self.ages * self.loadings**2

    def dense(self) -> np.ndarray:
        return self.rate * np.minimum.outer(self.ages, self.ages) * np.outer(self.loadings, self.loadings)


class StructuredCovariance:
    """V = diag(d) + G G^T + walk (module docstring); d > 0 [units of y^2]; G (N, m) or None; walk or None."""

    def __init__(self, d: np.ndarray, low_rank: np.ndarray | None = None, walk: RandomWalk | None = None) -> None:
        self.d = np.asarray(d, dtype=float)
        n = self.d.size
        self.g = np.zeros((n, 0)) if low_rank is None else np.asarray(low_rank, dtype=float).reshape(n, -1)
        self.walk = walk if walk is not None and walk.rate > 0 else None
        self._prepare()

    # ---------------------------------------------------------------- set-up, O(N)

    def _prepare(self) -> None:
        d, g = self.d, self.g
        m = g.shape[1]
        if self.walk is not None:
            ages = self.walk.ages
            moving = ages > 0  # a point read at age 0 sees no drift
            levels, group = np.unique(ages[moving], return_inverse=True)
            self.group = np.full(d.size, -1)
            self.group[moving] = group
            self.walk_b = np.where(moving, self.walk.loadings, 0.0)
            steps = np.diff(np.concatenate([[0.0], levels])) * self.walk.rate
            self.step_sd = np.sqrt(steps)
        else:
            levels = np.zeros(0)
            self.group = np.full(d.size, -1)
            self.walk_b = np.zeros(d.size)
            self.step_sd = np.zeros(0)
        k = levels.size
        self.k = k
        self.m = m
        if k:
            precision = 1.0 / self.step_sd**2  # R^T R of the walk: tridiagonal
            diag = precision.copy()
            diag[:-1] += precision[1:]
            off = -precision[1:]
            at = self.group >= 0
            diag += np.bincount(self.group[at], weights=self.walk_b[at] ** 2 / d[at], minlength=k)
            self.banded = np.vstack([np.concatenate([[0.0], off]), diag])  # upper form for solveh_banded
            border = np.zeros((k, m))
            for j in range(m):
                border[:, j] = np.bincount(self.group[at], weights=self.walk_b[at] * g[at, j] / d[at], minlength=k)
            self.border = border
            self.t_border = self._tri_solve(border) if m else np.zeros((k, 0))
        else:
            self.border = np.zeros((0, m))
            self.t_border = np.zeros((0, m))
        self.schur = np.eye(m) + (g / d[:, None]).T @ g - self.border.T @ self.t_border

    def _tri_solve(self, rhs: np.ndarray) -> np.ndarray:
        return solveh_banded(self.banded, rhs, check_finite=False)

    # ---------------------------------------------------------------- operations, O(N)

    def diagonal(self) -> np.ndarray:
        out = self.d + np.sum(self.g**2, axis=1)
        if self.walk is not None:
            out = out + self.walk.variance()
        return out

    def latent(self, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(z^, eta^) = P^-1 U^T D^-1 r for one vector r (N,) or several (N, p)."""
        r = np.asarray(r, dtype=float)
        scaled = r / (self.d if r.ndim == 1 else self.d[:, None])
        h_eta = self.g.T @ scaled
        if self.k:
            at = self.group >= 0
            wb = self.walk_b[at] if r.ndim == 1 else self.walk_b[at, None]
            h_z = _group_sum(self.group[at], wb * scaled[at], self.k)
            x = self._tri_solve(h_z)
            rhs = h_eta - self.border.T @ x
        else:
            x = np.zeros((0,) + r.shape[1:])
            rhs = h_eta
        eta = np.linalg.solve(self.schur, rhs) if self.m else np.zeros((0,) + r.shape[1:])
        z = x - self.t_border @ eta if self.k else x
        return z, eta

    def shared(self, z: np.ndarray, eta: np.ndarray) -> np.ndarray:
        """U s: the shared errors' sum at every point for latent values (z, eta)."""
        out = self.g @ eta
        if self.k:
            at = self.group >= 0
            wb = self.walk_b[at] if z.ndim == 1 else self.walk_b[at, None]
            out[at] += wb * z[self.group[at]]
        return out

    def solve(self, r: np.ndarray) -> np.ndarray:
        """V^-1 r (Woodbury: D^-1 (r - U s^))."""
        r = np.asarray(r, dtype=float)
        z, eta = self.latent(r)
        return (r - self.shared(z, eta)) / (self.d if r.ndim == 1 else self.d[:, None])

    def whiten(self, r: np.ndarray) -> np.ndarray:
        """[D^-1/2 (r - U s^), R s^]: linear in r, squared norm r^T V^-1 r (module docstring)."""
        r = np.asarray(r, dtype=float)
        z, eta = self.latent(r)
        sd = np.sqrt(self.d) if r.ndim == 1 else np.sqrt(self.d)[:, None]
        parts = [(r - self.shared(z, eta)) / sd]
        if self.k:
            step = self.step_sd if z.ndim == 1 else self.step_sd[:, None]
            parts.append(np.diff(np.concatenate([np.zeros((1,) + z.shape[1:]), z]), axis=0) / step)
        parts.append(eta)
        return np.concatenate(parts)

    def dense(self) -> np.ndarray:
        """The N x N matrix (for tests and small N only)."""
        out = np.diag(self.d) + self.g @ self.g.T
        if self.walk is not None:
            out = out + self.walk.dense()
        return out


def _group_sum(group: np.ndarray, values: np.ndarray, k: int) -> np.ndarray:
    if values.ndim == 1:
        return np.bincount(group, weights=values, minlength=k)
    return np.column_stack([np.bincount(group, weights=values[:, j], minlength=k) for j in range(values.shape[1])])
