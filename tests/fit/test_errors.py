"""Bad input to rig fit: named ParameterErrors (field, value, valid range; "did you mean"), data untouched."""

from __future__ import annotations

import hashlib
import shutil
from pathlib import Path

import pytest

from rig.cli import main as rig_main
from rig.compare.digitizer import DigitisedFormatError
from rig.errors import ParameterError, UnknownNameError
from rig.fit import fit_data
from rig.fit.data import parse_sigma
from rig.fit.parameters import parse_names

EXAMPLES = Path(__file__).resolve().parents[2] / "docs" / "examples"


@pytest.fixture
def curve(tmp_path):
    """A copy of the exact pure-spin curve and its sidecar in tmp_path."""
    for suffix in (".csv", ".toml"):
        shutil.copy(EXAMPLES / f"exact_pure_spin_circle{suffix}", tmp_path / f"curve{suffix}")
    return tmp_path / "curve.csv"


def test_unknown_parameter_suggests_the_closest_name():
    with pytest.raises(UnknownNameError) as info:
        parse_names(["mu", "psii"])
    assert info.value.name == "parameter" and "did you mean 'psi'" in str(info.value)


def test_repeated_or_no_parameter_is_an_error():
    with pytest.raises(ParameterError, match="each parameter at most once"):
        parse_names(["mu", "mu"])
    with pytest.raises(ParameterError, match="at least one"):
        parse_names([])


def test_start_value_outside_the_range_names_it(curve):
    with pytest.raises(ParameterError) as info:
        fit_data(curve, ["psi"], sigma=0.01, start={"psi": 0.5})
    assert info.value.name == "start value of psi" and info.value.value == 0.5 and "[1, 3]" in info.value.valid


def test_missing_sigma_for_a_digitised_curve_is_named(curve):
    with pytest.raises(ParameterError) as info:
        fit_data(curve, ["psi"])
    assert info.value.name == "sigma"
    with pytest.raises(UnknownNameError, match="did you mean 'nu_v'"):
        parse_sigma("nu_w=0.01", ["nu_v"])
    with pytest.raises(ParameterError, match="sigma"):
        parse_sigma(-1.0, ["nu_v"])


def test_data_without_a_fittable_quantity(curve):
    toml = curve.with_suffix(".toml")
    toml.write_text(toml.read_text().replace('quantity = "|F_y| / (mu F_N)"', 'column = "F_y_N"'))
    with pytest.raises(ParameterError) as info:
        fit_data(curve, ["psi"], sigma=0.01)
    assert info.value.name == "datasets.nu_v" and "nu_T, nu_v, nu_0" in info.value.valid


def test_fewer_points_than_parameters(tmp_path, curve):
    lines = curve.read_text().splitlines()
    curve.write_text("\n".join(lines[:3]) + "\n")  # one point per dataset
    with pytest.raises(ParameterError) as info:
        fit_data(curve, ["psi"], sigma=0.01, datasets=["nu_v"])
    assert info.value.name == "data points" and info.value.value == 1


def test_nan_in_the_data_names_the_row(curve):
    lines = curve.read_text().splitlines()
    lines[4] = lines[4].replace("0.0184814", "nan", 1)
    curve.write_text("\n".join(lines) + "\n")
    with pytest.raises(DigitisedFormatError) as info:  # the digitiser's reader names file and line
        fit_data(curve, ["psi"], sigma=0.01, datasets=["nu_v"])
    assert isinstance(info.value, ValueError) and info.value.line == 5


def test_cli_exit_status_2_and_data_unchanged(curve, tmp_path, capsys):
    digest = hashlib.sha256(curve.read_bytes()).hexdigest()
    status = rig_main(["fit", str(curve), "--params", "mu,pci", "--sigma", "0.01", "-o", str(tmp_path / "out")])
    assert status == 2
    assert "did you mean 'psi'" in capsys.readouterr().err
    assert hashlib.sha256(curve.read_bytes()).hexdigest() == digest
    assert not (tmp_path / "out").exists()
