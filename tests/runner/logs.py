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
