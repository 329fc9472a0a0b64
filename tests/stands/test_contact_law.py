"""The stands' contact law (rig.stands.contact_law): direct or table with one call signature, and the
signed physical wrapper - mirror symmetries checked against the rigid model (where only the slip
field counts, so the truth needs no mirror) and against solve_creepage with negative spin."""

from __future__ import annotations

import math
from types import SimpleNamespace
from unittest import mock

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rig.contact.materials import track_deformability
from rig.contact.solve import solve, solve_creepage
from rig.contact.surrogate import TableDomain
from rig.contact.surrogate_cache import CacheStatus
from rig.errors import ParameterError
from rig.stands.base import ContactSpec
from rig.stands.contact_law import ContactPatch, DirectLaw, TableLaw, contact_forces, make_contact_law

# Stand A at 96.2 N (Equations §3.1): line contact a = 1.215 mm, E* = 4906 MPa, p0 = 20.7 MPa, mu = 0.4
A = 1.215e-3
PATCH = ContactPatch(mu=0.4, normal_force_N=96.2, a_m=A, p0_Pa=20.7e6, modulus_Pa=2 * 4906e6)
MU_F = 0.4 * 96.2
DOMAIN = TableDomain(l_over_a=(-1.5, 1.5), c_over_a=(-0.9, 0.9), alpha=(0.3, 3.0))
SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                           HealthCheck.function_scoped_fixture])
signs = st.sampled_from([-1.0, 1.0])


def _law(model, surrogate, *, n=8, effects=None, points=(7, 7, 4), directory=None, shape="line"):
    spec = ContactSpec(model=model, n=n, poisson=0.3, effects=effects or {}, surrogate=surrogate, table_points=points)
    return make_contact_law(spec, shape, 1.0, DOMAIN if surrogate else None, cache_directory=directory)


@pytest.fixture(scope="module")
def rigid_direct():
    return _law("rigid", False)


@pytest.fixture(scope="module")
def kinematic_table(tmp_path_factory):
    return _law("kinematic", True, directory=tmp_path_factory.mktemp("tables"))


def _canonical(model, c, l, *, alpha=1.0, n=8, **effects):
    """solve() at the rolling point (c, l) [m] with w0 > 0, v > 0, scaled: (F_x, F_y, M_C, M_O)."""
    r = solve(model, shape="line", b_over_a=1.0, alpha=alpha, c_over_a=c / A, l_over_a=l / A, poisson=0.3, n=n,
              **effects)
    return np.array([MU_F * r.nu_T, MU_F * r.nu_v, MU_F * A * r.nu_MC, MU_F * A * r.nu_Mo])


def _forces(f):
    return np.array([f.force_x_N, f.force_y_N, f.moment_C_N_m, f.moment_O_N_m])


def test_alpha_prime_is_eq_21_and_gives_stand_a_value(rigid_direct):
    """v = 1.03 m/s, w0 = 44.5 rad/s: alpha' = 0.64 for b/a = 1, mu = 0.4 (Equations §3.1)."""
    f = contact_forces(rigid_direct, PATCH, speed=1.03, spin=44.5, c=0.0, l=0.0)
    assert f.alpha_prime == pytest.approx(track_deformability(0.4, 20.7e6, 1.03, A, 2 * 4906e6, 44.5), rel=1e-14)
    assert f.alpha_prime == pytest.approx(0.64, abs=0.01)
    # pure spin about the centre, full sliding: nu_0 of the line contact b/a = 1 is 0.71139 (Equations §1.10 a)
    assert f.nu_0 == pytest.approx(0.71139, abs=4e-3) and f.force_x_N == pytest.approx(0.0, abs=1e-12)


@SETTINGS
@given(sv=signs, sw=signs, v=st.floats(0.0, 3.0), w=st.floats(1.0, 100.0), c=st.floats(-2.0, 2.0),
       l=st.floats(-3.0, 3.0))
def test_rigid_sliding_mirrors_for_every_sign(rigid_direct, sv, sw, v, w, c, l):
    """Rigid sliding depends only on the slip field w0 (-(y - l), x - c), not on v: the truth is
    sign(w0) times the canonical solve at the same (c, l) - no mirror involved."""
    f = contact_forces(rigid_direct, PATCH, speed=sv * v, spin=sw * w, c=c * A, l=l * A)
    np.testing.assert_allclose(_forces(f), sw * _canonical("rigid", c * A, l * A), rtol=1e-9, atol=1e-12)
    assert f.friction_power_W == pytest.approx(-sw * w * f.moment_C_N_m, rel=1e-12)  # P_t = -w0 M_C >= 0
    assert f.friction_power_W >= 0.0


