"""Optional schema check: the channels, settings, readings and counters a consumer needs, with
their units, in every point of a log."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from rig.errors import LogFormatError, ParameterError
from rig.logbook import h5format
from rig.logbook import layout as L
from rig.logbook.opening import is_columnar, open_log
from rig.logbook.reader import read_metadata, read_points
from rig.logbook.units import check_name, check_unit


def _units_map(kind: str, given: object) -> Mapping[str, str]:
    if not isinstance(given, Mapping):
        raise ParameterError(kind, given, "a mapping of name -> unit")
    return MappingProxyType({check_name(f"{kind} name", k): check_unit(f"{kind}[{k!r}]", u) for k, u in given.items()})


@dataclass(frozen=True)
class LogSchema:
    """Required content of every point: ``{name: unit}`` per kind, and counter names."""

    channels: Mapping[str, str] = field(default_factory=dict)
    settings: Mapping[str, str] = field(default_factory=dict)
    readings: Mapping[str, str] = field(default_factory=dict)
    counters: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        for kind in ("channels", "settings", "readings"):
            object.__setattr__(self, kind, _units_map(kind, getattr(self, kind)))
        if isinstance(self.counters, str):
            raise ParameterError("counters", self.counters, "a sequence of counter names")
        object.__setattr__(self, "counters", tuple(check_name("counter", c) for c in self.counters))


def _check_kind(where: str, present: Mapping[str, object], kind: str, required: Mapping[str, str]) -> None:
    """Every required name of ``kind`` is present (a Quantity or Channel by name) with its units."""
    singular = kind[:-1]
    for name, unit in required.items():
        if name not in present:
            raise LogFormatError(f"{where}: {singular} {name!r} is missing (present: {', '.join(present) or 'none'})")
        found = present[name].unit
        if found != unit:
            raise LogFormatError(f"{where}: {singular} {name!r} has units {found!r}, expected {unit!r}")


def check_log(path: object, schema: LogSchema | None = None) -> list[int]:
    """Check a log completely (every object of every point is decoded) and, if given, that
    every point holds what ``schema`` requires. Returns the point indices; raises LogFormatError
    naming the file, the point and what is wrong.
    """
    if schema is not None and not isinstance(schema, LogSchema):
        raise ParameterError("schema", schema, "a LogSchema or None")
    read_metadata(path)
    indices = []
    for index, point in read_points(path):
        if isinstance(point, LogFormatError):
            raise point
        indices.append(index)
        if schema is None:
            continue
        where = f"{path}: point {index}"
        _check_kind(where, point.channels, "channels", schema.channels)
        _check_kind(where, point.settings, "settings", schema.settings)
        _check_kind(where, point.readings, "readings", schema.readings)
        present = {} if point.counters is None else point.counters.counters
        for name in schema.counters:
            if name not in present:
                raise LogFormatError(f"{where}: counter {name!r} is missing (present: {', '.join(present) or 'none'})")
    return indices


def check_units(path: object, schema: LogSchema) -> None:
    """Check the ``units`` attribute of every dataset of a columnar log that ``schema`` names
    (reading attributes only): a unit other than the schema's raises LogFormatError naming the
    dataset, the unit found and the unit expected. A dataset the log lacks is left to the
    per-point checks; a log of format version 1 is checked point by point by check_log."""
    if not isinstance(schema, LogSchema):
        raise ParameterError("schema", schema, "a LogSchema")
    with open_log(path) as handle:
        if not is_columnar(handle):
            return
        points = h5format.subgroup(handle, L.POINTS_GROUP)
        wanted = [(f"{L.SETTINGS_GROUP}/{name}", unit) for name, unit in schema.settings.items()]
        wanted += [(f"{L.READINGS_GROUP}/{name}", unit) for name, unit in schema.readings.items()]
        wanted += [(f"{L.CHANNELS_GROUP}/{name}/{L.SAMPLES_DATASET}", unit) for name, unit in schema.channels.items()]
        for where, unit in wanted:
            ds = points.get(where)
            if ds is None:
                continue
            found = h5format.units_of(ds)
            if found != unit:
                raise h5format.fail(ds, f"attribute 'units' = {found!r}, expected {unit!r}")
