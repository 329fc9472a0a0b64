"""The forward model of a fit: predicted y at every data point for given parameter values.

Cost (docs/fit.md): the contact coefficients (nu_T, nu_v, nu_0) are evaluated at *nodes* of the
free effect parameters (33 equally spaced over each parameter's range, spacing 0.0625 in Psi)
* for stand data (alpha' = mu K depends on mu) from the stand's own cached surrogate tables
  (rig.contact.surrogate over l/a, c/a, log alpha'; one table per b/a and node, built once and
  then loaded from the cache), so a model evaluation costs milliseconds;
* for a digitised contact curve (alpha' fixed by the data) by direct solves at the points, once
  per node (memoised);
and interpolated between them by cubic Hermite pieces with central-difference slopes
(Catmull-Rom; C1), so that a value needs only the 4 nodes around it (4^d for d free effects).
The coefficients are not smooth in an effect's parameter (at fig10's states nu_v stays flat in
Psi up to a threshold and then bends: the grid's cells turn from slip to stick one at a time; at
b/a = 2, alpha' = 1.15, l/a = 0.5, n = 16 none sticks up to Psi = 1.5, one of 256 from 1.55, two
at 2), so the nodes must be close. Measured at stand-A points with alpha' 7-10 (R_x = 20 mm,
150/300 N, n = 16; benchmarks/bench_fit_coverage.py's scene), against the stand's table at the
exact Psi: with 17 nodes the interpolation errs by up to 5.9e-4 in F_y/F_N at Psi = 1.3 - one
point-to-point u, chi2 2.8 of the difference alone, which biased Psi high (+0.045 on average);
with 33 nodes by up to 1.1e-4 (chi2 0.15). Nodes are built only where the fit reaches them.
:meth:`ForwardModel.direct` evaluates the same prediction by direct solves at the exact
parameter values; the fit reports table-vs-direct at the optimum and polishes with it when that
difference is not small against the data's u.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence

import numpy as np

from rig.contact.solve import solve
from rig.fit.data import Observations
from rig.fit.parameters import PARAMETERS, FitParameter

NODES_PER_EFFECT = 33


class ForwardModel:
    """y(theta) at the points of ``obs``; ``free``: the parameters theta names, in order.

    memo: node values and laws shared between models of the same observations (model choice).
    """

    def __init__(self, obs: Observations, free: Sequence[FitParameter], fixed: Mapping[str, float],
                 memo: dict | None = None) -> None:
        self.obs = obs
        self.free = tuple(free)
        self.fixed = dict(fixed)
        self.effects_free = [p for p in self.free if p.is_effect]
        self.nodes = [np.linspace(p.lo, p.hi, NODES_PER_EFFECT) for p in self.effects_free]
        memo = {} if memo is None else memo
        self._memo: dict[tuple, np.ndarray] = memo.setdefault("nodes", {})
        self._laws: dict[tuple, object] = memo.setdefault("laws", {})
        self.evaluations = 0

    # ---------------------------------------------------------------- parameter bookkeeping

    def values(self, theta: Sequence[float]) -> dict[str, float]:
        """All parameter values: the fixed ones, overridden by theta."""
        out = dict(self.fixed)
        out.update({p.name: float(v) for p, v in zip(self.free, theta)})
        return out

    def _effects(self, values: Mapping[str, float]) -> dict[str, float]:
        """Effect keywords for solve(); an effect at its off value is left out (off costs nothing)."""
        effects = dict(self.obs.fixed_effects)
        effects.update({k: v for k, v in values.items() if k != "mu"})
        return {k: v for k, v in effects.items() if k not in PARAMETERS or v != PARAMETERS[k].off}

    # ---------------------------------------------------------------- predictions

    def predict(self, theta: Sequence[float], *, dl: float = 0.0) -> np.ndarray:
        """Predicted y at every point (table/node interpolation); dl shifts every l/a [units of a]."""
        self.evaluations += 1
        values = self.values(theta)
        mu = values.get("mu", np.nan)
        nu = self._interpolated(values, mu, dl)
        return self._quantity(nu, mu)

    def direct(self, theta: Sequence[float], at: np.ndarray | None = None) -> np.ndarray:
        """Predicted y by direct solves at the exact parameter values (slow; for the polish);
        at: indices of the points to evaluate (None: all)."""
        values = self.values(theta)
        mu = values.get("mu", np.nan)
        nu = self._direct_nu(self._effects(values), mu, 0.0, at)
        if at is None:
            return self._quantity(nu, mu)
        full = np.full((self.obs.size, 3), np.nan)
        full[at] = nu
        return self._quantity(full, mu)[at]

    def _quantity(self, nu: np.ndarray, mu: float) -> np.ndarray:
        if hasattr(self.obs, "combine"):  # data with their own readings of the coefficients (rig.fit.stand_b)
            return self.obs.combine(nu, mu)
        q = self.obs.quantity
        out = np.empty(q.size)
        for column, name in enumerate(("nu_T", "nu_v", "nu_0")):
            out[q == name] = nu[q == name, column]
        stand = q == "F_y_per_F_N"
        out[stand] = mu * nu[stand, 1]
        return out

    def _interpolated(self, values: Mapping[str, float], mu: float, dl: float) -> np.ndarray:
        if not self.effects_free:
            return self._node_values(self._effects(values), mu, dl)
        stencils = [hermite_stencil(nodes, values[p.name]) for p, nodes in zip(self.effects_free, self.nodes)]
        out = 0.0
        for combo in itertools.product(*(s.items() for s in stencils)):  # tensor product of the stencils
            node = dict(values)
            node.update({p.name: float(nodes[k]) for p, nodes, (k, _) in zip(self.effects_free, self.nodes, combo)})
            out = out + np.prod([w for _, w in combo]) * self._node_values(self._effects(node), mu, dl)
        return out

    def _node_values(self, effects: dict[str, float], mu: float, dl: float) -> np.ndarray:
        """(N, 3) nu_T, nu_v, nu_0 at the points for these effects (and mu when alpha' needs it)."""
        if hasattr(self.obs, "coefficients"):  # data with their own forward model (rig.fit.stand_b)
            return self.obs.coefficients(effects, mu, dl)
        if self.obs.stand is not None:
            return self._table_nu(effects, mu, dl)
        key = tuple(sorted(effects.items())) + (dl,)
        if key not in self._memo:
            self._memo[key] = self._direct_nu(effects, mu, dl)
        return self._memo[key]

    def _alpha(self, mu: float) -> np.ndarray:
        return np.where(np.isnan(self.obs.alpha), mu * self.obs.alpha_per_mu, self.obs.alpha)

    def _direct_nu(self, effects: dict[str, float], mu: float, dl: float, at: np.ndarray | None = None) -> np.ndarray:
        """Direct solves at every point (or the points ``at``); dl shifts the measured regressor
        (obs.regressor: l/a, c/a or alpha')."""
        o = self.obs
        shift = {"l_over_a": 0.0, "c_over_a": 0.0, "alpha": 0.0}
        shift[o.regressor] = dl
        alpha = self._alpha(mu) + shift["alpha"]
        points = np.arange(o.size) if at is None else np.asarray(at)
        out = np.empty((points.size, 3))
        for k, i in enumerate(points):
            r = solve(o.contact.model, shape=o.contact.shape, b_over_a=float(o.b_over_a[i]), alpha=float(alpha[i]),
                      c_over_a=float(o.c[i] + shift["c_over_a"]), l_over_a=float(o.l[i] + shift["l_over_a"]),
                      poisson=o.contact.poisson, n=o.contact.n, **effects)
            out[k] = (r.nu_T, r.nu_v, r.nu_0)
        return out

    def _table_nu(self, effects: dict[str, float], mu: float, dl: float) -> np.ndarray:
        """Stand A: the stand's own contact law per b/a (cached surrogate tables), at alpha' = mu K."""
        from rig.stands.base import ContactSpec
        from rig.stands.contact_law import make_contact_law
        from rig.stands.yoke import laws

        o = self.obs
        alpha = self._alpha(mu)
        out = np.empty((o.size, 3))
        spec0 = o.stand.contact_spec
        for b in np.unique(o.b_over_a):
            at = o.b_over_a == b
            geometry = o.geometry[int(np.flatnonzero(at)[0])]
            key = (float(b), tuple(sorted(effects.items())))
            if key not in self._laws:
                spec = ContactSpec(model=spec0.model, n=o.contact.n, poisson=spec0.poisson, effects=dict(effects),
                                   surrogate=True, table_points=spec0.table_points)
                domain = laws.domain(geometry, float(b), laws.MU_MIN)
                self._laws[key] = (make_contact_law(spec, laws.SHAPE, float(b), domain), domain)
            law, domain = self._laws[key]
            l = np.clip(o.l[at] + dl, *domain.l_over_a)
            c = np.clip(o.c[at], *domain.c_over_a)
            a = np.clip(alpha[at], *domain.alpha)
            nu_t, nu_v, nu_0 = law(l, c, a)
            out[at] = np.column_stack([nu_t, nu_v, nu_0])
        return out


def hermite_stencil(nodes: np.ndarray, value: float) -> dict[int, float]:
    """{node index: weight} of the cubic Hermite interpolation at ``value`` on equally spaced
    ``nodes``, with slopes by central differences (one-sided at the ends): Catmull-Rom, C1,
    exact for straight lines; the weights sum to 1."""
    k = nodes.size
    i = int(np.clip(np.searchsorted(nodes, value, side="right") - 1, 0, k - 2))
    t = (value - nodes[i]) / (nodes[1] - nodes[0])
    weights = {i: 2 * t**3 - 3 * t**2 + 1, i + 1: -2 * t**3 + 3 * t**2}
    for j, factor in ((i, t**3 - 2 * t**2 + t), (i + 1, t**3 - t**2)):  # the slope at node j, per node step
        lo, hi = max(j - 1, 0), min(j + 1, k - 1)
        for index, sign in ((hi, 1.0), (lo, -1.0)):
            weights[index] = weights.get(index, 0.0) + sign * factor / (hi - lo)
    return weights