def test_independent_flips_would_fail_the_rigid_truth(rigid_direct):
    """Guard: the rule 'c -> -c for v < 0, l -> -l for w0 < 0, independently' gives the wrong sign
    for v < 0, w0 < 0 (a mirror in x also reverses the sense of rotation)."""
    c, l = 0.3 * A, 0.5 * A
    truth = -_canonical("rigid", c, l)
    naive = _canonical("rigid", -c, -l) * np.array([-1.0, -1.0, 1.0, 1.0])
    f = contact_forces(rigid_direct, PATCH, speed=-1.0, spin=-40.0, c=c, l=l)
    np.testing.assert_allclose(_forces(f), truth, rtol=1e-9)
    assert not np.allclose(naive, truth, rtol=0.1)


@pytest.mark.parametrize(("c", "l", "v", "w"), [(0.3, 0.5, 1.03, -44.5), (0.0, -0.8, 0.5, -20.0),
                                                (-0.4, 1.2, 2.0, -60.0)])
def test_negative_spin_matches_solve_creepage(c, l, v, w):
    """Kinematic model, v > 0 > w0: the wrapper's mirror y against the solver run on the actual
    negative spin, phi = a G (w0/v)/(mu p0) = -20 (1 - nu)/alpha' < 0 (rig.contact.kinematics)."""
    law = _law("kinematic", False)
    f = contact_forces(law, PATCH, speed=v, spin=w, c=c * A, l=l * A)
    phi = -20.0 * (1.0 - 0.3) / f.alpha_prime
    r = solve_creepage("kinematic", shape="line", b_over_a=1.0, xi=phi * l, eta=-phi * c, phi=phi, poisson=0.3, n=8)
    truth = np.array([MU_F * r.nu_T, MU_F * r.nu_v, MU_F * A * r.nu_MC, MU_F * A * r.nu_Mo])
    np.testing.assert_allclose(_forces(f), truth, rtol=1e-6, atol=1e-6 * MU_F * A)


@pytest.mark.parametrize(("sv", "sw"), [(1, 1), (1, -1), (-1, 1), (-1, -1)])
def test_kinematic_law_tends_to_rigid_sliding_as_v_goes_to_zero_for_every_sign(kinematic_table, sv, sw):
    """v -> 0 is alpha' -> 0 (hard case 3): the limit is finite and equals sign(w0) times the
    model's own alpha' = 0 result at (c, l), from either direction of rolling. This checks the
    mirror in x (v < 0) on the elastic model, which has no solver for material flowing in -x.
    At n = 16: the first two cells of a row take the rigid slip upstream of their centres
    (rig.contact.entry), which the alpha' = 0 result on the cell centres does not; the gap is
    O(h^2), 0.0007 (v > 0) and 0.0015 (v < 0) at n = 16 here, 0.004 and 0.011 at n = 8."""
    c, l, w = 0.25 * A, -0.6 * A, 40.0
    truth = sw * _canonical("kinematic", c, l, alpha=0.0, n=16)
    scale = np.array([MU_F, MU_F, MU_F * A, MU_F * A])
    near = contact_forces(_law("kinematic", False, n=16), PATCH, speed=sv * 1e-3, spin=sw * w, c=c, l=l)
    assert near.alpha_prime < 1e-3
    np.testing.assert_allclose(_forces(near) / scale, truth / scale, atol=3e-3)  # docs: alpha' -> 0 within 2e-3
    # the table at v = 0 exactly (its alpha' = 0 slice) and just off it, both sides: same finite limit
    at_zero = _forces(contact_forces(kinematic_table, PATCH, speed=0.0, spin=sw * w, c=c, l=l))
    off = _forces(contact_forces(kinematic_table, PATCH, speed=sv * 1e-12, spin=sw * w, c=c, l=l))
    np.testing.assert_allclose(off, at_zero, rtol=1e-9, atol=1e-12)
    truth = sw * _canonical("kinematic", c, l, alpha=0.0)  # the table's grid, n = 8
    np.testing.assert_allclose(at_zero / scale, truth / scale, atol=2e-2)  # between nodes of a 7 x 7 slice
    node_l = float(kinematic_table.table.inputs.axes()[0][2]) * A  # a node: exact
    at_node = contact_forces(kinematic_table, PATCH, speed=0.0, spin=sw * w, c=0.0, l=node_l)
    np.testing.assert_allclose(_forces(at_node), sw * _canonical("kinematic", 0.0, node_l, alpha=0.0),
                               rtol=1e-10, atol=1e-12)


