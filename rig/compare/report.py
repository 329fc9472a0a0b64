"""The metrics table of a comparison and its CSV/JSON files.

One row per dataset and model. Deviations (rmse, max_abs_dev) are in the units of the dataset's
y axis, given in ``y_units`` (they differ between datasets, so they cannot be in the column
names); x_at_max_abs_dev and x_shift are in ``x_units`` (x_shift: relative [1] on a log axis).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import pandas as pd

from rig.compare.comparison import DatasetComparison
from rig.compare.matching import conditions_text
from rig.compare.sidecar import AxisScale, Sidecar

METRICS_CSV = "compare_metrics.csv"
METRICS_JSON = "compare_metrics.json"

COLUMNS = (
    "dataset", "model", "y_column", "y_units", "x_column", "x_units", "conditions", "n_compared", "n_skipped",
    "rmse", "max_abs_dev", "max_rel_dev", "x_at_max_abs_dev", "x_shift", "x_shift_units",
)  # fmt: skip


def metrics_table(sidecar: Sidecar, items: Sequence[DatasetComparison]) -> pd.DataFrame:
    """The metrics of every dataset/model as a DataFrame with the columns ``COLUMNS``."""
    rows = []
    for item in items:
        m = item.comparison.metrics
        rows.append(
            dict(
                dataset=item.spec.name,
                model=item.model,
                y_column=item.spec.y.column + (" (magnitude)" if item.spec.y.magnitude else ""),
                y_units=item.spec.y.units,
                x_column=sidecar.x.column,
                x_units=sidecar.x.units,
                conditions=conditions_text(item.spec),
                n_compared=m.n_compared,
                n_skipped=m.n_skipped,
                rmse=m.rmse,
                max_abs_dev=m.max_abs_dev,
                max_rel_dev=m.max_rel_dev,
                x_at_max_abs_dev=m.x_at_max_abs_dev,
                x_shift=m.x_shift,
                x_shift_units="1 (relative)" if sidecar.x.scale is AxisScale.LOG else sidecar.x.units,
            )
        )
    return pd.DataFrame(rows, columns=list(COLUMNS))


def write_metrics(
    directory: str | Path, sidecar: Sidecar, items: Sequence[DatasetComparison], meta: Mapping[str, object]
) -> tuple[Path, Path]:
    """Write compare_metrics.csv and compare_metrics.json into ``directory``; return both paths.

    meta: extra JSON entries (inputs, options, thresholds, failures); NaN is written as null.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    table = metrics_table(sidecar, items)
    csv_path = directory / METRICS_CSV
    table.to_csv(csv_path, index=False)
    records = [{k: _json_value(v) for k, v in row.items()} for row in table.to_dict(orient="records")]
    document = {
        "figure": sidecar.figure,
        "source": sidecar.source,
        "x": {"column": sidecar.x.column, "units": sidecar.x.units, "scale": sidecar.x.scale.value},
        **{k: _json_value(v) for k, v in meta.items()},
        "datasets": records,
    }
    json_path = directory / METRICS_JSON
    json_path.write_text(json.dumps(document, indent=2, allow_nan=False) + "\n", encoding="utf-8")
    return csv_path, json_path


def _json_value(value: object) -> object:
    if isinstance(value, Mapping):
        return {str(k): _json_value(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_json_value(v) for v in value]
    if isinstance(value, float) and math.isnan(value):
        return None
    if hasattr(value, "item"):  # numpy scalar
        return _json_value(value.item())
    if value is pd.NA:
        return None
    return value
