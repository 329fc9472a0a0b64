"""What a log stores: frozen dataclasses that a stand fills and the readers give back.

Every number carries its unit (ASCII form of :mod:`rig.logbook.units`); names are identifiers.
The logbook is generic: it checks form (finite numbers, valid names and units), not physics.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from datetime import datetime, timezone
from types import MappingProxyType

import numpy as np

import rig
from rig import validate
from rig.errors import ParameterError
from rig.logbook.units import check_name, check_unit

MAX_SEED = 2**63 - 1
"""Largest seed the log can hold (stored as a 64-bit signed integer)."""


def _frozen_mapping(kind: str, given: object, value_type: type) -> Mapping:
    """Copy ``given`` into a read-only mapping after checking names and value types."""
    if not isinstance(given, Mapping):
        raise ParameterError(kind, given, f"a mapping of name -> {value_type.__name__}")
    checked = {}
    for key, value in given.items():
        check_name(f"{kind} name", key)
        if not isinstance(value, value_type):
            raise ParameterError(f"{kind}[{key!r}]", value, f"a {value_type.__name__}")
        checked[key] = value
    return MappingProxyType(dict(sorted(checked.items())))


def quantities(kind: str, given: object) -> Mapping[str, Quantity]:
    """Read-only copy of a ``{name: Quantity}`` mapping; ``kind`` names it in error messages."""
    return _frozen_mapping(kind, given, Quantity)


@dataclass(frozen=True)
class Quantity:
    """A finite scalar ``value`` in ``unit`` (e.g. ``Quantity(96.2, "N")``)."""

    value: float
    unit: str

    def __post_init__(self) -> None:
        object.__setattr__(self, "value", validate.number("value", self.value))
        check_unit("unit", self.unit)


@dataclass(frozen=True, eq=False)
class Channel:
    """A raw, uniformly sampled channel.

    ``samples`` (1-D, finite, stored as float64) in ``unit``; sample ``k`` is taken at
    ``start_time_s + k / sample_rate_Hz`` [s]; ``sample_rate_Hz`` > 0 [Hz].
    """

    samples: np.ndarray
    unit: str
    sample_rate_Hz: float
    start_time_s: float

    def __post_init__(self) -> None:
        try:
            data = np.array(self.samples, dtype=np.float64)
        except (TypeError, ValueError):
            raise ParameterError("samples", self.samples, "a 1-D sequence of real numbers") from None
        if data.ndim != 1 or data.size == 0:
            raise ParameterError("samples", f"array of shape {data.shape}", "a non-empty 1-D array")
        if not np.all(np.isfinite(data)):
            bad = int(np.flatnonzero(~np.isfinite(data))[0])
            raise ParameterError(f"samples[{bad}]", float(data[bad]), "a finite number")
        data.setflags(write=False)
        object.__setattr__(self, "samples", data)
        check_unit("unit", self.unit)
        rate = validate.number("sample_rate_Hz", self.sample_rate_Hz, 0.0, lo_open=True)
        object.__setattr__(self, "sample_rate_Hz", rate)
        object.__setattr__(self, "start_time_s", validate.number("start_time_s", self.start_time_s))

    def times_s(self) -> np.ndarray:
        """Sample times [s]: ``start_time_s + k / sample_rate_Hz``."""
        return self.start_time_s + np.arange(self.samples.size) / self.sample_rate_Hz

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Channel):
            return NotImplemented
        return (
            self.unit == other.unit
            and self.sample_rate_Hz == other.sample_rate_Hz
            and self.start_time_s == other.start_time_s
            and np.array_equal(self.samples, other.samples)
        )

    __hash__ = None  # type: ignore[assignment]


@dataclass(frozen=True)
class Counter:
    """Total of one pulse counter over the gate: ``count`` >= 0 pulses from a disc with
    ``marks_per_rev`` >= 1 marks (Equations §2: omega = 2 pi N / (z T))."""

    count: int
    marks_per_rev: int

    def __post_init__(self) -> None:
        object.__setattr__(self, "count", validate.integer("count", self.count, 0, MAX_SEED))
        object.__setattr__(self, "marks_per_rev", validate.integer("marks_per_rev", self.marks_per_rev, 1, MAX_SEED))


@dataclass(frozen=True)
class CounterReadings:
    """Counters read over one common gate of ``gate_time_s`` > 0 [s] (Equations §2)."""

    gate_time_s: float
    counters: Mapping[str, Counter]

    def __post_init__(self) -> None:
        object.__setattr__(self, "gate_time_s", validate.number("gate_time_s", self.gate_time_s, 0.0, lo_open=True))
        object.__setattr__(self, "counters", _frozen_mapping("counters", self.counters, Counter))


@dataclass(frozen=True)
class PointRecord:
    """Everything measured at one operating point (never the simulation's truth).

    ``index`` >= 0 orders the points; ``settings``, ``readings`` (scalar instrument readings,
    e.g. a tangent-balance torque) and each ``calibration`` record are ``{name: Quantity}``;
    ``channels`` are raw sampled signals; ``counters`` is None when the stand has none.
    """

    index: int
    settings: Mapping[str, Quantity]
    channels: Mapping[str, Channel] = field(default_factory=dict)
    counters: CounterReadings | None = None
    readings: Mapping[str, Quantity] = field(default_factory=dict)
    calibration: Mapping[str, Mapping[str, Quantity]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "index", validate.integer("index", self.index, 0, 10**6 - 1))
        object.__setattr__(self, "settings", quantities("settings", self.settings))
        object.__setattr__(self, "readings", quantities("readings", self.readings))
        object.__setattr__(self, "channels", _frozen_mapping("channels", self.channels, Channel))
        if self.counters is not None and not isinstance(self.counters, CounterReadings):
            raise ParameterError("counters", self.counters, "a CounterReadings or None")
        records = _frozen_mapping("calibration", self.calibration, Mapping)
        frozen = {name: quantities(f"calibration[{name!r}]", rec) for name, rec in records.items()}
        object.__setattr__(self, "calibration", MappingProxyType(frozen))


def utc_timestamp(moment: datetime | None = None) -> str:
    """``moment`` (default: now) as an ISO 8601 UTC string, e.g. ``2024-05-01T12:00:00Z``."""
    moment = datetime.now(timezone.utc) if moment is None else moment.astimezone(timezone.utc)
    return moment.strftime("%Y-%m-%dT%H:%M:%SZ")


@dataclass(frozen=True)
class RunMetadata:
    """Run-level facts stored at the root of the log.

    ``scene_toml``: the scene file's text; ``seed``: the run's random seed (0..2**63-1);
    ``stand``: stand name (identifier); ``created_utc``: ISO 8601 UTC time the run started
    (see :func:`utc_timestamp`); ``package_version``: friction-rig version that wrote it.
    """

    scene_toml: str
    seed: int
    stand: str
    created_utc: str
    package_version: str = rig.__version__

    def __post_init__(self) -> None:
        if not isinstance(self.scene_toml, str):
            raise ParameterError("scene_toml", type(self.scene_toml).__name__, "the scene file's text (str)")
        object.__setattr__(self, "seed", validate.integer("seed", self.seed, 0, MAX_SEED))
        check_name("stand", self.stand)
        _check_utc("created_utc", self.created_utc)
        if not isinstance(self.package_version, str) or not self.package_version:
            raise ParameterError("package_version", self.package_version, "a non-empty version string")


def _check_utc(name: str, text: object) -> None:
    valid = "an ISO 8601 UTC time such as '2024-05-01T12:00:00Z'"
    if not isinstance(text, str):
        raise ParameterError(name, text, valid)
    try:
        moment = datetime.fromisoformat(text.replace("Z", "+00:00"))
    except ValueError:
        raise ParameterError(name, text, valid) from None
    offset = moment.utcoffset()
    if offset is None or not math.isclose(offset.total_seconds(), 0.0):
        raise ParameterError(name, text, valid, hint="give the time zone as Z or +00:00")
