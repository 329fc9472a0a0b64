"""TOML sidecar: the shipped reference sidecar, the quantity table, and every kind of bad sidecar."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from rig.compare import quantities
from rig.compare.sidecar import AxisScale, load_sidecar, parse_sidecar
from rig.errors import LogFormatError, ParameterError, UnknownNameError

DATA = Path(__file__).parent / "data"

GOOD = {
    "figure": "Fig. 4",
    "conditions": {"shape": "ellipse", "b_over_a": 1.0},
    "x": {"column": "alpha", "units": "1", "scale": "log"},
    "datasets": {
        "a": {"column": "nu_v", "units": "1"},
        "b": {"quantity": "nu_0", "units": "1", "conditions": {"b_over_a": 2, "model": "kinematic"}},
    },
}


def test_reference_sidecar_maps_its_quantities_to_result_columns():
    sidecar = load_sidecar(DATA / "exact_pure_spin_circle.toml")
    assert sidecar.figure.startswith("pure spin, circular Hertz contact")
    assert (sidecar.x.column, sidecar.x.units, sidecar.x.scale) == ("alpha", "1", AxisScale.LOG)
    nu_v, nu_0 = sidecar.datasets
    assert (nu_v.name, nu_v.y.column, nu_v.y.magnitude) == ("nu_v", "nu_v", True)  # "|F_y| / (mu F_N)"
    assert (nu_0.name, nu_0.y.column, nu_0.y.magnitude) == ("nu_0", "nu_0", False)
    assert dict(nu_v.conditions) == {
        "shape": "ellipse", "b_over_a": 1.0, "poisson": 0.28, "c_over_a": 0.0, "l_over_a": 0.0
    }  # fmt: skip


def test_dataset_conditions_override_global_ones():
    sidecar = parse_sidecar(GOOD)
    a, b = sidecar.datasets
    assert dict(a.conditions) == {"shape": "ellipse", "b_over_a": 1.0}
    assert dict(b.conditions) == {"shape": "ellipse", "b_over_a": 2.0, "model": "kinematic"}
    assert sidecar.dataset("b") is b
    assert a.y.scale is AxisScale.LINEAR  # scale defaults to linear


@pytest.mark.parametrize(
    ("spelling", "column", "magnitude"),
    [("alpha'", "alpha", False), ("α'", "alpha", False), ("|F_y|/(μ F_N)", "nu_v", True),
     ("F_x / (mu F_N)", "nu_T", False), ("|moment about C| / (mu a F_N)", "nu_0", False), ("l/a", "l_over_a", False)],
)  # fmt: skip
def test_quantity_table(spelling, column, magnitude):
    found = quantities.lookup(spelling, "x.quantity")
    assert (found.column, found.magnitude) == (column, magnitude)


def _broken(path: tuple[str, ...], value) -> dict:
    data = copy.deepcopy(GOOD)
    target = data
    for key in path[:-1]:
        target = target[key]
    if value is None:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return data


@pytest.mark.parametrize(
    ("path", "value", "error", "words"),
    [
        (("figur",), "x", UnknownNameError, "did you mean 'figure'"),
        (("x", "unit"), "1", UnknownNameError, "did you mean 'units'"),
        (("datasets", "a", "colum"), "nu_v", UnknownNameError, "did you mean 'column'"),
        (("figure",), None, ParameterError, "figure = None"),
        (("figure",), "  ", ParameterError, "non-empty string"),
        (("x", "units"), None, ParameterError, "x.units = None"),
        (("datasets", "a", "units"), None, ParameterError, "datasets.a.units"),
        (("x", "scale"), "logarithmic", UnknownNameError, "one of linear, log"),
        (("datasets", "a", "column"), None, ParameterError, "`column` (a RESULT column) or a known `quantity`"),
        (("datasets", "b", "quantity"), "nu_zero", UnknownNameError, "known quantities"),
        (("conditions", "b_over_a"), [1, 2], ParameterError, "a number or a string"),
        (("conditions", "b_over_a"), True, ParameterError, "a number or a string"),
        (("conditions", "b_over_a"), float("nan"), ParameterError, "finite"),
        (("datasets",), {}, ParameterError, "at least one"),
        (("x",), None, ParameterError, "a TOML table [x]"),
        (("datasets", "a", "magnitude"), "yes", ParameterError, "true or false"),
    ],
)
def test_bad_sidecar_is_named(path, value, error, words):
    with pytest.raises(error) as info:
        parse_sidecar(_broken(path, value), source="fig.toml")
    assert words in str(info.value)


def test_toml_syntax_error_names_the_line(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('figure = "f"\n[x]\ncolumn = alpha\n')
    with pytest.raises(LogFormatError, match=r"bad\.toml.*line 3"):
        load_sidecar(path)


def test_missing_sidecar_file(tmp_path):
    with pytest.raises(ParameterError, match="an existing TOML file"):
        load_sidecar(tmp_path / "none.toml")
