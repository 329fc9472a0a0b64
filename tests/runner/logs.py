"""Compare two measurement logs by content (not bytes: HDF5 files differ in layout details)."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from rig.logbook import point_indices, read_metadata, read_point
from rig.logbook.truth import read_truth


def assert_same_log(a: Path, b: Path) -> None:
    """Same scene, seed, stand and version; same points with equal records and equal truth."""
    meta_a, meta_b = read_metadata(a), read_metadata(b)
    for field in ("scene_toml", "seed", "stand", "package_version"):
        assert getattr(meta_a, field) == getattr(meta_b, field), field
    indices = point_indices(a)
    assert indices == point_indices(b)
    for index in indices:
        assert read_point(a, index) == read_point(b, index), index
    pd.testing.assert_frame_equal(read_truth(a), read_truth(b), check_exact=True)


def log_objects(log: Path) -> dict:
    """Every object of an HDF5 log but the run's start time: {path: (attributes, data)}, so that two
    logs compare dataset by dataset (values, dtypes, units), the reduced table included."""
    import h5py
    import numpy as np

    out = {}
    with h5py.File(log, "r") as handle:
        def visit(name, obj):
            attrs = {k: np.asarray(v).tolist() for k, v in sorted(obj.attrs.items()) if k != "created_utc"}
            data = None
            if isinstance(obj, h5py.Dataset):
                value = obj[()]
                if isinstance(value, np.ndarray):  # numbers bit for bit (NaN too), text as text
                    data = (str(value.dtype), value.shape, value.tolist() if value.dtype.kind == "O" else value.tobytes())
                else:
                    data = value
            out[name] = (attrs, data)
        visit("/", handle)
        handle.visititems(visit)
    return out
