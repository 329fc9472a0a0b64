"""Reduce a finished log: the stand's reduce_log, truth beside it, reduced.csv and ``/reduced`` in the log.

The stand reduces its own log with eqs. (29)-(36) (``Stand.reduce_log(log_path, contact)``; the
runner passes the scene's ContactSpec, from which the stand builds the contact law at each
load's b/a). The table's index is the point index. When the stand's table has no ``true_``
columns and the log has a truth group, the runner adds ``true_<name>`` for l_over_a, c_over_a,
mu_v and mu_T from the dimensionless truth values of the same name; ``true_mu_v`` and
``true_mu_T`` fall back to the truth's single friction coefficient ``mu`` (the simulation uses
one mu for both directions), a choice of this runner.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.errors import LogFormatError, ParameterError, RigError
from rig.logbook import write_reduced
from rig.logbook.atomic import WRITE_FAILURES
from rig.logbook.truth import read_truth
from rig.logbook.units import DIMENSIONLESS
from rig.reduction.table import DAMAGED
from rig.runner.outputs import REDUCED_CSV
from rig.runner.off_truth import with_off_truth
from rig.stands.base import ContactSpec, Stand

TRUTH_SOURCES = {
    "l_over_a": ("l_over_a",),
    "c_over_a": ("c_over_a",),
    "mu_v": ("mu_v", "mu"),
    "mu_T": ("mu_T", "mu"),
}
"""true_<name> column -> dimensionless truth values (bare column names of read_truth) tried in order."""


@dataclass(frozen=True)
class Reduction:
    """A reduced log: the table (index: point), the CSV written, whether ``/reduced`` went into
    the log (``problem`` says why not), and the damaged points (reduced to NaN, reason given)."""

    table: pd.DataFrame
    csv: Path
    stored_in_log: bool
    problem: str | None
    damaged: tuple[int, ...] = ()
    notes: tuple[str, ...] = ()

    @property
    def problems(self) -> list[str]:
        """The lines for the summary: the damaged points and why /reduced is not in the log."""
        lines = []
        if self.damaged:
            shown = ", ".join(map(str, self.damaged[:20])) + (" ..." if len(self.damaged) > 20 else "")
            lines.append(f"{len(self.damaged)} damaged point(s) reduced to NaN (reduced.csv's reason names the "
                         f"dataset and the bad value): {shown}")
        return lines + list(self.notes) + ([self.problem] if self.problem else [])


def damaged_points(table: pd.DataFrame) -> tuple[int, ...]:
    """Indices of the rows whose reason says the log could not give the point."""
    if "reason" not in table:
        return ()
    marked = table["reason"].astype(str).str.startswith(DAMAGED)
    return tuple(int(i) for i in table.index[marked.to_numpy()])


def attach_truth(table: pd.DataFrame, truth: pd.DataFrame | None) -> pd.DataFrame:
    """``table`` with ``true_<name>`` columns from ``truth`` (rows matched by point index), unless it
    already has truth columns or there is none."""
    if truth is None or _has_truth_columns(table):
        return table
    table = table.copy()
    truth_units = truth.attrs.get("units", {})
    for name, sources in TRUTH_SOURCES.items():
        source = next((s for s in sources if truth_units.get(s) == DIMENSIONLESS), None)
        if source is not None:
            table[f"true_{name}"] = truth[source].reindex(table.index).to_numpy()
            if isinstance(table.attrs.get("units"), dict):
                table.attrs["units"] = table.attrs["units"] | {f"true_{name}": DIMENSIONLESS}
    return table


def read_truth_if_any(log_path: Path) -> pd.DataFrame | None:
    """The log's truth table, or None for a log without a truth group (a real stand's)."""
    try:
        return read_truth(log_path)
    except LogFormatError:
        return None


def reduce_table(stand: Stand, log_path: Path, contact: ContactSpec) -> pd.DataFrame:
    """The stand's reduced table of ``log_path`` with the truth beside it (``true_<name>``)."""
    table = stand.reduce_log(log_path, contact)
    if not isinstance(table, pd.DataFrame):
        raise RigError(f"stand {stand.name!r}: reduce_log returned {type(table).__name__}, not a DataFrame")
    if _has_truth_columns(table):  # the stand put its truth beside it: the log's truth is not read again
        return table
    return attach_truth(table, read_truth_if_any(log_path))


def _has_truth_columns(table: pd.DataFrame) -> bool:
    return any(str(c).startswith("true_") for c in table.columns)


