"""Stand B's measuring chain: dynamometers 5 (F_T, F_V), momentometer 8, the recorder, calibrations.

The bridges feed the recorder MC 201A (sensors.recorder) which samples the true signals at its
own rate; the log stores the digitised channels [V] and the calibration records, and the
reduction converts them (never with the design sensitivity). Calibrations run once per run
before the first point ("calibrated using special levers", [Koziarski] section 3.2 [text]): the
dynamometers with weights pulling along their axis (lever 1:1 [assumed]), the momentometer
with weights on an arm (parameters.py).

Random streams (rig.stands.base: from the run seed and the point index): white noise per point
and instrument (recorder_noise), per calibration and instrument; the zero drift of each
dynamometer is one random walk per run (dynamometer_drift), evaluated at the run time
t_run = index * point_period + t_point, so a resumed or parallel run reads the same drift.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from sensors import (
    CalibrationRecord,
    Lever,
    Recorder,
    TorqueArm,
    WeightSet,
    effect_rng,
    run_calibration,
    stand_b_dynamometer,
    stand_b_momentometer,
)
from rig.stands.disc_roller.parameters import StandBParameters

CHANNELS = {"F_T": "N", "F_V": "N", "T_Mo": "N m"}
"""Recorded channels and the unit of the quantity each one measures."""
INSTRUMENT_NAMES = {"F_T": "dynamometer_5_T", "F_V": "dynamometer_5_V", "T_Mo": "momentometer_8"}
CALIBRATION_START = {"F_T": -300.0, "F_V": -200.0, "T_Mo": -100.0}  # run time of each calibration [s] [assumed]
PIECES = 5  # weight pieces per calibration [assumed]
WEIGHT_BOUND = 0.098  # error bound of a piece [N] ([assumed] the 10 gf accuracy of stand A's weights)


@dataclass(frozen=True)
class InstrumentEffects:
    """Which instrument effects a scene named (absent: the component is not built)."""

    noise: bool
    drift: bool
    weight_errors: bool


def _transducer(channel: str, seed: int, stream: str, effects: InstrumentEffects):
    """One instrument with its noise stream ``stream`` and the run's drift (dynamometers)."""
    name = INSTRUMENT_NAMES[channel]
    noise = effect_rng(seed, f"{name}_{stream}", "noise") if effects.noise else None
    if channel == "T_Mo":
        return stand_b_momentometer(noise_rng=noise)
    drift = effect_rng(seed, name, "drift") if effects.drift else None
    return stand_b_dynamometer(noise_rng=noise, drift_rng=drift)


def calibrate(params: StandBParameters, seed: int, effects: InstrumentEffects) -> dict[str, CalibrationRecord]:
    """The three calibrations of a run (weights stacked on and off, least-squares line)."""
    recorder = Recorder(sample_rate_Hz=params.recorder_rate)
    records = {}
    for channel in CHANNELS:
        instrument = _transducer(channel, seed, "calibration", effects)
        if channel == "T_Mo":
            loading = TorqueArm(params.momentometer_arm)
            weights = WeightSet((params.momentometer_weight_piece,) * PIECES, WEIGHT_BOUND)
        else:
            loading = Lever(1.0, 1.0, 1.0)
            weights = WeightSet((params.dynamometer_weight_piece,) * PIECES, WEIGHT_BOUND)
        errors = effect_rng(seed, f"{INSTRUMENT_NAMES[channel]}_weights", "error") if effects.weight_errors else None
        records[channel] = run_calibration(
            recorder.reader(instrument), loading, weights, quantity_name=channel,
            t_start_s=CALIBRATION_START[channel], sample_rate_Hz=params.recorder_rate, weight_error_rng=errors,
        )
    return records


def record(
    params: StandBParameters, seed: int, index: int, effects: InstrumentEffects,
    t_s: np.ndarray, signals: Mapping[str, np.ndarray],
) -> dict[str, np.ndarray]:
    """Digitised channels [V] of the true signals (F_T, F_V [N], T_Mo [N m]) sampled at t_s [s].

    t_s are the recorder's instants in point time; drift is evaluated at the run time.
    """
    recorder = Recorder(sample_rate_Hz=params.recorder_rate)
    t_run = index * params.point_period + np.asarray(t_s, dtype=float)
    out = {}
    for channel in CHANNELS:
        instrument = _transducer(channel, seed, f"point_{index}", effects)
        out[channel] = np.asarray(recorder.digitise(t_run, signals[channel], instrument).volts, dtype=float)
    return out


def calibration_fields(record: CalibrationRecord) -> dict[str, tuple[float, str]]:
    """A record as {field: (value, unit)} for the log (the text field quantity_name is the key)."""
    return {k: v for k, v in record.as_dict().items() if k != "quantity_name"}


def record_from_fields(channel: str, fields: Mapping[str, float]) -> CalibrationRecord:
    """Rebuild a CalibrationRecord from the logged fields (values only, units as written)."""
    cov = fields["cov_sensitivity_offset"]
    return CalibrationRecord(
        quantity_name=channel, quantity_unit=CHANNELS[channel], reading_unit="V",
        sensitivity=fields["sensitivity"], offset=fields["offset"],
        covariance=((fields["u_sensitivity"] ** 2, cov), (cov, fields["u_offset"] ** 2)),
        residual_std=fields["residual_std"], n_steps=int(fields["n_steps"]),
    )
