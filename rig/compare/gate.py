"""Pass/fail thresholds on the comparison metrics (for gating a CI job).

``max_abs`` maps a dataset name or its RESULT y column to the largest allowed max |deviation|
[units of that y axis]; ``max_rmse`` bounds the RMSE of every dataset [units of each y axis].
A comparison fails when a metric exceeds its threshold or is NaN.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from rig import validate
from rig.compare.comparison import DatasetComparison
from rig.errors import ParameterError, UnknownNameError


@dataclass(frozen=True)
class Thresholds:
    """max_abs: dataset name or y column -> limit of max |dev| [y units]; max_rmse: limit of every RMSE."""

    max_abs: Mapping[str, float] = field(default_factory=dict)
    max_rmse: float | None = None

    def __post_init__(self) -> None:
        for name, value in self.max_abs.items():
            validate.number(f"--max-abs {name}", value, 0.0)
        if self.max_rmse is not None:
            validate.number("--max-rmse", self.max_rmse, 0.0)


def parse_max_abs(items: Sequence[str]) -> dict[str, float]:
    """Parse ``QUANTITY=VALUE`` strings (as given to --max-abs) into a mapping; ParameterError if malformed."""
    result: dict[str, float] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise ParameterError("--max-abs", item, "QUANTITY=VALUE, e.g. nu_v=0.02")
        try:
            limit = float(value)
        except ValueError:
            raise ParameterError(f"--max-abs {name.strip()}", value.strip(), "a number >= 0") from None
        result[name.strip()] = validate.number(f"--max-abs {name.strip()}", limit, 0.0)
    return result


def failures(items: Sequence[DatasetComparison], thresholds: Thresholds) -> list[str]:
    """One line per failing dataset/model saying which metric exceeded which limit.

    Parameters
    ----------
    items : sequence of DatasetComparison
        The comparisons (rig.compare.compare).
    thresholds : Thresholds
        Limits of max |dev| per dataset or y column and of every RMSE [y units].

    Returns
    -------
    list of str
        The failures (empty: all pass).
    """
    names = {name for item in items for name in (item.spec.name, item.spec.y.column)}
    for name in thresholds.max_abs:
        if name not in names:
            raise UnknownNameError("--max-abs quantity (a dataset or its y column)", name, names)
    lines = []
    for item in items:
        metrics = item.comparison.metrics
        label = item.spec.name + (f" (model {item.model})" if item.model is not None else "")
        reasons = []
        limit = thresholds.max_abs.get(item.spec.name, thresholds.max_abs.get(item.spec.y.column))
        if limit is not None and not metrics.max_abs_dev <= limit:
            reasons.append(f"max |dev| {_g(metrics.max_abs_dev)} > {_g(limit)}")
        if thresholds.max_rmse is not None and not metrics.rmse <= thresholds.max_rmse:
            reasons.append(f"RMSE {_g(metrics.rmse)} > {_g(thresholds.max_rmse)}")
        if reasons:
            lines.append(f"{label}: " + "; ".join(reasons) + f" [{item.spec.y.units}]")
    return lines


def _g(value: float) -> str:
    return "nan" if math.isnan(value) else f"{value:.4g}"
