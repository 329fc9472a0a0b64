"""Every content kind survives write -> read; tables carry units in column names."""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import h5py
import logbook_samples as samples
import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rig
import rig.logbook as lb
from rig.errors import ParameterError
from rig.logbook import Channel, LogWriter, PointRecord, Quantity, RunMetadata
from rig.logbook.truth import read_truth


@pytest.fixture(scope="module")
def log(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("roundtrip") / "run.h5"
    samples.write_run(path)
    return path


def test_metadata_round_trip(log: Path) -> None:
    meta = lb.read_metadata(log)
    assert meta == samples.metadata()
    assert meta.package_version == rig.__version__
    with h5py.File(log, "r") as f:
        assert f.attrs["format"] == "friction-rig-log" and f.attrs["format_version"] == 2
        assert f.attrs["seed"] == 7 and f.attrs["stand"] == "stand_A"


def test_point_records_round_trip_exactly(log: Path) -> None:
    assert lb.point_indices(log) == list(range(samples.N_POINTS))
    for k in range(samples.N_POINTS):
        assert lb.read_point(log, k) == samples.point(k)


def test_settings_table(log: Path) -> None:
    table = lb.read_settings(log)
    assert list(table.columns) == ["F_N_N", "delta_h_m", "omega_rad_s"]
    assert table.index.name == "point" and list(table.index) == list(range(samples.N_POINTS))
    assert table.attrs["units"] == {"F_N_N": "N", "delta_h_m": "m", "omega_rad_s": "rad/s"}
    assert (table["F_N_N"] == 96.2).all() and (table["delta_h_m"] == 1.06e-3).all()


def test_readings_and_calibration_tables(log: Path) -> None:
    readings = lb.read_readings(log)
    assert readings.attrs["units"] == {"F_y_N": "N", "T2_N_m": "N m"}
    np.testing.assert_allclose(readings["T2_N_m"], 0.35 + 0.01 * np.arange(samples.N_POINTS))
    calibration = lb.read_calibration(log)
    assert list(calibration.columns) == ["dynamometer_gain_N_V", "dynamometer_lever_ratio"]
    assert calibration.loc[2, "dynamometer_lever_ratio"] == 102 / 42.5


def test_counters_table_gives_back_the_speeds(log: Path) -> None:
    table = lb.read_counters(log)
    assert list(table.columns) == ["N1_count", "N1_marks_per_rev", "N2_count", "N2_marks_per_rev", "gate_time_s"]
    assert table["N1_count"].dtype == np.int64
    assert table.attrs["units"]["N1_marks_per_rev"] == "1/rev"
    # omega = 2 pi N / (z T) (Equations §2): 240 rpm = 25.13 rad/s to within 1 count.
    omega_1 = 2 * math.pi * table["N1_count"] / (table["N1_marks_per_rev"] * table["gate_time_s"])
    np.testing.assert_allclose(omega_1, 25.13, atol=2 * math.pi / (60 * 17.0))
    i_k = table["N2_count"] * table["N1_marks_per_rev"] / (table["N1_count"] * table["N2_marks_per_rev"])
    np.testing.assert_allclose(i_k[0], 0.8115, rtol=1 / 3311 + 1 / 4080)


def test_channel_tables(log: Path) -> None:
    table = lb.read_channel(log, 3, "F_dyn")
    expected = samples.point(3).channels["F_dyn"]
    assert list(table.columns) == ["time_s", "F_dyn_N"]
    assert table.attrs["units"] == {"time_s": "s", "F_dyn_N": "N"}
    assert table.attrs["sample_rate_Hz"] == 1000.0 and table.attrs["start_time_s"] == 2.5
    np.testing.assert_array_equal(table["F_dyn_N"], expected.samples)
    assert table["time_s"].iloc[0] == 2.5 and table["time_s"].iloc[-1] == pytest.approx(2.5 + 199 / 1000.0)
    both = lb.read_channels(log, 0)
    assert sorted(both) == ["F_dyn", "U_bridge"] and list(both["U_bridge"].columns) == ["time_s", "U_bridge_V"]


def test_truth_table(log: Path) -> None:
    truth = read_truth(log)
    assert truth.attrs["units"] == {"F_x_N": "N", "c_m": "m", "l_m": "m", "mu": "1"}
    np.testing.assert_allclose(truth["F_x_N"], 30.0 + np.arange(samples.N_POINTS))


def test_reduced_round_trip(log: Path, tmp_path: Path) -> None:
    path = tmp_path / "copy.h5"
    path.write_bytes(log.read_bytes())
    reduced = pd.DataFrame(
        {"mu_T": [0.41, np.nan, 0.39], "l_over_a": [0.0, 0.5, 1.0], "F_y_N": [4.1, 4.0, 3.9]},
        index=pd.Index([0, 1, 2], name="point"),
    )
    reduced.attrs["units"] = {"mu_T": "1", "l_over_a": "1", "F_y_N": "N"}
    lb.write_reduced(path, reduced)
    back = lb.read_reduced(path)
    pd.testing.assert_frame_equal(back, reduced)
    assert back.attrs["units"] == reduced.attrs["units"]
    lb.write_reduced(path, reduced.iloc[:1], units=reduced.attrs["units"])  # replaces the earlier table
    assert len(lb.read_reduced(path)) == 1
    assert samples.dump(path).keys() - samples.dump(log).keys() == {
        "reduced", "reduced/_index", "reduced/mu_T", "reduced/l_over_a", "reduced/F_y_N"}


@pytest.mark.parametrize(
    ("table", "units", "message"),
    [
        (pd.DataFrame({"F_y": [0.4]}), {"F_y": "N"}, "column = 'F_y' .* ending in '_N'"),
        (pd.DataFrame({"T2_N": [0.4]}), {"T2_N": "N m"}, "ending in '_N_m'"),
        (pd.DataFrame({"mu": [0.4]}), {}, "a unit for every column"),
        (pd.DataFrame({"mu": [0.4]}), None, "units = None"),
        (pd.DataFrame({"F_y_N": ["a"]}), {"F_y_N": "N"}, "dtype"),
        (pd.DataFrame({"mu": [0.4]}, index=["a"]), {"mu": "1"}, "integer index"),
    ],
)
def test_write_reduced_refuses_tables_without_units(log: Path, table, units, message: str) -> None:
    with pytest.raises(ParameterError, match=message):
        lb.write_reduced(log, table, units)


def test_no_counters_means_no_counter_group_and_no_call(tmp_path: Path) -> None:
    path = tmp_path / "plain.h5"
    writer = LogWriter(path, samples.metadata())
    writer.write_point(PointRecord(0, {"F_N": Quantity(9.0, "N")}), {})
    writer.finalize()
    with h5py.File(path, "r") as f:
        assert "counters" not in f["points"]
    assert lb.read_point(path, 0).counters is None
    assert lb.read_counters(path).shape == (1, 0)


def test_points_may_differ_in_content(tmp_path: Path) -> None:
    path = tmp_path / "mixed.h5"
    writer = LogWriter(path, samples.metadata())
    writer.write_point(samples.point(1), samples.truth(1))
    writer.write_point(PointRecord(4, {"F_N": Quantity(385.0, "N")}), {})
    writer.finalize()
    settings_ = lb.read_settings(path)
    assert settings_.loc[4, "F_N_N"] == 385.0 and math.isnan(settings_.loc[4, "omega_rad_s"])
    assert math.isnan(lb.read_counters(path).loc[4, "N1_count"])


_names = st.from_regex(r"[A-Za-z][A-Za-z0-9_]{0,8}", fullmatch=True)
_units = st.sampled_from(["1", "N", "N m", "rad/s", "m/s^2", "V", "Pa", "1/s"])
_values = st.floats(allow_nan=False, allow_infinity=False, width=64)


@settings(max_examples=20, deadline=None)
@given(
    st.dictionaries(_names, st.builds(Quantity, _values, _units), max_size=4),
    st.lists(_values, min_size=1, max_size=50),
    st.floats(min_value=1e-3, max_value=1e6),
    _values,
)
def test_any_point_round_trips(values: dict, samples_: list, rate: float, start: float) -> None:
    point = PointRecord(
        0, values, channels={"x": Channel(samples_, "V", rate, start)}, readings=values, calibration={"c": values}
    )
    meta = RunMetadata(scene_toml="ü = 'ünïcode'\n", seed=2**63 - 1, stand="s", created_utc="2000-01-01T00:00:00Z")
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "h.h5"
        writer = LogWriter(path, meta)
        writer.write_point(point, values)
        writer.finalize()
        assert lb.read_point(path, 0) == point
        assert lb.read_metadata(path) == meta
        assert lb.check_log(path) == [0]
