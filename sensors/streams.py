"""Seeded random streams: one independent numpy Generator per (instrument, effect).

A run is reproducible from one integer seed: every noisy effect draws from its own stream,
derived from the seed and the two names with :class:`numpy.random.SeedSequence` (spawn key
from CRC-32 of the names, so the stream does not depend on the order in which instruments are
built, nor on Python's salted ``hash``). Switching one effect off does not change the others.
"""

from __future__ import annotations

import zlib

import numpy as np

from sensors import validate
from sensors.errors import InstrumentParameterError


def _name_key(kind: str, name: object) -> int:
    if not isinstance(name, str) or not name:
        raise InstrumentParameterError(kind, name, "a non-empty string")
    return zlib.crc32(name.encode("utf-8"))


def effect_rng(seed: int, instrument: str, effect: str) -> np.random.Generator:
    """Random stream for one effect of one instrument, e.g. ``effect_rng(7, "dynamometer_10", "noise")``.

    Equal arguments give identical streams, different names statistically independent ones.

    Parameters
    ----------
    seed : int
        The run's seed, a whole number >= 0.
    instrument : str
        The instrument's name.
    effect : str
        The effect's name (``"noise"``, ``"drift"``, ...).

    Returns
    -------
    numpy.random.Generator
        The effect's own generator.
    """
    s = validate.integer("seed", seed, 0)
    key = (_name_key("instrument", instrument), _name_key("effect", effect))
    return np.random.default_rng(np.random.SeedSequence(s, spawn_key=key))
