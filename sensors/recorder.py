"""Signal recorder (stand B's MC 201A): samples analogue channels at a fixed rate and digitises them.

Stand B's dynamometers 5 and momentometer 8 feed bridges (AR 405C) whose outputs the recorder
stores on disc ([Koziarski] section 3.2). Here the recorder takes the *true* quantity as a sampled time
series (t [s], value), evaluates it at its own sample instants t0 + k/f_s by linear
interpolation, passes it through the transducer (anything with ``volts(t, value) -> V``, e.g.
:class:`~sensors.dynamometer.Dynamometer`, :class:`~sensors.momentometer.Momentometer`) - so
noise and drift are drawn at the recorder's sample instants - and digitises with its converter.
Channels recorded with one recorder over the same span share the sample instants.

Defaults (assumed; the MC 201A's data are not known): 500 Hz, faster than the shortest contact
relaxation time 2b/v ~ 8.5 ms of Equations §3.2 needs for a few samples per time constant, and
a 16-bit +-10 V converter. No anti-alias filter is modelled (the stand signals are smooth).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from sensors import validate
from sensors.adc import Adc, DigitalReading

DEFAULT_SAMPLE_RATE_HZ = 500.0
"""Recorder sample rate [Hz] (assumed)."""


class Transducer(Protocol):
    """An analogue instrument: quantity samples at times [s] -> output voltage [V]."""

    def volts(self, t_s: np.ndarray, value: np.ndarray) -> np.ndarray: ...


@dataclass(frozen=True)
class Recorder:
    """Sample rate [Hz] and converter of the recorder."""

    sample_rate_Hz: float = DEFAULT_SAMPLE_RATE_HZ
    adc: Adc = field(default_factory=Adc)

    def __post_init__(self) -> None:
        validate.number("sample_rate_Hz", self.sample_rate_Hz, 0.0, 1.0e6, lo_open=True)

    def sample_times(self, start_s: float, stop_s: float) -> np.ndarray:
        """Sample instants start + k/f_s inside [start, stop] [s]."""
        start = validate.number("start_s", start_s)
        stop = validate.number("stop_s", stop_s, start)
        n = int(np.floor((stop - start) * self.sample_rate_Hz * (1.0 + 1e-12))) + 1
        return start + np.arange(n) / self.sample_rate_Hz

    def record(self, t_s: np.ndarray, value: np.ndarray, transducer: Transducer) -> DigitalReading:
        """Record the true series (t [s], value [N or N m]) at the recorder's rate over its span."""
        t, x = validate.time_series("t_s", t_s, "value", value)
        ts = self.sample_times(float(t[0]), float(t[-1]))
        return self.digitise(ts, np.interp(ts, t, x), transducer)

    def digitise(self, t_s: np.ndarray, value: np.ndarray, transducer: Transducer) -> DigitalReading:
        """Digitise the quantity given exactly at the sample instants ``t_s`` [s] (no resampling)."""
        t = np.asarray(t_s, dtype=float)
        return self.adc.convert(t, transducer.volts(t, value))

    def reader(self, transducer: Transducer) -> Callable[[np.ndarray, np.ndarray], DigitalReading]:
        """``read(t, value) -> DigitalReading`` for this transducer (used by the calibration)."""
        return lambda t_s, value: self.digitise(t_s, value, transducer)
