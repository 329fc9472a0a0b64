"""The simulation's truth (true l, c, mu, forces, ...): written beside the measurements under
``/truth/point_NNNNNN`` and read only through :func:`read_truth`.

This module is deliberately not re-exported by :mod:`rig.logbook`: the readers the reduction
uses (:mod:`rig.logbook.reader`) never open ``/truth``, so a reduction cannot use the truth by
accident; tests and validation plots import ``rig.logbook.truth`` explicitly.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from rig.logbook import h5format
from rig.logbook import layout as L
from rig.logbook.content import Quantity
from rig.logbook.opening import open_log
from rig.logbook.tables import TableBuilder


def write_truth(handle, index: int, truth: Mapping[str, Quantity]) -> None:
    """Group ``/truth/point_NNNNNN`` with one scalar dataset (with ``units``) per true value."""
    container = handle.require_group(L.TRUTH_GROUP)
    group = container.create_group(L.point_group_name(index))
    group.attrs[L.ATTR_INDEX] = np.int64(index)
    h5format.write_quantities(group, truth)


def read_truth(path: object) -> pd.DataFrame:
    """What the simulation knew, one row per point (index ``point``), columns ``<name>_<unit>``.

    Raises LogFormatError if the log is damaged, foreign or has no ``/truth`` group (e.g. a log
    of a real stand).
    """
    with open_log(path) as handle:
        table = TableBuilder(str(path))
        for index, group in h5format.point_groups(handle, L.TRUTH_GROUP):
            table.row(index)
            table.add_quantities(index, "", h5format.read_quantities(group))
        return table.frame()
