"""Analogue-to-digital converter: volts [V] -> integer codes, with clipping reported.

Straight-binary mid-tread converter over [v_min, v_max] with ``bits`` bits:
LSB = (v_max - v_min)/2^bits, code = round((v - v_min)/LSB) in [0, 2^bits - 1], and the
reading in volts is v_min + code LSB. The quantisation error is within +-LSB/2 (standard
uncertainty LSB/sqrt(12)) while the input stays inside [v_min - LSB/2, v_max - 3 LSB/2];
outside it the code sticks at a rail and the sample is flagged in ``DigitalReading.clipped``
(never silent: ``n_clipped`` counts them and conversions to a physical quantity give NaN there).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError

DEFAULT_V_MIN = -10.0
"""Lower end of the input range [V] (assumed: the usual +-10 V range)."""
DEFAULT_V_MAX = 10.0
"""Upper end of the input range [V] (assumed)."""
DEFAULT_BITS = 16
"""Resolution [bit] (assumed)."""


def _readonly(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


@dataclass(frozen=True, eq=False)
class DigitalReading:
    """Digitised samples: times [s], codes [1], volts [V], clipped (bool per sample), and the
    converter's code width lsb_V [V] (its resolution, which a reduction needs for the step
    bias of a mean: sensors.quantisation)."""

    time_s: np.ndarray
    codes: np.ndarray
    volts: np.ndarray
    clipped: np.ndarray
    lsb_V: float

    @property
    def n_clipped(self) -> int:
        """Number of samples at a rail of the converter [1]."""
        return int(np.count_nonzero(self.clipped))


@dataclass(frozen=True)
class Adc:
    """A converter with input range [v_min_V, v_max_V] [V] and ``bits`` bits (4..24)."""

    v_min_V: float = DEFAULT_V_MIN
    v_max_V: float = DEFAULT_V_MAX
    bits: int = DEFAULT_BITS

    def __post_init__(self) -> None:
        validate.number("adc_v_min_V", self.v_min_V, -1000.0, 1000.0)
        validate.number("adc_v_max_V", self.v_max_V, -1000.0, 1000.0)
        if not self.v_max_V > self.v_min_V:
            raise InstrumentParameterError("adc_v_max_V", self.v_max_V, f"greater than adc_v_min_V = {self.v_min_V}")
        validate.integer("adc_bits", self.bits, 4, 24)

    @property
    def lsb_V(self) -> float:
        """Code width (least significant bit) [V]."""
        return (self.v_max_V - self.v_min_V) / 2**self.bits

    @property
    def max_code(self) -> int:
        """Highest code 2^bits - 1 [1]."""
        return 2**self.bits - 1

    def convert(self, t: np.ndarray, volts: np.ndarray) -> DigitalReading:
        """Digitise ``volts`` [V] sampled at times ``t`` [s]; clipped samples are flagged."""
        v = np.asarray(volts, dtype=float)
        raw = np.rint((v - self.v_min_V) / self.lsb_V)
        clipped = (raw < 0) | (raw > self.max_code) | ~np.isfinite(raw)
        codes = np.clip(np.nan_to_num(raw, nan=0.0), 0, self.max_code).astype(np.int64)
        return DigitalReading(
            time_s=_readonly(np.array(t, dtype=float)),
            codes=_readonly(codes),
            volts=_readonly(self.code_to_volts(codes)),
            clipped=_readonly(clipped),
            lsb_V=self.lsb_V,
        )

    def code_to_volts(self, codes: np.ndarray) -> np.ndarray:
        """Nominal volts [V] of the codes (the transfer the experimenter knows)."""
        return self.v_min_V + np.asarray(codes, dtype=float) * self.lsb_V
