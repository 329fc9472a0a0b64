"""Measured inputs of the reduction as plain numbers with standard uncertainties.

The stand adapters (rig.stands.*.reduction) build these from what a log records about each
instrument: its readings, its resolution and noise level, its calibration record. A reading
that is the mean of a scale's (or converter's) readings carries two parts (sensors.quantisation):
the scatter of the mean, ``u`` (normal), and the bias of the scale step, ``u_step``
(rectangular: it is the same for every reading of one value and does not average out). A "+-"
resolution quoted in the seed is a different statement - a bound - and gives half width/sqrt(3)
(rig.reduction.uncertainty.rectangular_u); docs/reduction.md section 4 compares the two readings.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.errors import ParameterError
from rig.reduction.uncertainty import Distribution, InputQuantity
from sensors.quantisation import noise_std_from_scatter, reading_scatter_variance, step_bias_variance


@dataclass(frozen=True)
class Measured:
    """A reading: value, standard uncertainty u of its random part (normal), and u_step of a scale
    step's bias (rectangular; 0 for a reading without a step). All in the unit of the field."""

    value: float
    u: float
    u_step: float = 0.0

    def __post_init__(self) -> None:
        validate.number("value", self.value)
        validate.number("u", self.u, 0.0)
        validate.number("u_step", self.u_step, 0.0)


def reading_inputs(name: str, unit_suffix: str, unit: str, reading: Measured, source: str) -> list[InputQuantity]:
    """The input quantities of one reading: ``<name>_<unit_suffix>`` (value, u, normal) and, when
    u_step > 0, ``<name>_step_<unit_suffix>`` (0, u_step, rectangular) whose value the chain adds;
    sources ``source`` and ``source (scale step)`` for the budget."""
    quantities = [InputQuantity(f"{name}_{unit_suffix}", reading.value, reading.u, unit, source)]
    if reading.u_step > 0.0:
        quantities.append(InputQuantity(f"{name}_step_{unit_suffix}", 0.0, reading.u_step, unit,
                                        f"{source} (scale step)", Distribution.RECTANGULAR))
    return quantities


def reading_value(values: Mapping[str, float], name: str, unit_suffix: str) -> float:
    """The reading's value in a chain evaluation: ``<name>_<suffix>`` plus its step input if present."""
    return values[f"{name}_{unit_suffix}"] + values.get(f"{name}_step_{unit_suffix}", 0.0)


@dataclass(frozen=True)
class ForceCalibration:
    """Linear force calibration signal = sensitivity F + offset, fitted against reference weights.

    sensitivity [V/N], offset [V], their standard uncertainties and covariance [V^2/N] from the
    fit; u_weights [N]: standard uncertainty of the reference weights *not already inside the
    fit's covariance*, added to the force as an independent term, F = (signal - offset)/sensitivity
    + e_w, e_w = 0 +- u_weights. A sensors.CalibrationRecord's covariance already holds the
    weights' error (its fit propagates the stacked weights, docs/instruments.md): with it,
    u_weights = 0 (counting them again would double them). A calibration quoted as a fit of the
    scatter alone (e.g. the worked example) needs the weights here.
    """

    sensitivity: float
    offset: float
    u_sensitivity: float
    u_offset: float
    covariance: float
    u_weights: float

    def __post_init__(self) -> None:
        validate.number("sensitivity", self.sensitivity, 0.0, lo_open=True)
        validate.number("offset", self.offset)
        validate.number("u_sensitivity", self.u_sensitivity, 0.0)
        validate.number("u_offset", self.u_offset, 0.0)
        bound = self.u_sensitivity * self.u_offset
        validate.number("covariance", self.covariance, -bound, bound)
        validate.number("u_weights", self.u_weights, 0.0)


def converter_mean(samples: np.ndarray, step: float) -> Measured:
    """Mean of a converter channel's samples [V] with u^2 = V_b(sigma) + s^2/n (one normal part).

    step: the converter's code width [V] as its calibration record logs it; sigma is estimated
    from the samples' scatter s^2 (type A - a channel has hundreds of samples per gate;
    sensors.quantisation). With the noise off and a constant signal, s = 0 and u = step/sqrt(12);
    with the noise on (sigma > step/2) u = s/sqrt(n). The step part is kept in one normal input:
    it is below 1 % of the calibration's share of u(F) for the stands' dynamometers.
    """
    x = np.asarray(samples, dtype=float)
    n = x.size
    scatter = _scatter(x)
    sigma = noise_std_from_scatter(step, scatter)
    return Measured(float(np.mean(x)), math.sqrt(step_bias_variance(step, sigma) + scatter / n))


def scale_mean(readings: np.ndarray, step: float, noise_std: float) -> Measured:
    """Mean of a graduated scale's readings (e.g. the tangent balance) [unit] in two parts.

    step, noise_std [unit]: the scale step and the reading noise the instrument states (its log
    readings). u = the scatter of the mean: the larger of the readings' own s^2 and the scatter
    the instrument alone gives, Delta^2/12 + sigma^2 - V_b, over n (a value that moves within the
    gate is covered); u_step = sqrt(V_b), the step's bias (rectangular, does not average out).
    A few readings cannot estimate sigma below the step, hence the stated noise level.
    """
    x = np.asarray(readings, dtype=float)
    n = x.size
    scatter = _scatter(x)
    scatter = max(scatter, reading_scatter_variance(step, noise_std))
    return Measured(float(np.mean(x)), math.sqrt(scatter / n), math.sqrt(step_bias_variance(step, noise_std)))


MAX_SAMPLE = 1e150
"""Largest |sample| [unit] whose square (the scatter) stays finite in float64 for any count."""


def _scatter(x: np.ndarray) -> float:
    """Sample variance s^2 (ddof 1) [unit^2]; exactly 0 when every sample is equal (np.var may
    leave an ulp of the mean there). A non-finite sample, or one whose square overflows (a damaged
    log's 1e300), raises ParameterError naming the sample and its value (no overflow warning)."""
    bad = np.flatnonzero(~(np.abs(x) <= MAX_SAMPLE))
    if bad.size:
        k = int(bad[0])
        raise ParameterError(f"samples[{k}]", float(x[k]), f"a finite sample with |x| <= {MAX_SAMPLE:g}")
    return float(np.var(x, ddof=1)) if x.size > 1 and np.ptp(x) > 0.0 else 0.0
