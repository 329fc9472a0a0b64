"""Write the reduction's table back into a log (``/reduced``, atomically) and read it."""

from __future__ import annotations

from collections.abc import Mapping

import h5py
import numpy as np
import pandas as pd

from rig.errors import LogFormatError, ParameterError
from rig.logbook import atomic, h5format
from rig.logbook import layout as L
from rig.logbook.columnar import COLUMN_FILTERS, chunks_for
from rig.logbook.opening import as_path, open_log
from rig.logbook.units import DIMENSIONLESS, UNIT_RULE, column_name, is_unit, safe_unit


def _column_units(table: pd.DataFrame, units: Mapping[str, str] | None) -> dict[str, str]:
    """Unit of every column; a dimensional column's name must end in ``_<safe unit>``; text
    columns (e.g. the reason a value could not be reduced) have unit "1"."""
    if units is None:
        units = table.attrs.get("units")
    if not isinstance(units, Mapping):
        raise ParameterError("units", units, "a mapping column -> unit (or table.attrs['units'])")
    out = {}
    for column in table.columns:
        if not isinstance(column, str) or column not in units:
            raise ParameterError("units", sorted(map(str, units)), f"a unit for every column, including {column!r}")
        unit = units[column]
        if not is_unit(unit):
            raise ParameterError(f"units[{column!r}]", unit, UNIT_RULE)
        if column_name(column, "1") != column or "/" in column:
            raise ParameterError("column", column, "an identifier-safe name")
        if unit != DIMENSIONLESS:
            suffix = "_" + safe_unit(unit)
            if not column.endswith(suffix) or column == suffix:
                raise ParameterError("column", column, f"a name ending in {suffix!r} (<name>_<unit>, unit {unit!r})")
        kind = table[column].dtype.kind
        if kind not in "iuf" and not (unit == DIMENSIONLESS and _is_text(table[column])):
            raise ParameterError(f"table[{column!r}].dtype", str(table[column].dtype), "numeric, or text with unit '1'")
        out[column] = unit
    return out


def _is_text(column: pd.Series) -> bool:
    return bool(column.map(lambda v: isinstance(v, str)).all())


def write_reduced(path: object, table: pd.DataFrame, units: Mapping[str, str] | None = None) -> None:
    """Store ``table`` as ``/reduced`` in the log ``path``, replacing any earlier one, atomically.

    ``units``: {column: unit} (default ``table.attrs["units"]``); every column must be numeric and
    named ``<name>_<safe unit>``; the (integer) index is stored too. NaN marks a value that could
    not be reduced. Every other object of the log is copied into a new file, which gets the
    table and is renamed over the original: the result depends only on the log's content and the
    table, not on whether the log was reduced before.
    """
    log = as_path("path", path)
    if not isinstance(table, pd.DataFrame):
        raise ParameterError("table", type(table).__name__, "a pandas DataFrame")
    if table.index.dtype.kind not in "iu":
        raise ParameterError("table.index.dtype", str(table.index.dtype), "an integer index (e.g. the point index)")
    if not table.columns.is_unique:
        raise ParameterError("table.columns", list(table.columns), "unique column names")
    column_units = _column_units(table, units)
    with open_log(log):
        pass
    with atomic.new_hdf5(log, mode_of=log) as new, h5py.File(log, "r") as old:
        for name, value in old.attrs.items():
            new.attrs[name] = value
        for name in old:
            if name != L.REDUCED_GROUP:
                old.copy(old[name], new, name=name)
        _write_table(new.create_group(L.REDUCED_GROUP), table, column_units)


def _write_table(group: h5py.Group, table: pd.DataFrame, units: Mapping[str, str]) -> None:
    group.attrs[L.ATTR_COLUMNS] = list(table.columns)
    group.attrs[L.ATTR_INDEX_NAME] = "" if table.index.name is None else str(table.index.name)
    compact = {"chunks": chunks_for(len(table)), **COLUMN_FILTERS}
    group.create_dataset(L.REDUCED_INDEX_DATASET, data=table.index.to_numpy(dtype=np.int64), **compact)
    for column in table.columns:
        values = table[column]
        if values.dtype.kind in "iuf":
            ds = group.create_dataset(column, data=values.to_numpy(), **compact)
        else:
            ds = group.create_dataset(column, data=values.astype(str).tolist(), dtype=h5py.string_dtype())
        ds.attrs[L.ATTR_UNITS] = units[column]


def read_reduced(path: object) -> pd.DataFrame:
    """The table stored by :func:`write_reduced` (``attrs["units"]`` = {column: unit})."""
    with open_log(path) as handle:
        if L.REDUCED_GROUP not in handle:
            raise LogFormatError(f"{path}: the log has no {L.REDUCED_GROUP!r} group (not reduced yet)")
        group = h5format.subgroup(handle, L.REDUCED_GROUP)
        columns = [str(c) for c in h5format.attr(group, L.ATTR_COLUMNS)]
        index_ds = group.get(L.REDUCED_INDEX_DATASET)
        if not isinstance(index_ds, h5py.Dataset) or index_ds.ndim != 1:
            raise h5format.fail(group, f"dataset {L.REDUCED_INDEX_DATASET!r} is missing")
        index = pd.Index(index_ds[()], name=h5format.text_attr(group, L.ATTR_INDEX_NAME) or None)
        data, units = {}, {}
        for column in columns:
            ds = group.get(column)
            if not isinstance(ds, h5py.Dataset) or ds.shape != index.shape:
                raise h5format.fail(group, f"column {column!r} is missing or not {len(index)} long")
            data[column] = ds.asstr()[()] if h5py.check_string_dtype(ds.dtype) else ds[()]
            units[column] = h5format.units_of(ds)
        table = pd.DataFrame(data, index=index, columns=columns)
        table.attrs["units"] = units
        return table
