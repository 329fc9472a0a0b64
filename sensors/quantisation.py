"""Quantised readings: what a scale step (or a converter's LSB) does to the mean of n readings.

A reading is Q(x + n): the true value x [unit] plus the instrument's noise n ~ N(0, sigma^2),
rounded to the step Delta (a scale graduation, an ADC code width). With the position of x within
the step unknown (uniform - the state of knowledge of a user who has only the reading; GUM
4.3.7), quantisation theory (Widrow & Kollar, "Quantization Noise", 2008, ch. 4-5) gives:

* one reading's error e = Q(x + n) - x has the variance Delta^2/12 + sigma^2;
* its mean over the noise, the *step bias* b(x) = E[Q(x + n)] - x, is a periodic function of x
  (the sawtooth -x for sigma = 0, smoothed by the noise) with the Fourier series
  b(x) = sum_k (-1)^k (Delta/(pi k)) exp(-2 pi^2 k^2 sigma^2/Delta^2) sin(2 pi k x/Delta), hence
      V_b(sigma) = (Delta^2/(2 pi^2)) sum_k exp(-4 pi^2 k^2 sigma^2/Delta^2)/k^2,
  = Delta^2/12 at sigma = 0 and negligible for sigma >~ Delta/2 (the noise dithers the step);
* b(x) is the same for every reading of one value: it does not average out. The mean of n
  readings of a constant x therefore has the variance
      V_b(sigma) + (Delta^2/12 + sigma^2 - V_b(sigma))/n,
  the first term from the step (distributed like b: rectangular at sigma = 0), the second the
  scatter of the mean.

Units: whatever the reading's unit is (N m for the tangent balance, V for a converter); step
> 0 and noise_std >= 0 in that unit. Tested against a Monte Carlo of Q(x + n) in
tests/reduction/test_input_uncertainties.py.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from sensors import validate

_TAIL_EXPONENT = 40.0  # terms with 4 pi^2 k^2 r^2 > 40 (< 4e-18 of the first) are dropped [1]
_MAX_TERMS = 2_000_000  # below r ~ 5e-7 the remaining deficit is < 1e-6 of Delta^2/12


def step_bias_variance(step: float, noise_std: float) -> float:
    """V_b = variance of the step bias b(x) over the unknown position of x [unit^2] (series above)."""
    d = validate.number("step", step, 0.0, lo_open=True)
    s = validate.number("noise_std", noise_std, 0.0)
    r = s / d
    if r == 0.0:
        return d * d / 12.0
    c = 4.0 * math.pi**2 * r * r
    n_terms = min(int(math.sqrt(_TAIL_EXPONENT / c)) + 1, _MAX_TERMS)
    k = np.arange(1, n_terms + 1, dtype=float)
    total = float(np.sum(np.exp(-c * k * k) / (k * k)))
    return d * d * total / (2.0 * math.pi**2)


def reading_scatter_variance(step: float, noise_std: float) -> float:
    """Variance of single readings about their own mean, Delta^2/12 + sigma^2 - V_b [unit^2]
    (averaged over the unknown position of x): what the scatter s^2 of n readings estimates;
    exactly 0 without noise (every reading of a constant value is the same)."""
    v_b = step_bias_variance(step, noise_std)
    if noise_std == 0.0:
        return 0.0
    return max(step * step / 12.0 + noise_std * noise_std - v_b, 0.0)


def mean_reading_variance(step: float, noise_std: float, n: int) -> float:
    """Variance of the mean of n readings of a constant value [unit^2]: V_b + scatter/n."""
    n = validate.integer("n", n, 1)
    return step_bias_variance(step, noise_std) + reading_scatter_variance(step, noise_std) / n


def noise_std_from_scatter(step: float, scatter_variance: float) -> float:
    """The noise sigma [unit] whose reading_scatter_variance equals an observed s^2 [unit^2].

    A type-A estimate for readings with many samples (e.g. a converter channel sampled over a
    gate); 0 for s^2 = 0 (all readings equal). reading_scatter_variance rises monotonically
    from 0 (sigma = 0) towards sigma^2 + Delta^2/12.
    """
    d = validate.number("step", step, 0.0, lo_open=True)
    v = validate.number("scatter_variance", scatter_variance, 0.0)
    if v == 0.0:
        return 0.0
    hi = math.sqrt(v) + d
    return float(brentq(lambda s: reading_scatter_variance(d, s) - v, 0.0, hi, xtol=1e-12 * hi))
