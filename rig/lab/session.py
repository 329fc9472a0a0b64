"""One student's session at a stand: set the controls, watch it settle, record gates, reduce, save.

The stand is built from a scene text (rig.lab.scene_text) by rig.scenes, exactly as ``rig run``
builds it, and stepped with the rig.stands.base contract: ``start_point`` (from the previous
settings' steady state) -> ``settle`` -> ``gate`` -> ``read``. The settling transient the page
plays is the same drive train integrated again from the point's start over the settle time
found by ``settle`` plus a short steady tail. Stand A (:class:`StandASession`, rig.stands.yoke)
adds the stroboscope view (sensors.strobe: disc 14 seen in flashes fired by disc 13's angle
times the strobe ratio); stand B (:class:`StandBSession`, rig.stands.disc_roller) shows the
recorder's three channels.

Recorded points are reduced by the stand's own ``reduce_log`` on a log written with
rig.logbook.LogWriter - the very file ``save`` writes and ``rig reduce`` reads - so the page's
reduction and the command line's agree to the last digit. Thread-safe: one lock per session
(a second tab or a reload talks to the same session; requests are served one at a time).

A session is persisted as its :meth:`LabSession.state` (the scene's inputs and, per recorded
point, its settings, the settings it started from and its gate time): the stands are pure in
those arguments, so :func:`restore` replays the points to the same floats (rig.lab.store).
"""

from __future__ import annotations

import math
import tempfile
import threading
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pandas as pd

from rig import validate
from rig.errors import ParameterError
from rig.lab.scene_text import stand_scene
from rig.logbook import LogWriter, RunMetadata, utc_timestamp
from rig.scenes.load import parse_scene
from rig.stands.base import PointOutcome, SettingSpec
from rig.stands.contact_law import LawCoefficients
from rig.stands.disc_roller import parameters as stand_b
from rig.stands.disc_roller.instruments import CHANNELS as STAND_B_CHANNELS
from rig.stands.yoke import integration
from rig.stands.yoke.instruments import BALANCE, DYNAMOMETER
from rig.stands.yoke.parameters import SETTINGS as STAND_A_SETTINGS
from sensors.strobe import StrobeDisc

SETTLE_TIMEOUT_S = 30.0  # simulated time allowed to settle [s]
TAIL_S = 1.0  # steady tail of the played transient after the settle time [s]
TRACE_POINTS = 400  # most samples of the transient sent to the page
GATE_LIMITS_S = (0.5, 60.0)  # gate times the lab accepts [s]
STROBE_RATIO_LIMITS = (0.05, 20.0)  # flash rate / disc-13 mark rate [1]
STATE_FORMAT = 1  # version of LabSession.state()


def _finite(x: object) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def _calibrated_channel(record, name: str) -> dict:
    """A recorded channel as the operator reads it: mean, scatter, samples, converter step, calibration."""
    volts = np.asarray(record.channels[name].samples, dtype=float)
    cal = record.calibration[name]
    return {"mean": float(volts.mean()), "std": float(volts.std()), "samples": int(volts.size),
            "resolution": cal["reading_resolution"].value, "sensitivity": cal["sensitivity"].value,
            "offset": cal["offset"].value}


@dataclass(frozen=True)
class Transient:
    """The settling transient: t [s], named series (units in the stand's TRACES), the wheel angles
    [rad] where the stand has a stroboscope (else None)."""

    settle_s: float
    t: np.ndarray
    series: Mapping[str, np.ndarray]
    theta_1: np.ndarray | None = None
    theta_2: np.ndarray | None = None


