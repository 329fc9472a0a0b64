"""Stand B's steady campaign of Figs. 14-15 as a forward model: F_T, F_V, T_Mo at the paper's settings
for given mu, Psi (plastic slip, eq. 25) and k (pressure-dependent mu, rig.contact.effects.pressure_friction).

Used by experiments/fig14_study.py (docs/findings-fig14.md); never imported by rig.

Per operating point (load F_N, roller position l, rolling-point offset c; forward running, 24 rpm):
the stand's own Hertz line contact (b/a, p0 = F_N/(pi a b): rig.stands.disc_roller.parameters),
the coefficient the contact runs at, mu0 = mu (p0/p_ref)^-k (mu at p_ref = the stand parameter
friction_reference_pressure_Pa, 1 MPa), alpha' = 10 mu0 (b/a) R_c/R_r (eq. 21), the kinematic
model's coefficients (n = 12, poisson 0.5: the fig14 scene's contact), and the steady loads

    F_T = mu0 F_N nu_T,  F_V = mu0 F_N nu_v,  T0 = mu0 a F_N nu_0,  T_Mo = T0 - R_c F_T

(docs/stand-b.md: the dynamic run settles on exactly this quasi-static state; bearing friction off).

Cost: the coefficients are solved directly at the campaign's 56 rolling points (not read from
the scene's surrogate table, whose error, up to 0.006 in nu, is several times the instruments' u
at the heavy loads) on a grid of alpha' (cubic in log alpha') and at 5 nodes of Psi and of k
(cubic between them, as rig.fit does); the solves are kept in an .npz cache (keyed on the
solver's DISCRETISATION_REVISION), so only the first run pays for them (9 x 728 solves).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

from rig.contact.effects.pressure_friction import friction_at_peak_pressure
from rig.contact.solve import DISCRETISATION_REVISION, solve
from rig.stands.disc_roller import parameters as P

LOADS_N = (9.0, 21.0, 36.0, 144.0)  # dead weights ([Koziarski] section 3.2.1)
POSITIONS_M = (-0.020, -0.010, -0.0032, 0.0, 0.0032, 0.010, 0.020)  # roller position l (text)
OFFSETS_M = (0.0, -0.008)  # c = 0 (Fig. 14) and c/a = -2 (Fig. 15)
MODEL = dict(shape="line", poisson=0.5, n=12)  # the fig14/fig15 scenes' contact
ALPHA_GRID = np.geomspace(2.0, 300.0, 13)  # alpha' nodes (covers mu0 = 0.15 ... 2.8 at every load)
PSI_NODES = np.linspace(1.0, 3.0, 5)
K_NODES = np.linspace(0.0, 1.0, 5)
CHANNELS = ("F_T_N", "F_V_N", "T_Mo_N_m")


@dataclass(frozen=True)
class Campaign:
    """The operating points: arrays of one length (loads [N], l [m], c [m]), in the order of the grid."""

    force: np.ndarray
    l: np.ndarray
    c: np.ndarray

    @classmethod
    def paper(cls) -> Campaign:
        grid = np.array([(f, l, c) for c in OFFSETS_M for f in LOADS_N for l in POSITIONS_M])
        return cls(grid[:, 0], grid[:, 1], grid[:, 2])

    @property
    def size(self) -> int:
        return int(self.force.size)


class CoefficientTable:
    """nu_T, nu_v, nu_0 of the campaign's points on ALPHA_GRID for one effect setting, solved once."""

    def __init__(self, campaign: Campaign, params: P.StandBParameters, effects: dict[str, float]) -> None:
        a = params.half_length
        self.values = np.empty((campaign.size, ALPHA_GRID.size, 3))
        for i in range(campaign.size):
            b_over_a = params.b_over_a(float(campaign.force[i]))
            for j, alpha in enumerate(ALPHA_GRID):
                r = solve("kinematic", b_over_a=b_over_a, alpha=float(alpha), c_over_a=float(campaign.c[i] / a),
                          l_over_a=float(campaign.l[i] / a), **MODEL, **effects)
                self.values[i, j] = (r.nu_T, r.nu_v, r.nu_0)


