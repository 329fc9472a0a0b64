"""Log shards: the points of a run written in pieces, one columnar log file per chunk of points,
and merged into the run's single log at the end.

A study run on several workers does not funnel every point through one writer: each chunk of
consecutive points becomes a *shard*, a complete columnar log (format version 2, the run's
metadata at its root) of just those points, which the worker that simulated them builds
(:func:`write_shard`) and can reduce like any log. The shards of a run wait in
``<log>.parts/shards/`` (the staging folder of rig.logbook.writer), each moved there whole
(:func:`store_shard`: temporary name, then a rename), so a shard is either complete or absent:
a run killed at any moment resumes with the shards it has (:func:`find_shards`) and simulates
only the points in none of them.

:func:`merge_logs` lays the points of several columnar logs out as one, in index order, with the
layout a run written point by point gets (rig.logbook.columnar): every per-point dataset is
concatenated (a point lacking a quantity gets NaN, or -1 for integers, as there), the channels'
samples are copied a block at a time and their ``first`` offsets recomputed. Dataset filters and
attributes are taken from the sources, so the merged log is laid out as they are. Its memory
holds the per-point columns (some tens of bytes a point per quantity), never all the samples.
Readers never see a shard: the run folder's ``log.h5`` is always one ordinary log.
"""

from __future__ import annotations

import contextlib
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

import h5py
import numpy as np

from rig.errors import LogFormatError, ParameterError
from rig.logbook import atomic, h5format
from rig.logbook import layout as L
from rig.logbook.columnar import SAMPLES_PER_BLOCK, chunks_for, write_columnar
from rig.logbook.content import RunMetadata
from rig.logbook.journal import Entry
from rig.logbook.opening import check_format, open_log
from rig.logbook.writer import same_run, staging_dir

SHARDS_FOLDER = "shards"
"""Folder of a run's shards inside the log's staging folder (``log.h5.parts/shards``)."""

_NAME = re.compile(r"points_(\d{7,})_(\d{7,})\.h5")


def shard_folder(log_path: Path) -> Path:
    """Where the shards of the log ``log_path`` wait: ``<log>.parts/shards``."""
    return staging_dir(Path(log_path)) / SHARDS_FOLDER


def shard_name(first: int, last: int) -> str:
    """File name of the shard holding points ``first`` .. ``last`` (indices, inclusive)."""
    return f"points_{first:07d}_{last:07d}.h5"


def write_shard(path: Path, metadata: RunMetadata, entries: Sequence[Entry]) -> None:
    """Write the columnar log of ``entries`` (rig.logbook.journal, in index order) to ``path``."""
    if not entries:
        raise ParameterError("entries", "none", "at least one point for a shard")
    with h5py.File(path, "w", libver=atomic.LIBVER) as handle:
        h5format.write_metadata(handle, metadata)
        write_columnar(handle, lambda: entries)


def store_shard(folder: Path, first: int, last: int, data: bytes) -> Path:
    """Put the bytes of a shard file (points ``first`` .. ``last``) into ``folder`` whole (a
    temporary name, fsync, rename): a killed process leaves the shard complete or absent."""
    folder.mkdir(parents=True, exist_ok=True)
    target = folder / shard_name(first, last)
    with atomic.replace_atomically(target, atomic.temporary_path(folder, target.name)) as tmp:
        with open(tmp, "wb") as handle:
            handle.write(data)
    return target


@dataclass(frozen=True)
class Shard:
    """A complete shard in the staging folder: its file and the point indices it holds (ascending)."""

    path: Path
    indices: tuple[int, ...]


def find_shards(folder: Path, metadata: RunMetadata) -> list[Shard]:
    """The shards of the run ``metadata`` in ``folder``, by first index. Leftover temporary files,
    and shards that cannot be read or belong to another run (scene, seed, stand, version), are
    removed: their points are simply simulated again."""
    if not folder.is_dir():
        return []
    found = []
    for path in sorted(folder.iterdir()):
        if path.name.endswith(atomic.TMP_SUFFIX):
            path.unlink()
            continue
        if not _NAME.fullmatch(path.name):
            continue
        indices = _shard_indices(path, metadata)
        if indices is None:
            path.unlink()
            continue
        found.append(Shard(path, indices))
    return sorted(found, key=lambda shard: shard.indices[0])


