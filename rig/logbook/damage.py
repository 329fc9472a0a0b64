"""The reason a point of a log could not be reduced: the file, the dataset, the point and the value.

A stand's reduction raises a ParameterError when a value read from the log is outside what its
instruments can give (a calibration sensitivity of 0, a negative standard uncertainty, a normal
force <= 0, a sample whose square overflows). :func:`damage_reason` turns such an error into the
``reason`` of that point: it finds the dataset of the point's record that holds the offending
value (by the error's parameter name first, then by the value) and names it with its in-file path
(docs/log-format.md, "Damaged points").
"""

from __future__ import annotations

import math

import numpy as np

from rig.errors import LogFormatError, ParameterError
from rig.logbook import layout as L
from rig.logbook.content import PointRecord


def _scalars(record: PointRecord):
    """(in-file path, name, value) of every scalar of the record."""
    for kind, values in ((L.SETTINGS_GROUP, record.settings), (L.READINGS_GROUP, record.readings)):
        for name, q in values.items():
            yield f"/{L.POINTS_GROUP}/{kind}/{name}", name, q.value
    for rec, fields in record.calibration.items():
        for name, q in fields.items():
            yield f"/{L.POINTS_GROUP}/{L.CALIBRATION_GROUP}/{rec}/{name}", name, q.value
    if record.counters is not None:
        gate = f"/{L.POINTS_GROUP}/{L.COUNTERS_GROUP}/{L.GATE_TIME_DATASET}"
        yield gate, L.GATE_TIME_DATASET, record.counters.gate_time_s


def _same(a: object, b: object) -> bool:
    try:
        return float(a) == float(b) or (math.isnan(float(a)) and math.isnan(float(b)))
    except (TypeError, ValueError):
        return False


def locate(record: PointRecord, error: ParameterError) -> str | None:
    """In-file path of the record's dataset holding ``error.value`` (``name[k]``: sample k of a
    channel), preferring one named as ``error.name``; None when no dataset holds it."""
    name = str(error.name).split("[")[0].split(".")[-1]
    scalars = list(_scalars(record))
    for path, field, value in scalars:
        if field == name and _same(value, error.value):
            return path
    for path, _, value in scalars:
        if _same(value, error.value):
            return path
    for channel, data in record.channels.items():
        try:
            hits = np.flatnonzero(data.samples == float(error.value))
        except (TypeError, ValueError):
            break
        if hits.size:
            return f"/{L.POINTS_GROUP}/{L.CHANNELS_GROUP}/{channel}/{L.SAMPLES_DATASET}[{int(hits[0])}]"
    return None


def damage_reason(path: object, index: int, error: Exception, record: PointRecord | None = None) -> str:
    """One line: what is wrong with point ``index`` of the log ``path``, naming the file, the
    dataset (found in ``record`` for a ParameterError), the point and the value."""
    text = " ".join(str(error).split())
    if isinstance(error, ParameterError) and record is not None:
        where = locate(record, error)
        if where is not None:
            text = f"{where}: point {index}: {text}"
    if f"point {index}" not in text:
        text = f"point {index}: {text}"
    if not text.startswith(str(path)):
        text = f"{path}: {text}"
    return text


__all__ = ["LogFormatError", "damage_reason", "locate"]
