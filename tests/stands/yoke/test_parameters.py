"""Stand A's parameter file: one place, every default with its source, geometry reused from the reduction."""

from __future__ import annotations

import math

import pytest

from rig.errors import ParameterError, UnknownNameError
from rig.reduction.geometry import StandAGeometry
from rig.stands import stand_class
from rig.stands.yoke import parameters as P
from rig.stands.yoke.stand import YokeStand


def test_every_default_has_a_tagged_source_and_lies_in_its_range():
    for name, spec in P.PARAMETERS.items():
        assert spec.source.split()[0] in ("[text]", "[computed]", "[assumed]"), name
        assert spec.lo <= spec.default <= spec.hi, name
        assert spec.unit, name


def test_geometry_defaults_are_the_reductions_values_not_copies():
    g = StandAGeometry()
    for name, field in P.GEOMETRY_FIELDS.items():
        assert P.PARAMETERS[name].default == getattr(g, field)
    assert P.resolve({}).geometry == g


def test_text_numbers_of_seed_000():
    # [Koziarski] section 3.1: 102 mm lever, R_v = 42.5 mm (printed 42.2), 0.098 N weights -> 0.235 N on F_y
    g = P.resolve({}).geometry
    assert g.dynamometer_lever == 0.102 and g.yoke_lever == 0.0425
    assert g.lateral_force_half_width == pytest.approx(0.235, abs=5e-4)
    assert g.balance_moment_half_width == pytest.approx(0.0196, rel=1e-9)  # 0.049 N x 0.400 m
    # 240 rpm of wheel 1 = 25.13 rad/s is the text's speed (SETTINGS range contains it)
    spec = P.SETTINGS["omega_1_set_rad_s"]
    assert spec.lo <= 240 * 2 * math.pi / 60 <= spec.hi


def test_overrides_replace_the_geometry_and_are_range_checked():
    p = P.resolve({"a_m": 1.7e-3, "mu": 0.3})
    assert p.geometry.a == 1.7e-3 and p.mu == 0.3
    with pytest.raises(ParameterError, match=r"a_m = 0.1 is not valid; valid: \[0.0003, 0.005\]"):
        P.resolve({"a_m": 0.1})
    with pytest.raises(UnknownNameError, match="did you mean 'mu'"):
        P.resolve({"muu": 0.3})
    with pytest.raises(ParameterError, match="marks_1"):
        P.resolve({"marks_1": 60.5})


def test_effect_parameters_are_checked_by_name_and_range():
    assert P.effect_values("brake_dynamics", {})["loop_gain"] == 10.0
    with pytest.raises(ParameterError, match="effects.bearing_friction.moment_1_N_m"):
        P.effect_values("bearing_friction", {"moment_1_N_m": -1.0})
    with pytest.raises(UnknownNameError, match="did you mean 'loop_gain'"):
        P.effect_values("brake_dynamics", {"loop_gian": 3.0})
    for spec in P.EFFECTS.values():
        for name, (default, _unit) in spec.parameters.items():
            lo, hi = P.EFFECT_RANGES[name]
            assert lo <= default <= hi, name


def test_registry_maps_yoke_to_this_stand():
    assert stand_class("yoke") is YokeStand
    assert set(YokeStand.SETTINGS) >= {"brake_setpoint_N_m", "normal_force_N", "delta_h_m", "omega_1_set_rad_s"}
    assert set(YokeStand.EFFECTS) >= {"drive_compliance", "brake_dynamics", "bearing_friction",
                                      "brake_friction_fluctuation", "dynamometer_noise", "dynamometer_drift",
                                      "balance_noise", "counter_pulse_noise"}