class LabSession:
    """A session at one stand with friction coefficient ``mu`` [1] (hidden from the page), run ``seed``,
    the named ``effects`` (None: the lab's EFFECTS) and the controls ``free`` (setting names the
    student may change; the others stay at ``start``). Subclasses name the stand and its controls."""

    STAND: ClassVar[str]
    START: ClassVar[Mapping[str, float]]
    EFFECTS: ClassVar[Mapping[str, Mapping[str, float]]]
    CONTROLS: ClassVar[Mapping[str, SettingSpec]]
    """The lab's controls {name: spec}: the stand's settings, as the lab offers them, and ``direction``."""
    SHOWN: ClassVar[tuple[str, ...]]
    """Reduced outputs the lab sheet shows and checks (each with u_ and U95_)."""
    TRUTH: ClassVar[tuple[str, ...]]
    """Truth quantities sent after submission."""
    TRACES: ClassVar[Mapping[str, str]]
    """Series of the settling transient {name: unit}."""

    def __init__(self, session_id: str, *, seed: int, mu: float, effects: Mapping[str, Mapping[str, float]] | None = None,
                 free: tuple[str, ...] | None = None, start: Mapping[str, float] | None = None,
                 description: str = "rig lab session") -> None:
        self.id = session_id
        self.inputs = {"seed": int(seed), "mu": float(mu), "effects": dict(self.EFFECTS if effects is None else effects),
                       "free": None if free is None else list(free), "start": None if start is None else dict(start),
                       "description": description}
        self.start = dict(self.START) if start is None else dict(self.START) | dict(start)
        self.scene_text = stand_scene(self.STAND, seed=seed, mu=mu, effects=self.inputs["effects"], start=self.start,
                                      description=description)
        self.scene = parse_scene(self.scene_text, name="lab", source="rig lab session")
        self.stand = self.scene.build_stand()
        self.check_settings(self.start)
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
        self.points: list[dict] = []  # per recorded point: settings, previous, gate_time_s (replayed by restore)
        self.answers: dict[int, dict[str, float]] = {}  # the values the student last checked, per point
        self.checks: list[dict] = []  # the log of Checks in an exercise: time_utc, point, passed, step
        self.transient: Transient | None = None
        self._point = None
        self._previous: dict[str, float] | None = None  # what self._point started from
        self._table: pd.DataFrame | None = None
        self.version = 0

    # ------------------------------------------------------------------------------ controls

    @classmethod
    def check_controls(cls, changes: Mapping[str, float], where: str = "settings") -> dict[str, float]:
        """``changes`` {control: SI value}, each checked against the lab's range and choices (errors
        name ``<where>.<control>``)."""
        for name, value in changes.items():
            validate.known_keys(where, [name], cls.CONTROLS)
            spec = cls.CONTROLS[name]
            value = validate.number(f"{where}.{name}", value)
            if not spec.lo <= value <= spec.hi:
                raise ParameterError(f"{where}.{name}", value, f"[{spec.lo:g}, {spec.hi:g}] {spec.unit}")
            spec.check_choice(f"{where}.{name}", value)
        return dict(changes)

    def set_controls(self, changes: Mapping[str, float]) -> Transient:
        """Apply ``changes`` {setting: SI value} (free controls only), settle, return the transient."""
        changes = self.check_controls(changes)
        for name in changes:
            if name not in self.free:
                raise ParameterError(name, changes[name], f"left at {self.settings[name]:g}: this exercise fixes it "
                                     f"(free controls: {', '.join(self.free)})")
        return self._settle(self.check_settings(self.settings | dict(changes)))

    def check_settings(self, settings: Mapping[str, float]) -> dict[str, float]:
        """A full set of the stand's settings, checked by the stand (named errors); SI floats."""
        return self.stand.check_settings(settings)

    def set_strobe_ratio(self, ratio: float) -> None:
        """The stroboscope's flash rate as a multiple of disc 13's mark rate [1]."""
        self.strobe_ratio = validate.number("strobe_ratio", ratio, *STROBE_RATIO_LIMITS)

    def _settle(self, settings: Mapping[str, float]) -> Transient:
        """Step from the running settings to ``settings`` and settle; the session changes only if it
        settles (SettleTimeoutError otherwise)."""
        point = self.stand.start_point(len(self.outcomes), settings, self.running, self.scene.seed)
        y0 = self._start_state(point)
        report = point.settle(SETTLE_TIMEOUT_S)
        self.transient = self._transient(point, y0, report.duration_s)
        self._point, self._previous = point, self.running
        self.settings = dict(settings)
        self.running = dict(settings)
        self.version += 1
        return self.transient

    @staticmethod
    def _start_state(point) -> np.ndarray:
        """The drive train's state at the point's start (before ``settle`` moves it)."""
        raise NotImplementedError

    @staticmethod
    def _transient(point, y0: np.ndarray, settle_s: float) -> Transient:
        raise NotImplementedError

    def strobe(self) -> dict | None:
        """The stroboscope view (stand A), or None."""
        return None

    # ------------------------------------------------------------------------------ gate

    def record(self, gate_time_s: float) -> dict:
        """Open the gate for ``gate_time_s`` [s] at the settled state, read the instruments, keep the
        point; returns its readings."""
        gate_time = validate.number("gate_time_s", gate_time_s, *GATE_LIMITS_S)
        if self._point is None:
            self._settle(self.settings)  # first gate, or a second gate at the same settings: a new point
        point, self._point = self._point, None
        outcome = point.read(point.gate(gate_time))
        self.outcomes.append(outcome)
        self.points.append({"settings": dict(self.settings), "previous": self._previous, "gate_time_s": gate_time})
        self._table = None
        self.version += 1
        return self.readings(len(self.outcomes) - 1)

    def readings(self, index: int) -> dict:
        """What the operator reads off the instruments for point ``index`` (SI units)."""
        raise NotImplementedError

    # ------------------------------------------------------------------------------ reduction

    def _write_log(self, path: Path) -> Path:
        writer = LogWriter(path, RunMetadata(self.scene_text, self.scene.seed, self.scene.stand, self.created))
        for outcome in self.outcomes:
            writer.write_point(outcome.record, outcome.truth)
        return writer.finalize()

    def table(self) -> pd.DataFrame:
        """The stand's reduction of the recorded points, as ``rig reduce`` computes it."""
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
            values = {f"{prefix}{name}": _finite(row[f"{prefix}{name}"]) for name in self.SHOWN
                      for prefix in ("", "u_", "U95_")}
            reason = row.get("reason")
            rows.append({"point": int(index), "values": values, "reason": reason if isinstance(reason, str) else ""})
        return rows

    def truth(self, index: int) -> dict[str, float]:
        """The simulation's truth of point ``index`` (sent only after the student submits)."""
        truth = self.outcomes[index].truth
        return {name: truth[name].value for name in self.TRUTH if name in truth}

    def coefficients(self, index: int):
        """(b/a [1], the contact law as the reduction asks it: coefficients(l/a, c/a, alpha') ->
        (nu_T, nu_v, nu_0)) at recorded point ``index``'s load: the lab sheet's nu lookup."""
        raise NotImplementedError

    def nu_lookup(self, index: int, l_over_a: float, c_over_a: float, alpha_prime: float) -> dict:
        """nu_T, nu_v, nu_0 [1] of the contact law at point ``index``'s b/a and (l/a, c/a, alpha')
        ([Koziarski] eqs. (24)-(26)'s coefficients; OutsideModelDomain, a named ParameterError,
        outside the law's table), with the curve of each over alpha' across the table's range."""
        b_over_a, law = self.coefficients(index)
        nu_t, nu_v, nu_0 = law(l_over_a, c_over_a, alpha_prime)
        lo, hi = law.domain.alpha
        alphas = np.geomspace(max(lo, 1e-3 * hi), hi, 41)
        curve = np.array([law(l_over_a, c_over_a, float(x)) for x in alphas], dtype=float)
        return {"b_over_a": b_over_a, "alpha_range": [lo, hi], "nu_T": nu_t, "nu_v": nu_v, "nu_0": nu_0,
                "curve": {"alpha_prime": alphas.tolist(), "nu_T": curve[:, 0].tolist(), "nu_v": curve[:, 1].tolist(),
                          "nu_0": curve[:, 2].tolist()}}

    def save(self, folder: Path) -> Path:
        """Write the session as ``folder/log.h5`` (the format of ``rig run``; ``rig reduce`` reads it)."""
        if not self.outcomes:
            raise ParameterError("point", "none recorded", "record a gate before saving")
        folder.mkdir(parents=True, exist_ok=True)
        return self._write_log(folder / "log.h5")

    # ------------------------------------------------------------------------------ persistence

    def state(self) -> dict:
        """Everything needed to rebuild this session (JSON-able; hidden values included: server side only)."""
        return {"format": STATE_FORMAT, "id": self.id, "stand": self.STAND, **self.inputs, "created": self.created,
                "settings": self.settings, "running": self.running, "strobe_ratio": self.strobe_ratio,
                "points": self.points, "answers": {str(k): v for k, v in self.answers.items()}, "checks": self.checks,
                "pending": None if self._point is None else {"previous": self._previous},
                "version": self.version}


