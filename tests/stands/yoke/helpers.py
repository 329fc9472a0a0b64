"""Shared set-up of the stand-A tests: a stand with the closed-form stand-in law, settings, one point."""

from __future__ import annotations

from rig.stands.base import ContactSpec, DriveMode
from rig.stands.yoke.stand import YokeStand
from tests.stands.yoke import standin

SPEC = ContactSpec("rigid", None, 0.3)
EFFECTS_ALL = ("drive_compliance", "brake_dynamics", "bearing_friction", "brake_friction_fluctuation",
               "dynamometer_noise", "dynamometer_drift", "balance_noise", "counter_pulse_noise",
               "calibration_weight_error", "load_device")
INSTRUMENT_EFFECTS = ("dynamometer_noise", "dynamometer_drift", "balance_noise", "counter_pulse_noise",
                      "calibration_weight_error")


def stand(effects=(), drive=DriveMode.DYNAMIC, parameters=None, **effect_values) -> YokeStand:
    """A YokeStand with the stand-in law; ``effects`` named with defaults, ``effect_values`` overrides."""
    named = {name: {} for name in effects}
    named.update(effect_values)
    return YokeStand(parameters or {}, named, SPEC, drive, law_factory=standin.factory)


def settings(brake=0.3, force=96.2, delta_h=1.06e-3, omega=25.13) -> dict[str, float]:
    """Stand-A settings: brake set-point [N m], F_N [N], Delta h [m], w1 set-point [rad/s]."""
    return dict(brake_setpoint_N_m=brake, normal_force_N=force, delta_h_m=delta_h, omega_1_set_rad_s=omega)


def run_point(st: YokeStand, s, previous=None, *, index=0, seed=1, gate_time=20.0, timeout=30.0):
    """settle -> gate -> read; returns (settle report, gate data, outcome)."""
    point = st.start_point(index, s, previous, seed)
    report = point.settle(timeout)
    gate = point.gate(gate_time)
    return report, gate, point.read(gate)
