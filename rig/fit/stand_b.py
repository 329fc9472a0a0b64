"""``rig fit`` on stand-B logs: F_T, F_V and T_Mo as the stand records them, fitted with mu and contact effects.

The paper draws Psi > 1 (plastic slip, [Koziarski] eq. 25) from stand B, and it is there that Psi
is observable: near the contact centre at c = 0 plastic slip turns part of the spin's lateral
force into stick (docs/findings-fig14.md). This module turns a stand-B run (``log.h5``, or its
``reduced.csv`` with the log beside it) into Observations for the fit engine (rig.fit.engine,
the same likelihood as stand A: generalised least squares with each instrument's one
calibration as a covariance common to its points, profile-likelihood intervals).

Per logged point (rig.stands.disc_roller.reduction.point_readings: calibrated means with u, in
the canonical forward frame; reverse points mirrored) three observations, one per instrument:

    F_T/F_N = mu nu_T,   F_V/F_N = mu nu_v       ([Koziarski] eqs. 27-28)
    T_Mo/(a F_N) = mu (nu_0 - (R_c/a) nu_T)        (T_Mo = T0 - R_c F_T, T0 = mu a F_N nu_0, eq. 26)

with (nu_T, nu_v, nu_0) of the scene's contact model at (l/a, c/a, alpha'), alpha' = mu K,
K = 10 (b/a) R_c/R_r (eq. 21, Hertz line contact), the disc-bearing friction taken as absent.
Forward model: direct solves of the contact model (rig.contact.solve, the scene's model, grid and
Poisson ratio) at each point on a fine grid in ln alpha' (step ALPHA_STEP, solved only where the
fit goes, memoised) and cubic Hermite between the nodes (rig.fit.forward.hermite_stencil), the
free effects at the engine's nodes. The stand's surrogate table is not used: its error can reach
a few u of the instruments (docs/findings-fig14.md).

Errors: u of each reading as the reduction states it (calibration covariance and the gate's own
scatter); the calibration's part is common to all points of an instrument (one calibration per
run) and enters as a covariance (:class:`InstrumentCalibrations`, the form of
rig.fit.common_errors per instrument). The roller position (u_l_setting) and the twist
(u_twist: c = e sin(sigma), eq. 36) are measured regressors: their errors reach y through
df/dl and df/dc (effective variance, rig.fit.engine); at c = 0 F_V is steep in c, so the twist
matters there. Not modelled: the dead weights' error (u_normal_force, a few 1e-4 relative) and
a pressure-dependent mu.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from rig.contact.solve import solve
from rig.errors import LogFormatError, ParameterError
from rig.fit.common_errors import CommonErrors
from rig.fit.covariance import StructuredCovariance
from rig.fit.data import ContactCondition, Observations
from rig.fit.forward import hermite_stencil

STAND = "disc_roller"
CHANNELS = ("F_T", "F_V", "T_Mo")
QUANTITY = {"F_T": "F_T_per_F_N", "F_V": "F_V_per_F_N", "T_Mo": "T_Mo_per_a_F_N"}
"""Observed quantity per instrument: F_T/F_N, F_V/F_N [1], T_Mo/(a F_N) [1]."""
ALPHA_STEP = 0.05  # node spacing of the forward model in ln alpha' [1]
LN_ALPHA = np.arange(math.log(1e-3), math.log(1e5) + ALPHA_STEP, ALPHA_STEP)
REGRESSOR_STEP = 1e-3  # finite-difference step of df/dl, df/dc [units of a]


class InstrumentCalibrations:
    """The covariance of the stacked y shared between points: each instrument's one calibration.

    blocks: (indices of the instrument's observations, CommonErrors of its calibration). The
    interface is rig.fit.common_errors.CommonErrors's (low_rank, variance, covariance, structured,
    with the sensitivity's part at the values y, the true y's estimate, or without it for y None):
    the blocks' low-rank factors side by side, so the fit keeps it in O(N) memory.
    """

    fixed = None  # no dense part: the engine takes the structured (O(N)) form
    walk = None  # no zero drift shared between the instruments' points

    def __init__(self, size: int, blocks: list[tuple[np.ndarray, CommonErrors]]) -> None:
        self.size = size
        self.blocks = blocks

    def low_rank(self, y: np.ndarray | None) -> np.ndarray | None:
        """G (N, m) with G G^T this covariance at the values y: each block's factor in its own rows and columns."""
        parts = []
        for index, errors in self.blocks:
            g = errors.low_rank(None if y is None else np.asarray(y, dtype=float)[index])
            if g is not None:
                parts.append((index, g))
        if not parts:
            return None
        out = np.zeros((self.size, sum(g.shape[1] for _, g in parts)))
        column = 0
        for index, g in parts:
            out[index, column:column + g.shape[1]] = g
            column += g.shape[1]
        return out

    def variance(self, y: np.ndarray | None) -> np.ndarray:
        """The diagonal of :meth:`covariance` in O(N)."""
        out = np.zeros(self.size)
        for index, errors in self.blocks:
            out[index] += errors.variance(None if y is None else np.asarray(y, dtype=float)[index])
        return out

    def covariance(self, y: np.ndarray | None) -> np.ndarray:
        """(N, N) covariance [1]; for small N and tests (the fit uses :meth:`structured`)."""
        out = np.zeros((self.size, self.size))
        for index, errors in self.blocks:
            part = errors.covariance(None if y is None else np.asarray(y, dtype=float)[index])
            out[np.ix_(index, index)] = part
        return out

    def structured(self, y: np.ndarray | None, independent: np.ndarray) -> StructuredCovariance:
        """diag(independent) + this covariance at y, in O(N) form."""
        return StructuredCovariance(independent, self.low_rank(y), None)