class StandASession(LabSession):
    """Stand A (the yoke/spring stand, rig.stands.yoke) with the stroboscope."""

    STAND = "yoke"
    START = {"brake_setpoint_N_m": 0.0, "normal_force_N": 96.2, "delta_h_m": 0.0, "omega_1_set_rad_s": 25.13}
    """Settings when a session opens (SI; the default scene's operating point without load)."""
    EFFECTS = {"drive_compliance": {}, "brake_dynamics": {}, "dynamometer_noise": {}, "balance_noise": {}}
    """Effects of a lab stand A unless an exercise names others: a drive train and brake that settle
    visibly, noisy dynamometer and balance."""
    CONTROLS = dict(STAND_A_SETTINGS) | {"direction": SettingSpec(
        "1", -1.0, 1.0, "+1: stand A's model runs forward only (docs/stand-a.md section 2, 'rolling direction': "
        "wheel 1 never reverses and the contact uses |v|, so a reversed drive would give wrong numbers, not a "
        "mirrored stand); stand B runs both ways", (1.0,))}
    SHOWN = ("i_k", "l_over_a", "c_over_a", "F_y_N", "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T")
    TRUTH = ("mu", "l_over_a", "c_over_a", "i_k")
    TRACES = {"omega_1": "rad/s", "omega_2": "rad/s", "brake_moment": "N m"}

    def set_controls(self, changes: Mapping[str, float]) -> Transient:
        changes = dict(self.check_controls(changes))
        changes.pop("direction", None)  # forward, the only value check_controls lets through
        return super().set_controls(changes)

    @staticmethod
    def _start_state(point) -> np.ndarray:
        return point.y0

    @staticmethod
    def _transient(point, y0: np.ndarray, settle_s: float) -> Transient:
        train = point.train
        t, y = integration.gate(train, 0.0, y0, settle_s + TAIL_S, point.stand.params.ode_tolerance_factor)
        theta_1, theta_2 = train.angles(t, y)
        series = {"omega_1": np.asarray(train.omega_1(t, y), dtype=float), "omega_2": np.asarray(y[2], dtype=float),
                  "brake_moment": np.asarray(train.brake_moment(t, y), dtype=float)}
        return Transient(settle_s, t, series, np.asarray(theta_1), np.asarray(theta_2))

    def coefficients(self, index: int):
        settings = self.outcomes[index].record.settings
        geometry = self.stand.params.geometry_at(settings["delta_h"].value)
        b_over_a = geometry.b_over_a(settings["normal_force"].value)
        law, domain = self.stand.law(b_over_a, geometry)
        return b_over_a, LawCoefficients(law, domain)

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

    def readings(self, index: int) -> dict:
        record = self.outcomes[index].record
        counters = record.counters
        dynamometer = _calibrated_channel(record, DYNAMOMETER)
        balance = np.asarray(record.channels[BALANCE].samples, dtype=float)
        return {
            "point": record.index,
            "settings": {name: q.value for name, q in record.settings.items()},
            "gate_time_s": counters.gate_time_s,
            "counts": {name: c.count for name, c in counters.counters.items()},
            "marks": {name: c.marks_per_rev for name, c in counters.counters.items()},
            "dynamometer_V": {k: dynamometer[k] for k in ("mean", "std", "samples", "resolution")},
            "calibration": {"sensitivity_V_per_N": dynamometer["sensitivity"], "offset_V": dynamometer["offset"]},
            "balance_N_m": {"readings": balance.tolist(), "T2": record.readings["T2"].value,
                            "resolution": record.readings["balance_resolution"].value},
        }


