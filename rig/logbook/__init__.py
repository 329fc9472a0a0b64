"""Self-describing HDF5 measurement logs, one file per run (layout: ``docs/log-format.md``).

Write with :class:`LogWriter` (one checksummed journal frame per finished point, resumable,
laid out as the columnar log - one row per point per quantity - atomically by
:meth:`LogWriter.finalize`); read with the ``read_*`` functions, each group of all points as a
pandas DataFrame in one call, column names carrying units (``F_y_N``, ``T2_N_m``,
``omega_rad_s``), or every point as a PointRecord with :func:`read_points`. Logs of format
version 1 (one HDF5 group per point) are read by the same functions.
The simulation's truth is read only through :mod:`rig.logbook.truth` (not exported here).
The logbook is generic: it stores what it is given and knows no stand or sensor.
"""

from __future__ import annotations

from rig.logbook.content import (
    Channel,
    Counter,
    CounterReadings,
    PointRecord,
    Quantity,
    RunMetadata,
    utc_timestamp,
)
from rig.logbook.layout import FORMAT_NAME, FORMAT_VERSION
from rig.logbook.reader import (
    channel_names,
    point_indices,
    read_calibration,
    read_channel,
    read_channels,
    read_counters,
    read_metadata,
    read_point,
    read_points,
    read_readings,
    read_settings,
)
from rig.logbook.reduced import read_reduced, write_reduced
from rig.logbook.schema import LogSchema, check_log
from rig.logbook.units import column_name, safe_unit
from rig.logbook.writer import LogWriter, staging_dir

__all__ = [
    "FORMAT_NAME",
    "FORMAT_VERSION",
    "Channel",
    "Counter",
    "CounterReadings",
    "LogSchema",
    "LogWriter",
    "PointRecord",
    "Quantity",
    "RunMetadata",
    "channel_names",
    "check_log",
    "column_name",
    "point_indices",
    "read_calibration",
    "read_channel",
    "read_channels",
    "read_counters",
    "read_metadata",
    "read_point",
    "read_points",
    "read_readings",
    "read_reduced",
    "read_settings",
    "safe_unit",
    "staging_dir",
    "utc_timestamp",
    "write_reduced",
]
