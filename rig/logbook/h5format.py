"""Decode the one-group-per-point layout of format version 1 (and encode the run metadata).

Version-1 logs are no longer written (the writer lays out the columnar version 2,
rig.logbook.columnar); their encoder survives only in the tests (tests/logbook/logbook_samples.py).

Decoding checks every object it touches and raises :class:`LogFormatError` naming the file, the
object's path inside it (which names the point) and what is wrong.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from typing import TypeVar

import h5py
import numpy as np

from rig.errors import LogFormatError, ParameterError
from rig.logbook import layout as L
from rig.logbook.content import Channel, Counter, CounterReadings, PointRecord, Quantity, RunMetadata
from rig.logbook.units import UNIT_RULE, is_unit

T = TypeVar("T")


def fail(obj: h5py.HLObject, what: str) -> LogFormatError:
    """A :class:`LogFormatError` for ``obj`` naming its file and in-file path."""
    return LogFormatError(f"{obj.file.filename}: {obj.name}: {what}")


def shown(value: object) -> str:
    """``repr`` of a value read from a file, NumPy scalars shown as plain Python values."""
    return repr(value.item() if isinstance(value, np.generic) else value)


def decoded(obj: h5py.HLObject, build: Callable[[], T]) -> T:
    """Run ``build``; a ParameterError (bad value read from the file) or text that is not UTF-8
    (damaged bytes) becomes a LogFormatError."""
    try:
        return build()
    except ParameterError as err:
        raise fail(obj, f"bad value read from the file: {err}") from None
    except UnicodeDecodeError as err:
        raise fail(obj, f"damaged text, not UTF-8 ({err.reason} at byte {err.start})") from None


# ----------------------------------------------------------------------------- attributes

def attr(obj: h5py.HLObject, name: str) -> object:
    """Attribute ``name`` of ``obj`` or a LogFormatError saying it is missing."""
    if name not in obj.attrs:
        raise fail(obj, f"attribute {name!r} is missing")
    return obj.attrs[name]


def text_attr(obj: h5py.HLObject, name: str) -> str:
    value = attr(obj, name)
    if not isinstance(value, str):
        raise fail(obj, f"attribute {name!r} = {shown(value)} is not a text string")
    return value


def number_attr(obj: h5py.HLObject, name: str, *, integer: bool = False) -> float | int:
    value = attr(obj, name)
    kinds = "iu" if integer else "iuf"
    if not (isinstance(value, np.generic | int | float) and np.asarray(value).dtype.kind in kinds):
        raise fail(obj, f"attribute {name!r} = {shown(value)} is not {'an integer' if integer else 'a number'}")
    return int(value) if integer else float(value)


def units_of(obj: h5py.HLObject) -> str:
    """The ``units`` attribute of ``obj``, checked against the ASCII unit form."""
    unit = attr(obj, L.ATTR_UNITS)
    if not is_unit(unit):
        raise fail(obj, f"attribute 'units' = {shown(unit)} is not valid; valid: {UNIT_RULE}")
    return unit  # type: ignore[return-value]


def subgroup(parent: h5py.Group, name: str) -> h5py.Group:
    """Group ``name`` inside ``parent`` or a LogFormatError saying it is missing."""
    obj = parent.get(name)
    if not isinstance(obj, h5py.Group):
        raise fail(parent, f"group {name!r} is missing" if obj is None else f"{name!r} is not a group")
    return obj


def scalar(ds: object, parent: h5py.Group, name: str, kinds: str = "iuf") -> float | int:
    """Value of the scalar numeric dataset ``ds`` (``parent[name]``), checked."""
    if not isinstance(ds, h5py.Dataset):
        raise fail(parent, f"{name!r} is not a dataset")
    if ds.shape != () or ds.dtype.kind not in kinds:
        raise fail(ds, f"expected a scalar number, found shape {ds.shape} dtype {ds.dtype}")
    return ds[()].item()


# ----------------------------------------------------------------------------- run metadata

def write_metadata(handle: h5py.File, meta: RunMetadata) -> None:
    """Root attributes and the scene text of a log (or of the writer's ``run.h5`` part)."""
    handle.attrs[L.ATTR_FORMAT] = L.FORMAT_NAME
    handle.attrs[L.ATTR_FORMAT_VERSION] = np.int64(L.FORMAT_VERSION)
    handle.attrs[L.ATTR_PACKAGE_VERSION] = meta.package_version
    handle.attrs[L.ATTR_SEED] = np.int64(meta.seed)
    handle.attrs[L.ATTR_STAND] = meta.stand
    handle.attrs[L.ATTR_CREATED_UTC] = meta.created_utc
    handle.attrs[L.ATTR_SCENE_SHA256] = scene_digest(meta.scene_toml)
    handle.create_dataset(L.SCENE_DATASET, data=meta.scene_toml, dtype=h5py.string_dtype("utf-8"))


def scene_digest(text: str) -> str:
    """SHA-256 (hex) of the scene text's UTF-8 bytes (root attribute ``scene_sha256``)."""
    return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()


def read_metadata(handle: h5py.File) -> RunMetadata:
    scene = handle.get(L.SCENE_DATASET)
    if not isinstance(scene, h5py.Dataset) or scene.shape != () or scene.dtype.kind != "O":
        raise fail(handle, f"text dataset {L.SCENE_DATASET!r} is missing or not a string")
    text = decoded(scene, lambda: scene.asstr()[()])
    if L.ATTR_SCENE_SHA256 in handle.attrs and text_attr(handle, L.ATTR_SCENE_SHA256) != scene_digest(text):
        raise fail(scene, f"the scene text does not match its checksum (root attribute {L.ATTR_SCENE_SHA256!r}): "
                          "damaged bytes")
    return decoded(
        handle,
        lambda: RunMetadata(
            scene_toml=text,
            seed=number_attr(handle, L.ATTR_SEED, integer=True),
            stand=text_attr(handle, L.ATTR_STAND),
            created_utc=text_attr(handle, L.ATTR_CREATED_UTC),
            package_version=text_attr(handle, L.ATTR_PACKAGE_VERSION),
        ),
    )


# ----------------------------------------------------------------------------- scalars

def read_quantities(group: h5py.Group) -> dict[str, Quantity]:
    out = {}
    for name, ds in group.items():
        value = scalar(ds, group, name)
        unit = units_of(ds)
        out[name] = decoded(ds, lambda: Quantity(value, unit))
    return out


# ----------------------------------------------------------------------------- channels

def read_channel(group: h5py.Group, name: str) -> Channel:
    ds = group.get(name)
    if ds is None:
        present = ", ".join(group.keys()) or "none"
        raise fail(group, f"channel {name!r} is missing (present: {present})")
    if not isinstance(ds, h5py.Dataset) or ds.ndim != 1 or ds.dtype.kind not in "iuf":
        raise fail(group, f"channel {name!r} is not a 1-D numeric dataset")
    unit = units_of(ds)
    rate = number_attr(ds, L.ATTR_SAMPLE_RATE)
    start = number_attr(ds, L.ATTR_START_TIME)
    samples = ds[()]
    return decoded(ds, lambda: Channel(samples, unit, rate, start))


# ----------------------------------------------------------------------------- counters

def read_counters(point_group: h5py.Group) -> CounterReadings | None:
    if L.COUNTERS_GROUP not in point_group:
        return None
    group = subgroup(point_group, L.COUNTERS_GROUP)
    gate = number_attr(group, L.ATTR_GATE_TIME)
    counters = {}
    for name, ds in group.items():
        count = scalar(ds, group, name, kinds="iu")
        if units_of(ds) != L.COUNT_UNIT:
            raise fail(ds, f"attribute 'units' = {shown(ds.attrs[L.ATTR_UNITS])}; a counter's units must be {L.COUNT_UNIT!r}")
        marks = number_attr(ds, L.ATTR_MARKS, integer=True)
        counters[name] = decoded(ds, lambda: Counter(count, marks))
    return decoded(group, lambda: CounterReadings(gate, counters))


# ----------------------------------------------------------------------------- points

def point_index(group: h5py.Group) -> int:
    """The ``index`` attribute of a point group, checked against the group's name."""
    index = number_attr(group, L.ATTR_INDEX, integer=True)
    if not 0 <= index < 10**L.POINT_DIGITS or L.point_group_name(index) != group.name.rsplit("/", 1)[-1]:
        raise fail(group, f"attribute 'index' = {index} does not match the group name")
    return index


def point_groups(handle: h5py.File, parent: str = L.POINTS_GROUP) -> list[tuple[int, h5py.Group]]:
    """``(index, group)`` of every point under ``/points`` (or ``/truth``), in index order."""
    container = subgroup(handle, parent)
    found = []
    for name, group in container.items():
        if not isinstance(group, h5py.Group):
            raise fail(container, f"{name!r} is not a point group")
        found.append((point_index(group), group))
    return sorted(found, key=lambda pair: pair[0])


def read_point(group: h5py.Group) -> PointRecord:
    """Decode one ``/points/point_NNNNNN`` group (checks every object)."""
    for name in L.POINT_SUBGROUPS:
        subgroup(group, name)
    channels_group = subgroup(group, L.CHANNELS_GROUP)
    calibration = subgroup(group, L.CALIBRATION_GROUP)
    records = {}
    for name in calibration:
        records[name] = read_quantities(subgroup(calibration, name))
    index = point_index(group)
    settings = read_quantities(subgroup(group, L.SETTINGS_GROUP))
    readings = read_quantities(subgroup(group, L.READINGS_GROUP))
    channels = {name: read_channel(channels_group, name) for name in channels_group}
    counters = read_counters(group)
    return decoded(group, lambda: PointRecord(index, settings, channels, counters, readings, records))