class ForwardModel:
    """F_T, F_V, T_Mo (N, N, N m) of the campaign for (mu, Psi, k): mu at p_ref; Psi = 1 and k = 0 are off."""

    def __init__(self, campaign: Campaign, cache: Path | None = None, log=print) -> None:
        self.campaign = campaign
        self.params = P.resolve_parameters({})
        self.b_over_a = np.array([self.params.b_over_a(float(f)) for f in campaign.force])
        self.p0 = np.array([self.params.peak_pressure(float(f)) for f in campaign.force])
        self.node_tables = self._tables(cache, log)
        self._log_alpha = np.log(ALPHA_GRID)

    def _tables(self, cache: Path | None, log) -> dict[str, np.ndarray]:
        """{'psi': (5, N, A, 3), 'k': (5, N, A, 3)} coefficient tables at the effect nodes."""
        if cache is not None and cache.is_file():
            with np.load(cache) as stored:
                if (np.array_equal(stored["alpha"], ALPHA_GRID) and stored["psi"].shape[1] == self.campaign.size
                        and "revision" in stored and int(stored["revision"]) == DISCRETISATION_REVISION):
                    return {"psi": stored["psi"], "k": stored["k"]}
        t0 = time.perf_counter()
        plain = CoefficientTable(self.campaign, self.params, {}).values
        log(f"forward model: effect-free coefficients solved in {time.perf_counter() - t0:.0f} s")
        tables = {"psi": [plain], "k": [plain]}
        for name, keyword, nodes in (("psi", "psi", PSI_NODES), ("k", "pressure_exponent", K_NODES)):
            for value in nodes[1:]:
                tables[name].append(CoefficientTable(self.campaign, self.params, {keyword: float(value)}).values)
                log(f"forward model: {keyword} = {value:g} solved ({time.perf_counter() - t0:.0f} s)")
        out = {name: np.stack(v) for name, v in tables.items()}
        if cache is not None:
            cache.parent.mkdir(parents=True, exist_ok=True)
            partial = cache.with_name(cache.name + ".tmp.npz")
            np.savez(partial, alpha=ALPHA_GRID, revision=DISCRETISATION_REVISION, **out)
            partial.replace(cache)
        return out

    def friction(self, mu: float, k: float) -> np.ndarray:
        """mu0 per point [1]: the coefficient at the point's peak pressure (mu at p_ref)."""
        if k == 0.0:
            return np.full(self.campaign.size, mu)
        return np.array([friction_at_peak_pressure(mu, p0, self.params.friction_reference_pressure, k)
                         for p0 in self.p0])

    def alpha(self, mu0: np.ndarray) -> np.ndarray:
        """alpha' per point [1], eq. (21) with mu0."""
        p = self.params
        return 10.0 * mu0 * self.b_over_a * p.radius_c / p.roller_radius

    def coefficients(self, mu0: np.ndarray, psi: float, k: float) -> np.ndarray:
        """(N, 3) nu_T, nu_v, nu_0 at alpha'(mu0), Psi and k (one of them at its off value)."""
        if psi != 1.0 and k != 0.0:
            raise ValueError("the tables hold Psi and k one at a time (the other off)")
        table = self.node_tables["k"][0]
        if psi != 1.0:
            table = CubicSpline(PSI_NODES, self.node_tables["psi"], axis=0)(psi)
        elif k != 0.0:
            table = CubicSpline(K_NODES, self.node_tables["k"], axis=0)(k)
        x = np.log(self.alpha(mu0))
        if np.any(x < self._log_alpha[0]) or np.any(x > self._log_alpha[-1]):
            raise ValueError(f"alpha' {np.exp(x.min()):.3g} .. {np.exp(x.max()):.3g} outside the table "
                             f"{ALPHA_GRID[0]:g} .. {ALPHA_GRID[-1]:g}")
        every = CubicSpline(self._log_alpha, table, axis=1)(x)  # (N points, N alpha's, 3): keep the diagonal
        index = np.arange(self.campaign.size)
        return every[index, index]

    def loads(self, mu: float, psi: float = 1.0, k: float = 0.0) -> dict[str, np.ndarray]:
        """Steady F_T_N, F_V_N [N], T_Mo_N_m, M_C_N_m (= T0) [N m] and mu0, alpha' at every point."""
        mu0 = self.friction(mu, k)
        nu = self.coefficients(mu0, psi, k)
        f = mu0 * self.campaign.force
        a, r_c = self.params.half_length, self.params.radius_c
        f_t, f_v, t0 = f * nu[:, 0], f * nu[:, 1], f * a * nu[:, 2]
        return dict(F_T_N=f_t, F_V_N=f_v, M_C_N_m=t0, T_Mo_N_m=t0 - r_c * f_t, mu0=mu0, alpha_prime=self.alpha(mu0))

    def vector(self, mu: float, psi: float = 1.0, k: float = 0.0) -> np.ndarray:
        """F_T, F_V, T_Mo stacked (3N,): the quantities the instruments read."""
        loads = self.loads(mu, psi, k)
        return np.concatenate([loads[c] for c in CHANNELS])
