"""The columnar log (format version 2): one row per point in per-quantity datasets.

Writing: :func:`write_columnar` lays out the entries of a run (rig.logbook.journal) in two
passes - the first finds every quantity and its unit and the channels' total lengths, the second
fills the rows - so that memory holds the scalars of all points but the channels' samples only a
block at a time. Reading: :class:`ColumnarLog` reads each dataset with one slice and gives the
rows as DataFrames or the points as PointRecords (a block of points' samples at a time).

Where a point lacks a quantity other points have, its row holds NaN (float64) or -1 (counts and
marks); a channel it lacks has length 0. A stored quantity is finite, so NaN always means absent.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator

import h5py
import numpy as np
import pandas as pd

from rig.errors import LogFormatError, ParameterError
from rig.logbook import h5format
from rig.logbook import layout as L
from rig.logbook.content import Channel, Counter, CounterReadings, PointRecord, Quantity
from rig.logbook.journal import Entry
from rig.logbook.tables import INDEX_NAME, frame_of

SAMPLES_PER_BLOCK = 1 << 20
"""Samples held in memory per channel while writing or reading the ragged channels."""
SCALAR_KINDS = ("settings", "readings", "truth")


MAX_CHUNK = 1 << 16
"""Largest chunk of a dataset [elements] (512 KiB of float64)."""
COLUMN_FILTERS = {"compression": "gzip", "compression_opts": 4, "shuffle": True, "fletcher32": True}
"""Filters of the one-row-per-point columns (deflate and Fletcher-32 are in every HDF5 build:
plain h5py reads them); the channels' samples get the Fletcher-32 checksum only
(SAMPLE_FILTERS). A chunk whose bytes changed on disk then fails to read instead of giving other
numbers."""
SAMPLE_FILTERS = {"fletcher32": True}
"""Filters of the channels' samples: a checksum per chunk, no compression."""