@dataclass(frozen=True, eq=False)
class StandBObservations(Observations):
    """Observations of a stand-B run (rig.fit.data.Observations plus what the forward model needs).

    weights: (N, 3) y = mu weights . (nu_T, nu_v, nu_0) per observation [1]; point: the log's
    point index of each observation; u_c: standard uncertainty of c/a [1] (the twist's).
    """

    weights: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    point: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    u_c: np.ndarray = field(default_factory=lambda: np.zeros(0))
    _memo: dict = field(default_factory=dict, repr=False)

    def combine(self, nu: np.ndarray, mu: float) -> np.ndarray:
        """y of every observation from (N, 3) coefficients at mu [1]."""
        return mu * np.einsum("ij,ij->i", self.weights, nu)

    def _solve(self, effects: tuple, i: int, l_shift: float, c_shift: float, node: int) -> np.ndarray:
        key = (effects, float(self.l[i] + l_shift), float(self.c[i] + c_shift), float(self.b_over_a[i]), node)
        found = self._memo.get(key)
        if found is None:
            contact = self.contact
            r = solve(contact.model, shape=contact.shape, b_over_a=key[3], alpha=float(math.exp(LN_ALPHA[node])),
                      c_over_a=key[2], l_over_a=key[1], poisson=contact.poisson, n=contact.n, **dict(effects))
            found = self._memo[key] = np.array([r.nu_T, r.nu_v, r.nu_0])
        return found

    def _at(self, effects: tuple, mu: float, l_shift: float, c_shift: float, nearest: bool = False) -> np.ndarray:
        """(N, 3) coefficients at alpha' = mu K by cubic Hermite in ln alpha' on LN_ALPHA (nearest:
        at the nearest node, for the regressors' slopes, whose own error matters to second order)."""
        out = np.empty((self.size, 3))
        for i in range(self.size):
            x = math.log(mu * float(self.alpha_per_mu[i]))
            if not LN_ALPHA[1] <= x <= LN_ALPHA[-2]:
                raise ParameterError("alpha'", math.exp(x), f"[{math.exp(LN_ALPHA[1]):.3g}, "
                                     f"{math.exp(LN_ALPHA[-2]):.3g}] (the stand-B forward model's range)")
            if nearest:
                out[i] = self._solve(effects, i, l_shift, c_shift, int(round((x - LN_ALPHA[0]) / ALPHA_STEP)))
                continue
            out[i] = sum(w * self._solve(effects, i, l_shift, c_shift, k)
                         for k, w in hermite_stencil(LN_ALPHA, x).items())
        return out

    def coefficients(self, effects: Mapping[str, float], mu: float, dl: float) -> np.ndarray:
        """(N, 3) nu_T, nu_v, nu_0 at the points for these effects and mu (rig.fit.forward's hook).

        dl != 0 (the engine's df/dl for the regressor variance, rig.fit.engine.regressor_variance):
        the coefficients are moved so that the y's slope is sqrt((df/dl)^2 + (df/dc u_c/u_l)^2) per
        point, so that (slope u_l)^2 = (df/dl u_l)^2 + (df/dc u_c)^2: the twist's error joins the
        roller position's (both independent).
        """
        key = tuple(sorted(effects.items()))
        nu = self._at(key, mu, 0.0, 0.0)
        if dl == 0.0:
            return nu
        h = REGRESSOR_STEP
        y = lambda n: self.combine(n, mu)  # noqa: E731
        here = y(self._at(key, mu, 0.0, 0.0, True))  # forward differences at the nearest node (shared solves)
        slope_l = (y(self._at(key, mu, h, 0.0, True)) - here) / h
        slope_c = (y(self._at(key, mu, 0.0, h, True)) - here) / h
        u_l = np.where(self.u_l > 0, self.u_l, 1.0)
        slope = np.sqrt(slope_l**2 + (slope_c * self.u_c / u_l) ** 2)
        norm = np.einsum("ij,ij->i", self.weights, self.weights)
        return nu + (dl * slope / (mu * norm))[:, None] * self.weights


