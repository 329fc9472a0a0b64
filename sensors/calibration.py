"""Calibration with known weights through a lever: least-squares sensitivity and offset.

Procedure (stand A, [Koziarski] section 3.1.1; stand B "calibrated using special levers", 3.2): weight
pieces are stacked one by one on a lever and taken off again (loads 0, w1, w1+w2, ..., all,
..., 0); at each step the instrument is read for ``dwell_s`` and the readings averaged. The
straight line  reading = s Q + o  (s: sensitivity [V per unit of Q], o: offset [V]) is fitted
by least squares to the step means against the *nominal* calibrated quantity Q (what the
experimenter knows), and its covariance is reported. A reduction converts readings with this
record - never with the instrument's true (design) sensitivity.

Weight uncertainty model (choice, docs/instruments.md): the paper's "weights with accuracy of
0.098 N" (= 10 gf, a round tolerance) is taken as a *bound* of each piece's error, not as a
standard uncertainty: it is a stated limit, and the author propagates it linearly
(102/42.5 x 0.098 N = 0.235 N) like a limit of error. Following GUM 4.3.7 with only limits
known, each piece's error is uniform in +-bound, u_w = bound/sqrt(3) = 0.0566 N, independent
between pieces. Stacking makes the step loads correlated: V_Q = (dQ/dW)^2 u_w^2 A A^T with A
the 0/1 stacking matrix.

Covariance of (s, o): with L = (X^T X)^-1 X^T, X = [Q_nom, 1],
    Cov = L (sigma^2 I + s^2 V_Q) L^T,
where the reading scatter sigma^2 of a step mean is estimated from the residuals after removing
the part the weight errors put there: E[RSS] = sigma^2 (n - 2) + s^2 tr(M V_Q), M = I - X L,
so sigma^2 = max(RSS - s^2 tr(M V_Q), 0)/(n - 2) (no double counting).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np

from sensors import validate
from sensors.adc import DigitalReading
from sensors.errors import InstrumentParameterError

STAND_A_WEIGHT_BOUND_N = 0.098
"""Error bound of each calibration weight [N] (text: "accuracy of 0.098 N" = 10 gf)."""
STAND_A_PIECE_N = 0.200 * 9.80665
"""Nominal calibration piece [N] (assumed: 200 g pieces)."""


@dataclass(frozen=True)
class Lever:
    """Lever about one pivot: weights hang at weight_arm_m, the sensor reacts at sensor_arm_m,
    the calibrated force quantity acts at quantity_arm_m [m] (moment balance about the pivot)."""

    weight_arm_m: float
    sensor_arm_m: float
    quantity_arm_m: float
    quantity_unit: ClassVar[str] = "N"

    def __post_init__(self) -> None:
        for name in ("weight_arm_m", "sensor_arm_m", "quantity_arm_m"):
            validate.number(name, getattr(self, name), 0.0, 10.0, lo_open=True)

    @property
    def quantity_per_weight(self) -> float:
        """dQ/dW = weight_arm/quantity_arm [1]."""
        return self.weight_arm_m / self.quantity_arm_m

    def sensor_input(self, weight_N: np.ndarray) -> np.ndarray:
        """Force on the sensor [N] from the weight [N]."""
        return np.asarray(weight_N, dtype=float) * self.weight_arm_m / self.sensor_arm_m

    def quantity(self, weight_N: np.ndarray) -> np.ndarray:
        """Calibrated force quantity [N] from the weight [N]."""
        return np.asarray(weight_N, dtype=float) * self.quantity_per_weight


STAND_A_LEVER = Lever(weight_arm_m=0.102, sensor_arm_m=0.102, quantity_arm_m=0.0425)
"""Stand A yoke: weights and dynamometer 10 at 102 mm from axle 4, F_y at R_v = 42.5 mm
(text; "42.2" is a misprint of 42.5, Equations §3.1). Q = F_y = W 102/42.5."""


@dataclass(frozen=True)
class TorqueArm:
    """Calibration arm of length arm_m [m] for a torque sensor: Q = sensor input = W arm [N m]."""

    arm_m: float
    quantity_unit: ClassVar[str] = "N m"

    def __post_init__(self) -> None:
        validate.number("arm_m", self.arm_m, 0.0, 10.0, lo_open=True)

    @property
    def quantity_per_weight(self) -> float:
        """dQ/dW = arm [m]."""
        return self.arm_m

    def sensor_input(self, weight_N: np.ndarray) -> np.ndarray:
        """Torque on the sensor [N m]."""
        return np.asarray(weight_N, dtype=float) * self.arm_m

    def quantity(self, weight_N: np.ndarray) -> np.ndarray:
        """Calibrated torque [N m]."""
        return self.sensor_input(weight_N)


Loading = Lever | TorqueArm


@dataclass(frozen=True)
class WeightSet:
    """Nominal weight pieces [N] and the error bound of each piece [N] (uniform within +-bound)."""

    nominal_N: tuple[float, ...]
    error_bound_N: float = STAND_A_WEIGHT_BOUND_N

    def __post_init__(self) -> None:
        if len(self.nominal_N) < 1:
            raise InstrumentParameterError("nominal_N", self.nominal_N, "at least one weight piece")
        for i, w in enumerate(self.nominal_N):
            validate.number(f"nominal_N[{i}]", w, 0.0, 1.0e4, lo_open=True)
        validate.number("error_bound_N", self.error_bound_N, 0.0)

    @property
    def standard_uncertainty_N(self) -> float:
        """u of one piece, bound/sqrt(3) [N] (rectangular distribution)."""
        return self.error_bound_N / np.sqrt(3.0)

    def actual_N(self, error_rng: np.random.Generator | None) -> np.ndarray:
        """The pieces' true weights [N]: nominal when the weight-error effect is off (None)."""
        nominal = np.asarray(self.nominal_N, dtype=float)
        if error_rng is None:
            return nominal
        return nominal + error_rng.uniform(-self.error_bound_N, self.error_bound_N, size=nominal.size)


