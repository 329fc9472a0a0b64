"""Comparison of simulated results with digitised figures (``rig compare``, docs/compare.md).

Modules: ``digitizer`` (WebPlotDigitizer exports), ``sidecar`` (the TOML description of a
figure), ``quantities`` (known quantity names), ``matching`` (which RESULT rows belong to a
dataset), ``metrics`` (interpolation, deviations, x shift; pure), ``comparison`` (ties them
together), ``gate`` (pass/fail thresholds), ``report`` (CSV/JSON), ``overlay`` (the figure).
"""

from rig.compare.comparison import CompareOptions, DatasetComparison, compare, compare_files
from rig.compare.digitizer import DigitisedFormatError, ExportLayout, parse_export, read_export
from rig.compare.gate import Thresholds, failures
from rig.compare.metrics import CurveComparison, CurveMetrics, Interpolation, compare_curve, interpolate
from rig.compare.sidecar import AxisScale, Sidecar, load_sidecar, parse_sidecar

__all__ = [
    "AxisScale",
    "CompareOptions",
    "CurveComparison",
    "CurveMetrics",
    "DatasetComparison",
    "DigitisedFormatError",
    "ExportLayout",
    "Interpolation",
    "Sidecar",
    "Thresholds",
    "compare",
    "compare_curve",
    "compare_files",
    "failures",
    "interpolate",
    "load_sidecar",
    "parse_export",
    "parse_sidecar",
    "read_export",
]
