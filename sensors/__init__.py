"""friction-rig instruments: the measuring chain of Koziarski's two test stands.

A stand-alone package (it does not import ``rig``): strain-gauge dynamometers, the tangent
balance, the torque meter (momentometer), stroboscope discs with photocells, pulse amplifiers
and counters on a common gate timer, the signal recorder, and the calibration with weights.
Noise and drift are optional effect components (``None`` = off, never called); random streams
come from :func:`sensors.streams.effect_rng`. See docs/instruments.md.
"""

from __future__ import annotations

from sensors.adc import Adc, DigitalReading
from sensors.amplifier import Amplifier
from sensors.balance import BalanceReading, TangentBalance, stand_a_balance
from sensors.bridge import Bridge, BridgeConfiguration
from sensors.calibration import (
    STAND_A_LEVER,
    STAND_A_WEIGHTS,
    CalibrationRecord,
    Lever,
    TorqueArm,
    WeightSet,
    fit_line,
    run_calibration,
    stacking_schedule,
)
from sensors.counters import (
    COUNT_QUANTISATION_STD,
    CounterChannel,
    CountReading,
    Photocell,
    PulseAmplifier,
    SpeedCounters,
    count_quantisation_variance,
    stand_a_counters,
)
from sensors.dynamometer import Dynamometer, stand_a_dynamometer, stand_b_dynamometer
from sensors.errors import InstrumentParameterError
from sensors.momentometer import Momentometer, stand_b_momentometer
from sensors.noise import LinearDrift, RandomWalkDrift, WhiteNoise
from sensors.recorder import Recorder
from sensors.streams import effect_rng
from sensors.strobe import StrobeDisc

__all__ = [
    "Adc", "Amplifier", "BalanceReading", "Bridge", "BridgeConfiguration", "COUNT_QUANTISATION_STD",
    "CalibrationRecord", "CountReading", "CounterChannel", "DigitalReading", "Dynamometer",
    "InstrumentParameterError", "Lever", "LinearDrift", "Momentometer", "Photocell", "PulseAmplifier",
    "RandomWalkDrift", "Recorder", "STAND_A_LEVER", "STAND_A_WEIGHTS", "SpeedCounters", "StrobeDisc",
    "TangentBalance", "TorqueArm", "WeightSet", "WhiteNoise", "count_quantisation_variance", "effect_rng",
    "fit_line", "run_calibration", "stacking_schedule", "stand_a_balance", "stand_a_counters",
    "stand_a_dynamometer", "stand_b_dynamometer", "stand_b_momentometer",
]
