"""Compare a RESULT table with a digitised figure: one :class:`DatasetComparison` per dataset and model."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from rig.compare.digitizer import digitised_frames, read_export
from rig.compare.matching import SimulatedCurve, check_sidecar, read_result, select_curves
from rig.compare.metrics import CurveComparison, Interpolation, compare_curve
from rig.compare.sidecar import DatasetSpec, Sidecar, load_sidecar


@dataclass(frozen=True)
class CompareOptions:
    """How to compare: interpolation of the simulation, x-shift tolerance (None: no shift), one model only."""

    interpolation: Interpolation = Interpolation.LINEAR
    x_shift_tolerance: float | None = None
    model: str | None = None


@dataclass(frozen=True)
class DatasetComparison:
    """One dataset against one model: the sidecar entry, the digitised frame, the simulated curve, the result."""

    spec: DatasetSpec
    digitised: pd.DataFrame
    simulated: SimulatedCurve
    comparison: CurveComparison

    @property
    def model(self) -> str | None:
        """The model compared (None when RESULT has no model column)."""
        return self.simulated.model


def compare(
    result: pd.DataFrame, digitised: dict[str, pd.DataFrame], sidecar: Sidecar, options: CompareOptions
) -> list[DatasetComparison]:
    """Compare every sidecar dataset (in sidecar order) with each model of RESULT that matches it.

    Parameters
    ----------
    result : pandas.DataFrame
        The simulated RESULT table, one column per quantity, units in the column names.
    digitised : dict of str to pandas.DataFrame
        Digitised points per dataset name: x and y in the units of the sidecar's axes.
    sidecar : Sidecar
        The figure's description (axes, datasets, conditions).
    options : CompareOptions
        Interpolation, x-shift tolerance, model selection.

    Returns
    -------
    list of DatasetComparison
        One per dataset and matching model, in sidecar order.
    """
    check_sidecar(sidecar)
    items = []
    for spec in sidecar.datasets:
        frame = digitised[spec.name]
        x_ref = frame.iloc[:, 0].to_numpy(dtype=float)
        y_ref = frame.iloc[:, 1].to_numpy(dtype=float)
        for curve in select_curves(result, sidecar.x, spec, model=options.model):
            comparison = compare_curve(
                curve.x,
                curve.y,
                x_ref,
                y_ref,
                x_scale=sidecar.x.scale,
                y_scale=spec.y.scale,
                method=options.interpolation,
                shift_tolerance=options.x_shift_tolerance,
            )
            items.append(DatasetComparison(spec=spec, digitised=frame, simulated=curve, comparison=comparison))
    return items


def default_sidecar_path(digitised_path: str | Path) -> Path:
    """The sidecar next to a digitised export: same name, suffix .toml."""
    return Path(digitised_path).with_suffix(".toml")


def compare_files(
    result_path: str | Path,
    digitised_path: str | Path,
    sidecar_path: str | Path | None = None,
    options: CompareOptions | None = None,
) -> tuple[Sidecar, list[DatasetComparison]]:
    """Read RESULT, the digitised export and its sidecar and compare them.

    Parameters
    ----------
    result_path : str or pathlib.Path
        The simulated RESULT CSV (one column per quantity, units in the column names).
    digitised_path : str or pathlib.Path
        A WebPlotDigitizer CSV export.
    sidecar_path : str or pathlib.Path, optional
        The figure's TOML sidecar (default: the export's name with suffix .toml).
    options : CompareOptions, optional
        How to compare (default: linear interpolation, no x shift, every model).

    Returns
    -------
    tuple of (Sidecar, list of DatasetComparison)
        The sidecar read and one comparison per dataset and matching model.
    """
    sidecar = load_sidecar(sidecar_path if sidecar_path is not None else default_sidecar_path(digitised_path))
    _, curves = read_export(digitised_path)
    frames = digitised_frames(curves, sidecar, str(digitised_path))
    result = read_result(result_path)
    return sidecar, compare(result, frames, sidecar, options or CompareOptions())
