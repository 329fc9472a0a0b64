"""WebPlotDigitizer export parser: both layouts, separators, decimal commas, padding, malformed lines."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.compare.digitizer import DigitisedFormatError, ExportLayout, digitised_frames, parse_export, read_export
from rig.compare.sidecar import load_sidecar, parse_sidecar
from rig.errors import LogFormatError, ParameterError, UnknownNameError

DATA = Path(__file__).parent / "data"

ALL_DATASETS = """\
upper,,lower,
X,Y,X,Y
0.1,1.5,0.1,0.5
0.2,1.6,0.2,0.4
0.3,1.7,,
0.4,1.8
,,,
"""

PER_DATASET_COMMA = "0.5,1.25\n1.5,2.25\n2.5e1,-3.5E-2\n"

PER_DATASET_SEMICOLON = "0,5;1,25\r\n1,5;2,25\r\n\r\n2,5e1;-3,5E-2\r\n"


def test_all_datasets_with_ragged_blank_padding():
    layout, curves = parse_export(ALL_DATASETS)
    assert layout is ExportLayout.ALL_DATASETS
    assert [c.name for c in curves] == ["upper", "lower"]
    np.testing.assert_array_equal(curves[0].x, [0.1, 0.2, 0.3, 0.4])
    np.testing.assert_array_equal(curves[0].y, [1.5, 1.6, 1.7, 1.8])
    np.testing.assert_array_equal(curves[1].x, [0.1, 0.2])
    np.testing.assert_array_equal(curves[1].y, [0.5, 0.4])
    np.testing.assert_array_equal(curves[0].lines, [3, 4, 5, 6])


def test_per_dataset_comma_and_semicolon_with_decimal_commas_give_the_same_points():
    layout_c, (comma,) = parse_export(PER_DATASET_COMMA)
    layout_s, (semicolon,) = parse_export(PER_DATASET_SEMICOLON)
    assert layout_c is layout_s is ExportLayout.SINGLE_DATASET
    assert comma.name is None
    np.testing.assert_array_equal(comma.x, [0.5, 1.5, 25.0])
    np.testing.assert_array_equal(comma.y, [1.25, 2.25, -0.035])
    np.testing.assert_array_equal(semicolon.x, comma.x)
    np.testing.assert_array_equal(semicolon.y, comma.y)
    np.testing.assert_array_equal(semicolon.lines, [1, 2, 4])  # the blank line 3 is skipped


def test_all_datasets_with_semicolons_and_decimal_commas_and_bom():
    text = "\ufeffa;;b;\nX;Y;X;Y\n0,1;2,5;0,1;7\n0,2;2,75;;\n"
    _, (a, b) = parse_export(text)
    np.testing.assert_array_equal(a.y, [2.5, 2.75])
    np.testing.assert_array_equal(b.x, [0.1])


def test_reference_file_has_33_points_per_dataset():
    layout, curves = read_export(DATA / "exact_pure_spin_circle.csv")
    assert layout is ExportLayout.ALL_DATASETS
    assert [c.name for c in curves] == ["nu_v", "nu_0"]
    assert [c.x.size for c in curves] == [33, 33]
    assert curves[1].y[0] == pytest.approx(0.588977)  # first row of the file
    assert curves[0].x[-1] == pytest.approx(102313.0)


@pytest.mark.parametrize(
    ("text", "line", "words"),
    [
        ("0.1,0.2\n0.3,abc\n", 2, "'abc', not a number"),
        ("0.1,0.2\n0.3,0.4,0.5\n", 2, "expected 2 values"),
        ("0.1,0.2\n\n0.3\n", 3, "found 1"),
        ("0.1,0.2\n0.3,1_0\n", 2, "not a number"),  # float() would accept 1_0
        ("0.1,0.2\n0.3,nan\n", 2, "not a number"),
        ("a,,b,\nX,Y,X,Y\n1,2,3,4\n1,2,3,4,5\n", 4, "found 5 cells, the header has 4"),
        ("a,,b,\nX,Y,X,Y\n1,2,3,\n", 3, "only one of x, y"),
        ("a,,b,\nX,Y,X,Y\n1,2,,\n1,2,3,4\n", 4, "continues after blank padding"),
        ("a,,b,\nX,Y,X,Y\n1,2,3,x4\n", 3, "y of dataset 'b' is 'x4'"),
        ("a,,b,\nX,Y,Y,X\n1,2,3,4\n", 2, "expected X,Y,X,Y"),
        ("a,,a,\nX,Y,X,Y\n1,2,3,4\n", 1, "repeated: a"),
        ("a,oops,b,\nX,Y,X,Y\n1,2,3,4\n", 1, "must be blank"),
        ("a,,b,\nX,Y,X,Y\n1,2,,\n", 1, "dataset 'b' has no points"),
        ("\n \n", 1, "no data"),
    ],
)
def test_malformed_line_is_named(text, line, words):
    with pytest.raises(DigitisedFormatError) as info:
        parse_export(text, source="fig.csv")
    assert info.value.line == line
    assert f"fig.csv, line {line}:" in str(info.value)
    assert words in str(info.value)
    assert isinstance(info.value, LogFormatError) and isinstance(info.value, ValueError)


def test_missing_file_is_a_format_error(tmp_path):
    with pytest.raises(DigitisedFormatError, match="no such file"):
        read_export(tmp_path / "absent.csv")


def _sidecar(*names: str):
    datasets = {name: {"column": name, "units": "1"} for name in names}
    return parse_sidecar({"figure": "f", "x": {"column": "alpha", "units": "1"}, "datasets": datasets})


def test_frames_carry_result_column_names_and_units():
    sidecar = load_sidecar(DATA / "exact_pure_spin_circle.toml")
    _, curves = read_export(DATA / "exact_pure_spin_circle.csv")
    frames = digitised_frames(curves, sidecar, "ref.csv")
    assert list(frames) == ["nu_v", "nu_0"]
    assert list(frames["nu_v"].columns) == ["alpha", "nu_v", "line"]
    assert frames["nu_0"].attrs["y_units"] == "1" and frames["nu_0"].attrs["x_units"] == "1"


def test_headerless_export_takes_the_only_sidecar_dataset():
    _, curves = parse_export(PER_DATASET_COMMA)
    frames = digitised_frames(curves, _sidecar("nu_v"), "one.csv")
    assert list(frames) == ["nu_v"]
    with pytest.raises(ParameterError, match="exactly one dataset"):
        digitised_frames(curves, _sidecar("nu_v", "nu_0"), "one.csv")


def test_export_and_sidecar_datasets_must_agree():
    _, curves = parse_export(ALL_DATASETS)
    with pytest.raises(UnknownNameError, match="'upper' is not valid.*did you mean 'uper'"):
        digitised_frames(curves, _sidecar("uper", "lower"), "all.csv")
    with pytest.raises(UnknownNameError, match="not found in all.csv"):
        digitised_frames(curves, _sidecar("upper", "lower", "middle"), "all.csv")


finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_subnormal=False)
points = st.lists(st.tuples(finite, finite), min_size=1, max_size=6, unique_by=lambda p: p[0])  # a function of x


def _cell(value: float, decimal_comma: bool) -> str:
    text = repr(value)
    return text.replace(".", ",") if decimal_comma else text


@settings(max_examples=60, deadline=None)
@given(st.lists(points, min_size=1, max_size=4), st.sampled_from([",", ";", "\t"]), st.booleans())
def test_round_trip_all_datasets(datasets, separator, crlf):
    """Any ragged set of datasets written in the all-datasets layout reads back exactly."""
    comma = separator != ","
    names = [f"set{k}" for k in range(len(datasets))]
    rows = [separator.join(f"{n}{separator}" for n in names), separator.join(["X", "Y"] * len(names))]
    for i in range(max(len(d) for d in datasets)):
        cells = []
        for d in datasets:
            cells += [_cell(d[i][0], comma), _cell(d[i][1], comma)] if i < len(d) else ["", ""]
        rows.append(separator.join(cells))
    text = ("\r\n" if crlf else "\n").join(rows)
    layout, curves = parse_export(text)
    assert layout is ExportLayout.ALL_DATASETS
    for name, d, curve in zip(names, datasets, curves):
        assert curve.name == name
        np.testing.assert_array_equal(curve.x, [p[0] for p in d])
        np.testing.assert_array_equal(curve.y, [p[1] for p in d])


@settings(max_examples=60, deadline=None)
@given(points, st.sampled_from([",", ";"]))
def test_round_trip_per_dataset(data, separator):
    comma = separator == ";"
    text = "\n".join(f"{_cell(x, comma)}{separator}{_cell(y, comma)}" for x, y in data) + "\n"
    layout, (curve,) = parse_export(text)
    assert layout is ExportLayout.SINGLE_DATASET
    np.testing.assert_array_equal(curve.x, [p[0] for p in data])
    np.testing.assert_array_equal(curve.y, [p[1] for p in data])
