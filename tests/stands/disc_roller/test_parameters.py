"""Stand B parameters against the Equations page's arithmetic (3.2, 4.2) and the named errors."""

from __future__ import annotations

import math

import pytest

from rig.errors import ParameterError, UnknownNameError
from rig.reduction.geometry import StandBGeometry
from rig.stands.disc_roller import parameters as P

PARAMS = P.resolve_parameters({})
SETTINGS = dict(normal_force_N=36.0, l_m=0.0, sigma_rad=0.0, speed_step=1, direction=1)


@pytest.mark.parametrize("load, b_over_a", [(9.0, 0.5), (21.0, 0.764), (36.0, 1.0), (144.0, 2.0)])
def test_b_over_a_from_hertz_with_the_apparent_modulus(load, b_over_a):
    # Equations §3.2: E* = 22.4 MPa gives b = 2, 3.06, 4, 8 mm (text 0.75 at 21 N; b ~ sqrt(F_N) gives 0.764)
    assert PARAMS.b_over_a(load) == pytest.approx(b_over_a, rel=2e-3)


@pytest.mark.parametrize("load, alpha", [(9.0, 10.6), (36.0, 21.3), (144.0, 42.6)])
def test_alpha_prime_is_26_6_mu_b_over_a(load, alpha):
    # Equations §3.2: alpha' = 10 mu (b/a)(R_c/R_r) = 26.6 mu (b/a) = 10.6 / 21.3 / 42.6 for mu = 0.8
    assert PARAMS.alpha_prime(load) == pytest.approx(alpha, abs=0.05)  # printed to 3 digits


def test_kinematics_of_the_gear_loop():
    assert PARAMS.gear_ratio == pytest.approx(2.661, abs=5e-4)  # Equations §3.2
    # 24/48/72 rpm roller -> disc 0.945/1.889/2.834 rad/s, v = 0.157/0.314/0.471 m/s (Equations §3.2)
    for step, disc, v in ((1, 0.945, 0.157), (2, 1.889, 0.314), (3, 2.834, 0.471)):
        w_r = PARAMS.roller_speed(step)
        assert w_r / PARAMS.gear_ratio == pytest.approx(disc, abs=1e-3)
        assert w_r * PARAMS.roller_radius == pytest.approx(v, abs=1e-3)


def test_twist_of_eq_36_and_shared_geometry():
    settings = P.point_settings(dict(SETTINGS, sigma_rad=math.radians(6.54)))
    assert settings.offset_c(PARAMS.pivot_distance) == pytest.approx(8.0e-3, rel=2e-3)  # sigma = 6.54 deg for 8 mm
    assert PARAMS.geometry == StandBGeometry()  # the reduction's constants, not copies of them


def test_momentometer_stiffness_is_the_loop_compliance():
    k = P.EFFECTS["loop_compliance"].parameters["stiffness_N_m_per_rad"][0]
    assert k == pytest.approx(3.26e3, rel=2e-3)  # docs/instruments.md
    assert 2e3 <= k <= 1e4  # Equations §4.2 range


def test_every_parameter_has_a_tagged_source_and_its_default_in_range():
    for name, spec in P.PARAMETERS.items():
        assert spec.source.startswith(("[text]", "[computed]", "[assumed]")), name
        assert spec.lo <= spec.default <= spec.hi, name
    for name, spec in P.EFFECTS.items():
        for key, (default, _unit) in spec.parameters.items():
            lo, hi = P.EFFECT_RANGES[name][key]
            assert lo <= default <= hi, (name, key)


def test_bad_parameters_and_effects_are_named():
    with pytest.raises(UnknownNameError, match="did you mean 'disc_inertia_kg_m2'"):
        P.resolve_parameters({"disk_inertia_kg_m2": 0.1})
    with pytest.raises(ParameterError, match=r"mu = 5\.0 .*\[0\.05, 2\]"):
        P.resolve_parameters({"mu": 5.0})
    with pytest.raises(UnknownNameError, match="loop_compliance"):
        P.resolve_effects({"loop_complience": {}})
    with pytest.raises(ParameterError, match="loop_compliance.stiffness_N_m_per_rad"):
        P.resolve_effects({"loop_compliance": {"stiffness_N_m_per_rad": -1.0}})
    with pytest.raises(ParameterError, match="gear_backlash together with loop_compliance"):
        P.resolve_effects({"gear_backlash": {}})
    with pytest.raises(ParameterError, match="swinging_drive together with contact_relaxation"):
        P.resolve_effects({"swinging_drive": {}})


@pytest.mark.parametrize("change, message", [
    (dict(speed_step=1.5), "speed_step"), (dict(direction=0.0), "direction"), (dict(l_m=0.03), r"l_m = 0\.03"),
    (dict(normal_force_N=0.0), "normal_force_N"),
])
def test_bad_settings_are_named(change, message):
    with pytest.raises(ParameterError, match=message):
        P.point_settings(dict(SETTINGS, **change))


def test_missing_setting_is_an_error_not_a_default():
    settings = dict(SETTINGS)
    del settings["sigma_rad"]
    with pytest.raises(ParameterError, match="sigma_rad .*required per point"):
        P.point_settings(settings)


def test_docs_name_every_parameter_effect_and_setting():
    from pathlib import Path

    text = (Path(__file__).resolve().parents[3] / "docs" / "stand-b.md").read_text()
    for name in (*P.PARAMETERS, *P.EFFECTS, *P.SETTINGS):
        assert f"`{name}`" in text, name
