"""The simulation's truth (true l, c, mu, forces, ...): written beside the measurements under
``/truth`` (one dataset per value, one row per point; version 1: ``/truth/point_NNNNNN``) and
read only through :func:`read_truth`.

This module is deliberately not re-exported by :mod:`rig.logbook`: the readers the reduction
uses (:mod:`rig.logbook.reader`) never open ``/truth``, so a reduction cannot use the truth by
accident; tests and validation plots import ``rig.logbook.truth`` explicitly.
"""

from __future__ import annotations

import pandas as pd

from rig.errors import LogFormatError, RigError

from rig.logbook import h5format
from rig.logbook import layout as L
from rig.logbook.columnar import ColumnarLog
from rig.logbook.opening import is_columnar, open_log
from rig.logbook.tables import TableBuilder


class DamagedTruthError(RigError, ValueError):
    """The log has a ``/truth`` group that cannot be read (damaged bytes, units, values): names the
    file, the dataset and what is wrong. Not a LogFormatError, which the callers take to mean a
    log without truth (a real stand's): a damaged truth must not silently drop the truth columns."""


def read_truth(path: object) -> pd.DataFrame:
    """What the simulation knew, one row per point (index ``point``), columns ``<name>_<unit>``.

    Raises LogFormatError if the log is damaged, foreign or has no ``/truth`` group (e.g. a log
    of a real stand), and DamagedTruthError if it has a ``/truth`` group that cannot be read.
    """
    with open_log(path) as handle:
        has_truth = L.TRUTH_GROUP in handle
    try:
        with open_log(path) as handle:
            if is_columnar(handle):
                return ColumnarLog(handle).frame("truth")
            table = TableBuilder(str(path))
            for index, group in h5format.point_groups(handle, L.TRUTH_GROUP):
                table.row(index)
                table.add_quantities(index, "", h5format.read_quantities(group))
            return table.frame()
    except LogFormatError as error:
        if not has_truth:
            raise
        raise DamagedTruthError(f"the truth group cannot be read: {error}") from None