def test_zero_spin_is_a_named_error_and_small_spin_leaves_the_table(kinematic_table, rigid_direct):
    """w0 = 0: rolling point at infinity, alpha' infinite -> ParameterError naming spin. A small w0
    with a table law: alpha' beyond the table -> ParameterError naming alpha, with the state."""
    with pytest.raises(ParameterError, match="spin = 0.0 .*non-zero.*creepages") as info:
        contact_forces(kinematic_table, PATCH, speed=1.0, spin=0.0, c=0.0, l=0.0)
    assert info.value.name == "spin"
    with pytest.raises(ParameterError, match=r"alpha = .*\[0, 3\].*w0 = 0.001 rad/s") as info:
        contact_forces(kinematic_table, PATCH, speed=1.0, spin=1e-3, c=0.0, l=0.0)
    assert info.value.name == "alpha"
    f = contact_forces(rigid_direct, PATCH, speed=1.0, spin=1e-3, c=0.1 * A, l=0.2 * A)  # direct: no domain
    assert np.all(np.isfinite(_forces(f)))


@pytest.mark.parametrize(("name", "kwargs"), [("speed", dict(speed=math.nan)), ("spin", dict(spin=math.inf)),
                                              ("c", dict(c=math.nan)), ("l", dict(l=-math.inf)),
                                              ("c", dict(c="0.1 mm"))])
def test_non_finite_state_is_a_named_error(rigid_direct, name, kwargs):
    state = dict(speed=1.0, spin=40.0, c=0.0, l=0.0)
    state.update(kwargs)
    with pytest.raises(ParameterError) as info:
        contact_forces(rigid_direct, PATCH, **state)
    assert info.value.name == name


def test_canonical_state_outside_the_table_names_the_mapping(kinematic_table):
    with pytest.raises(ParameterError, match=r"l_over_a = 1.8\d* .*canonical l/a = 1.8") as info:
        contact_forces(kinematic_table, PATCH, speed=1.0, spin=-40.0, c=0.0, l=-1.8 * A)  # mirror y: l -> -l
    assert info.value.name == "l_over_a"


@SETTINGS
@given(sv=signs, sw=signs, v=st.floats(0.05, 2.0), w=st.floats(20.0, 100.0), c=st.floats(-0.85, 0.85),
       l=st.floats(-1.45, 1.45))
def test_jacobian_matches_finite_differences(kinematic_table, sv, sw, v, w, c, l):
    state = dict(speed=sv * v, spin=sw * w, c=c * A, l=l * A)
    jac = contact_forces(kinematic_table, PATCH, jacobian=True, **state).jacobian
    assert jac.shape == (4, 4)
    for k, (name, h) in enumerate((("speed", 1e-7), ("spin", 1e-5), ("c", 1e-10), ("l", 1e-10))):
        up, down = dict(state), dict(state)
        up[name] += h
        down[name] -= h
        high = _forces(contact_forces(kinematic_table, PATCH, **up))
        fd = (high - _forces(contact_forces(kinematic_table, PATCH, **down))) / (2 * h)
        scale = np.array([MU_F, MU_F, MU_F * A, MU_F * A]) / {"speed": 1.0, "spin": 40.0, "c": A, "l": A}[name]
        assert np.all(np.abs(jac[:, k] - fd) <= 1e-5 * scale + 1e-5 * np.abs(fd)), (name, jac[:, k], fd)


@pytest.mark.parametrize("sv", [1.0, -1.0])
def test_rolling_length_moves_the_rolling_point_forward_along_the_flow(rigid_direct, sv):
    """With f/a = 0.1 the rigid law slides about (c + sign(v) f, l); M_O = M_C + (c + sign(v) f) F_y - l F_x."""
    law = _law("rigid", False, effects={"rolling_length": 0.1})
    c, l, f = 0.2 * A, 0.4 * A, 0.1 * A
    out = contact_forces(law, PATCH, speed=sv * 1.0, spin=40.0, c=c, l=l)
    np.testing.assert_allclose(_forces(out), _canonical("rigid", c + sv * f, l), rtol=1e-9, atol=1e-12)
    assert out.moment_O_N_m == pytest.approx(out.moment_C_N_m + (c + sv * f) * out.force_y_N - l * out.force_x_N)