DEAD_WEIGHTS_N = (9.0, 21.0, 36.0, 144.0)
"""The loads of the text ([Koziarski] section 3.2): the lab's stand B offers these dead weights (one contact
table each, built once and cached)."""
LAB_MU_RANGE_B = (0.5, 1.0)
"""The hidden mu of a stand-B session lies here (the lab's law_mu_range: one table per load) [1]."""


class StandBSession(LabSession):
    """Stand B (the disc-roller stand, rig.stands.disc_roller) with the recorder's three channels."""

    STAND = "disc_roller"
    START = {"normal_force_N": 36.0, "l_m": 0.01, "sigma_rad": 0.0, "speed_step": 1.0, "direction": 1.0}
    """Settings when a session opens (SI): 36 N, the roller at l = 10 mm, no twist, 24 rpm, forward."""
    EFFECTS = {"loop_compliance": {}, "recorder_noise": {}, "calibration_weight_errors": {},
               "law_mu_range": {"mu_low": LAB_MU_RANGE_B[0], "mu_high": LAB_MU_RANGE_B[1]}}
    """fig14's effects (the momentometer's torsion: a loop that settles visibly; bridge noise; weight
    errors) and the lab's table range of mu."""
    CONTROLS = dict(stand_b.SETTINGS) | {
        "normal_force_N": SettingSpec("N", DEAD_WEIGHTS_N[0], DEAD_WEIGHTS_N[-1],
                                      "the dead weights of the text (9, 21, 36, 144 N)", DEAD_WEIGHTS_N),
        "l_m": SettingSpec("m", -0.02, 0.02, "roller position l by the handwheel (screw 19), text: 0...+-20 mm"),
        "sigma_rad": SettingSpec("rad", -0.15, 0.15, "twist sigma of body 14, screw 15: c = e sin(sigma), eq. (36); "
                                 "the lab keeps |c/a| <= 2.6, inside the contact table (|c/a| <= 3.49), so that the "
                                 "reduction's perturbed inputs stay in it too"),
    }
    SHOWN = ("l_over_a", "c_over_a", "M_C_N_m", "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T", "mu_M")
    TRUTH = ("mu", "l_over_a", "c_over_a", "M_C")
    TRACES = {"roller_speed": "rad/s", "disc_speed": "rad/s", "F_T": "N", "F_V": "N", "T_Mo": "N m"}

    def coefficients(self, index: int):
        b_over_a = self.stand.params.b_over_a(self.outcomes[index].record.settings["normal_force"].value)
        return b_over_a, LawCoefficients(self.stand.law(b_over_a), self.stand.law_domain(b_over_a))

    def check_settings(self, settings: Mapping[str, float]) -> dict[str, float]:
        stand_b.point_settings(settings)
        return {name: float(value) for name, value in settings.items()}

    @staticmethod
    def _start_state(point) -> np.ndarray:
        return np.array(point.y, dtype=float)

    @staticmethod
    def _transient(point, y0: np.ndarray, settle_s: float) -> Transient:
        end = settle_s + TAIL_S
        t = np.linspace(0.0, end, int(end * 200) + 1)  # 200 samples a second
        out = point.train.evaluate(t, point.integrator.run(0.0, end, y0, dense=True).sol(t))
        names = {"roller_speed": "roller_speed", "disc_speed": "disc_speed", "F_T": "force_x", "F_V": "force_y",
                 "T_Mo": "momentometer_torque"}  # as rig.stands.disc_roller.simulation's gate signals
        return Transient(settle_s, t, {name: np.asarray(out[key], dtype=float) for name, key in names.items()})

    def readings(self, index: int) -> dict:
        record = self.outcomes[index].record
        channels = {name: _calibrated_channel(record, name) for name in STAND_B_CHANNELS}
        first = record.channels["F_T"]
        return {
            "point": record.index,
            "settings": {name: q.value for name, q in record.settings.items()},
            "gate_time_s": (channels["F_T"]["samples"] - 1) / first.sample_rate_Hz,
            "recorder_V": channels,
            "units": dict(STAND_B_CHANNELS),
        }


