"""Build the one-row-per-point DataFrames of the readers (units in the column names)."""

from __future__ import annotations

from collections.abc import Mapping

import pandas as pd

from rig.errors import LogFormatError
from rig.logbook.content import Quantity
from rig.logbook.units import column_name

INDEX_NAME = "point"
"""Name of the index of every per-point table (the point index)."""


class TableBuilder:
    """Collects ``{column: value}`` rows and the unit of every column, then makes a DataFrame."""

    def __init__(self, where: str) -> None:
        self.where = where
        self.rows: dict[int, dict[str, float | int]] = {}
        self.units: dict[str, str] = {}
        self.sources: dict[str, str] = {}

    def add(self, index: int, source: str, name: str, value: float | int, unit: str) -> None:
        """Add ``value`` [``unit``] of ``name`` at point ``index``; ``source`` names it in errors."""
        column = column_name(name, unit)
        known = self.sources.setdefault(column, source)
        if known != source or self.units.setdefault(column, unit) != unit:
            raise LogFormatError(
                f"{self.where}: point {index}: {source} [{unit}] and {known} [{self.units[column]}] "
                f"both give the column name {column!r}; rename one of them"
            )
        self.rows.setdefault(index, {})[column] = value

    def add_quantities(self, index: int, prefix: str, values: Mapping[str, Quantity]) -> None:
        for name, q in values.items():
            self.add(index, f"{prefix}{name}", f"{prefix}{name}", q.value, q.unit)

    def row(self, index: int) -> None:
        """Make sure point ``index`` has a row even if it has no values."""
        self.rows.setdefault(index, {})

    def frame(self) -> pd.DataFrame:
        """The table: index ``point``, columns sorted by name, ``attrs["units"]`` = {column: unit}."""
        columns = sorted(self.units)
        index = pd.Index(sorted(self.rows), name=INDEX_NAME, dtype="int64")
        table = pd.DataFrame.from_records(
            [self.rows[i] for i in index], index=index, columns=columns
        )
        table.attrs["units"] = {c: self.units[c] for c in columns}
        return table


def frame_of(where: str, index: pd.Index, columns: list[tuple[str, str, object, str]]) -> pd.DataFrame:
    """A per-point table from whole columns: ``(source, name, values, unit)`` each, one value per
    row of ``index``; ``source`` names the column in errors. Columns sorted by name, units in
    ``attrs["units"]``; two columns that get the same name are a LogFormatError, as in TableBuilder."""
    data, units, sources = {}, {}, {}
    for source, name, values, unit in columns:
        column = column_name(name, unit)
        if column in sources:
            raise LogFormatError(f"{where}: {source} [{unit}] and {sources[column]} [{units[column]}] both give the "
                                 f"column name {column!r}; rename one of them")
        data[column], units[column], sources[column] = values, unit, source
    order = sorted(data)
    table = pd.DataFrame({c: data[c] for c in order}, index=index, columns=order)
    table.attrs["units"] = {c: units[c] for c in order}
    return table
