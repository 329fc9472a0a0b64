"""One student's session at stand A: set the controls, watch it settle, record gates, reduce, save.

The stand is built from a scene text (rig.lab.scene_text) by rig.scenes, exactly as ``rig run``
builds it, and stepped with the rig.stands.base contract: ``start_point`` (from the previous
settings' steady state) -> ``settle`` -> ``gate`` -> ``read``. The settling transient the page
plays is the same drive train (rig.stands.yoke) integrated again from the point's start over
the settle time found by ``settle`` plus a short steady tail. The stroboscope view is
sensors.strobe: disc 14 seen in flashes fired by disc 13's angle times the strobe ratio.

Recorded points are reduced by the stand's own ``reduce_log`` on a log written with
rig.logbook.LogWriter - the very file ``save`` writes and ``rig reduce`` reads - so the page's
reduction and the command line's agree to the last digit. Thread-safe: one lock per session
(a second tab or a reload talks to the same session; requests are served one at a time).
"""

from __future__ import annotations

import math
import tempfile
import threading
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig import validate
from rig.errors import ParameterError
from rig.lab.scene_text import stand_a_scene
from rig.logbook import LogWriter, RunMetadata, utc_timestamp
from rig.scenes.load import parse_scene
from rig.stands.base import PointOutcome
from rig.stands.yoke import integration
from rig.stands.yoke.instruments import BALANCE, DYNAMOMETER
from sensors.strobe import StrobeDisc

LAB_EFFECTS: Mapping[str, Mapping[str, float]] = {
    "drive_compliance": {}, "brake_dynamics": {}, "dynamometer_noise": {}, "balance_noise": {},
}
"""Effects of a lab stand A unless an exercise names others: a drive train and brake that settle
visibly, noisy dynamometer and balance."""
START: Mapping[str, float] = {"brake_setpoint_N_m": 0.0, "normal_force_N": 96.2, "delta_h_m": 0.0,
                              "omega_1_set_rad_s": 25.13}
"""Settings when a session opens (SI; the default scene's operating point without load)."""
SETTLE_TIMEOUT_S = 30.0  # simulated time allowed to settle [s]
TAIL_S = 1.0  # steady tail of the played transient after the settle time [s]
TRACE_POINTS = 400  # most samples of the transient sent to the page
GATE_LIMITS_S = (0.5, 60.0)  # gate times the lab accepts [s]
STROBE_RATIO_LIMITS = (0.05, 20.0)  # flash rate / disc-13 mark rate [1]
SHOWN = ("i_k", "l_over_a", "c_over_a", "nu_T", "nu_v", "mu_v", "mu_T")
"""Reduced outputs the lab sheet shows and checks (each with u_ and U95_)."""


def _finite(x: object) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


@dataclass(frozen=True)
class Transient:
    """The settling transient: t [s], speeds [rad/s], brake moment [N m], wheel angles [rad]."""

    settle_s: float
    t: np.ndarray
    omega_1: np.ndarray
    omega_2: np.ndarray
    brake_moment: np.ndarray
    theta_1: np.ndarray
    theta_2: np.ndarray