STAND_A_WEIGHTS = WeightSet((STAND_A_PIECE_N,) * 5)
"""Five 200 g pieces (assumed): up to 9.8 N on dynamometer 10, 23.5 N of F_y."""


def stacking_schedule(n_pieces: int) -> np.ndarray:
    """The stacking schedule: load up piece by piece, then unload.

    Parameters
    ----------
    n_pieces : int
        Number of weight pieces, >= 1.

    Returns
    -------
    numpy.ndarray
        0/1 matrix A [steps x pieces], 2 n + 1 steps: row k says which pieces hang at step k.
    """
    n = validate.integer("n_pieces", n_pieces, 1)
    up = np.tril(np.ones((n + 1, n)), -1)
    return np.vstack([up, up[-2::-1]])


@dataclass(frozen=True)
class CalibrationRecord:
    """Result of a calibration: reading = sensitivity * Q + offset, with covariance of (s, o).

    Units: sensitivity [reading_unit per quantity_unit], offset [reading_unit], covariance
    [[s^2, s*o], [s*o, o^2]] in those units; residual_std is the scatter of a step mean;
    reading_resolution [reading_unit] is the code width of the converter that made the
    readings (0 = not recorded), logged with the record so that a reduction knows the step of
    the channel it converts (sensors.quantisation).
    """

    quantity_name: str
    quantity_unit: str
    reading_unit: str
    sensitivity: float
    offset: float
    covariance: tuple[tuple[float, float], tuple[float, float]]
    residual_std: float
    n_steps: int
    reading_resolution: float = 0.0

    @property
    def u_sensitivity(self) -> float:
        """Standard uncertainty of the sensitivity [reading_unit per quantity_unit]."""
        return float(np.sqrt(self.covariance[0][0]))

    @property
    def u_offset(self) -> float:
        """Standard uncertainty of the offset [reading_unit]."""
        return float(np.sqrt(self.covariance[1][1]))

    def to_quantity(self, reading: DigitalReading | np.ndarray) -> np.ndarray:
        """Q = (reading - offset)/sensitivity [quantity_unit]; clipped samples become NaN."""
        if isinstance(reading, DigitalReading):
            q = (reading.volts - self.offset) / self.sensitivity
            return np.where(reading.clipped, np.nan, q)
        return (np.asarray(reading, dtype=float) - self.offset) / self.sensitivity

    def quantity_standard_uncertainty(self, reading: np.ndarray, reading_std: float = 0.0) -> np.ndarray:
        """First-order u(Q) [quantity_unit] from Cov(s, o) and a reading scatter [reading_unit]."""
        validate.number("reading_std", reading_std, 0.0)
        s = self.sensitivity
        q = (np.asarray(reading, dtype=float) - self.offset) / s
        (vss, vso), (_, voo) = self.covariance
        var = (q / s) ** 2 * vss + voo / s**2 + 2.0 * q * vso / s**2 + (reading_std / s) ** 2
        return np.sqrt(np.maximum(var, 0.0))

    def scaled(self, factor: float, quantity_name: str, quantity_unit: str) -> CalibrationRecord:
        """The record for Q' = factor * Q (e.g. F_y from the dynamometer force, 102/42.5)."""
        f = validate.number("factor", factor)
        if f == 0.0:
            raise InstrumentParameterError("factor", factor, "a non-zero real number")
        (vss, vso), (_, voo) = self.covariance
        return replace(
            self,
            quantity_name=quantity_name,
            quantity_unit=quantity_unit,
            sensitivity=self.sensitivity / f,
            covariance=((vss / f**2, vso / f), (vso / f, voo)),
        )

    def with_zero(self, zero_readings: np.ndarray) -> CalibrationRecord:
        """Re-zeroed record: offset = mean of unloaded readings [reading_unit] (taring against drift)."""
        z = validate.finite_array("zero_readings", zero_readings)
        var_o = z.var(ddof=1) / z.size if z.size > 1 else self.residual_std**2
        vss = self.covariance[0][0]
        return replace(self, offset=float(z.mean()), covariance=((vss, 0.0), (0.0, float(var_o))))

    def as_dict(self) -> dict[str, object]:
        """Plain values with units, for a measurement log."""
        su = f"{self.reading_unit}/{self.quantity_unit}"
        return {
            "quantity_name": self.quantity_name,
            "sensitivity": (self.sensitivity, su),
            "offset": (self.offset, self.reading_unit),
            "u_sensitivity": (self.u_sensitivity, su),
            "u_offset": (self.u_offset, self.reading_unit),
            "cov_sensitivity_offset": (self.covariance[0][1], self.reading_unit + "^2/" + self.quantity_unit),
            "residual_std": (self.residual_std, self.reading_unit),
            "n_steps": (self.n_steps, "1"),
            "reading_resolution": (self.reading_resolution, self.reading_unit),
        }