def _shard_indices(path: Path, metadata: RunMetadata) -> tuple[int, ...] | None:
    try:
        with open_log(path) as handle:
            if same_run(metadata, h5format.read_metadata(handle)) is not None:
                return None
            index = handle[f"{L.POINTS_GROUP}/{L.INDEX_DATASET}"][()]
    except (LogFormatError, KeyError, OSError):
        return None
    if index.ndim != 1 or index.size == 0 or np.any(np.diff(index) <= 0):
        return None
    return tuple(int(i) for i in index)


def remove_shards(folder: Path) -> None:
    """Remove the shards folder and everything in it (after a merge, or for a run started anew)."""
    if not folder.is_dir():
        return
    for path in folder.iterdir():
        path.unlink()
    with contextlib.suppress(OSError):
        folder.rmdir()


# ----------------------------------------------------------------------------- merging

@dataclass
class _Column:
    """One per-point dataset across the sources: its dtype, attributes and filters (from the first
    source that has it) and each source's rows (None where a source lacks it)."""

    dtype: np.dtype
    attrs: dict
    filters: dict
    rows: list


def _filters(ds: h5py.Dataset) -> dict:
    """The filters of ``ds`` as create_dataset arguments (so a merged dataset is stored like its source)."""
    out = {"shuffle": ds.shuffle, "fletcher32": ds.fletcher32}
    if ds.compression is not None:
        out.update(compression=ds.compression, compression_opts=ds.compression_opts)
    if ds.scaleoffset is not None:
        out["scaleoffset"] = ds.scaleoffset
    return out


def _absent(path: str, dtype: np.dtype) -> float | int:
    """The value of a row that lacks the quantity: NaN, -1 for integers, 0 samples for a channel."""
    if dtype.kind == "f":
        return np.nan
    return 0 if path.endswith("/" + L.SAMPLE_COUNT_DATASET) else L.ABSENT_INTEGER


def _channel_of(path: str) -> str | None:
    """The channel a dataset path ``points/channels/<name>/<dataset>`` belongs to, else None."""
    parts = path.split("/")
    if len(parts) == 4 and parts[0] == L.POINTS_GROUP and parts[1] == L.CHANNELS_GROUP:
        return parts[2]
    return None


@dataclass
class LogColumns:
    """What a columnar log holds besides its samples, read in one pass (:func:`read_columns`): its
    number of points, every group of ``/points`` and ``/truth`` with its attributes, every per-point
    dataset (dtype, attributes, filters, rows) and every channel's samples dataset (dtype,
    attributes, filters). A worker reads its shard's columns and sends them with the shard, so that
    the merge does not open every dataset of every shard again."""

    n: int
    groups: dict[str, dict]
    columns: dict[str, tuple[np.dtype, dict, dict, np.ndarray]]
    samples: dict[str, tuple[np.dtype, dict, dict]]


def read_columns(path: Path) -> LogColumns:
    """The columns of the columnar log ``path`` (see LogColumns)."""
    with open_log(path) as handle:
        check_format(handle)
        n = handle[f"{L.POINTS_GROUP}/{L.INDEX_DATASET}"].shape[0]
        found = LogColumns(n, {}, {}, {})

        def visit(name: str, obj) -> None:
            if isinstance(obj, h5py.Group):
                found.groups[name] = dict(obj.attrs)
            elif name.endswith("/" + L.SAMPLES_DATASET) and _channel_of(name) is not None:
                found.samples[name] = (obj.dtype, dict(obj.attrs), _filters(obj))
            elif obj.ndim != 1 or obj.shape[0] != n:
                raise h5format.fail(obj, f"expected one row per point ({n}), found shape {obj.shape}")
            else:
                found.columns[name] = (obj.dtype, dict(obj.attrs), _filters(obj), obj[()])

        for root in (L.POINTS_GROUP, L.TRUTH_GROUP):
            group = h5format.subgroup(handle, root)
            visit(root, group)
            group.visititems(lambda name, obj, root=root: visit(f"{root}/{name}", obj))
    return found


