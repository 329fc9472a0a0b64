"""Damaged, foreign and truncated files raise LogFormatError naming the file, point and fault.

These hold for logs of format version 1 (one group per point, as earlier versions wrote them:
``rig reduce`` still reads them); the columnar layout's faults: test_logbook_columnar.py."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import h5py
import logbook_samples as samples
import numpy as np
import pytest

import rig.logbook as lb
from rig.errors import LogFormatError
from rig.logbook import LogSchema, LogWriter, PointRecord, Quantity, check_log
from rig.logbook.truth import DamagedTruthError, read_truth

SCHEMA = LogSchema(
    channels={"F_dyn": "N", "U_bridge": "V"},
    settings={"F_N": "N", "omega": "rad/s"},
    readings={"T2": "N m"},
    counters=("N1", "N2"),
)


@pytest.fixture(scope="module")
def good(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("good") / "run.h5"
    samples.write_v1_run(path)
    return path


@pytest.fixture
def log(good: Path, tmp_path: Path) -> Path:
    path = tmp_path / "damaged.h5"
    path.write_bytes(good.read_bytes())
    return path


def _edit(path: Path, change: Callable[[h5py.File], None]) -> None:
    with h5py.File(path, "r+") as f:
        change(f)


def test_good_log_passes_the_schema(good: Path) -> None:
    assert check_log(good, SCHEMA) == list(range(samples.N_POINTS))


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(LogFormatError, match=r"nowhere\.h5: no such log file"):
        lb.read_settings(tmp_path / "nowhere.h5")


def test_not_hdf5(tmp_path: Path) -> None:
    path = tmp_path / "notes.h5"
    path.write_text("F_N = 96.2\n")
    with pytest.raises(LogFormatError, match=r"notes\.h5: not an HDF5 file"):
        lb.read_metadata(path)


def test_truncated_file(log: Path) -> None:
    data = log.read_bytes()
    log.write_bytes(data[: len(data) // 2])
    with pytest.raises(LogFormatError, match=r"damaged\.h5: a truncated or damaged HDF5 file .*truncated"):
        lb.read_settings(log)


def test_foreign_hdf5_file(tmp_path: Path) -> None:
    path = tmp_path / "foreign.h5"
    with h5py.File(path, "w") as f:
        f["x"] = np.arange(3)
    with pytest.raises(LogFormatError, match=r"foreign\.h5: not a friction-rig log: root attribute 'format' is missing"):
        lb.read_counters(path)
    _edit(path, lambda f: f.attrs.__setitem__("format", "other-log"))
    with pytest.raises(LogFormatError, match="'format' = 'other-log', expected 'friction-rig-log'"):
        lb.read_counters(path)


def test_other_format_version(log: Path) -> None:
    _edit(log, lambda f: f.attrs.__setitem__("format_version", 3))
    with pytest.raises(LogFormatError, match="'format_version' = 3; this friction-rig reads versions 1 and 2"):
        lb.point_indices(log)


def test_missing_channel(log: Path) -> None:
    _edit(log, lambda f: f.__delitem__("points/point_000002/channels/F_dyn"))
    message = r"damaged\.h5: point 2: channel 'F_dyn' is missing \(present: U_bridge\)"
    with pytest.raises(LogFormatError, match=message):
        check_log(log, SCHEMA)
    with pytest.raises(LogFormatError, match=r"/points/point_000002/channels: channel 'F_dyn' is missing"):
        lb.read_channel(log, 2, "F_dyn")
    assert check_log(log) == list(range(samples.N_POINTS))  # without a schema a channel is optional


@pytest.mark.parametrize(
    ("units", "message"),
    [
        ("mV", r"point 1: channel 'U_bridge' has units 'mV', expected 'V'"),
        ("\u00b5V", r"/points/point_000001/channels/U_bridge: attribute 'units' = '\u00b5V' is not valid"),
        (np.float64(1.0), r"/points/point_000001/channels/U_bridge: attribute 'units' = .*1\.0.* is not valid"),
    ],
)
def test_wrong_units_attribute(log: Path, units: object, message: str) -> None:
    _edit(log, lambda f: f["points/point_000001/channels/U_bridge"].attrs.__setitem__("units", units))
    with pytest.raises(LogFormatError, match=message):
        check_log(log, SCHEMA)


@pytest.mark.parametrize(
    ("obj", "attribute", "reader"),
    [
        ("points/point_000004/channels/F_dyn", "units", lambda p: lb.read_channel(p, 4, "F_dyn")),
        ("points/point_000004/channels/F_dyn", "sample_rate_Hz", lambda p: lb.read_channel(p, 4, "F_dyn")),
        ("points/point_000004/channels/F_dyn", "start_time_s", lambda p: lb.read_point(p, 4)),
        ("points/point_000004/settings/F_N", "units", lb.read_settings),
        ("points/point_000004/counters", "gate_time_s", lb.read_counters),
        ("points/point_000004/counters/N2", "marks_per_rev", lb.read_counters),
        ("points/point_000004", "index", lb.point_indices),
        ("truth/point_000004/mu", "units", read_truth),
    ],
)
def test_missing_attribute_is_named(log: Path, obj: str, attribute: str, reader) -> None:
    _edit(log, lambda f: f[obj].attrs.__delitem__(attribute))
    # a damaged truth group raises DamagedTruthError (not taken for a log without truth)
    with pytest.raises((LogFormatError, DamagedTruthError),
                       match=re.escape(f"damaged.h5: /{obj}: attribute '{attribute}' is missing")):
        reader(log)


def test_other_faults_are_named(log: Path) -> None:
    _edit(log, lambda f: f.__delitem__("points/point_000000/readings"))
    with pytest.raises(LogFormatError, match=r"/points/point_000000: group 'readings' is missing"):
        lb.read_readings(log)
    _edit(log, lambda f: f["points/point_000001/settings/F_N"].write_direct(np.array(np.nan)))
    with pytest.raises(LogFormatError, match=r"/points/point_000001/settings/F_N: bad value .*value = nan"):
        lb.read_settings(log)
    with pytest.raises(LogFormatError, match=r"point 9 is not in the log \(points: \[0, 1, 2, 3, 4, 5\]\)"):
        lb.read_point(log, 9)
    _edit(log, lambda f: f["points/point_000002"].attrs.__setitem__("index", 7))
    with pytest.raises(LogFormatError, match=r"point_000002: attribute 'index' = 7 does not match"):
        lb.read_settings(log)
    _edit(log, lambda f: f.__delitem__("points"))
    with pytest.raises(LogFormatError, match=r"damaged\.h5: /: group 'points' is missing"):
        lb.point_indices(log)


def test_counter_with_other_units(log: Path) -> None:
    _edit(log, lambda f: f["points/point_000003/counters/N1"].attrs.__setitem__("units", "1"))
    with pytest.raises(LogFormatError, match=r"point_000003/counters/N1: attribute 'units' = '1'; .*must be 'count'"):
        lb.read_counters(log)


def test_schema_reports_missing_setting_reading_counter(log: Path) -> None:
    for schema, message in [
        (LogSchema(settings={"F_N": "kN"}), r"point 0: setting 'F_N' has units 'N', expected 'kN'"),
        (LogSchema(settings={"sigma": "rad"}), r"point 0: setting 'sigma' is missing \(present: F_N, delta_h, omega\)"),
        (LogSchema(readings={"T0": "N m"}), r"point 0: reading 'T0' is missing"),
        (LogSchema(counters=("N3",)), r"point 0: counter 'N3' is missing \(present: N1, N2\)"),
    ]:
        with pytest.raises(LogFormatError, match=message):
            check_log(log, schema)


def test_column_name_clash_is_an_error(tmp_path: Path) -> None:
    path = tmp_path / "clash.h5"
    writer = LogWriter(path, samples.metadata())
    writer.write_point(PointRecord(0, {"F": Quantity(1.0, "N m"), "F_N": Quantity(2.0, "m")}), {})
    writer.finalize()
    with pytest.raises(LogFormatError, match=r"clash\.h5: .*both give the column name 'F_N_m'"):
        lb.read_settings(path)


def test_readers_never_touch_truth(log: Path) -> None:
    """Damaging /truth breaks read_truth but no reader the reduction uses."""
    _edit(log, lambda f: f["truth/point_000000/mu"].attrs.__setitem__("units", "bogus units!"))
    for reader in (lb.read_settings, lb.read_readings, lb.read_counters, lb.read_calibration, lb.read_metadata):
        reader(log)
    assert check_log(log, SCHEMA) == list(range(samples.N_POINTS))
    assert not hasattr(lb, "read_truth") and "read_truth" not in lb.__all__
    with pytest.raises(DamagedTruthError, match="truth/point_000000/mu: attribute 'units'"):
        read_truth(log)
