"""Bridge (instrumentation) amplifier: output [V] = gain * (input [V] + drift + noise).

Noise and zero drift are input-referred [V at the amplifier input] - the way bridge amplifiers
are specified - and are optional components: ``None`` means off (never built, never called).
The bandwidth is taken as much higher than the signals of the stands (the instruments are read
slower than the contact relaxation, Equations §4.2), so no filter is modelled [assumed].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sensors import validate
from sensors.noise import Drift, WhiteNoise


@dataclass(frozen=True, eq=False)
class Amplifier:
    """Gain [V/V] > 0 with optional input-referred white noise and zero drift [V]."""

    gain: float
    noise: WhiteNoise | None = None
    drift: Drift | None = None

    def __post_init__(self) -> None:
        validate.number("amplifier_gain", self.gain, 0.0, 1.0e6, lo_open=True)

    def output_V(self, t: np.ndarray, v_in: np.ndarray) -> np.ndarray:
        """Output voltage [V] for input ``v_in`` [V] sampled at the times ``t`` [s]."""
        v = np.array(v_in, dtype=float)
        if self.drift is not None:
            v += self.drift.sample(t)
        if self.noise is not None:
            v += self.noise.sample(v.size)
        return self.gain * v
