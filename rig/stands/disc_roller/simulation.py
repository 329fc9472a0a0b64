"""One operating point of stand B: settle, gate, read (rig.stands.base.PointSimulation).

Start: the quasi-static steady state of the previous point's settings (rest if none), then the
step to this point's settings at t = 0 (point time); the swinging drive, which has no steady
state, starts with the disc following the roller at the start of a stroke. DYNAMIC: the drive-train ODE is integrated
until the state stays within ``settle_tolerance`` of this point's steady state (normalised F_x,
F_y by mu F_N, T_Mo by mu a F_N, roller speed by its set value) over one check interval;
the swinging drive settles when the state at the end of a period repeats within the tolerance.
QUASI_STATIC: the steady state directly, constant true signals over the gate.
"""

from __future__ import annotations

import math

import numpy as np

from rig.errors import ParameterError
from rig.logbook import Channel, PointRecord, Quantity
from rig.stands.base import DriveMode, GateData, PointOutcome, PointSimulation, SettleReport, SettleTimeoutError
from rig.stands.disc_roller import instruments as I
from rig.stands.disc_roller.drive_train import DriveTrain
from rig.stands.disc_roller.integration import Integrator, SettleResult, absolute_tolerances, settle
from rig.stands.disc_roller.parameters import LOG_UNITS, PointSettings
from rig.stands.disc_roller.steady_state import SteadyState, following_state, rest_state, steady_state
from rig.stands.disc_roller.truth import point_truth

CHECK_INTERVAL = 0.1  # settle check interval of the continuous drive [s]
SIGNAL_UNITS = {
    "F_T": "N", "F_V": "N", "T_Mo": "N m", "roller_speed": "rad/s", "disc_speed": "rad/s", "rolling_speed": "m/s",
}


