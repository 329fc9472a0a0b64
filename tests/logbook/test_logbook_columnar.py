"""The columnar layout (format version 2): one slice per quantity, the same tables and records as
the version-1 layout of the same run, and its faults named."""

from __future__ import annotations

from pathlib import Path

import h5py
import logbook_samples as samples
import numpy as np
import pandas as pd
import pytest

import rig.logbook as lb
from rig.errors import LogFormatError
from rig.logbook.truth import read_truth

TABLES = [lb.read_settings, lb.read_readings, lb.read_counters, lb.read_calibration, read_truth]


@pytest.fixture(scope="module")
def logs(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    folder = tmp_path_factory.mktemp("layouts")
    samples.write_run(folder / "v2.h5")
    samples.write_v1_run(folder / "v1.h5")
    return folder / "v1.h5", folder / "v2.h5"


@pytest.fixture
def log(logs, tmp_path: Path) -> Path:
    path = tmp_path / "damaged.h5"
    path.write_bytes(logs[1].read_bytes())
    return path


@pytest.mark.parametrize("reader", TABLES, ids=lambda r: r.__name__)
def test_both_layouts_give_the_same_tables(logs, reader) -> None:
    old, new = (reader(path) for path in logs)
    pd.testing.assert_frame_equal(old, new, check_exact=True)
    assert old.attrs["units"] == new.attrs["units"] and new.attrs["units"]


def test_both_layouts_give_the_same_points(logs) -> None:
    old, new = (list(lb.read_points(path)) for path in logs)
    assert [i for i, _ in new] == list(range(samples.N_POINTS))
    assert old == new == [(k, samples.point(k)) for k in range(samples.N_POINTS)]
    assert lb.read_channel(logs[0], 4, "U_bridge").equals(lb.read_channel(logs[1], 4, "U_bridge"))


def test_a_quantity_of_all_points_is_one_extendable_dataset(logs) -> None:
    with h5py.File(logs[1], "r") as f:
        assert f.attrs["format_version"] == 2
        t2 = f["points/readings/T2"]
        assert t2.shape == (samples.N_POINTS,) and t2.maxshape == (None,) and t2.attrs["units"] == "N m"
        np.testing.assert_allclose(t2[:], 0.35 + 0.01 * np.arange(samples.N_POINTS))
        assert f["points/counters/counts/N1"].dtype == np.int64 and f["points/counters/marks/N1"].attrs["units"] == "1/rev"
        channel = f["points/channels/F_dyn"]
        assert channel["length"][:].tolist() == [200] * samples.N_POINTS and channel["samples"].attrs["units"] == "N"
        assert f["truth/index"][:].tolist() == f["points/index"][:].tolist()


def _edit(path: Path, change) -> None:
    with h5py.File(path, "r+") as f:
        change(f)


def test_a_nan_sample_damages_its_point_only(log: Path) -> None:
    _edit(log, lambda f: f["points/channels/F_dyn/samples"].__setitem__(3 * 200 + 5, np.nan))
    found = dict(lb.read_points(log))
    assert all(found[k] == samples.point(k) for k in (0, 1, 2, 4, 5))
    assert isinstance(found[3], LogFormatError)
    assert "/points/channels/F_dyn/samples: point 3: sample 5 (of 200) = nan is not finite" in str(found[3])
    with pytest.raises(LogFormatError, match="point 3: sample 5"):
        lb.check_log(log)


def test_faults_of_the_columns_are_named(log: Path) -> None:
    _edit(log, lambda f: f["points/settings/F_N"].__setitem__(1, np.inf))
    with pytest.raises(LogFormatError, match=r"/points/settings/F_N: point 1: value inf is not finite"):
        lb.read_settings(log)
    _edit(log, lambda f: f["points/readings/T2"].attrs.__setitem__("units", "bogus!"))
    with pytest.raises(LogFormatError, match=r"/points/readings/T2: attribute 'units' = 'bogus!' is not valid"):
        lb.read_readings(log)
    _edit(log, lambda f: f["points/counters"].__delitem__("gate_time"))
    with pytest.raises(LogFormatError, match=r"/points/counters: dataset 'gate_time' is missing"):
        lb.read_counters(log)
    _edit(log, lambda f: f["points/calibration/dynamometer"].__delitem__("gain"))
    _edit(log, lambda f: f["points/calibration/dynamometer"].create_dataset("gain", data=np.zeros(2)))
    with pytest.raises(LogFormatError, match=r"dynamometer/gain: expected a 1-D numeric dataset of 6 rows"):
        lb.read_calibration(log)
    _edit(log, lambda f: f["points/channels/U_bridge/length"].__setitem__(5, 10**6))
    with pytest.raises(LogFormatError, match=r"/points/channels/U_bridge: point 5: first = 500, length = 1000000 lie "
                                             r"outside the 600 samples"):
        lb.read_channel(log, 5, "U_bridge")
    _edit(log, lambda f: f["points"].__delitem__("index"))
    with pytest.raises(LogFormatError, match=r"/points: dataset 'index' is missing"):
        lb.point_indices(log)
