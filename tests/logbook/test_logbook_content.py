"""The content model and unit strings: bad input raises a named ParameterError."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.logbook import Channel, Counter, CounterReadings, PointRecord, Quantity, RunMetadata, column_name, safe_unit
from rig.logbook.content import utc_timestamp
from rig.logbook.units import UNIT_PATTERN, is_name, is_unit


@pytest.mark.parametrize(
    ("name", "unit", "column"),
    [
        ("F_y", "N", "F_y_N"),
        ("T2", "N m", "T2_N_m"),
        ("omega", "rad/s", "omega_rad_s"),
        ("a", "m/s^2", "a_m_s2"),
        ("mu", "1", "mu"),  # dimensionless: bare name
        ("z", "1/rev", "z_per_rev"),
        ("gain", "N/V", "gain_N_V"),
        ("N1", "count", "N1_count"),
    ],
)
def test_column_names_carry_units(name: str, unit: str, column: str) -> None:
    assert column_name(name, unit) == column


@pytest.mark.parametrize("unit", ["", "m" * 33, "N*m", "N·m", "µm", "m/s**2", "N  m", "rad/", "1 m", "m^-1", "%", 1.0, None])
def test_bad_units_are_refused_with_the_rule(unit: object) -> None:
    with pytest.raises(ParameterError, match=r"unit = .* valid: at most 32 characters, an ASCII unit"):
        Quantity(1.0, unit)  # type: ignore[arg-type]


_FACTOR = st.from_regex(r"[A-Za-z]{1,3}(\^[2-9])?", fullmatch=True)
_UNITS = st.one_of(
    st.just("1"),
    st.builds(
        lambda lead, first, rest: lead + first + "".join(sep + f for sep, f in rest),
        st.sampled_from(["", "1/"]),
        _FACTOR,
        st.lists(st.tuples(st.sampled_from([" ", "/"]), _FACTOR), max_size=4),
    ),
)


@given(_UNITS)
def test_safe_unit_of_any_valid_unit_is_an_identifier(unit: str) -> None:
    assert UNIT_PATTERN.fullmatch(unit) and len(unit) <= 32
    assert is_unit(unit)
    safe = safe_unit(unit)
    assert (safe.replace("_", "a")).isalnum() and safe.isascii()
    assert is_name("x_" + safe)


@pytest.mark.parametrize("name", ["", "1x", "a b", "F/N", "_x", "x" * 65, "é"])
def test_bad_names_are_refused(name: str) -> None:
    with pytest.raises(ParameterError, match="settings name"):
        PointRecord(0, {name: Quantity(1.0, "N")})


@pytest.mark.parametrize("value", [float("nan"), float("inf"), "three", True, None])
def test_quantity_value_must_be_a_finite_number(value: object) -> None:
    with pytest.raises(ParameterError, match="value"):
        Quantity(value, "N")  # type: ignore[arg-type]


def test_channel_checks() -> None:
    with pytest.raises(ParameterError, match=r"sample_rate_Hz = 0\.0 .*\(0, inf\)"):
        Channel([1.0], "V", 0.0, 0.0)
    with pytest.raises(ParameterError, match=r"samples\[1\] = nan"):
        Channel([1.0, np.nan], "V", 10.0, 0.0)
    with pytest.raises(ParameterError, match="non-empty 1-D"):
        Channel(np.zeros((2, 2)), "V", 10.0, 0.0)
    with pytest.raises(ParameterError, match="non-empty 1-D"):
        Channel([], "V", 10.0, 0.0)
    ch = Channel([1, 2, 3], "V", 4.0, 0.5)
    assert ch.samples.dtype == np.float64 and not ch.samples.flags.writeable
    np.testing.assert_array_equal(ch.times_s(), [0.5, 0.75, 1.0])  # 0.5 + k / 4 Hz


def test_counter_checks() -> None:
    with pytest.raises(ParameterError, match="count = -1"):
        Counter(-1, 60)
    with pytest.raises(ParameterError, match="marks_per_rev = 0"):
        Counter(10, 0)
    with pytest.raises(ParameterError, match="count = 1.5"):
        Counter(1.5, 60)  # type: ignore[arg-type]
    with pytest.raises(ParameterError, match="gate_time_s = 0"):
        CounterReadings(0, {"N1": Counter(1, 1)})
    with pytest.raises(ParameterError, match=r"counters\['N1'\]"):
        CounterReadings(1.0, {"N1": 5})  # type: ignore[dict-item]


def test_point_record_checks_and_is_immutable() -> None:
    with pytest.raises(ParameterError, match="index = -1"):
        PointRecord(-1, {})
    with pytest.raises(ParameterError, match=r"settings\['F'\]"):
        PointRecord(0, {"F": 3.0})  # type: ignore[dict-item]
    with pytest.raises(ParameterError, match=r"calibration\['dyn'\]\['gain'\]"):
        PointRecord(0, {}, calibration={"dyn": {"gain": 2.5}})  # type: ignore[dict-item]
    given_settings = {"F": Quantity(1.0, "N")}
    point = PointRecord(0, given_settings)
    given_settings["G"] = Quantity(2.0, "N")  # the record keeps its own copy
    assert list(point.settings) == ["F"]
    with pytest.raises(TypeError):
        point.settings["H"] = Quantity(1.0, "N")  # type: ignore[index]


def test_run_metadata_checks() -> None:
    good = dict(scene_toml="x = 1\n", seed=3, stand="stand_A", created_utc="2024-05-01T12:00:00Z")
    assert RunMetadata(**good).seed == 3
    for key, bad, message in [
        ("seed", -1, "seed = -1"),
        ("seed", 2**63, "seed = 9223372036854775808"),
        ("stand", "stand A", "stand = 'stand A'"),
        ("created_utc", "2024-05-01T12:00:00+02:00", "time zone"),
        ("created_utc", "yesterday", "ISO 8601"),
        ("scene_toml", b"x", "scene_toml"),
    ]:
        with pytest.raises(ParameterError, match=message):
            RunMetadata(**{**good, key: bad})
    stamp = utc_timestamp()
    assert stamp.endswith("Z") and RunMetadata(**{**good, "created_utc": stamp}).created_utc == stamp
