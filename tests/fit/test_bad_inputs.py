"""Garbage in `rig fit`: each a named one-line error (exit 2) before any solving, the data untouched.

The file-level cases need only a file called log.h5 beside the table (they fail before it is read);
the cases that read the log use the small stand-A run of conftest.py.
"""

from __future__ import annotations

import shutil

import pandas as pd
import pytest

from rig.cli import main as rig_main
from rig.errors import ParameterError
from rig.fit import fit_data
from rig.fit.data import SceneMismatchError
from rig.fit.inputs import HDF5_SIGNATURE, DataFileError


def _fit_exit(capsys, *args) -> tuple[int, str]:
    status = rig_main(["fit", *map(str, args)])
    err = capsys.readouterr().err
    return status, err


@pytest.fixture
def beside_a_log(tmp_path):
    """A folder with a stand-in log.h5 (HDF5 signature only) for the table-level checks."""
    (tmp_path / "log.h5").write_bytes(HDF5_SIGNATURE + b"\x00" * 64)
    return tmp_path


@pytest.mark.parametrize("content, problem", [
    (b"", "an empty file"),
    (b"\n \n", "blank"),
    (b"point,l_over_a,u_l_over_a,c_over_a,F_y_N,u_F_y_N,i_k\n", "a header and no data rows"),
    (b"\x7fELF\x02\x01\x01\x00\x00\x00" + bytes(range(256)), "binary, not text"),
    (b"point,l_over_a\n1,\xff\xfe0.5\n", "not UTF-8 text"),
])
def test_unreadable_reduced_tables_are_named(beside_a_log, capsys, content, problem):
    data = beside_a_log / "reduced.csv"
    data.write_bytes(content)
    with pytest.raises(DataFileError) as info:
        fit_data(data, ["mu", "psi"])
    assert info.value.name == "DATA" and problem in info.value.problem
    status, err = _fit_exit(capsys, data, "--params", "mu,psi", "-o", beside_a_log / "out")
    assert status == 2 and err.count("\n") == 1 and "DATA" in err and str(data) in err
    assert "Traceback" not in err and not (beside_a_log / "out").exists()
    assert data.read_bytes() == content


def test_a_csv_with_neither_sidecar_nor_log_is_named(tmp_path, capsys):
    data = tmp_path / "points.csv"
    data.write_text("")
    status, err = _fit_exit(capsys, data, "--params", "mu", "-o", tmp_path / "out")
    assert status == 2 and "neither a sidecar points.toml nor a log.h5 beside it" in err


def test_an_empty_log_and_a_folder_are_named(tmp_path):
    (tmp_path / "log.h5").write_bytes(b"")
    with pytest.raises(DataFileError, match="an empty file"):
        fit_data(tmp_path / "log.h5", ["mu"])
    with pytest.raises(DataFileError, match="a folder"):
        fit_data(tmp_path, ["mu"])


def test_grid_is_checked_before_the_data_is_read(tmp_path):
    """--n 3: refused by name although DATA does not even exist (nothing is loaded first)."""
    with pytest.raises(ParameterError) as info:
        fit_data(tmp_path / "missing.csv", ["mu", "psi"], n=3)
    assert info.value.name == "n" and "[4, 512]" in info.value.valid


def _edited_copy(run, folder, edit):
    """``run``'s log.h5 and its reduced.csv changed by ``edit(table)`` in ``folder``; the csv's path."""
    folder.mkdir()
    shutil.copy(run / "log.h5", folder / "log.h5")
    table = pd.read_csv(run / "reduced.csv")
    edit(table)
    table.to_csv(folder / "reduced.csv", index=False)
    return folder / "reduced.csv"


def test_no_finite_rolling_point_is_named(static_ratio_run, tmp_path):
    def no_rolling_point(table):
        table["l_over_a"] = float("nan")

    data = _edited_copy(static_ratio_run, tmp_path / "run", no_rolling_point)
    with pytest.raises(ParameterError) as info:
        fit_data(data, ["mu", "psi"])
    assert info.value.name == "DATA" and "finite l_over_a" in info.value.valid


def test_points_not_in_the_log_are_named(static_ratio_run, tmp_path):
    def foreign_point(table):
        table.loc[0, "point"] = 999

    data = _edited_copy(static_ratio_run, tmp_path / "run", foreign_point)
    with pytest.raises(ParameterError) as info:
        fit_data(data, ["mu"])
    assert info.value.name == "DATA point" and "not from this log" in info.value.valid


def test_a_wrong_scene_is_a_named_error_unless_forced(static_ratio_run, capsys, tmp_path):
    """fig10's R_x is 143.7 mm, the log's 20 mm: alpha' (eq. 21) would be 7x off."""
    with pytest.raises(SceneMismatchError) as info:
        fit_data(static_ratio_run / "reduced.csv", ["mu"], scene="fig10")
    assert "radius_x_m: 0.1437 vs 0.02" in str(info.value)
    status, err = _fit_exit(capsys, static_ratio_run / "reduced.csv", "--params", "mu", "--scene", "fig10",
                            "-o", tmp_path / "out")
    assert status == 2 and "--force-scene" in err and err.count("\n") == 1