class DiscRollerPoint(PointSimulation):
    """Point ``index`` of a run of ``stand`` at ``settings``, from ``previous`` (None: rest)."""

    def __init__(self, stand, index: int, settings: PointSettings, previous: PointSettings | None, seed: int):
        self.stand, self.index, self.settings, self.seed = stand, index, settings, seed
        self.train: DriveTrain = stand.drive_train(settings)
        self.swinging = self.train.swinging is not None
        self.target: SteadyState | None = None if self.swinging else steady_state(self.train, settings.direction)
        if self.swinging:
            self.start, self.y = "disc following the roller at the start of the stroke", following_state(self.train)
        elif previous is None:
            self.start, self.y = "rest", rest_state(self.train)
        else:
            self.start = "previous point"
            self.y = steady_state(stand.drive_train(previous), previous.direction).y
        self.t = 0.0
        set_speed = abs(self.train.set_speed) if not self.swinging else self._swing_speed()
        self.integrator = Integrator(self.train, absolute_tolerances(self.train, set_speed), self._max_step(),
                                     stand.params.ode_tolerance_factor)
        self.settled = False
        self.report: SettleReport | None = None

    # ---- helpers ---------------------------------------------------------------------------
    def _swing_speed(self) -> float:
        s = self.train.swinging
        return s.amplitude * 2.0 * math.pi * s.frequency

    def _max_step(self) -> float:
        return self.train.swinging.period / 50.0 if self.swinging else np.inf

    def _scales(self) -> tuple[float, float, float]:
        c = self.train.contact
        force = c.mu * c.normal_force
        return force, force * c.a, max(abs(self.train.set_speed), 1e-12)

    def _signals(self, t, y: np.ndarray) -> dict[str, np.ndarray]:
        out = self.train.evaluate(t, y)
        return {
            "F_T": out["force_x"], "F_V": out["force_y"], "T_Mo": out["momentometer_torque"],
            "roller_speed": out["roller_speed"], "disc_speed": out["disc_speed"],
            "rolling_speed": out["rolling_speed"],
        }

    def _residual(self, t: float, y: np.ndarray) -> float:
        s = self._signals(t, y[:, None])
        ss = self.target
        force, moment, speed = self._scales()
        return float(max(
            abs(s["F_T"][0] - ss.contact.force_x) / force, abs(s["F_V"][0] - ss.contact.force_y) / force,
            abs(s["T_Mo"][0] - ss.momentometer_torque) / moment, abs(s["roller_speed"][0] - ss.roller_speed) / speed,
        ))

    def _criterion(self) -> str:
        tol = self.stand.params.settle_tolerance
        if self.swinging:
            return f"state at the end of a period repeats within {tol:g} (normalised)"
        return (f"|F_T - F_T,ss|, |F_V - F_V,ss| < {tol:g} mu F_N, |T_Mo - T_Mo,ss| < {tol:g} mu a F_N and "
                f"|w_r - w_r,ss| < {tol:g} w_set at two checks {CHECK_INTERVAL:g} s apart")

    # ---- contract --------------------------------------------------------------------------
    def settle(self, timeout_s: float) -> SettleReport:
        """Integrate from the step until steady (SettleTimeoutError past timeout_s [s])."""
        if not timeout_s > 0.0:
            raise ParameterError("timeout_s", timeout_s, "> 0 [s]")
        tol = self.stand.params.settle_tolerance
        if self.stand.drive is DriveMode.QUASI_STATIC:
            self.y, self.t, self.settled = self.target.y.copy(), 0.0, True
            self.report = SettleReport(0.0, "quasi-static: the steady state solved directly", 0.0, self.start)
            return self.report
        if self.swinging:
            result = self._settle_periodic(tol, timeout_s)
        else:
            result = settle(self.integrator, self.y, self._residual, tol, CHECK_INTERVAL, timeout_s)
        self.t, self.y = result.t, result.y
        if not result.settled:
            raise SettleTimeoutError(self.settings.as_mapping(), timeout_s, result.residual, self._criterion())
        self.settled = True
        self.report = SettleReport(result.t, self._criterion(), result.residual, self.start)
        return self.report

    def _settle_periodic(self, tol: float, timeout_s: float):
        period = self.train.swinging.period
        force, moment, _ = self._scales()
        scale = np.empty(self.train.layout.size)
        lay = self.train.layout
        if lay.twist is not None:
            scale[lay.twist] = moment / self.train.loop.stiffness
            scale[lay.disc] = self._swing_speed() / self.train.gear_ratio
        scale[lay.loads] = np.array([force, force, moment])
        t, y = 0.0, self.y
        value = math.inf
        while t + period <= timeout_s:
            y_next = self.integrator.run(t, t + period, y).y[:, -1]
            value = float(np.max(np.abs(y_next - y) / scale))
            t, y = t + period, y_next
            if value < tol:
                return SettleResult(t, y, value, True)
        return SettleResult(t, y, value, False)

    def gate(self, gate_time_s: float) -> GateData:
        """True signals at the recorder's instants over [t, t + gate_time_s] (point time [s])."""
        if not self.settled:
            raise ParameterError("gate", "called before settle", "settle() first (the operator's order)")
        if not gate_time_s > 0.0:
            raise ParameterError("gate_time_s", gate_time_s, "> 0 [s]")
        rate = self.stand.params.recorder_rate
        t = self.t + np.arange(int(math.floor(gate_time_s * rate * (1.0 + 1e-12))) + 1) / rate
        if self.stand.drive is DriveMode.QUASI_STATIC:
            y = np.repeat(self.y[:, None], t.size, axis=1)
        else:
            sol = self.integrator.run(self.t, t[-1], self.y, dense=True)
            y = sol.sol(t)
            self.t, self.y = float(t[-1]), sol.y[:, -1]
        signals = self._signals(t, y)
        return GateData(float(t[0]), gate_time_s, t, signals, dict(SIGNAL_UNITS))

    def read(self, gate: GateData) -> PointOutcome:
        """Digitised channels and calibrations (the record) and the truth of the gate."""
        stand = self.stand
        calibration = stand.calibrate(self.seed)
        volts = I.record(stand.params, self.seed, self.index, stand.instrument_effects, gate.t_s, gate.signals)
        rate = stand.params.recorder_rate
        start = self.index * stand.params.point_period + float(gate.t_s[0])
        record = PointRecord(
            index=self.index,
            settings={k: Quantity(v, LOG_UNITS[k]) for k, v in self.settings.as_mapping().items()},
            channels={name: Channel(volts[name], "V", rate, start) for name in I.CHANNELS},
            calibration={name: {f: Quantity(v, u) for f, (v, u) in I.calibration_fields(rec).items()}
                         for name, rec in calibration.items()},
        )
        return PointOutcome(record, point_truth(self, gate), self.report)
