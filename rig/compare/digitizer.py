"""Reader of WebPlotDigitizer exports: the "all datasets" CSV and the headerless per-dataset export.

Layouts (docs/compare.md):

* all datasets: line 1 holds the dataset names (each in the X cell of its pair, the Y cell blank),
  line 2 holds ``X,Y`` per dataset, then one point per dataset per line; a shorter dataset is
  padded with blank cells (or the line simply ends early);
* per dataset: no header, one ``x,y`` point per line.

The separator is taken from the first line holding one: ``;`` (then decimal commas are read,
``0,5`` = 0.5), else a tab (decimal commas too), else ``,``. Blank lines and lines of
separators only (padding) are skipped.
A line that cannot be read (or a number beyond a float's range, or an x repeated with another y)
raises :class:`DigitisedFormatError` naming the file and the line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import Enum
from pathlib import Path

import numpy as np
import pandas as pd

from rig.compare.sidecar import Sidecar
from rig.errors import LogFormatError, ParameterError, UnknownNameError

_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")


class DigitisedFormatError(LogFormatError):
    """A digitised export that cannot be read; names the file, the line (1-based) and the reason."""

    def __init__(self, source: str, line: int, reason: str) -> None:
        self.source = source
        self.line = line
        self.reason = reason
        super().__init__(f"{source}, line {line}: {reason}")


class ExportLayout(Enum):
    """Which WebPlotDigitizer export a file is."""

    ALL_DATASETS = "all datasets"
    SINGLE_DATASET = "single dataset"


@dataclass(frozen=True)
class DigitisedCurve:
    """One digitised dataset in file order: x, y [units of the figure's axes] and source line numbers.

    name is None for a headerless per-dataset export (the sidecar then names it).
    """

    name: str | None
    x: np.ndarray
    y: np.ndarray
    lines: np.ndarray


@dataclass(frozen=True)
class _Line:
    number: int
    cells: list[str]
    decimal_comma: bool


def read_export(path: str | Path) -> tuple[ExportLayout, list[DigitisedCurve]]:
    """Read a WebPlotDigitizer export file (UTF-8, optional BOM); see :func:`parse_export`.

    Parameters
    ----------
    path : str or pathlib.Path
        The export file.

    Returns
    -------
    tuple of (ExportLayout, list of DigitisedCurve)
        The layout and the datasets in file order.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise DigitisedFormatError(str(path), 0, "no such file") from None
    except UnicodeDecodeError as error:
        raise DigitisedFormatError(str(path), 0, f"not UTF-8 text ({error.reason})") from None
    return parse_export(text, source=str(path))


def parse_export(text: str, source: str = "<text>") -> tuple[ExportLayout, list[DigitisedCurve]]:
    """Parse the text of a WebPlotDigitizer export.

    Parameters
    ----------
    text : str
        The export's CSV text (all datasets, or one dataset without a header).
    source : str, optional
        Its name in error messages (default ``"<text>"``).

    Returns
    -------
    tuple of (ExportLayout, list of DigitisedCurve)
        The layout and the datasets in file order (x, y in the units of the figure's axes).
    """
    lines = _split(text)
    if not lines:
        raise DigitisedFormatError(source, 1, "no data (the file is empty or blank)")
    if len(lines) > 1 and lines[1].cells and lines[1].cells[0].upper() == "X":
        return ExportLayout.ALL_DATASETS, _all_datasets(lines, source)
    return ExportLayout.SINGLE_DATASET, [_single_dataset(lines, source)]


def _split(text: str) -> list[_Line]:
    """Non-blank lines as stripped cells; the separator (and decimal comma) from the first one."""
    raw = text.splitlines()
    first = next((line for line in raw if any(sep in line for sep in ";\t,")), "")
    separator = ";" if ";" in first else "\t" if "\t" in first else ","
    decimal_comma = separator != ","
    result = []
    for number, line in enumerate(raw, start=1):
        cells = [cell.strip() for cell in line.split(separator)]
        while cells and not cells[-1]:
            cells.pop()
        if cells:
            result.append(_Line(number, cells, decimal_comma))
    return result


def _number(cell: str, line: _Line, what: str, source: str) -> float:
    text = cell.replace(",", ".") if line.decimal_comma else cell
    if not _NUMBER.fullmatch(text):
        raise DigitisedFormatError(source, line.number, f"{what} is {cell!r}, not a number")
    value = float(text)
    if not np.isfinite(value):
        raise DigitisedFormatError(source, line.number, f"{what} is {cell!r}, beyond the range of a float")
    return value


def _single_dataset(lines: list[_Line], source: str) -> DigitisedCurve:
    points = []
    for line in lines:
        if len(line.cells) != 2:
            raise DigitisedFormatError(
                source, line.number, f"expected 2 values (x, y) in a per-dataset export, found {len(line.cells)}"
            )
        x = _number(line.cells[0], line, "x", source)
        y = _number(line.cells[1], line, "y", source)
        points.append((x, y, line.number))
    return _curve(None, points, source)


def _all_datasets(lines: list[_Line], source: str) -> list[DigitisedCurve]:
    names = _names(lines[0], source)
    width = 2 * len(names)
    header = lines[1]
    expected = ["X", "Y"] * len(names)
    if [cell.upper() for cell in header.cells] != expected:
        raise DigitisedFormatError(
            source, header.number, f"expected {','.join(expected)} under the {len(names)} dataset names"
        )
    points: list[list[tuple[float, float, int]]] = [[] for _ in names]
    ended = [False] * len(names)
    for line in lines[2:]:
        if len(line.cells) > width:
            raise DigitisedFormatError(
                source, line.number, f"found {len(line.cells)} cells, the header has {width} ({len(names)} datasets)"
            )
        cells = line.cells + [""] * (width - len(line.cells))
        for k, name in enumerate(names):
            x_cell, y_cell = cells[2 * k], cells[2 * k + 1]
            if not x_cell and not y_cell:
                ended[k] = True
                continue
            if not x_cell or not y_cell:
                raise DigitisedFormatError(source, line.number, f"dataset {name!r} has only one of x, y")
            if ended[k]:
                raise DigitisedFormatError(source, line.number, f"dataset {name!r} continues after blank padding")
            x = _number(x_cell, line, f"x of dataset {name!r}", source)
            y = _number(y_cell, line, f"y of dataset {name!r}", source)
            points[k].append((x, y, line.number))
    for name, pts in zip(names, points):
        if not pts:
            raise DigitisedFormatError(source, lines[0].number, f"dataset {name!r} has no points")
    return [_curve(name, pts, source) for name, pts in zip(names, points)]


def _names(line: _Line, source: str) -> list[str]:
    cells = line.cells + [""] * (len(line.cells) % 2)
    names = cells[0::2]
    for k, (name, y_cell) in enumerate(zip(names, cells[1::2])):
        if not name:
            raise DigitisedFormatError(source, line.number, f"dataset name {k + 1} is blank")
        if y_cell:
            raise DigitisedFormatError(
                source, line.number, f"cell {2 * k + 2} is {y_cell!r}; the Y cell of a name pair must be blank"
            )
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise DigitisedFormatError(source, line.number, f"dataset name(s) repeated: {', '.join(duplicates)}")
    return names


def _curve(name: str | None, points: list[tuple[float, float, int]], source: str) -> DigitisedCurve:
    """The dataset's points; an x given twice with two different y is an error (the curve must be a
    function of x to be interpolated), naming both lines."""
    first: dict[float, tuple[float, int]] = {}
    for x, y, number in points:
        y_seen, line_seen = first.setdefault(x, (y, number))
        if y != y_seen:
            where = "" if name is None else f"dataset {name!r}: "
            raise DigitisedFormatError(source, number, f"{where}x = {x:g} repeats line {line_seen} with another y "
                                       f"({y:g}, there {y_seen:g}); a digitised curve must be a function of x")
    data = np.array(points, dtype=float).reshape(-1, 3)
    return DigitisedCurve(name=name, x=data[:, 0], y=data[:, 1], lines=data[:, 2].astype(int))


def digitised_frames(curves: list[DigitisedCurve], sidecar: Sidecar, source: str) -> dict[str, pd.DataFrame]:
    """One DataFrame per sidecar dataset, columns named after the RESULT columns (which carry units).

    Columns: the x column, the y column and ``line`` (source line number); ``attrs`` holds the
    dataset name, figure and the units of x and y from the sidecar. Every dataset of the export
    must be described by the sidecar and vice versa; a headerless export holds exactly one
    dataset and takes the sidecar's only dataset name.
    """
    names = [d.name for d in sidecar.datasets]
    if len(curves) == 1 and curves[0].name is None:
        if len(names) != 1:
            raise ParameterError(
                "datasets of the sidecar", names, f"exactly one dataset for the headerless per-dataset export {source}"
            )
        curves = [DigitisedCurve(names[0], curves[0].x, curves[0].y, curves[0].lines)]
    exported = [c.name for c in curves]
    for name in exported:
        if name not in names:
            raise UnknownNameError(f"dataset of {source} (not described by the sidecar)", name, names)
    for name in names:
        if name not in exported:
            raise UnknownNameError(f"sidecar dataset (not found in {source})", name, exported)
    frames = {}
    x_axis = sidecar.x
    for curve in curves:
        spec = sidecar.dataset(curve.name)
        y_name = spec.y.column if spec.y.column != x_axis.column else f"{spec.y.column}_y"
        frame = pd.DataFrame({x_axis.column: curve.x, y_name: curve.y, "line": curve.lines})
        frame.attrs.update(
            dataset=spec.name, figure=sidecar.figure, x_units=x_axis.units, y_units=spec.y.units, source=source
        )
        frames[spec.name] = frame
    return frames
