"""Names of the groups, datasets and attributes of a friction-rig log (format versions 1 and 2).

The layout is documented in ``docs/log-format.md``; this module is the single place the code
spells it, so that writer, readers and the documentation test agree.
"""

from __future__ import annotations

import re

FORMAT_NAME = "friction-rig-log"
"""Value of the root attribute ``format`` that marks a file as one of ours."""
FORMAT_VERSION = 2
"""Value of the root attribute ``format_version`` written by this package (2: columnar)."""
COLUMNAR_VERSION = 2
"""First version with one row per point in per-quantity datasets (docs/log-format.md)."""
READABLE_VERSIONS = (1, 2)
"""Versions the readers accept: 1 (one group per point) and 2 (columnar)."""

# Root attributes.
ATTR_FORMAT = "format"
ATTR_FORMAT_VERSION = "format_version"
ATTR_PACKAGE_VERSION = "package_version"
ATTR_SEED = "seed"
ATTR_STAND = "stand"
ATTR_CREATED_UTC = "created_utc"
ATTR_SCENE_SHA256 = "scene_sha256"
"""SHA-256 (hex) of the UTF-8 scene text: the text lives in HDF5's global heap, which has no checksum."""
ROOT_ATTRS = (ATTR_FORMAT, ATTR_FORMAT_VERSION, ATTR_PACKAGE_VERSION, ATTR_SEED, ATTR_STAND, ATTR_CREATED_UTC,
              ATTR_SCENE_SHA256)

# Root objects.
SCENE_DATASET = "scene_toml"
POINTS_GROUP = "points"
TRUTH_GROUP = "truth"
REDUCED_GROUP = "reduced"

# Inside /points/point_NNNNNN.
ATTR_INDEX = "index"
SETTINGS_GROUP = "settings"
READINGS_GROUP = "readings"
CHANNELS_GROUP = "channels"
COUNTERS_GROUP = "counters"
CALIBRATION_GROUP = "calibration"
POINT_SUBGROUPS = (SETTINGS_GROUP, READINGS_GROUP, CHANNELS_GROUP, CALIBRATION_GROUP)

# Attributes of datasets and groups (units in the attribute name where the value is a number).
ATTR_UNITS = "units"
ATTR_SAMPLE_RATE = "sample_rate_Hz"
ATTR_START_TIME = "start_time_s"
ATTR_GATE_TIME = "gate_time_s"
ATTR_MARKS = "marks_per_rev"
COUNT_UNIT = "count"
"""``units`` of every counter total."""
MARKS_UNIT = "1/rev"
"""Unit of the marks per revolution of a stroboscope disc (column ``<name>_marks_per_rev``)."""

# Columnar layout (version 2): /points/<kind>/... datasets of one row per point.
INDEX_DATASET = "index"
"""``/points/index`` (int64, one row per point): the point index of each row, ascending."""
GATE_TIME_DATASET = "gate_time"
COUNTS_GROUP = "counts"
MARKS_GROUP = "marks"
SAMPLES_DATASET = "samples"
"""``/points/channels/<name>/samples``: every point's samples, one after the other (ragged)."""
FIRST_SAMPLE_DATASET = "first"
SAMPLE_COUNT_DATASET = "length"
ABSENT_INTEGER = -1
"""Value of an int64 row (count, marks) for a point that has no such counter."""

# Inside /reduced.
ATTR_COLUMNS = "columns"
ATTR_INDEX_NAME = "index_name"
REDUCED_INDEX_DATASET = "_index"

NAME_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
"""Every channel, setting, reading, counter, calibration and truth name (an identifier)."""

POINT_DIGITS = 6


def point_group_name(index: int) -> str:
    """Name of the group of operating point ``index`` (e.g. ``point_000003``)."""
    return f"point_{index:0{POINT_DIGITS}d}"