def load_stand_b_run(path: str | Path, scene=None, *, n: int | None = None) -> StandBObservations:
    """Observations F_T/F_N, F_V/F_N, T_Mo/(a F_N) versus l/a from a stand-B run (module docstring).

    path: log.h5, or reduced.csv with log.h5 beside it (the readings come from the log);
    scene: a loaded scene (None: the log's own); n: contact grid (None: the scene's). A damaged
    point is left out and counted in ``notes``.
    """
    from rig.logbook import read_points
    from rig.logbook.reader import read_metadata
    from rig.scenes.load import parse_scene
    from rig.stands.disc_roller.instruments import record_from_fields
    from rig.stands.disc_roller.reduction import CALIBRATION_FIELDS, point_readings

    path = Path(path)
    log = path.with_name("log.h5") if path.suffix == ".csv" else path
    if not log.is_file():
        raise ParameterError("DATA", str(path), "a stand-B log.h5, or a reduced.csv with its log.h5 beside it")
    if scene is None:
        scene = parse_scene(read_metadata(log).scene_toml, name=f"scene of {log}", source=str(log))
    stand = scene.build_stand()
    if getattr(stand, "name", "") != STAND:
        raise ParameterError("stand", getattr(stand, "name", stand), f"{STAND} (stand B) for this loader")
    if "swinging_drive" in stand.effects:
        raise ParameterError("effects", "swinging_drive", "the continuous drive (a swinging drive has no steady "
                             "operating point to fit)")
    params = stand.params
    g = params.geometry
    spec = stand.contact
    rows, calibrations, damaged = [], {}, []
    for index, record in read_points(log):
        if isinstance(record, LogFormatError):
            damaged.append(index)
            continue
        try:
            r = point_readings(record, params, f"point {index}")
        except LogFormatError:
            damaged.append(index)
            continue
        direction = float(record.settings["direction"].value)
        for channel in CHANNELS:
            fields = {f: float(record.calibration[channel][f].value) for f in CALIBRATION_FIELDS}
            calibrations.setdefault(channel, []).append(fields)
        rows.append((index, r, direction))
    if not rows:
        raise ParameterError("DATA", str(path), "a stand-B log with at least one undamaged point")
    a, r_c = g.a, g.radius_c
    obs_rows = []
    for index, r, direction in rows:
        f_n = r.normal_force.value
        per_mu = 10.0 * r.b_over_a * g.spin_radius / g.radius_x  # eq. (21): alpha' = mu K
        l_a = r.l_setting.value / a
        c_a = g.pivot_distance * math.sin(r.twist.value) / a  # eq. (36), canonical frame
        u_c = g.pivot_distance * abs(math.cos(r.twist.value)) * r.twist.u / a
        for channel, reading, scale, weights in (
            ("F_T", r.peripheral_force, f_n, (1.0, 0.0, 0.0)),
            ("F_V", r.lateral_force, f_n, (0.0, 1.0, 0.0)),
            ("T_Mo", r.momentometer_torque, a * f_n, (-r_c / a, 0.0, 1.0)),
        ):
            obs_rows.append(dict(point=index, channel=channel, y=reading.value / scale, u=reading.u / scale,
                                 scale=scale, direction=direction, l=l_a, c=c_a, u_l=r.l_setting.u / a, u_c=u_c,
                                 per_mu=per_mu, b_over_a=r.b_over_a, f_n=f_n, weights=weights))
    table = pd.DataFrame(obs_rows)
    if np.any(table["u"] <= 0) or not np.all(np.isfinite(table[["y", "u"]].to_numpy())):
        bad = table[(table["u"] <= 0) | ~np.isfinite(table["y"])].iloc[0]
        raise ParameterError(f"u of {bad['channel']} at point {bad['point']}", float(bad["u"]),
                             "a finite reading with u > 0")
    blocks, notes = [], []
    for channel in CHANNELS:
        found = calibrations[channel]
        index = np.flatnonzero(table["channel"].to_numpy() == channel)
        if any(f != found[0] for f in found):
            notes.append(f"{channel}: calibrated more than once in this log: its calibration errors treated as "
                         "independent")
            continue
        cal = record_from_fields(channel, found[0])
        (var_s, cov), (_, var_o) = cal.covariance
        part = table.iloc[index]
        slope = -part["direction"].to_numpy() / (cal.sensitivity * part["scale"].to_numpy())
        blocks.append((index, CommonErrors(cal.sensitivity, math.sqrt(var_s), math.sqrt(var_o), cov, slope, None)))
        notes.append(f"{channel}: one calibration common to all points (u(S)/S = "
                     f"{math.sqrt(var_s) / cal.sensitivity:.2%}): generalised least squares with its covariance")
    if damaged:
        notes.append(f"{len(damaged)} damaged point(s) left out: {', '.join(map(str, damaged[:20]))}")
    notes.append("the dead weights' error (u_normal_force) and the disc-bearing friction are not in the model")
    size = len(table)
    series = np.array([f"{ch}, F_N = {f:g} N, c/a = {c:.2f}" for ch, f, c in
                       zip(table["channel"], table["f_n"], table["c"])])
    return StandBObservations(
        quantity=np.array([QUANTITY[ch] for ch in table["channel"]]),
        y=table["y"].to_numpy(dtype=float), u=table["u"].to_numpy(dtype=float),
        x=table["l"].to_numpy(dtype=float), x_label="l/a",
        l=table["l"].to_numpy(dtype=float), c=table["c"].to_numpy(dtype=float),
        u_l=table["u_l"].to_numpy(dtype=float),
        alpha=np.full(size, np.nan), alpha_per_mu=table["per_mu"].to_numpy(dtype=float),
        b_over_a=table["b_over_a"].to_numpy(dtype=float), series=series,
        contact=ContactCondition(spec.model, stand.SHAPE, spec.poisson, spec.n if n is None else n),
        fixed_effects=dict(spec.effects), source=f"{path} (stand B, scene {scene.name})",
        stand=stand, geometry=None, notes=tuple(notes),
        common=InstrumentCalibrations(size, blocks) if blocks else None,
        weights=np.array(table["weights"].tolist(), dtype=float), point=table["point"].to_numpy(dtype=int),
        u_c=table["u_c"].to_numpy(dtype=float),
    )