def fit_line(
    quantity: np.ndarray,
    readings: np.ndarray,
    quantity_covariance: np.ndarray,
    *,
    quantity_name: str,
    quantity_unit: str,
    reading_unit: str = "V",
    reading_resolution: float = 0.0,
) -> CalibrationRecord:
    """Least-squares line through (Q_nominal, step-mean reading) with the covariance model above.

    Parameters
    ----------
    quantity : numpy.ndarray
        Nominal calibration quantity per step [quantity_unit, e.g. N or N m], at least 3 steps.
    readings : numpy.ndarray
        Step-mean readings [reading_unit].
    quantity_covariance : numpy.ndarray
        Covariance of the steps' true quantities [quantity_unit^2] (the weights' errors, shared by
        the steps that carry the same piece).
    quantity_name, quantity_unit : str
        What was calibrated and its unit, kept in the record.
    reading_unit : str, optional
        Unit of the readings (default ``"V"``).
    reading_resolution : float, optional
        The converter's code width [reading_unit], kept in the record (0: unknown).

    Returns
    -------
    CalibrationRecord
        Sensitivity [reading_unit / quantity_unit], offset [reading_unit], their uncertainties and
        covariance, the residual scatter.
    """
    q = validate.finite_array("quantity", quantity, min_length=3)
    y = validate.finite_array("readings", readings, min_length=3)
    if y.size != q.size:
        raise InstrumentParameterError("readings", f"{y.size} values", f"as many as quantity ({q.size})")
    v_q = np.asarray(quantity_covariance, dtype=float)
    if v_q.shape != (q.size, q.size):
        raise InstrumentParameterError("quantity_covariance", f"shape {v_q.shape}", f"shape ({q.size}, {q.size})")
    if np.ptp(q) == 0.0:
        raise InstrumentParameterError("quantity", q.tolist(), "at least two different loads")
    x = np.column_stack([q, np.ones_like(q)])
    lmat = np.linalg.solve(x.T @ x, x.T)
    beta = lmat @ y
    resid = y - x @ beta
    m = np.eye(q.size) - x @ lmat
    s = beta[0]
    dof = q.size - 2
    sigma2 = max(float(resid @ resid) - s**2 * float(np.trace(m @ v_q)), 0.0) / dof
    cov = lmat @ (sigma2 * np.eye(q.size) + s**2 * v_q) @ lmat.T
    return CalibrationRecord(
        quantity_name=quantity_name,
        quantity_unit=quantity_unit,
        reading_unit=reading_unit,
        sensitivity=float(s),
        offset=float(beta[1]),
        covariance=((float(cov[0, 0]), float(cov[0, 1])), (float(cov[1, 0]), float(cov[1, 1]))),
        residual_std=float(np.sqrt(sigma2)),
        n_steps=int(q.size),
        reading_resolution=float(validate.number("reading_resolution", reading_resolution, 0.0)),
    )