def test_direct_and_table_laws_share_one_call_signature(kinematic_table):
    direct = _law("kinematic", False)
    assert isinstance(direct, DirectLaw) and isinstance(kinematic_table, TableLaw)
    l_nodes, c_nodes, _ = kinematic_table.table.inputs.axes()
    alphas = kinematic_table.table.inputs.alpha_nodes()
    state = (float(l_nodes[2]), float(c_nodes[4]), float(alphas[1]))
    for law in (direct, kinematic_table):
        values = law(*state)
        assert isinstance(values, tuple) and all(isinstance(v, float) for v in values)
        arrays = law(np.array([[state[0]], [state[0]]]), state[1], np.array([state[2], state[2]]))
        assert all(a.shape == (2, 2) for a in arrays)
        v, jac = law.derivatives(*state)
        assert v.shape == (3,) and jac.shape == (3, 3)
    np.testing.assert_allclose(kinematic_table(*state), direct(*state), atol=1e-12)  # a node
    between = (0.1, 0.2, 1.1)
    np.testing.assert_allclose(kinematic_table(*between), direct(*between), atol=0.03)


def test_direct_law_solves_each_distinct_state_once():
    """A quasi-static gate evaluates its one steady state at every sample: one solve for each distinct
    state (0.0 and -0.0 apart), the same values as state by state."""
    law = _law("kinematic", False)
    l = np.array([0.3, 0.3, -0.2, 0.3, -0.2, 0.0, -0.0])
    c = np.array([0.1, 0.1, 0.0, 0.1, 0.0, 0.2, 0.2])
    alpha = np.full(l.size, 1.5)
    alone = np.array([law.value_one(*state) for state in zip(l, c, alpha)]).T
    with mock.patch("rig.stands.contact_law.solve", wraps=solve) as counted:
        values = law(l, c, alpha)
    assert counted.call_count == 4
    np.testing.assert_array_equal(np.array(values), alone)


def test_direct_law_derivatives_follow_linear_theory():
    """Linear theory (eq. 4): every coefficient is proportional to the creepage, i.e. to 1/alpha',
    and nu_T = -C11 xi (...) is proportional to l: d nu/d alpha' = -nu/alpha', d nu_T/d(l/a) = nu_T/(l/a)."""
    law = _law("linear", False)
    l, c, alpha = 0.4, 0.3, 50.0
    values, jac = law.derivatives(l, c, alpha)
    np.testing.assert_allclose(jac[:, 2], -values / alpha, rtol=1e-6)
    assert jac[0, 0] == pytest.approx(values[0] / l, rel=1e-6)
    assert jac[0, 1] == pytest.approx(0.0, abs=1e-9)


def test_make_contact_law_builds_only_what_the_scene_names(tmp_path):
    with mock.patch("rig.stands.contact_law.load_or_build") as build:
        law = _law("rigid", False)
    build.assert_not_called()
    assert isinstance(law, DirectLaw)
    duck = SimpleNamespace(l_over_a=(-1.0, 1.0), c_over_a=(0.0, 0.5), alpha=(0.5, 2.0))
    spec = ContactSpec(model="rigid", n=8, poisson=0.3, surrogate=True, table_points=(5, 4, 4))
    first = make_contact_law(spec, "ellipse", 1.0, duck, cache_directory=tmp_path)
    with mock.patch("rig.contact.surrogate.solve") as solve_mock:
        second = make_contact_law(spec, "ellipse", 1.0, duck, cache_directory=tmp_path)
    solve_mock.assert_not_called()
    assert first.cache.status is CacheStatus.BUILT and second.cache.status is CacheStatus.HIT
    with pytest.raises(ParameterError, match="domain"):
        make_contact_law(spec, "ellipse", 1.0, None)
    with pytest.raises(ParameterError, match="spec"):
        make_contact_law({"model": "rigid"}, "ellipse", 1.0, duck)
    with pytest.raises(ParameterError, match="psi"):
        make_contact_law(ContactSpec("rigid", 8, 0.3, effects={"psi": 2.0}, surrogate=False), "line", 1.0, None)


def test_the_error_budget_is_offered_only_when_the_spec_names_it(tmp_path):
    from rig.stands.contact_law import LawCoefficients

    for budget in (False, True):
        spec = ContactSpec(model="kinematic", n=8, poisson=0.3, surrogate=True, table_points=(7, 7, 4),
                           error_budget=budget)
        law = make_contact_law(spec, "line", 1.0, DOMAIN, cache_directory=tmp_path)
        coefficients = LawCoefficients(law, DOMAIN)
        if not budget:
            assert coefficients.numerical_error is None
            continue
        error = coefficients.numerical_error(0.5, 0.2, 1.0)
        assert error.shape == (3,) and np.all(np.isfinite(error)) and np.all(error >= 0.0)
        assert 1e-5 < error[1] < 0.05  # an 8-cell table: a real but bounded error
