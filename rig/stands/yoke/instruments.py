"""Stand A's measuring chain built from ``sensors``: counters, dynamometer 10, tangent balance, calibration.

* Counters 18/19 on strobe discs 13/14 (wheels 1, 2) with one common gate (timer 22); the marks'
  angle at the gate opening is random per point (seeded), which gives the +-1 count quantisation.
* Dynamometer 10 holds the yoke at the lever ``dynamometer_lever`` (102 mm) from axle 4 against
  F_y at R_v (42.5 mm): F_dyn = F_y R_v/102 mm (eq. 33, T_v = F_y R_v). Sign: a positive F_y (on
  wheel 1, Equations §1.1) gives a positive reading [our mounting convention]. Its output is
  sampled at ``dynamometer_rate_Hz`` over the gate; the drift (if on) is one random walk over the
  run, evaluated at the point's place in the run schedule (calibration first, then point k at
  calibration end + k ``point_period_s``), so points stay independent yet share one drift path.
  Each point records what the reduction needs for the zero's drift since the calibration
  (:func:`zero_drift_readings`: gain, the walk's variance rate, the zero's age).
* Calibration once per run with weights at the dynamometer itself ([Koziarski] section 3.1.1: weights of
  +-0.098 N accuracy, 102/42.5 x 0.098 N = 0.235 N on F_y): the calibrated quantity is the force
  on the dynamometer [N]; the weights' uncertainty is inside the fit's covariance.
* Tangent balance: the brake's reaction moment at the arm ``balance_arm`` (0.400 m), rounded to the
  scale step ``balance_step_N`` (the stated reading of the paper's accuracy, sensors.balance), read at
  ``balance_rate_Hz`` over the gate; the log's T2 is the mean of those readings.
Random streams: sensors.effect_rng(seed, instrument, effect); per point the seed is derived from
(run seed, point index) by :func:`point_seed`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from rig.logbook import Channel, Counter, CounterReadings, Quantity
from rig.stands.base import GateData
from rig.stands.yoke.parameters import YokeParameters
from sensors import (
    STAND_A_WEIGHTS,
    Adc,
    Amplifier,
    Bridge,
    BridgeConfiguration,
    CalibrationRecord,
    CounterChannel,
    Dynamometer,
    Lever,
    Photocell,
    RandomWalkDrift,
    SpeedCounters,
    StrobeDisc,
    TangentBalance,
    WhiteNoise,
    effect_rng,
    run_calibration,
)
from sensors.dynamometer import STAND_A_GAIN, STAND_A_STRAIN_PER_NEWTON

DYNAMOMETER = "dynamometer_10"
BALANCE = "tangent_balance"
CHANNELS = ("wheel_1", "wheel_2")
DISCS = ("strobe_disc_13", "strobe_disc_14")
CALIBRATION_DWELL_S = 2.0  # [s] per weight step (sensors default)
CALIBRATION_RATE_HZ = 50.0  # [Hz]


def point_seed(seed: int, index: int) -> int:
    """Seed [0, 2^63) of operating point ``index`` in a run with ``seed`` (SeedSequence spawn key)."""
    state = np.random.SeedSequence(seed, spawn_key=(index,)).generate_state(1, np.uint64)[0]
    return int(state) & (2**63 - 1)


def calibration_duration_s() -> float:
    """Run time taken by the calibration [s]: (2 n + 1) weight steps of CALIBRATION_DWELL_S."""
    return (2 * len(STAND_A_WEIGHTS.nominal_N) + 1) * CALIBRATION_DWELL_S


def dynamometer(effects: Mapping[str, Mapping[str, float]], run_seed: int, noise_seed: int,
                noise_effect: str = "noise") -> Dynamometer:
    """Dynamometer 10 (sensors' stand A transducer) with the named effects only."""
    noise = drift = None
    if "dynamometer_noise" in effects:
        noise = WhiteNoise(effects["dynamometer_noise"]["std_V"], effect_rng(noise_seed, DYNAMOMETER, noise_effect))
    if "dynamometer_drift" in effects:
        drift = RandomWalkDrift(effects["dynamometer_drift"]["diffusion_V_per_sqrt_s"],
                                effect_rng(run_seed, DYNAMOMETER, "drift"))
    return Dynamometer(STAND_A_STRAIN_PER_NEWTON, Bridge(BridgeConfiguration.FULL),
                       Amplifier(STAND_A_GAIN, noise=noise, drift=drift), Adc())


def calibrate(params: YokeParameters, effects: Mapping[str, Mapping[str, float]], seed: int) -> CalibrationRecord:
    """Calibrate dynamometer 10 with the weights at its own lever: reading [V] per N on the dynamometer."""
    lever = params.geometry.dynamometer_lever
    weight_rng = effect_rng(seed, "calibration_weights", "error") if "calibration_weight_error" in effects else None
    instrument = dynamometer(effects, seed, seed, noise_effect="calibration_noise")
    return run_calibration(instrument.read, Lever(lever, lever, lever), STAND_A_WEIGHTS, quantity_name="F_dyn",
                           dwell_s=CALIBRATION_DWELL_S, sample_rate_Hz=CALIBRATION_RATE_HZ,
                           weight_error_rng=weight_rng)


def calibration_quantities(record: CalibrationRecord) -> dict[str, Quantity]:
    """The record as log quantities (every numeric field with its unit; the quantity's name is text)."""
    fields = record.as_dict()
    return {name: Quantity(float(pair[0]), pair[1]) for name, pair in fields.items() if isinstance(pair, tuple)}


@dataclass(frozen=True, eq=False)
class PointInstruments:
    """The instruments of one operating point: counters, dynamometer, balance; the point's
    offset in the run schedule [s] (for the drift) and the sampling rates [Hz]."""

    counters: SpeedCounters
    dynamometer: Dynamometer
    balance: TangentBalance
    run_offset_s: float
    dynamometer_rate_Hz: float
    balance_rate_Hz: float
    force_ratio: float  # F_dyn/F_y = R_v/dynamometer lever [1]


def point_instruments(params: YokeParameters, effects: Mapping[str, Mapping[str, float]], seed: int,
                      index: int) -> PointInstruments:
    """Build the instruments of point ``index`` (random streams from (seed, index))."""
    s = point_seed(seed, index)
    channels = {}
    for name, disc, marks in zip(CHANNELS, DISCS, (params.marks_1, params.marks_2)):
        phase = float(effect_rng(s, disc, "phase").uniform(0.0, 2.0 * np.pi))
        noise = None
        if "counter_pulse_noise" in effects:
            noise = WhiteNoise(effects["counter_pulse_noise"]["std_V"], effect_rng(s, f"photocell_{name}", "noise"))
        channels[name] = CounterChannel(StrobeDisc(marks, phase), Photocell(amplitude_noise=noise))
    balance_noise = None
    if "balance_noise" in effects:
        balance_noise = WhiteNoise(effects["balance_noise"]["std_N"], effect_rng(s, BALANCE, "noise"))
    g = params.geometry
    return PointInstruments(
        counters=SpeedCounters(channels),
        dynamometer=dynamometer(effects, seed, s),
        balance=TangentBalance(arm_m=g.balance_arm, resolution_N=params.balance_step_N, noise=balance_noise),
        run_offset_s=calibration_duration_s() + index * params.point_period_s,
        dynamometer_rate_Hz=params.dynamometer_rate_Hz,
        balance_rate_Hz=params.balance_rate_Hz,
        force_ratio=g.yoke_lever / g.dynamometer_lever,
    )


def _sample_times(start: float, duration: float, rate: float) -> np.ndarray:
    n = max(int(np.floor(duration * rate * (1.0 + 1e-12))), 1)
    return start + np.arange(n) / rate


@dataclass(frozen=True)
class Measurement:
    """What the instruments gave over one gate: log channels, counters and scalar readings."""

    channels: dict[str, Channel]
    counters: CounterReadings
    readings: dict[str, Quantity]


def zero_drift_readings(inst: PointInstruments, gate_centre_s: float) -> dict[str, Quantity]:
    """What the reduction needs for the dynamometer's zero drift since the calibration took the zero:
    the amplifier gain [V/V], the input-referred random walk's variance rate D^2 [V^2/s] (0: drift
    off) and the zero's age at the gate's centre [s], counted from the calibration's mid-time (its
    offset is the zero of the whole stacking sequence)."""
    amplifier = inst.dynamometer.amplifier
    drift = amplifier.drift
    rate = drift.diffusion**2 if isinstance(drift, RandomWalkDrift) else 0.0
    age = inst.run_offset_s + gate_centre_s - 0.5 * calibration_duration_s()
    return {
        "dynamometer_gain": Quantity(float(amplifier.gain), "1"),
        "dynamometer_drift_variance_rate": Quantity(float(rate), "V^2/s"),
        "dynamometer_zero_age": Quantity(float(age), "s"),
    }


def measure(inst: PointInstruments, gate: GateData) -> Measurement:
    """Feed the gate's true signals (theta_1/2 [rad], F_y [N], brake moment [N m]) to the instruments."""
    t = np.asarray(gate.t_s, dtype=float)
    sig = gate.signals
    t0, duration = gate.gate_open_s, gate.gate_time_s
    count = inst.counters.measure({"wheel_1": (t, sig["theta_1"]), "wheel_2": (t, sig["theta_2"])}, t0, duration)
    td = _sample_times(t0, duration, inst.dynamometer_rate_Hz)
    f_dyn = np.interp(td, t, sig["F_y"]) * inst.force_ratio
    dyn = inst.dynamometer.read(inst.run_offset_s + td, f_dyn)
    tb = _sample_times(t0, duration, inst.balance_rate_Hz)
    bal = inst.balance.read(np.interp(tb, t, sig["brake_moment"]))
    counters = CounterReadings(duration, {n: Counter(count.counts[n], count.marks[n]) for n in CHANNELS})
    channels = {
        DYNAMOMETER: Channel(np.asarray(dyn.volts), "V", inst.dynamometer_rate_Hz, float(td[0])),
        BALANCE: Channel(bal.moment_N_m, "N m", inst.balance_rate_Hz, float(tb[0])),
    }
    readings = {
        "T2": Quantity(float(np.mean(bal.moment_N_m)), "N m"),
        "balance_over_range": Quantity(float(np.count_nonzero(bal.over_range)), "1"),
        "balance_resolution": Quantity(bal.resolution_N_m, "N m"),  # scale step, for the reduction's u(T2)
        "balance_noise_std": Quantity(bal.noise_std_N_m, "N m"),  # reading noise (0: effect off)
        "dynamometer_signal": Quantity(float(np.mean(dyn.volts)), "V"),
        "dynamometer_clipped": Quantity(float(dyn.n_clipped), "1"),
        **zero_drift_readings(inst, t0 + 0.5 * duration),
    }
    return Measurement(channels, counters, readings)
