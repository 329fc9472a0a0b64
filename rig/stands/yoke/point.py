"""One operating point of stand A: from the previous point's steady state, step to the new settings,
settle, open the common gate, read the instruments (rig.stands.base.PointSimulation).

DYNAMIC drive: the drive-train ODE (rig.stands.yoke.drive_train, integrated implicitly by
rig.stands.yoke.integration). QUASI_STATIC drive: no ODE; the steady state of the settings
(rig.stands.yoke.steady_state) holds during the whole gate and the wheel angles grow linearly.
Truth per point: gate means of the true signals (l, c, l/a, c/a, alpha', forces, moments, nu's,
speeds) and the simulation's mu.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from rig import validate
from rig.errors import ParameterError
from rig.logbook import PointRecord, Quantity
from rig.stands.base import DriveMode, GateData, PointOutcome, PointSimulation, SettleReport, SettleTimeoutError
from rig.stands.yoke import instruments, integration
from rig.stands.yoke.brake import BrakeFrictionFluctuation, BrakeLoop, IdealBrake
from rig.stands.yoke.drive_train import BearingFriction, Compliance, DriveTrain, SpeedReference
from rig.stands.yoke.parameters import LOG_SETTINGS
from sensors import effect_rng

REST = "rest"
PREVIOUS = "previous point"
UNITS = {
    "theta_1": "rad", "theta_2": "rad", "omega_1": "rad/s", "omega_2": "rad/s", "omega_0": "rad/s",
    "brake_moment": "N m", "F_x": "N", "F_y": "N", "M_C": "N m", "M_O": "N m", "T2_contact": "N m",
    "l": "m", "c": "m", "alpha_prime": "1", "nu_T": "1", "nu_v": "1", "nu_0": "1",
}


class YokePoint(PointSimulation):
    """Operating point ``index`` of a YokeStand (built by YokeStand.start_point)."""

    def __init__(self, stand, index: int, settings: Mapping[str, float], previous: Mapping[str, float] | None,
                 seed: int) -> None:
        self.stand = stand
        self.index = validate.integer("index", index, 0)
        self.settings = stand.check_settings(settings)
        self.seed = validate.integer("seed", seed, 0)
        p = stand.params
        self.contact = stand.contact_for(self.settings)
        bearing = None
        if "bearing_friction" in stand.effects:
            e = stand.effects["bearing_friction"]
            bearing = BearingFriction(e["moment_1_N_m"], e["moment_2_N_m"], p.brake_speed_eps_rad_s)
        self.bearing = bearing
        self.target = stand.steady_state(self.settings, bearing)
        self.start, start_state = self._start(previous)
        self.train = None
        if stand.drive is DriveMode.DYNAMIC:
            self.train = self._drive_train(start_state)
            self.y0 = self._initial_state(start_state)
        self.instruments = instruments.point_instruments(p, stand.effects, self.seed, self.index)
        self._settled: tuple[float, np.ndarray | None] | None = None
        self._report: SettleReport | None = None

    # ----------------------------------------------------------------------------- set-up

    def _start(self, previous):
        """('rest' | 'previous point', steady OperatingPoint of the previous settings or None)."""
        if previous is None:
            return REST, None
        prev = self.stand.check_settings(previous)
        try:
            op = self.stand.steady_state(prev, self.bearing)
        except ParameterError:
            return REST, None  # the previous settings have no steady state: start from rest
        return PREVIOUS, op

    def _drive_train(self, start_state) -> DriveTrain:
        stand, p = self.stand, self.stand.params
        t_set = self.settings["brake_setpoint_N_m"]
        if "brake_dynamics" in stand.effects:
            e = stand.effects["brake_dynamics"]
            fluctuation = None
            if "brake_friction_fluctuation" in stand.effects:
                f = stand.effects["brake_friction_fluctuation"]
                rng = effect_rng(instruments.point_seed(self.seed, self.index), "brake_12", "friction_fluctuation")
                fluctuation = BrakeFrictionFluctuation(f["relative_rms"], f["f_min_Hz"], f["f_max_Hz"], rng)
            brake = BrakeLoop(e["loop_gain"], (e["tau_lever_s"], e["tau_shoe_s"], e["tau_lining_s"]), t_set,
                              fluctuation)
        else:
            brake = IdealBrake(t_set)
        compliance = None
        if "drive_compliance" in stand.effects:
            compliance = Compliance.from_effect(stand.effects["drive_compliance"], p.J_1_kg_m2)
        w_start = 0.0 if start_state is None else start_state.omega_1
        reference = SpeedReference(w_start, self.settings["omega_1_set_rad_s"], p.speed_ramp_s)
        return DriveTrain(self.contact, J_1=p.J_1_kg_m2, J_2=p.J_2_kg_m2, reference=reference, brake=brake,
                          brake_speed_eps=p.brake_speed_eps_rad_s, carrier=(self.target.omega_1, self.target.omega_2),
                          compliance=compliance, bearing=self.bearing)

    def _initial_state(self, op) -> np.ndarray:
        if op is None:
            return np.zeros(self.train.n_states)
        return self.train.state(omega_1=op.omega_1, omega_2=op.omega_2, moment_1=op.motor_moment,
                                brake_moment=op.brake_moment)

    # ----------------------------------------------------------------------------- contract

    def settle(self, timeout_s: float) -> SettleReport:
        """Integrate until steady (criterion: integration.Target); SettleTimeoutError past timeout_s [s]."""
        timeout = validate.number("settle_timeout_s", timeout_s, 0.0, lo_open=True)
        target = integration.Target(self.target.omega_1, self.target.omega_2, self.target.brake_moment,
                                    self.target.slope)
        if self.train is None:
            self._settled = (0.0, None)
            self._report = SettleReport(0.0, "quasi-static drive: the steady state is solved directly", 0.0,
                                        self.start)
            return self._report
        t, y, residual = integration.settle(self.train, self.y0, target, timeout,
                                            self.stand.params.ode_tolerance_factor)
        if residual > 1.0:
            raise SettleTimeoutError(self.settings, timeout, residual, target.criterion)
        self._settled = (t, y)
        self._report = SettleReport(t, target.criterion, residual, self.start)
        return self._report

    def gate(self, gate_time_s: float) -> GateData:
        """The true signals over the common gate of gate_time_s [s] (after settle)."""
        duration = validate.number("gate_time_s", gate_time_s, 0.0, lo_open=True)
        if self._settled is None:
            raise ParameterError("gate", "called before settle", "settle(timeout) first (operator order)")
        t_open, y_open = self._settled
        if self.train is None:
            return self._static_gate(duration)
        t, y = integration.gate(self.train, t_open, y_open, duration, self.stand.params.ode_tolerance_factor)
        w1 = np.asarray(self.train.omega_1(t, y), dtype=float)
        sample = self.contact.evaluate(w1, y[2])
        theta_1, theta_2 = self.train.angles(t, y)
        signals = dict(theta_1=theta_1, theta_2=theta_2, omega_1=w1, omega_2=y[2],
                       brake_moment=np.asarray(self.train.brake_moment(t, y), dtype=float))
        signals.update(self._contact_signals(sample))
        return GateData(t_open, duration, t, signals, {k: UNITS[k] for k in signals})

    def _static_gate(self, duration: float) -> GateData:
        n = max(int(np.ceil(duration * integration.GATE_SAMPLE_RATE_HZ)), 2) + 1
        t = np.linspace(0.0, duration, n)
        op = self.target
        ones = np.ones_like(t)
        signals = dict(theta_1=op.omega_1 * t, theta_2=op.omega_2 * t, omega_1=op.omega_1 * ones,
                       omega_2=op.omega_2 * ones, brake_moment=op.brake_moment * ones)
        signals.update({k: float(v) * ones for k, v in self._contact_signals(op.contact).items()})
        return GateData(0.0, duration, t, signals, {k: UNITS[k] for k in signals})

    @staticmethod
    def _contact_signals(s) -> dict[str, np.ndarray]:
        return dict(F_x=s.F_x, F_y=s.F_y, M_C=s.M_C, M_O=s.M_O, T2_contact=s.T2, l=s.l, c=s.c, omega_0=s.w0,
                    alpha_prime=s.alpha, nu_T=s.nu_T, nu_v=s.nu_v, nu_0=s.nu_0)

    def read(self, gate: GateData) -> PointOutcome:
        """Instruments fed with the gate's true signals: the log record and the truth (gate means)."""
        if self._report is None:
            raise ParameterError("read", "called before settle", "settle(timeout), gate(T), read(gate) in order")
        m = instruments.measure(self.instruments, gate)
        settings = {LOG_SETTINGS[k][0]: Quantity(v, LOG_SETTINGS[k][1]) for k, v in self.settings.items()}
        calibration = instruments.calibration_quantities(self.stand.calibration(self.seed))
        record = PointRecord(
            index=self.index, settings=settings, channels=m.channels, counters=m.counters, readings=m.readings,
            calibration={instruments.DYNAMOMETER: calibration},
        )
        return PointOutcome(record, self._truth(gate), self._report)

    def _truth(self, gate: GateData) -> dict[str, Quantity]:
        sig = gate.signals
        mean = {k: float(np.mean(sig[k])) for k in sig if k not in ("theta_1", "theta_2")}
        a = self.contact.geometry.a
        p = self.stand.params
        truth = {k: Quantity(v, UNITS[k]) for k, v in mean.items()}
        truth.update(
            l_over_a=Quantity(mean["l"] / a, "1"), c_over_a=Quantity(mean["c"] / a, "1"),
            mu=Quantity(p.mu, "1"), mu_v=Quantity(p.mu, "1"), mu_T=Quantity(p.mu, "1"),
            i_k=Quantity(mean["omega_2"] / mean["omega_1"], "1"), b_over_a=Quantity(self.contact.b_over_a, "1"),
            T2=Quantity(mean["brake_moment"], "N m"),
            p0=Quantity(self.contact.b_over_a * a * p.contact_modulus_Pa / (2.0 * self.contact.geometry.radius_x),
                        "Pa"),
        )
        return truth