class _Plan:
    """What the sources hold (the first pass): every group, every per-point column with each
    source's rows, every channel's samples dataset, and the rows' index order."""

    def __init__(self, sources: Sequence[LogColumns]) -> None:
        self.groups: dict[str, dict] = {}
        self.columns: dict[str, _Column] = {}
        self.samples: dict[str, tuple[np.dtype, dict, dict]] = {}
        self.sizes = [source.n for source in sources]
        for number, source in enumerate(sources):
            for path, attrs in source.groups.items():
                self.groups.setdefault(path, attrs)
            for path, (dtype, attrs, filters) in source.samples.items():
                known = self.samples.setdefault(path, (dtype, attrs, filters))
                _same_units(path, known[1], attrs)
            for path, (dtype, attrs, filters, rows) in source.columns.items():
                column = self.columns.get(path)
                if column is None:
                    column = self.columns[path] = _Column(dtype, attrs, filters, [])
                _same_units(path, column.attrs, attrs)
                column.rows += [None] * (number - len(column.rows))
                column.rows.append(rows)
        for column in self.columns.values():
            column.rows += [None] * (len(sources) - len(column.rows))
        self.index = self._concatenated(f"{L.POINTS_GROUP}/{L.INDEX_DATASET}")
        self.order = np.argsort(self.index, kind="stable")
        self.index = self.index[self.order]
        if np.any(np.diff(self.index) <= 0):
            raise ParameterError("sources", f"{len(sources)} logs", "logs holding different points (a point is in two)")

    def _concatenated(self, path: str) -> np.ndarray:
        column = self.columns[path]
        fill = _absent(path, column.dtype)
        return np.concatenate([np.full(n, fill, dtype=column.dtype) if rows is None else rows.astype(column.dtype, copy=False)
                               for rows, n in zip(column.rows, self.sizes)])

    def rows(self, path: str) -> np.ndarray:
        """The merged rows of a per-point column, in index order."""
        return self._concatenated(path)[self.order]

    def source_rows(self) -> tuple[np.ndarray, np.ndarray]:
        """(source number, row in that source) of every merged row, in index order."""
        source = np.repeat(np.arange(len(self.sizes)), self.sizes)
        local = np.concatenate([np.arange(n) for n in self.sizes]) if self.sizes else np.empty(0, dtype=np.int64)
        return source[self.order], local[self.order]


def _same_units(path: str, known: dict, attrs: dict) -> None:
    unit, other = known.get(L.ATTR_UNITS), attrs.get(L.ATTR_UNITS)
    if unit != other:
        raise ParameterError(f"{path}.units", other, f"{unit!r}, the unit of the earlier points (one unit per quantity)")


