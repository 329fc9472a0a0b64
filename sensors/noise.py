"""Noise and zero-drift effect components (the "off" form of each is ``None`` in the instrument).

Each component adds to a signal in the unit of the point where it acts (the amplifiers use them
input-referred, in volts [V]). All randomness comes from the numpy Generator handed in, so a run
is reproducible (see :mod:`sensors.streams`). Model choices [assumed, documented in
docs/instruments.md]:

* :class:`WhiteNoise` - independent Gaussian samples N(0, std^2) per reading.
* :class:`RandomWalkDrift` - a slow zero drift: a Wiener process W(t) with W(0) = 0 and
  Var W(t) = D^2 |t| (diffusion D [unit/sqrt(s)]), realised on a fixed time grid of step
  ``grid_step_s`` and interpolated linearly between grid points. Forward (t > 0) and backward
  (t < 0) halves come from two child streams, so the value at a time does not depend on the
  order or the batching of the calls (calibration before the run, then the run, gives the same
  drift as one long call).
* :class:`LinearDrift` - a zero drift growing linearly in time, rate drawn once ~ N(0, rate_std^2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError


def _generator(name: str, rng: object) -> np.random.Generator:
    if not isinstance(rng, np.random.Generator):
        raise InstrumentParameterError(name, rng, "a numpy.random.Generator (None switches the effect off)")
    return rng


@dataclass(frozen=True, eq=False)
class WhiteNoise:
    """Gaussian white noise of standard deviation ``std`` [unit of the signal, e.g. V], > 0."""

    std: float
    rng: np.random.Generator

    def __post_init__(self) -> None:
        validate.number("noise_std", self.std, 0.0, lo_open=True)
        _generator("noise_rng", self.rng)

    def sample(self, n: int) -> np.ndarray:
        """``n`` independent samples [unit of std]."""
        return self.rng.normal(0.0, self.std, size=n)


@dataclass(eq=False)
class RandomWalkDrift:
    """Zero drift as a random walk: diffusion [unit/sqrt(s)], e.g. V/sqrt(s); value 0 at t = 0."""

    diffusion: float
    rng: np.random.Generator
    grid_step_s: float = 1.0
    _forward: np.ndarray = field(init=False, repr=False)
    _backward: np.ndarray = field(init=False, repr=False)
    _streams: tuple[np.random.Generator, np.random.Generator] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        validate.number("drift_diffusion", self.diffusion, 0.0, lo_open=True)
        validate.number("drift_grid_step_s", self.grid_step_s, 0.0, lo_open=True)
        self._streams = tuple(_generator("drift_rng", self.rng).spawn(2))
        self._forward = np.zeros(1)
        self._backward = np.zeros(1)

    def _extend(self, which: int, n_points: int) -> None:
        path = self._forward if which == 0 else self._backward
        if path.size >= n_points:
            return
        grow = max(n_points - path.size, path.size, 64)
        steps = self._streams[which].normal(0.0, self.diffusion * np.sqrt(self.grid_step_s), size=grow)
        new = np.concatenate([path, path[-1] + np.cumsum(steps)])
        if which == 0:
            self._forward = new
        else:
            self._backward = new

    def sample(self, t: np.ndarray) -> np.ndarray:
        """Drift at the times ``t`` [s] (any order, any sign) [unit of diffusion * sqrt(s)]."""
        t = np.asarray(t, dtype=float)
        if t.size == 0:
            return np.zeros(0)
        k_hi = int(np.ceil(max(t.max(), 0.0) / self.grid_step_s)) + 1
        k_lo = int(np.ceil(max(-t.min(), 0.0) / self.grid_step_s)) + 1
        self._extend(0, k_hi + 1)
        self._extend(1, k_lo + 1)
        grid_values = np.concatenate([self._backward[k_lo:0:-1], self._forward[: k_hi + 1]])
        grid_times = np.arange(-k_lo, k_hi + 1) * self.grid_step_s
        return np.interp(t, grid_times, grid_values)


@dataclass(frozen=True, eq=False)
class LinearDrift:
    """Zero drift rate * (t - t0); the rate [unit/s] is drawn once from N(0, rate_std^2)."""

    rate_std: float
    rng: np.random.Generator
    t0_s: float = 0.0
    rate: float = field(init=False)

    def __post_init__(self) -> None:
        validate.number("drift_rate_std", self.rate_std, 0.0, lo_open=True)
        validate.number("drift_t0_s", self.t0_s)
        object.__setattr__(self, "rate", float(_generator("drift_rng", self.rng).normal(0.0, self.rate_std)))

    def sample(self, t: np.ndarray) -> np.ndarray:
        """Drift at the times ``t`` [s] [unit of rate * s]."""
        return self.rate * (np.asarray(t, dtype=float) - self.t0_s)


Drift = RandomWalkDrift | LinearDrift
"""A zero-drift component: anything with ``sample(t) -> values``."""
