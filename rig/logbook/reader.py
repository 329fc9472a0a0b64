"""Read a finished log into pandas DataFrames (units in every column name), either layout.

A columnar log (version 2) is read with one slice per dataset (rig.logbook.columnar); a log of
format version 1 (one group per point) point by point as before. These readers never open ``/truth`` (see :mod:`rig.logbook.truth`). Every reader first checks
that the file is an HDF5 file of our format and raises :class:`LogFormatError` naming the file,
the point and what is wrong otherwise.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

import pandas as pd

from rig import validate
from rig.errors import LogFormatError
from rig.logbook import h5format
from rig.logbook import layout as L
from rig.logbook.content import Channel, PointRecord, Quantity, RunMetadata
from rig.logbook.columnar import ColumnarLog
from rig.logbook.opening import is_columnar, open_log
from rig.logbook.tables import TableBuilder
from rig.logbook.units import check_name, column_name

TIME_COLUMN = "time_s"


def read_metadata(path: object) -> RunMetadata:
    """Scene text, seed, stand, start time [UTC] and package version of the run."""
    with open_log(path) as handle:
        return h5format.read_metadata(handle)


def point_indices(path: object) -> list[int]:
    """Indices of the operating points in the log, ascending."""
    with open_log(path) as handle:
        if is_columnar(handle):
            return ColumnarLog(handle).index.tolist()
        return [index for index, _ in h5format.point_groups(handle)]


def _point_group(handle, path: object, index: int):
    validate.integer("index", index, 0)
    group = handle.get(f"{L.POINTS_GROUP}/{L.point_group_name(index)}")
    if group is None:
        present = [i for i, _ in h5format.point_groups(handle)]
        raise LogFormatError(f"{path}: point {index} is not in the log (points: {present})")
    return group


def read_point(path: object, index: int) -> PointRecord:
    """Every measurement of point ``index`` as a :class:`PointRecord` (all objects checked)."""
    validate.integer("index", index, 0)
    with open_log(path) as handle:
        if is_columnar(handle):
            log = ColumnarLog(handle)
            _, record = next(log.records([log.row(index)]))
            if isinstance(record, LogFormatError):
                raise record
            return record
        return h5format.read_point(_point_group(handle, path, index))


def read_points(path: object) -> Iterator[tuple[int, PointRecord | LogFormatError]]:
    """Every point of the log in index order, reading the file once: ``(index, PointRecord)``, or
    ``(index, LogFormatError)`` for a damaged point (a non-finite sample, a damaged group) - the
    error names the dataset, the point and the bad value, and the other points are read as usual.
    A log damaged as a whole (not ours, truncated, no points group) raises LogFormatError."""
    with open_log(path) as handle:
        if is_columnar(handle):
            yield from ColumnarLog(handle).records()
            return
        for index, group in h5format.point_groups(handle):
            try:
                yield index, h5format.read_point(group)
            except LogFormatError as error:
                yield index, error


def _quantities_of(kind: str):
    """Extractor of the ``{name: Quantity}`` stored in subgroup ``kind`` of a point."""
    return lambda group: h5format.read_quantities(h5format.subgroup(group, kind))


def _calibration_of(group) -> dict[str, Quantity]:
    """Calibration fields of a point as ``{"<record>_<field>": Quantity}``."""
    records = h5format.subgroup(group, L.CALIBRATION_GROUP)
    out = {}
    for record in records:
        for name, q in h5format.read_quantities(h5format.subgroup(records, record)).items():
            out[f"{record}_{name}"] = q
    return out


def _per_point(path: object, kind: str, extract: Callable[[object], dict[str, Quantity]]) -> pd.DataFrame:
    with open_log(path) as handle:
        if is_columnar(handle):
            return ColumnarLog(handle).frame(kind)
        table = TableBuilder(str(path))
        for index, group in h5format.point_groups(handle):
            table.row(index)
            table.add_quantities(index, "", extract(group))
        return table.frame()


def read_settings(path: object) -> pd.DataFrame:
    """Settings, one row per point (index ``point``), columns ``<name>_<unit>`` (e.g. ``F_N_N``)."""
    return _per_point(path, "settings", _quantities_of(L.SETTINGS_GROUP))


def read_readings(path: object) -> pd.DataFrame:
    """Scalar instrument readings, one row per point, columns ``<name>_<unit>`` (e.g. ``T2_N_m``)."""
    return _per_point(path, "readings", _quantities_of(L.READINGS_GROUP))


def read_calibration(path: object) -> pd.DataFrame:
    """Calibration records, one row per point, columns ``<record>_<field>_<unit>``."""
    return _per_point(path, "calibration", _calibration_of)


def read_counters(path: object) -> pd.DataFrame:
    """Counter totals, one row per point: ``gate_time_s``, ``<name>_count`` and
    ``<name>_marks_per_rev`` (marks of the stroboscope disc); empty cells where a point has none."""
    with open_log(path) as handle:
        if is_columnar(handle):
            return ColumnarLog(handle).frame("counters")
        table = TableBuilder(str(path))
        for index, group in h5format.point_groups(handle):
            table.row(index)
            readings = h5format.read_counters(group)
            if readings is None:
                continue
            table.add(index, L.ATTR_GATE_TIME, "gate_time", readings.gate_time_s, "s")
            for name, counter in readings.counters.items():
                table.add(index, f"counter {name}", name, counter.count, L.COUNT_UNIT)
                table.add(index, f"marks of {name}", f"{name}_marks", counter.marks_per_rev, L.MARKS_UNIT)
        return table.frame()


def read_channel(path: object, index: int, name: str) -> pd.DataFrame:
    """Channel ``name`` of point ``index``: columns ``time_s`` and ``<name>_<unit>``.

    ``attrs`` holds ``units`` ({column: unit}), ``sample_rate_Hz`` [Hz] and ``start_time_s`` [s].
    """
    check_name("name", name)
    validate.integer("index", index, 0)
    with open_log(path) as handle:
        if is_columnar(handle):
            log = ColumnarLog(handle)
            row = log.row(index)
            names = log.channel_names()
            if name not in names:
                raise LogFormatError(f"{path}: point {index}: channel {name!r} is missing (present: {', '.join(names) or 'none'})")
            ds, unit, first, length, rate, start = log.channel(name)
            if length[row] == 0:
                raise LogFormatError(f"{path}: point {index}: channel {name!r} is missing")
            samples = ds[first[row]:first[row] + length[row]]
            channel = h5format.decoded(ds, lambda: Channel(samples, unit, rate[row], start[row]))
        else:
            group = h5format.subgroup(_point_group(handle, path, index), L.CHANNELS_GROUP)
            channel = h5format.read_channel(group, name)
    value_column = column_name(name, channel.unit)
    table = pd.DataFrame({TIME_COLUMN: channel.times_s(), value_column: channel.samples.copy()})
    table.attrs["units"] = {TIME_COLUMN: "s", value_column: channel.unit}
    table.attrs[L.ATTR_SAMPLE_RATE] = channel.sample_rate_Hz
    table.attrs[L.ATTR_START_TIME] = channel.start_time_s
    return table


def channel_names(path: object, index: int) -> list[str]:
    """Names of the channels of point ``index``."""
    validate.integer("index", index, 0)
    with open_log(path) as handle:
        if is_columnar(handle):
            log = ColumnarLog(handle)
            row = log.row(index)
            return [name for name in log.channel_names() if log.channel(name)[3][row] > 0]
        return sorted(h5format.subgroup(_point_group(handle, path, index), L.CHANNELS_GROUP))


def read_channels(path: object, index: int) -> dict[str, pd.DataFrame]:
    """Every channel of point ``index`` as in :func:`read_channel`, by name."""
    return {name: read_channel(path, index, name) for name in channel_names(path, index)}