def chunks_for(n: int) -> tuple[int]:
    """Chunk length for a 1-D dataset of ``n`` elements: equal chunks of at most MAX_CHUNK, so
    that the last one is (nearly) full and the file holds little unused space."""
    n = max(n, 1)
    count = -(-n // MAX_CHUNK)
    return (-(-n // count),)


def column(group: h5py.Group, name: str, values: np.ndarray, unit: str | None) -> h5py.Dataset:
    """An extendable (chunked, unlimited, deflated) 1-D dataset, with ``units`` unless ``unit`` is None."""
    ds = group.create_dataset(name, data=values, chunks=chunks_for(values.size), maxshape=(None,), **COLUMN_FILTERS)
    if unit is not None:
        ds.attrs[L.ATTR_UNITS] = unit
    return ds


class _Layout:
    """Every quantity of a run with its unit (first pass over the entries)."""

    def __init__(self) -> None:
        self.scalars: dict[str, dict[str, str]] = {kind: {} for kind in SCALAR_KINDS}
        self.calibration: dict[tuple[str, str], str] = {}
        self.records: set[str] = set()
        self.counters: set[str] = set()
        self.has_counters = False
        self.channels: dict[str, str] = {}
        self.samples: dict[str, int] = {}
        self.n = 0

    @staticmethod
    def _unit(known: dict, key, unit: str, what: str) -> None:
        if known.setdefault(key, unit) != unit:
            raise ParameterError(what, unit, f"{known[key]!r}, the unit of the earlier points (one unit per quantity)")

    def add(self, entry: Entry) -> None:
        h = entry.header
        self.n += 1
        for kind in SCALAR_KINDS:
            for name, _, unit in h[kind]:
                self._unit(self.scalars[kind], name, unit, f"{kind}[{name!r}].unit")
        self.records.update(h["records"])
        for rec, name, _, unit in h["calibration"]:
            self._unit(self.calibration, (rec, name), unit, f"calibration[{rec!r}][{name!r}].unit")
        if h["counters"] is not None:
            self.has_counters = True
            self.counters.update(c[0] for c in h["counters"]["counters"])
        for name, unit, _, _, n in h["channels"]:
            self._unit(self.channels, name, unit, f"channels[{name!r}].unit")
            self.samples[name] = self.samples.get(name, 0) + n


def write_columnar(root: h5py.Group, entries: Callable[[], Iterable[Entry]]) -> None:
    """Write ``/points`` and ``/truth`` of the points ``entries()`` gives in index order (called twice)."""
    layout = _Layout()
    for entry in entries():
        layout.add(entry)
    n = layout.n
    index = np.empty(n, dtype=np.int64)
    scalars = {kind: {name: np.full(n, np.nan) for name in names} for kind, names in layout.scalars.items()}
    calibration = {key: np.full(n, np.nan) for key in layout.calibration}
    gate = np.full(n, np.nan)
    counts = {name: np.full(n, L.ABSENT_INTEGER, dtype=np.int64) for name in layout.counters}
    marks = {name: np.full(n, L.ABSENT_INTEGER, dtype=np.int64) for name in layout.counters}
    first = {name: np.zeros(n, dtype=np.int64) for name in layout.channels}
    length = {name: np.zeros(n, dtype=np.int64) for name in layout.channels}
    rate = {name: np.full(n, np.nan) for name in layout.channels}
    start = {name: np.full(n, np.nan) for name in layout.channels}

    points = root.create_group(L.POINTS_GROUP)
    channels_group = points.create_group(L.CHANNELS_GROUP)
    samples = {}
    for name in sorted(layout.channels):
        total = layout.samples[name]
        group = channels_group.create_group(name)
        samples[name] = group.create_dataset(L.SAMPLES_DATASET, shape=(total,), dtype=np.float64,
                                             chunks=chunks_for(total), maxshape=(None,), **SAMPLE_FILTERS)
        samples[name].attrs[L.ATTR_UNITS] = layout.channels[name]
    pending: dict[str, list[np.ndarray]] = {name: [] for name in layout.channels}
    written = dict.fromkeys(layout.channels, 0)
    buffered = dict.fromkeys(layout.channels, 0)

    def flush(name: str) -> None:
        if pending[name]:
            block = np.concatenate(pending[name])
            samples[name][written[name]:written[name] + block.size] = block
            written[name] += block.size
            pending[name].clear()
            buffered[name] = 0

    for row, entry in enumerate(entries()):
        h = entry.header
        index[row] = entry.index
        for kind in SCALAR_KINDS:
            for name, value, _ in h[kind]:
                scalars[kind][name][row] = value
        for rec, name, value, _ in h["calibration"]:
            calibration[(rec, name)][row] = value
        if h["counters"] is not None:
            gate[row] = h["counters"]["gate_time_s"]
            for name, count, mark in h["counters"]["counters"]:
                counts[name][row], marks[name][row] = count, mark
        for name, _, sample_rate, start_time, size in h["channels"]:
            first[name][row] = written[name] + buffered[name]
            length[name][row], rate[name][row], start[name][row] = size, sample_rate, start_time
            pending[name].append(entry.channels[name])
            buffered[name] += size
            if buffered[name] >= SAMPLES_PER_BLOCK:
                flush(name)
    for name in pending:
        flush(name)
    if np.any(np.diff(index) <= 0):
        raise ParameterError("entries", "point indices not strictly ascending", "points in index order")

    column(points, L.INDEX_DATASET, index, None)
    for kind in ("settings", "readings"):
        group = points.create_group(kind)
        for name in sorted(scalars[kind]):
            column(group, name, scalars[kind][name], layout.scalars[kind][name])
    calibration_group = points.create_group(L.CALIBRATION_GROUP)
    for rec in sorted(layout.records):
        calibration_group.create_group(rec)
    for rec, name in sorted(calibration):
        column(calibration_group[rec], name, calibration[(rec, name)], layout.calibration[(rec, name)])
    if layout.has_counters:
        counters_group = points.create_group(L.COUNTERS_GROUP)
        column(counters_group, L.GATE_TIME_DATASET, gate, "s")
        counts_group, marks_group = counters_group.create_group(L.COUNTS_GROUP), counters_group.create_group(L.MARKS_GROUP)
        for name in sorted(counts):
            column(counts_group, name, counts[name], L.COUNT_UNIT)
            column(marks_group, name, marks[name], L.MARKS_UNIT)
    for name in sorted(layout.channels):
        group = channels_group[name]
        column(group, L.FIRST_SAMPLE_DATASET, first[name], None)
        column(group, L.SAMPLE_COUNT_DATASET, length[name], None)
        column(group, L.ATTR_SAMPLE_RATE, rate[name], "Hz")
        column(group, L.ATTR_START_TIME, start[name], "s")
    truth = root.create_group(L.TRUTH_GROUP)
    column(truth, L.INDEX_DATASET, index, None)
    for name in sorted(scalars["truth"]):
        column(truth, name, scalars["truth"][name], layout.scalars["truth"][name])


# ----------------------------------------------------------------------------- reading

class ColumnarLog:
    """Reader of an open version-2 log: every dataset checked (shape, dtype, units) when read."""

    def __init__(self, handle: h5py.File) -> None:
        self.handle = handle
        self.points = h5format.subgroup(handle, L.POINTS_GROUP)
        self.index = self._rows(self.points, L.INDEX_DATASET, "iu", None)
        if np.any(np.diff(self.index) <= 0) or (self.index.size and self.index[0] < 0):
            raise h5format.fail(self.points[L.INDEX_DATASET], "point indices are not ascending and >= 0")

    @property
    def n(self) -> int:
        return int(self.index.size)

    def _rows(self, group: h5py.Group, name: str, kinds: str, n: int | None = -1) -> np.ndarray:
        """Dataset ``name`` of ``group``: 1-D, ``kinds`` dtype, one row per point (unless n is None)."""
        ds = group.get(name)
        if not isinstance(ds, h5py.Dataset):
            raise h5format.fail(group, f"dataset {name!r} is missing" if ds is None else f"{name!r} is not a dataset")
        expected = self.n if n == -1 else n
        if ds.ndim != 1 or ds.dtype.kind not in kinds or (expected is not None and ds.shape[0] != expected):
            raise h5format.fail(ds, f"expected a 1-D {'integer' if kinds == 'iu' else 'numeric'} dataset of "
                                    f"{'one row per point' if expected is None else f'{expected} rows'}, "
                                    f"found shape {ds.shape} dtype {ds.dtype}")
        return read_dataset(ds)

    def _quantity_rows(self, group: h5py.Group, name: str,
                       faults: dict[int, str] | None = None) -> tuple[np.ndarray, str]:
        """Rows and unit of a quantity; a non-finite row raises, or with ``faults`` ({row: what is
        wrong}) is recorded there as that point's fault."""
        values = self._rows(group, name, "iuf").astype(np.float64, copy=False)
        for row in np.flatnonzero(np.isinf(values)):
            what = f"point {int(self.index[row])}: value {h5format.shown(values[row])} is not finite"
            if faults is None:
                raise h5format.fail(group[name], what)
            faults.setdefault(int(row), str(h5format.fail(group[name], what)))
        return values, h5format.units_of(group[name])

    def quantities(self, kind: str, root: str = L.POINTS_GROUP,
                   faults: dict[int, str] | None = None) -> dict[str, tuple[np.ndarray, str]]:
        """{name: (rows, unit)} of ``settings``/``readings`` (or of ``/truth`` with kind None)."""
        group = h5format.subgroup(self.handle, root) if kind is None else h5format.subgroup(self.points, kind)
        return {name: self._quantity_rows(group, name, faults) for name in group if name != L.INDEX_DATASET}

    def calibration(self, faults: dict[int, str] | None = None) -> dict[tuple[str, str], tuple[np.ndarray, str]]:
        """{(record, field): (rows, unit)}; see also :meth:`empty_records`."""
        records = h5format.subgroup(self.points, L.CALIBRATION_GROUP)
        return {(rec, name): self._quantity_rows(h5format.subgroup(records, rec), name, faults)
                for rec in records for name in h5format.subgroup(records, rec)}

    def empty_records(self) -> list[str]:
        """Calibration records without fields (every point has them, empty)."""
        records = h5format.subgroup(self.points, L.CALIBRATION_GROUP)
        return [rec for rec in records if len(h5format.subgroup(records, rec)) == 0]

    def counters(self, faults: dict[int, str] | None = None
                 ) -> tuple[np.ndarray, dict[str, tuple[np.ndarray, np.ndarray]]] | None:
        """(gate time rows [s], {name: (count rows, marks rows)}), or None without counters."""
        if L.COUNTERS_GROUP not in self.points:
            return None
        group = h5format.subgroup(self.points, L.COUNTERS_GROUP)
        gate, unit = self._quantity_rows(group, L.GATE_TIME_DATASET, faults)
        if unit != "s":
            raise h5format.fail(group[L.GATE_TIME_DATASET], f"attribute 'units' = {unit!r}, expected 's'")
        counts, marks = h5format.subgroup(group, L.COUNTS_GROUP), h5format.subgroup(group, L.MARKS_GROUP)
        out = {}
        for name in counts:
            for sub, expected in ((counts, L.COUNT_UNIT), (marks, L.MARKS_UNIT)):
                if name in sub and h5format.units_of(sub[name]) != expected:
                    raise h5format.fail(sub[name], f"attribute 'units' = {sub[name].attrs[L.ATTR_UNITS]!r}; "
                                                   f"must be {expected!r}")
            out[name] = (self._rows(counts, name, "iu"), self._rows(marks, name, "iu"))
        return gate, out

    def channel(self, name: str, faults: dict[int, str] | None = None
                ) -> tuple[h5py.Dataset, str, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(samples dataset, unit, first, length, sample rate [Hz], start time [s]) of channel ``name``;
        a point whose first/length lie outside the samples raises, or with ``faults`` is recorded
        there (its length then reads as 0)."""
        group = h5format.subgroup(h5format.subgroup(self.points, L.CHANNELS_GROUP), name)
        samples = group.get(L.SAMPLES_DATASET)
        if not isinstance(samples, h5py.Dataset) or samples.ndim != 1 or samples.dtype.kind not in "iuf":
            raise h5format.fail(group, f"dataset {L.SAMPLES_DATASET!r} is missing or not 1-D numeric")
        first, length = self._rows(group, L.FIRST_SAMPLE_DATASET, "iu"), self._rows(group, L.SAMPLE_COUNT_DATASET, "iu")
        total = samples.shape[0]
        outside = (length < 0) | (first < 0) | (first > total) | (length > total - np.minimum(first, total))
        for row in np.flatnonzero(outside):
            what = (f"point {int(self.index[row])}: first = {int(first[row])}, length = {int(length[row])} "
                    f"lie outside the {total} samples")
            if faults is None:
                raise h5format.fail(group, what)
            faults.setdefault(int(row), str(h5format.fail(group, what)))
        if outside.any():
            length = np.where(outside, 0, length)
        rate = self._rows(group, L.ATTR_SAMPLE_RATE, "f")
        start = self._rows(group, L.ATTR_START_TIME, "f")
        return samples, h5format.units_of(samples), first, length, rate, start

    def channel_names(self) -> list[str]:
        return sorted(h5format.subgroup(self.points, L.CHANNELS_GROUP))

    def row(self, index: int) -> int:
        """Row of point ``index``; LogFormatError naming the points present if absent."""
        row = int(np.searchsorted(self.index, index))
        if row >= self.n or self.index[row] != index:
            raise LogFormatError(f"{self.handle.filename}: point {index} is not in the log "
                                 f"(points: {self.index.tolist()})")
        return row

    # ------------------------------------------------------------------------- tables

    def frame(self, kind: str) -> pd.DataFrame:
        """One row per point, columns ``<name>_<unit>`` (see rig.logbook.tables.frame_of)."""
        where = str(self.handle.filename)
        if kind in ("settings", "readings"):
            columns = [(name, name, values, unit) for name, (values, unit) in self.quantities(kind).items()]
        elif kind == "truth":
            columns = [(name, name, values, unit) for name, (values, unit) in self.quantities(None, L.TRUTH_GROUP).items()]
        elif kind == "calibration":
            columns = [(f"{r}/{f}", f"{r}_{f}", v, u) for (r, f), (v, u) in self.calibration().items()]
        else:
            columns = []
            found = self.counters()
            if found is not None:
                columns.append((L.ATTR_GATE_TIME, "gate_time", found[0], "s"))
                for name, (counts, marks) in found[1].items():
                    columns.append((f"counter {name}", name, _absent_as_nan(counts), L.COUNT_UNIT))
                    columns.append((f"marks of {name}", f"{name}_marks", _absent_as_nan(marks), L.MARKS_UNIT))
        return frame_of(where, pd.Index(self.index, name=INDEX_NAME, dtype="int64"), columns)

    # ------------------------------------------------------------------------- points

    def records(self, rows: Iterable[int] | None = None) -> Iterator[tuple[int, PointRecord | LogFormatError]]:
        """(index, PointRecord) per row (all rows by default), or (index, LogFormatError) for a
        damaged point (a non-finite sample, a bad counter): the error names the dataset, the
        point and the bad value, and the other points are read as usual."""
        rows = range(self.n) if rows is None else list(rows)
        faults: dict[int, str] = {}  # row -> what is wrong with that point alone
        scalars = {kind: self.quantities(kind, faults=faults) for kind in ("settings", "readings")}
        calibration = self.calibration(faults)
        self._empty = self.empty_records()
        counters = self.counters(faults)
        # the counters' objects, named in a decoding error: looked up once (an h5py lookup costs ~0.1 ms)
        counter_objects = None if counters is None else (self.points[L.COUNTERS_GROUP], {
            name: self.points[f"{L.COUNTERS_GROUP}/{L.COUNTS_GROUP}/{name}"] for name in counters[1]})
        channels = {name: self.channel(name, faults) for name in self.channel_names()}
        blocks = _blocks(list(rows), channels)
        for block in blocks:
            data = {name: self._read_block(channels[name], block, faults) for name in channels}
            for row in block:
                index = int(self.index[row])
                if row in faults:
                    yield index, LogFormatError(faults[row])
                    continue
                try:
                    yield index, self._record(row, scalars, calibration, counters, counter_objects, channels, data)
                except LogFormatError as error:
                    yield index, error

    def _read_block(self, channel, rows: list[int], faults: dict[int, str]) -> tuple[int, np.ndarray]:
        """The rows' samples of one channel (rig.logbook.columnar._read_block); when the slice cannot
        be read (a chunk that fails its checksum), the rows are read one by one and each row whose
        samples cannot be read is recorded in ``faults`` (its samples read as empty)."""
        try:
            return _read_block(channel, rows)
        except LogFormatError:
            pass
        ds, _, first, length, _, _ = channel
        lo = min((int(first[r]) for r in rows if length[r] > 0), default=0)
        hi = max((int(first[r] + length[r]) for r in rows if length[r] > 0), default=0)
        out = np.zeros(max(hi - lo, 0))
        for row in rows:
            if length[row] == 0:
                continue
            try:
                span = slice(int(first[row]), int(first[row] + length[row]))
                out[span.start - lo:span.stop - lo] = read_dataset(ds, span)
            except LogFormatError as error:
                faults.setdefault(row, f"{error}: point {int(self.index[row])}: samples {int(first[row])} .. "
                                       f"{int(first[row] + length[row]) - 1} cannot be read")
        return lo, out

    def _record(self, row, scalars, calibration, counters, counter_objects, channels, data) -> PointRecord:
        index = int(self.index[row])

        def present(values: dict) -> dict[str, Quantity]:
            return {name: Quantity(float(v[row]), u) for name, (v, u) in values.items() if not np.isnan(v[row])}

        records: dict[str, dict[str, Quantity]] = {rec: {} for rec in self._empty}
        for (rec, name), (values, unit) in calibration.items():
            if not np.isnan(values[row]):
                records.setdefault(rec, {})[name] = Quantity(float(values[row]), unit)
        reading = None
        if counters is not None and not np.isnan(counters[0][row]):
            found = {}
            for name, (counts, marks) in counters[1].items():
                if counts[row] == L.ABSENT_INTEGER:
                    continue
                found[name] = h5format.decoded(counter_objects[1][name],
                                               lambda: Counter(int(counts[row]), int(marks[row])))
            gate = float(counters[0][row])
            reading = h5format.decoded(counter_objects[0], lambda: CounterReadings(gate, found))
        point_channels = {}
        for name, (ds, unit, first, length, rate, start) in channels.items():
            if length[row] == 0:
                continue
            offset = first[row] - data[name][0]
            values = data[name][1][offset:offset + length[row]]
            bad = np.flatnonzero(~np.isfinite(values))
            if bad.size:
                raise h5format.fail(ds, f"point {index}: sample {int(bad[0])} (of {int(length[row])}) = "
                                        f"{h5format.shown(values[bad[0]])} is not finite")
            point_channels[name] = h5format.decoded(ds, lambda: Channel(values, unit, rate[row], start[row]))
        return PointRecord(index, present(scalars["settings"]), point_channels, reading,
                           present(scalars["readings"]), records)


def _absent_as_nan(values: np.ndarray) -> np.ndarray:
    """Integer rows with the absent marker -1 as NaN (float64); unchanged when none is absent."""
    absent = values == L.ABSENT_INTEGER
    if not absent.any():
        return values
    out = values.astype(np.float64)
    out[absent] = np.nan
    return out


def _blocks(rows: list[int], channels: dict) -> Iterator[list[int]]:
    """Consecutive groups of rows whose samples together stay within SAMPLES_PER_BLOCK per channel."""
    block, held = [], 0
    for row in rows:
        size = max((int(c[3][row]) for c in channels.values()), default=0)
        if block and held + size > SAMPLES_PER_BLOCK:
            yield block
            block, held = [], 0
        block.append(row)
        held += size
    if block:
        yield block


def _read_block(channel, rows: list[int]) -> tuple[int, np.ndarray]:
    """(first sample position, samples) covering the rows' samples of one channel (one slice)."""
    ds, _, first, length, _, _ = channel
    present = [r for r in rows if length[r] > 0]
    if not present:
        return 0, np.empty(0)
    lo = int(min(first[r] for r in present))
    hi = int(max(first[r] + length[r] for r in present))
    return lo, read_dataset(ds, slice(lo, hi)).astype(np.float64, copy=False)


def read_dataset(ds: h5py.Dataset, where: slice | tuple = ()) -> np.ndarray:
    """``ds[where]``; a read that fails (a chunk failing its checksum, damaged bytes) raises a
    LogFormatError naming the file, the dataset and the cause."""
    try:
        return ds[where]
    except (OSError, RuntimeError, ValueError, KeyError, TypeError) as error:
        cause = " ".join(str(error).split())[:160]
        raise h5format.fail(ds, f"unreadable ({cause})") from None