def run_calibration(
    read: Callable[[np.ndarray, np.ndarray], DigitalReading],
    loading: Loading,
    weights: WeightSet,
    *,
    quantity_name: str,
    t_start_s: float = 0.0,
    dwell_s: float = 2.0,
    sample_rate_Hz: float = 50.0,
    weight_error_rng: np.random.Generator | None = None,
) -> CalibrationRecord:
    """Simulate the stacking calibration and fit it.

    A clipped sample raises (the loads exceed the converter range).

    Parameters
    ----------
    read : callable
        ``read(t [s], sensor input [N or N m]) -> DigitalReading``: the instrument (e.g.
        ``Dynamometer.read`` or ``Recorder.reader(momentometer)``).
    loading : Lever or TorqueArm
        How the weights load the sensor.
    weights : WeightSet
        The weight pieces (nominal masses [kg] and their tolerances).
    quantity_name : str
        What is calibrated (kept in the record).
    t_start_s : float, optional
        Start time [s] (default 0).
    dwell_s : float, optional
        Duration of each step [s] (default 2).
    sample_rate_Hz : float, optional
        Sampling rate [Hz] (default 50).
    weight_error_rng : numpy.random.Generator, optional
        Stream of the weights' true deviations from nominal; None: the weights are exact.

    Returns
    -------
    CalibrationRecord
        The fitted line (rig's reduction reads sensitivity and offset from it).
    """
    t0 = validate.number("t_start_s", t_start_s)
    dwell = validate.number("dwell_s", dwell_s, 0.0, 3600.0, lo_open=True)
    rate = validate.number("sample_rate_Hz", sample_rate_Hz, 0.0, 1.0e6, lo_open=True)
    per_step = max(int(round(dwell * rate)), 1)
    a = stacking_schedule(len(weights.nominal_N))
    load_true = a @ weights.actual_N(weight_error_rng)
    load_nominal = a @ np.asarray(weights.nominal_N, dtype=float)
    n_steps = a.shape[0]
    t = t0 + (np.arange(n_steps)[:, None] * dwell + np.arange(per_step)[None, :] / rate).ravel()
    reading = read(t, np.repeat(loading.sensor_input(load_true), per_step))
    if reading.n_clipped:
        raise InstrumentParameterError(
            "weights", f"{load_nominal.max():g} N in total", "loads that keep the instrument inside its converter range"
        )
    means = np.asarray(reading.volts, dtype=float).reshape(n_steps, per_step).mean(axis=1)
    v_q = (loading.quantity_per_weight * weights.standard_uncertainty_N) ** 2 * (a @ a.T)
    return fit_line(
        loading.quantity(load_nominal), means, v_q,
        quantity_name=quantity_name, quantity_unit=loading.quantity_unit, reading_resolution=reading.lsb_V,
    )
