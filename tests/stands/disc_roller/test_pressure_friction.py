"""Stand B with a pressure-dependent mu (contact effect pressure_exponent): each load runs at mu(p0)."""

import math

import pytest

from rig.errors import ParameterError
from rig.stands.base import ContactSpec, DriveMode
from rig.stands.disc_roller.stand import DiscRollerStand
from rig.stands.yoke.stand import YokeStand
from tests.stands.disc_roller.conftest import settings
from tests.stands.disc_roller.laws import smooth_factory


def _stand(effects, parameters=None):
    spec = ContactSpec("rigid", 16, 0.5, effects=effects)
    return DiscRollerStand(parameters or {}, {}, spec, DriveMode.QUASI_STATIC, law_factory=smooth_factory)


def _truth(stand, force):
    point = stand.start_point(0, settings(normal_force_N=force), None, seed=3)
    point.settle(timeout_s=5.0)
    return point.read(point.gate(0.5)).truth


def test_peak_pressure_is_hertz_line_contact():
    """p0 = F_N/(pi a b): 36 N on 2a = 8 mm with b = a = 4 mm (Equations §3.2) is 716 kPa."""
    assert _stand({}).params.peak_pressure(36.0) == pytest.approx(36.0 / (math.pi * 0.004 * 0.004), rel=1e-3)


@pytest.mark.parametrize("force", [9.0, 144.0])
def test_each_load_runs_at_mu_of_its_peak_pressure(force):
    plain = _stand({})
    k = 0.4
    dependent = _stand({"pressure_exponent": k}, {"friction_reference_pressure_Pa": 5e5})
    mu0 = 0.8 * (plain.params.peak_pressure(force) / 5e5) ** (-k)
    before, after = _truth(plain, force), _truth(dependent, force)
    assert after["mu"].value == pytest.approx(mu0, rel=1e-12)
    assert after["alpha_prime"].value == pytest.approx(before["alpha_prime"].value * mu0 / 0.8, rel=1e-12)
    # the stand-in law does not know k: the forces scale with mu0 and with the law's weak alpha' dependence
    nu_ratio = after["nu_T"].value / before["nu_T"].value
    assert after["F_T"].value == pytest.approx(before["F_T"].value * mu0 / 0.8 * nu_ratio, rel=1e-6)


def test_off_leaves_the_parameter_mu_and_exponent_0_equals_off():
    plain, zero = _truth(_stand({}), 21.0), _truth(_stand({"pressure_exponent": 0.0}), 21.0)
    assert zero["mu"].value == plain["mu"].value == 0.8
    assert zero["F_T"].value == plain["F_T"].value


def test_stand_a_refuses_it_by_name():
    with pytest.raises(ParameterError, match="pressure_exponent"):
        YokeStand({}, {}, ContactSpec("rigid", 16, 0.3, effects={"pressure_exponent": 0.2}), DriveMode.QUASI_STATIC)


def _scene_text(effects: str) -> str:
    from importlib.resources import files

    text = files("rig.scenes.builtin").joinpath("fig14.toml").read_text()
    return text.replace('table_points = [25, 9, 5]', 'table_points = [25, 9, 5]\neffects = { %s }' % effects) \
        .replace("mu = 0.8 ", "mu = 0.8\nfriction_reference_pressure_Pa = 7e5 ")


def test_a_scene_names_it_and_a_misspelling_gets_did_you_mean():
    from rig.errors import UnknownNameError
    from rig.scenes.load import parse_scene

    scene = parse_scene(_scene_text("pressure_exponent = 0.3"), name="k", source="test")
    assert scene.contact.effects == {"pressure_exponent": 0.3}
    assert scene.build_stand().friction(36.0) == pytest.approx(0.8 * (36.0 / (math.pi * 0.004**2) / 7e5) ** -0.3,
                                                               rel=2e-3)
    with pytest.raises(UnknownNameError, match="did you mean 'pressure_exponent'"):
        parse_scene(_scene_text("pressure_exponant = 0.3"), name="k", source="test")
    with pytest.raises(ParameterError, match="pressure_exponent"):
        parse_scene(_scene_text("pressure_exponent = 1.5"), name="k", source="test")