def gathered_table(tables: list[pd.DataFrame | None]) -> pd.DataFrame | None:
    """The reduced table of a log from the reduced tables of its shards (in point order): their rows
    one after the other, as the whole log's reduction gives them (a point's row depends only on
    its record). None when a shard's table is missing or the tables differ in columns, dtypes or
    units (then the log is reduced whole). ``tables`` is emptied once they are joined (the parent's
    memory then holds the whole table only)."""
    if not tables or any(table is None for table in tables):
        return None
    first = tables[0]
    notes = list(dict.fromkeys(note for part in tables for note in part.attrs.get("notes", ())))
    for table in tables[1:]:
        if (list(table.columns) != list(first.columns) or not table.dtypes.equals(first.dtypes)
                or table.attrs.get("units") != first.attrs.get("units") or table.index.name != first.index.name):
            return None
    table = pd.concat(tables) if len(tables) > 1 else first.copy()
    tables.clear()  # the caller's list: the chunks' tables are not held beside the whole one
    if not table.index.is_monotonic_increasing or not table.index.is_unique:
        return None
    table.attrs = {"units": dict(first.attrs.get("units", {}))} | ({"notes": notes} if notes else {})
    return table


CSV_LINE_END = "\n"
"""The line end of reduced.csv, on every system (the rows formatted on workers are joined with it)."""


@dataclass(frozen=True)
class FormattedRows:
    """A file of reduced.csv's lines (csv_rows) of a table with ``columns``, in point order."""

    path: Path
    columns: tuple[str, ...]


def csv_rows(table: pd.DataFrame) -> str | None:
    """``table``'s rows as lines of reduced.csv (the header left out), formatted where the table was
    reduced - a chunk's on its worker: pandas formats each value on its own, so the lines of the
    chunks one after the other are the lines of the whole table. None when a value holds a line
    break (then a line is not a row)."""
    text = table.to_csv(header=False, index=True, lineterminator=CSV_LINE_END)
    return text if text.count(CSV_LINE_END) == len(table) else None


def reduce_to_files(stand: Stand, log_path: Path, contact: ContactSpec, out_dir: Path) -> Reduction:
    """Reduce ``log_path`` with ``stand``; write ``out_dir/reduced.csv`` and ``/reduced`` into the log."""
    return table_to_files(reduce_table(stand, log_path, contact), log_path, out_dir)


def table_to_files(table: pd.DataFrame, log_path: Path, out_dir: Path, rows: FormattedRows | None = None
                   ) -> Reduction:
    """Write a reduced table of ``log_path`` as ``out_dir/reduced.csv`` and as ``/reduced`` into the log,
    with the twin's off-truth flags (rig.runner.off_truth.with_off_truth) taken over the whole run.
    ``rows``: the table's rows as csv_rows formatted them on the workers (every column up to
    ``z_max``), in the table's order; reduced.csv is then those lines with the flags added, not
    formatted again."""
    table = with_off_truth(table)
    damaged = damaged_points(table)
    notes = tuple(table.attrs.get("notes", ()))
    csv = write_csv(table, out_dir / REDUCED_CSV, rows)
    try:
        write_reduced(log_path, table)
    except (ParameterError, OSError) as error:  # e.g. a read-only log: reported; reduced.csv holds the table
        if isinstance(error, OSError) and error.errno in WRITE_FAILURES:
            raise  # a full disk: the run stops with that error
        return Reduction(table, csv, False, f"reduced table not stored in {log_path.name}: {error}", damaged, notes)
    return Reduction(table, csv, True, None, damaged, notes)


def write_csv(table: pd.DataFrame, csv: Path, rows: FormattedRows | None = None) -> Path:
    """Write the (flagged) reduced ``table`` as ``csv``: the table's to_csv, or - when ``rows`` holds its
    lines as the workers formatted them - those lines with the ``off_truth`` flags added, the same bytes."""
    if rows is None or not _csv_from_rows(table, rows, csv):
        table.to_csv(csv, index=True, index_label=_index_label(table), lineterminator=CSV_LINE_END)
    return csv


def _index_label(table: pd.DataFrame) -> str:
    return table.index.name or "point"


def _csv_from_rows(table: pd.DataFrame, rows: FormattedRows, csv: Path) -> bool:
    """Write ``csv`` as table.to_csv would, from the lines of ``rows`` (every column but ``off_truth``,
    added here: its threshold is the whole run's); False when those lines are not of the table's
    columns or not one per row."""
    flags = None
    if list(table.columns) != [*rows.columns, *(["off_truth"] if "off_truth" in table else [])]:
        return False
    if "off_truth" in table:  # a float column: each value as to_csv writes it (astype(str), NaN empty)
        values = table["off_truth"].to_numpy(dtype=float)
        flags = [flag.encode() for flag in np.where(np.isnan(values), "", values.astype(str)).tolist()]
    header = table.iloc[:0].to_csv(index=True, index_label=_index_label(table), lineterminator=CSV_LINE_END)
    count = 0
    with open(rows.path, "rb") as source, open(csv, "wb") as out:  # binary: lines end at "\n" only
        out.write(header.encode())
        for line in source:
            if count == len(table):
                return False
            out.write(line if flags is None else line[:-1] + b"," + flags[count] + b"\n")
            count += 1
    return count == len(table)
