"""Tangent balance (stand A, braking moment T2 of wheel 2): moment [N m] -> scale reading.

The brake's reaction moment is taken by an arm of length r and balanced by a pendulum whose
deflection is read on a scale graduated in force at the arm; the reading is the force at the
arm rounded to the scale step times the arm. The paper gives an accuracy of 0.049 N (5 gf) at
the arm "corresponding to" 0.0196 N m, hence the arm r = 0.0196/0.049 = 0.400 m (Equations §3.1).

How to read "accuracy 0.049 N" is a stated parameter, the scale step ``resolution_N`` [N]:
* as a +-limit of the reading error (the default, conservative): step 2 x 0.049 = 0.098 N, so the
  rounding error lies within +-0.049 N, u = step/sqrt(12) = 0.0283 N at the arm = 0.0113 N m;
* as the scale step itself: step 0.049 N, error within +-0.0245 N, u = 0.0141 N = 0.0057 N m.
The log records the step (in moment) that the reduction then uses, so the two cannot disagree;
docs/instruments.md says why the limit is the default. Readings beyond the full scale stick at
+-full scale and are flagged (never silent). Optional noise [N at the arm] models reading
scatter (pivot friction, pointer jitter); off by default. Each reading states the step and the
noise level in moment units, so that a log carries what a reduction needs for the uncertainty
of their mean (sensors.quantisation: the step's bias does not average out, the scatter does).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError
from sensors.noise import WhiteNoise

STAND_A_ACCURACY_N = 0.049
"""The paper's "accuracy" of the balance at the arm [N] (text: 0.049 N = 5 gf)."""
STEP_IF_ACCURACY_IS_LIMIT_N = 2.0 * STAND_A_ACCURACY_N
"""Scale step [N] whose rounding error lies within +-0.049 N (the accuracy read as a +-limit; default)."""
STEP_IF_ACCURACY_IS_STEP_N = STAND_A_ACCURACY_N
"""Scale step [N] if the accuracy is read as the scale step itself."""
STAND_A_ARM_M = 0.0196 / 0.049
"""Arm of the balance [m] (computed from the text: 0.0196 N m / 0.049 N = 0.400 m)."""
STAND_A_FULL_SCALE_N = 25.0
"""Full scale at the arm [N] (assumed: T2 <= mu F_N r2 ~ 7.8 N m, i.e. <= 19.5 N at 0.4 m)."""
DEFAULT_NOISE_STD_N = 0.01
"""Reading scatter at the arm when the noise effect is on [N] (assumed, ~ step/5)."""


@dataclass(frozen=True, eq=False)
class BalanceReading:
    """Moment readings [N m], a flag per reading for over-range (reading stuck at full scale),
    the scale step in moment resolution_N_m [N m] and the reading noise noise_std_N_m [N m]
    (0 when the noise effect is off)."""

    moment_N_m: np.ndarray
    over_range: np.ndarray
    resolution_N_m: float
    noise_std_N_m: float


@dataclass(frozen=True, eq=False)
class TangentBalance:
    """Arm [m], scale step at the arm [N] (default: the paper's accuracy read as a +-limit, above),
    full scale at the arm [N], optional noise [N]."""

    arm_m: float = STAND_A_ARM_M
    resolution_N: float = STEP_IF_ACCURACY_IS_LIMIT_N
    full_scale_N: float = STAND_A_FULL_SCALE_N
    noise: WhiteNoise | None = None

    def __post_init__(self) -> None:
        validate.number("balance_arm_m", self.arm_m, 0.0, 5.0, lo_open=True)
        validate.number("balance_resolution_N", self.resolution_N, 0.0, 100.0, lo_open=True)
        validate.number("balance_full_scale_N", self.full_scale_N, 0.0, 1.0e5, lo_open=True)
        if self.full_scale_N < self.resolution_N:
            raise InstrumentParameterError(
                "balance_full_scale_N", self.full_scale_N, f">= balance_resolution_N = {self.resolution_N}"
            )

    @property
    def resolution_N_m(self) -> float:
        """Scale step in moment, arm * resolution [N m] (stand A: 0.0392 N m, or 0.0196 N m read as a step)."""
        return self.arm_m * self.resolution_N

    @property
    def resolution_standard_uncertainty_N_m(self) -> float:
        """Standard uncertainty from the scale step, step/sqrt(12) [N m]."""
        return self.resolution_N_m / np.sqrt(12.0)

    def read(self, moment_N_m: np.ndarray | float) -> BalanceReading:
        """Scale readings [N m] for the true moments [N m] (array or scalar)."""
        m = validate.finite_array("moment_N_m", np.atleast_1d(np.asarray(moment_N_m, dtype=float)))
        force = m / self.arm_m
        if self.noise is not None:
            force = force + self.noise.sample(force.size)
        over = np.abs(force) > self.full_scale_N
        force = np.clip(force, -self.full_scale_N, self.full_scale_N)
        reading = np.rint(force / self.resolution_N) * self.resolution_N * self.arm_m
        noise_std = 0.0 if self.noise is None else self.noise.std * self.arm_m
        return BalanceReading(moment_N_m=reading, over_range=over, resolution_N_m=self.resolution_N_m,
                              noise_std_N_m=noise_std)


def stand_a_balance(*, noise_rng: np.random.Generator | None = None) -> TangentBalance:
    """Stand A's tangent balance with the defaults above.

    Parameters
    ----------
    noise_rng : numpy.random.Generator, optional
        The reading noise's stream; None: no noise (the effect is not built).

    Returns
    -------
    TangentBalance
        The balance [N m readings].
    """
    noise = None if noise_rng is None else WhiteNoise(DEFAULT_NOISE_STD_N, noise_rng)
    return TangentBalance(noise=noise)
