"""Pick, from a RESULT table, the simulated curve that belongs to each digitised dataset.

Rules (docs/compare.md): a RESULT row belongs to a dataset when every condition of the dataset
(global [conditions] merged with its own) holds in that row - numbers equal within
``CONDITION_RTOL``/``CONDITION_ATOL``, strings exactly. When the selected rows hold several
models (column ``model``, not pinned by a condition) each model is compared separately; the
``model`` argument keeps only one. The selected rows of one model must have distinct x values
(otherwise a column that varies among them has to be pinned), finite x and y; the curve is
sorted by x and, for a magnitude axis, y is replaced by |y|.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.compare.sidecar import Axis, ConditionValue, DatasetSpec, Sidecar
from rig.errors import LogFormatError, ParameterError, UnknownNameError

CONDITION_RTOL = 1e-6  # relative tolerance of a numeric condition [1]
CONDITION_ATOL = 1e-9  # absolute tolerance of a numeric condition [units of the column]
MODEL_COLUMN = "model"


@dataclass(frozen=True)
class SimulatedCurve:
    """The simulated curve of one dataset and one model (None: RESULT has no model column).

    x, y: sorted by x, in the units of the RESULT columns named by the sidecar axes.
    """

    dataset: str
    model: str | None
    x: np.ndarray
    y: np.ndarray


def read_result(path: str | Path) -> pd.DataFrame:
    """Read a RESULT CSV (one column per quantity, units in the column names)."""
    path = Path(path)
    if not path.is_file():
        raise ParameterError("RESULT", str(path), "an existing CSV file")
    try:
        frame = pd.read_csv(path, skipinitialspace=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as error:
        raise LogFormatError(f"{path}: not a readable CSV table: {error}") from None
    frame.columns = [str(c).strip() for c in frame.columns]
    return frame


def unit_suffix(units: str) -> str:
    """The column-name suffix of a unit ("N m" -> "N_m", "rad/s" -> "rad_s"); "" for "1"."""
    if units.strip() == "1":
        return ""
    text = units.strip().replace("^", "")
    for char in " */·.":
        text = text.replace(char, "_")
    return "_".join(part for part in text.split("_") if part)


def check_units(axis: Axis, where: str) -> None:
    """A dimensional axis must name a column that ends in its unit suffix (e.g. units "N" -> "F_y_N")."""
    suffix = unit_suffix(axis.units)
    if suffix and not axis.column.endswith("_" + suffix):
        raise ParameterError(
            f"{where}.units",
            axis.units,
            f"the units of RESULT column {axis.column!r} (a column in {axis.units} ends in '_{suffix}')",
        )


def select_curves(
    result: pd.DataFrame, x_axis: Axis, spec: DatasetSpec, *, model: str | None = None
) -> list[SimulatedCurve]:
    """The simulated curves (one per model) of dataset ``spec`` from RESULT; see the module rules."""
    columns = list(result.columns)
    for axis, where in ((x_axis, "x"), (spec.y, f"datasets.{spec.name}")):
        if axis.column not in columns:
            raise UnknownNameError(f"column of RESULT for [{where}]", axis.column, columns)
        check_units(axis, where)
    rows = _rows_matching(result, spec)
    groups: list[tuple[str | None, pd.DataFrame]]
    if MODEL_COLUMN in columns:
        if model is not None:
            present = sorted(map(str, result[MODEL_COLUMN].unique()))
            if model not in present:
                raise UnknownNameError("model (--model)", model, present)
            rows = rows[rows[MODEL_COLUMN].astype(str) == model]
            if rows.empty:
                raise ParameterError("--model", model, f"a model with rows matching dataset {spec.name!r}")
        groups = [(str(name), group) for name, group in rows.groupby(MODEL_COLUMN, sort=True)]
    else:
        if model is not None:
            raise ParameterError("--model", model, f"no model selection: RESULT has no {MODEL_COLUMN!r} column")
        groups = [(None, rows)]
    return [_curve(spec, x_axis, name, group) for name, group in groups]


def _rows_matching(result: pd.DataFrame, spec: DatasetSpec) -> pd.DataFrame:
    rows = result
    for column, value in spec.conditions.items():
        where = f"condition {column} of dataset {spec.name!r}"
        if column not in result.columns:
            raise UnknownNameError(f"{where}: column of RESULT", column, list(result.columns))
        mask = _condition_mask(rows[column], value, where)
        if not mask.any():
            found = sorted(map(str, pd.unique(rows[column])))[:12]
            raise ParameterError(
                where, value, "a value present in RESULT rows matching the other conditions: " + ", ".join(found)
            )
        rows = rows[mask]
    return rows


def _condition_mask(values: pd.Series, value: ConditionValue, where: str) -> np.ndarray:
    numeric = pd.api.types.is_numeric_dtype(values) and not pd.api.types.is_bool_dtype(values)
    if isinstance(value, str):
        if numeric:
            raise ParameterError(where, value, "a number (the RESULT column holds numbers)")
        return (values.astype(str).str.strip() == value).to_numpy()
    if not numeric:
        raise ParameterError(where, value, "a string (the RESULT column holds text)")
    return np.isclose(values.to_numpy(dtype=float), value, rtol=CONDITION_RTOL, atol=CONDITION_ATOL)


def _curve(spec: DatasetSpec, x_axis: Axis, model: str | None, rows: pd.DataFrame) -> SimulatedCurve:
    label = f"dataset {spec.name!r}" + (f", model {model!r}" if model is not None else "")
    x = pd.to_numeric(rows[x_axis.column], errors="coerce").to_numpy(dtype=float)
    y = pd.to_numeric(rows[spec.y.column], errors="coerce").to_numpy(dtype=float)
    bad = ~(np.isfinite(x) & np.isfinite(y))
    if bad.any():
        raise ParameterError(
            f"RESULT rows of {label}",
            f"{int(bad.sum())} non-finite {x_axis.column}/{spec.y.column} value(s) (first at row {rows.index[bad][0]})",
            "finite numbers (filter the failed points out of RESULT)",
        )
    if x.size < 2:
        raise ParameterError(f"RESULT rows of {label}", x.size, "at least 2 rows to interpolate between")
    order = np.argsort(x, kind="stable")
    x, y = x[order], y[order]
    repeated = np.flatnonzero(np.diff(x) == 0.0)
    if repeated.size:
        x_rep = x[repeated[0]]
        same = rows.iloc[order][x == x_rep]
        varying = [c for c in rows.columns if c not in (x_axis.column, spec.y.column) and same[c].nunique() > 1]
        raise ParameterError(
            f"RESULT rows of {label}",
            f"{x_axis.column} = {x_rep:g} repeated",
            "one row per x: pin the column(s) that vary ("
            + (", ".join(varying) or "none besides the compared ones")
            + ") in [conditions]",
        )
    return SimulatedCurve(dataset=spec.name, model=model, x=x, y=np.abs(y) if spec.y.magnitude else y)


def conditions_text(spec: DatasetSpec) -> str:
    """The conditions of a dataset as 'a=1, shape=ellipse' (for reports)."""
    return ", ".join(f"{k}={v:g}" if isinstance(v, float) else f"{k}={v}" for k, v in spec.conditions.items())


def check_sidecar(sidecar: Sidecar) -> None:
    """Conditions may not name the compared columns (an x or y column cannot also be held fixed)."""
    for spec in sidecar.datasets:
        for column in (sidecar.x.column, spec.y.column):
            if column in spec.conditions:
                raise ParameterError(
                    f"condition {column} of dataset {spec.name!r}",
                    spec.conditions[column],
                    "no condition on a compared (x or y) column",
                )