def merge_logs(target: Path, metadata: RunMetadata, sources: Sequence[Path], *, tmp_folder: Path | None = None,
               columns: Sequence[LogColumns | None] | None = None) -> Path:
    """Write the points of the columnar logs ``sources`` (disjoint sets of points of the run
    ``metadata``) as one columnar log ``target``, atomically; returns ``target``.

    The result holds what a run writing the same points one by one holds (rig.logbook.writer);
    a ``/reduced`` table of a source is not carried over. ``tmp_folder``: where the temporary
    file is written (default: the target's folder; same file system). ``columns``: the sources'
    columns where already read (read_columns; None: read here).
    """
    if not sources:
        raise ParameterError("sources", "none", "at least one log")
    given = list(columns) if columns is not None else [None] * len(sources)
    plan = _Plan([read_columns(path) if known is None else known for path, known in zip(sources, given)])
    with atomic.new_hdf5(Path(target), tmp_folder=tmp_folder) as out:
        h5format.write_metadata(out, metadata)
        for path in sorted(plan.groups):
            group = out.require_group(path)
            group.attrs.update(plan.groups[path])
        lengths = {}
        for path, column in plan.columns.items():
            channel = _channel_of(path)
            if channel is not None and path.endswith("/" + L.SAMPLE_COUNT_DATASET):
                lengths[channel] = plan.rows(path)
        for path, column in plan.columns.items():
            channel = _channel_of(path)
            if channel is not None and path.endswith("/" + L.FIRST_SAMPLE_DATASET):
                values = _firsts(lengths[channel], plan.rows(path.rsplit("/", 1)[0] + "/" + L.ATTR_SAMPLE_RATE))
            elif path == f"{L.TRUTH_GROUP}/{L.INDEX_DATASET}":
                values = plan.index
            else:
                values = plan.rows(path)
            ds = out.create_dataset(path, data=values, chunks=chunks_for(values.size), maxshape=(None,), **column.filters)
            ds.attrs.update(column.attrs)
        _copy_samples(out, plan, sources, lengths)
    return Path(target)


def _firsts(lengths: np.ndarray, rates: np.ndarray) -> np.ndarray:
    """Offsets of each row's samples in the merged channel: the samples of the rows before it; 0 for
    a row without the channel (NaN sample rate), as rig.logbook.columnar writes them."""
    before = np.cumsum(lengths) - lengths
    return np.where(np.isnan(rates), 0, before).astype(np.int64)


def _runs(source: np.ndarray, local: np.ndarray) -> Iterable[tuple[int, int, int]]:
    """(source, first merged row, end merged row) of each stretch of merged rows that are
    consecutive rows of one source (one stretch per source unless their points interleave)."""
    if source.size == 0:
        return
    breaks = np.flatnonzero((np.diff(source) != 0) | (np.diff(local) != 1)) + 1
    starts = np.concatenate([[0], breaks])
    ends = np.concatenate([breaks, [source.size]])
    for start, end in zip(starts, ends):
        yield int(source[start]), int(start), int(end)


def _copy_samples(out: h5py.File, plan: _Plan, sources: Sequence[Path], lengths: dict[str, np.ndarray]) -> None:
    """Create every channel's samples dataset and copy the sources' samples into it, a stretch of
    consecutive rows (and at most SAMPLES_PER_BLOCK samples) at a time."""
    source, local = plan.source_rows()
    targets = {}
    for path, (dtype, attrs, filters) in plan.samples.items():
        channel = _channel_of(path)
        total = int(lengths[channel].sum()) if channel in lengths else 0
        ds = out.create_dataset(path, shape=(total,), dtype=dtype, chunks=chunks_for(total), maxshape=(None,), **filters)
        ds.attrs.update(attrs)
        targets[channel] = (path, ds, np.cumsum(lengths[channel]) - lengths[channel] if channel in lengths else None)
    runs = list(_runs(source, local))
    for number, path in enumerate(sources):
        mine = [run for run in runs if run[0] == number]
        if not mine:
            continue
        with open_log(path) as handle:
            for channel, (samples_path, ds, at) in targets.items():
                group_path = samples_path.rsplit("/", 1)[0]
                first = plan.columns.get(f"{group_path}/{L.FIRST_SAMPLE_DATASET}")
                if first is None or first.rows[number] is None:
                    continue
                src = handle[samples_path]
                first = first.rows[number]
                length = plan.columns[f"{group_path}/{L.SAMPLE_COUNT_DATASET}"].rows[number]
                for _, start, end in mine:
                    rows = local[start:end]
                    count = int(length[rows].sum())
                    if count == 0:
                        continue
                    held = rows[length[rows] > 0]
                    lo = int(first[held[0]])
                    to = int(at[start + int(np.flatnonzero(length[rows] > 0)[0])])
                    for offset in range(0, count, SAMPLES_PER_BLOCK):
                        size = min(SAMPLES_PER_BLOCK, count - offset)
                        ds[to + offset:to + offset + size] = src[lo + offset:lo + offset + size]