SESSIONS: Mapping[str, type[LabSession]] = {"yoke": StandASession, "disc_roller": StandBSession}
"""Session class of each stand the lab operates."""


def restore(state: Mapping[str, object]) -> LabSession:
    """Rebuild a session from its :meth:`LabSession.state`: the same scene, and every recorded point
    replayed from its start settings (the stands are pure in them: the same floats)."""
    if state.get("format") != STATE_FORMAT:
        raise ParameterError("state.format", state.get("format"), f"{STATE_FORMAT}")
    cls = SESSIONS[state["stand"]]
    free = state["free"]
    session = cls(state["id"], seed=state["seed"], mu=state["mu"], effects=state["effects"],
                  free=None if free is None else tuple(free), start=state["start"], description=state["description"])
    session.created = state["created"]
    for point in state["points"]:
        session.settings, session.running = dict(point["settings"]), point["previous"]
        session._settle(session.settings)
        session.record(point["gate_time_s"])
    session.settings, session.running = dict(state["settings"]), state["running"]
    session.transient, session._point = None, None
    if state["pending"] is not None:  # settled at these settings after the last gate: the same point again
        session.running = state["pending"]["previous"]
        session._settle(session.settings)
    session.strobe_ratio = state["strobe_ratio"]
    session.answers = {int(k): dict(v) for k, v in state["answers"].items()}
    session.checks = list(state.get("checks", []))
    session.version = state["version"]
    return session