class LabSession:
    """A session at stand A with friction coefficient ``mu`` [1] (hidden from the page), run ``seed``,
    the named ``effects`` and the controls ``free`` (setting names the student may change; the
    others stay at ``start``)."""

    def __init__(self, session_id: str, *, seed: int, mu: float, effects: Mapping[str, Mapping[str, float]] = LAB_EFFECTS,
                 free: tuple[str, ...] | None = None, start: Mapping[str, float] | None = None,
                 description: str = "rig lab session") -> None:
        self.id = session_id
        self.start = dict(START) if start is None else dict(START) | dict(start)
        self.scene_text = stand_a_scene(seed=seed, mu=mu, effects=effects, start=self.start, description=description)
        self.scene = parse_scene(self.scene_text, name="lab", source="rig lab session")
        self.stand = self.scene.build_stand()
        self.stand.check_settings(self.start)
        self.free = tuple(self.stand.SETTINGS) if free is None else tuple(free)
        for name in self.free:
            validate.known_keys("free control", [name], self.stand.SETTINGS)
        self.stand.calibrate(self.scene.seed)
        self.created = utc_timestamp()
        self.lock = threading.Lock()
        self.settings = dict(self.start)
        self.running: dict[str, float] | None = None  # settings of the last settled point (None: at rest)
        self.strobe_ratio = 1.0
        self.outcomes: list[PointOutcome] = []
        self.transient: Transient | None = None
        self._point = None
        self._table: pd.DataFrame | None = None
        self.version = 0

    # ------------------------------------------------------------------------------ controls

    def set_controls(self, changes: Mapping[str, float]) -> Transient:
        """Apply ``changes`` {setting: SI value} (free controls only), settle, return the transient."""
        for name in changes:
            validate.known_keys("control", [name], self.stand.SETTINGS)
            if name not in self.free:
                raise ParameterError(name, changes[name], f"left at {self.settings[name]:g}: this exercise fixes it "
                                     f"(free controls: {', '.join(self.free)})")
        return self._settle(self.stand.check_settings(self.settings | dict(changes)))

    def set_strobe_ratio(self, ratio: float) -> None:
        """The stroboscope's flash rate as a multiple of disc 13's mark rate [1]."""
        self.strobe_ratio = validate.number("strobe_ratio", ratio, *STROBE_RATIO_LIMITS)

    def _settle(self, settings: Mapping[str, float]) -> Transient:
        """Step from the running settings to ``settings`` and settle; the session changes only if it
        settles (SettleTimeoutError otherwise)."""
        point = self.stand.start_point(len(self.outcomes), settings, self.running, self.scene.seed)
        report = point.settle(SETTLE_TIMEOUT_S)
        self.transient = self._transient(point, report.duration_s)
        self._point = point
        self.settings = dict(settings)
        self.running = dict(settings)
        self.version += 1
        return self.transient

    @staticmethod
    def _transient(point, settle_s: float) -> Transient:
        train = point.train
        t, y = integration.gate(train, 0.0, point.y0, settle_s + TAIL_S, point.stand.params.ode_tolerance_factor)
        theta_1, theta_2 = train.angles(t, y)
        return Transient(settle_s, t, np.asarray(train.omega_1(t, y), dtype=float), np.asarray(y[2], dtype=float),
                         np.asarray(train.brake_moment(t, y), dtype=float), np.asarray(theta_1), np.asarray(theta_2))

    def strobe(self) -> dict:
        """Disc 14 as the operator sees it: flash instants [s], the apparent position of its marks
        (mark coordinate modulo 1 [1]) at each flash over the transient, and the apparent drift of
        the marks in the steady tail [marks/s] (0: they stand still; the flash-to-flash step taken
        as the nearest whole number of marks, as the eye does)."""
        tr = self.transient
        if tr is None:
            return {"t": [], "phase": [], "drift_marks_s": None}
        p = self.stand.params
        disc_14 = StrobeDisc(p.marks_2)
        flashes = disc_14.crossing_times(tr.t, tr.theta_1 * self.strobe_ratio * p.marks_2 / p.marks_1)
        u2 = np.interp(flashes, tr.t, disc_14.mark_coordinate(tr.theta_2))
        steady = flashes >= tr.settle_s
        drift = None
        if np.count_nonzero(steady) >= 2:
            step_marks = np.diff(u2[steady])
            drift = float(np.sum(step_marks - np.round(step_marks)) / (flashes[steady][-1] - flashes[steady][0]))
        every = max(1, flashes.size // TRACE_POINTS)
        return {"t": flashes[::every].tolist(), "phase": np.mod(u2[::every], 1.0).tolist(), "drift_marks_s": drift}

    # ------------------------------------------------------------------------------ gate

    def record(self, gate_time_s: float) -> dict:
        """Open the common gate for ``gate_time_s`` [s] at the settled state, read the instruments,
        keep the point; returns its readings."""
        gate_time = validate.number("gate_time_s", gate_time_s, *GATE_LIMITS_S)
        if self._point is None:
            self._settle(self.settings)  # first gate, or a second gate at the same settings: a new point
        point, self._point = self._point, None
        outcome = point.read(point.gate(gate_time))
        self.outcomes.append(outcome)
        self._table = None
        self.version += 1
        return self.readings(len(self.outcomes) - 1)

    def readings(self, index: int) -> dict:
        """What the operator reads off the instruments for point ``index`` (SI units)."""
        record = self.outcomes[index].record
        counters = record.counters
        cal = record.calibration[DYNAMOMETER]
        dyn = np.asarray(record.channels[DYNAMOMETER].samples, dtype=float)
        balance = np.asarray(record.channels[BALANCE].samples, dtype=float)
        return {
            "point": record.index,
            "settings": {name: q.value for name, q in record.settings.items()},
            "gate_time_s": counters.gate_time_s,
            "counts": {name: c.count for name, c in counters.counters.items()},
            "marks": {name: c.marks_per_rev for name, c in counters.counters.items()},
            "dynamometer_V": {"mean": float(dyn.mean()), "std": float(dyn.std()), "samples": int(dyn.size),
                              "resolution": cal["reading_resolution"].value},
            "calibration": {"sensitivity_V_per_N": cal["sensitivity"].value, "offset_V": cal["offset"].value},
            "balance_N_m": {"readings": balance.tolist(), "T2": record.readings["T2"].value,
                            "resolution": record.readings["balance_resolution"].value},
        }

    # ------------------------------------------------------------------------------ reduction

    def _write_log(self, path: Path) -> Path:
        writer = LogWriter(path, RunMetadata(self.scene_text, self.scene.seed, self.scene.stand, self.created))
        for outcome in self.outcomes:
            writer.write_point(outcome.record, outcome.truth)
        return writer.finalize()

    def table(self) -> pd.DataFrame:
        """The stand's reduction (eqs. 29-35) of the recorded points, as ``rig reduce`` computes it."""
        if self._table is None:
            if not self.outcomes:
                raise ParameterError("point", "none recorded", "record a gate first")
            with tempfile.TemporaryDirectory(prefix="rig-lab-") as folder:
                path = self._write_log(Path(folder) / "log.h5")
                self._table = self.stand.reduce_log(path, self.scene.contact)
        return self._table

    def reduced(self) -> list[dict]:
        """The reduction without any truth: per point, SHOWN outputs with u_ and U95_ (None = not reducible)."""
        if not self.outcomes:
            return []
        table = self.table()
        rows = []
        for index, row in table.iterrows():
            values = {f"{prefix}{name}": _finite(row[f"{prefix}{name}"]) for name in SHOWN
                      for prefix in ("", "u_", "U95_")}
            reason = row.get("reason")
            rows.append({"point": int(index), "values": values, "reason": reason if isinstance(reason, str) else ""})
        return rows

    def truth(self, index: int) -> dict[str, float]:
        """The simulation's truth of point ``index`` (sent only after the student submits)."""
        truth = self.outcomes[index].truth
        return {name: truth[name].value for name in ("mu", "l_over_a", "c_over_a", "i_k") if name in truth}

    def save(self, folder: Path) -> Path:
        """Write the session as ``folder/log.h5`` (the format of ``rig run``; ``rig reduce`` reads it)."""
        if not self.outcomes:
            raise ParameterError("point", "none recorded", "record a gate before saving")
        folder.mkdir(parents=True, exist_ok=True)
        return self._write_log(folder / "log.h5")

