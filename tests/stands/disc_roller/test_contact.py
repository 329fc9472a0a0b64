"""Stand B's contact loads: the signed mapping against the shared wrapper, steady loads, hard cases."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.stands.base import ContactSpec
from rig.stands.contact_law import ContactLaw, ContactPatch, contact_forces, make_contact_law
from rig.stands.disc_roller.contact import ContactPoint
from rig.stands.disc_roller.parameters import resolve_parameters
from tests.stands.disc_roller.laws import smooth_law

P = resolve_parameters({})
A = P.half_length


class SmoothLaw(ContactLaw):
    """smooth_law as a ContactLaw, so that rig.stands.contact_law.contact_forces can use it."""

    def __init__(self) -> None:
        super().__init__("smooth", "line", 1.0, 0.5, 16, ())

    def _values(self, l, c, a):
        return np.array(smooth_law(l, c, a))

    def _with_derivatives(self, l, c, a):
        raise NotImplementedError


def point(law=smooth_law, load=36.0, l_set=0.01, c=3e-3, eps=0.01) -> ContactPoint:
    b_over_a = P.b_over_a(load)
    return ContactPoint(law=law, normal_force=load, mu=P.mu, a=A, b=b_over_a * A, alpha=P.alpha_prime(load),
                        alpha_max=4 * P.alpha_prime(load), l_set=l_set, c=c, radius_c=P.radius_c, spin_eps=eps,
                        l_limit=8.0)


def patch(load=36.0) -> ContactPatch:
    """The Hertz line contact of the stand (p0 = 2F/(pi b 2a), E = 2 E*, eqs. 21-23)."""
    b = P.b_over_a(load) * A
    return ContactPatch(P.mu, load, A, 2 * load / (math.pi * b * 2 * A), 2 * P.contact_modulus)


@settings(max_examples=60, deadline=None)
@given(v=st.floats(0.02, 0.5), sign_v=st.sampled_from([-1.0, 1.0]), sign_w=st.sampled_from([-1.0, 1.0]),
       creep=st.floats(-0.02, 0.02), c=st.floats(-8e-3, 8e-3), l_set=st.floats(-0.02, 0.02))
def test_loads_agree_with_the_shared_signed_wrapper(v, sign_v, sign_w, creep, c, l_set):
    """Every sign combination of (v, w0), against rig.stands.contact_law.contact_forces."""
    cp = point(l_set=l_set, c=c)
    speed = sign_v * v
    spin = sign_w * v * (1 + creep) / P.radius_c
    f_x, f_y, m_o = cp.loads(speed, spin)[:, 0]
    l = float(cp.rolling_point(speed, spin))
    if sign_v * sign_w < 0:  # the state maps to the canonical l' = -l (mirror y); it must lie in the domain
        l_canonical = -l
    else:
        l_canonical = l
    if abs(l_canonical) > 8 * A:
        return  # clipped by the stand (hard case 6): compared in test_far_rolling_point_is_clipped
    ref = contact_forces(SmoothLaw(), patch(), speed=speed, spin=spin, c=c, l=l)
    assert f_x == pytest.approx(ref.force_x_N, rel=1e-9, abs=1e-9)
    assert f_y == pytest.approx(ref.force_y_N, rel=1e-9, abs=1e-9)
    assert m_o == pytest.approx(ref.moment_O_N_m, rel=1e-9, abs=1e-12)


def test_steady_loads_forward_and_reverse():
    cp = point()
    w_d = P.roller_speed(1) / P.gear_ratio
    for direction in (1, -1):
        steady = cp.steady(direction)
        f_x, f_y, m_o = cp.loads(direction * w_d * P.radius_c, direction * w_d)[:, 0]
        assert (f_x, f_y, m_o) == pytest.approx((steady.force_x, steady.force_y, steady.moment_o), rel=1e-12)
        # canonical coefficients at (l_set, direction c): smooth_law directly
        nu_t, nu_v, nu_0 = smooth_law(0.01 / A, direction * 3e-3 / A, P.alpha_prime(36.0))
        scale = P.mu * 36.0
        assert steady.force_x == pytest.approx(direction * scale * nu_t)
        assert steady.force_y == pytest.approx(scale * nu_v)
        assert steady.moment_c == pytest.approx(-direction * scale * A * nu_0)
        assert steady.resisting_moment == pytest.approx(scale * A * nu_0)  # T0 >= 0 in both directions


def test_rigid_model_against_the_full_sliding_table():
    """Equations §1.10(a), line contact b/a = 1, l/a = 0.5, c = 0: nu_T = -0.44604, nu_0 = 0.82383."""
    law = make_contact_law(ContactSpec("rigid", 48, 0.5, surrogate=False), "line", 1.0, None)
    cp = point(law=law, l_set=0.5 * A, c=0.0)
    steady = cp.steady(1)
    assert steady.nu_T == pytest.approx(-0.44604, abs=2e-3)
    assert steady.nu_0 == pytest.approx(0.82383, abs=2e-3)
    reverse = cp.steady(-1)  # mirror x: F_x and M_C change sign, F_y = 0 stays
    assert reverse.force_x == pytest.approx(-steady.force_x)
    assert reverse.moment_c == pytest.approx(-steady.moment_c)


def test_roller_sliding_on_a_disc_at_rest_drags_it_forward_on_both_sides_of_zero():
    cp = point(c=0.0)
    v = 0.15
    loads = cp.loads(np.array([v, v, v]), np.array([1e-9, 0.0, -1e-9]))
    assert np.allclose(loads[0], loads[0, 0], rtol=1e-12)  # continuous through w_d = 0
    assert loads[0, 0] > 0.9 * P.mu * 36.0  # saturated, along the roller's motion
    assert np.allclose(loads[:, 0], loads[:, 2], rtol=1e-12, atol=1e-9)
    assert abs(loads[1, 1]) < 1e-6 and abs(loads[2, 1]) < 1e-6  # far field: F_y, M_O -> 0


def test_loads_vanish_at_rest_and_are_continuous_there():
    cp = point()
    tiny = np.array([0.0, 1e-12, 1e-9])
    loads = cp.loads(tiny * P.radius_c, tiny)
    assert np.all(np.isfinite(loads))
    assert np.all(np.abs(loads[:, 0]) == 0.0)
    assert np.all(np.abs(loads[:2]) < 1e-3 * P.mu * 36.0)


def test_far_rolling_point_is_clipped_with_saturated_force_and_decaying_moment():
    cp = point(c=0.0)
    w = 1.0
    at_limit, far = cp.loads(np.array([P.radius_c - 8 * A * 0.999, 5.0 * P.radius_c]) * w, np.array([w, w])).T
    alpha_far = 4 * P.alpha_prime(36.0)  # v/w0 = 5 R_c: alpha' clipped to the domain's upper end
    nu_t, _, _ = smooth_law(-8.0, 0.0, alpha_far)  # canonical l' = R_c - 5 R_c -> clipped to -8 a
    assert far[0] == pytest.approx(P.mu * 36.0 * nu_t, rel=1e-12)  # saturated force of the clip point
    l_far = abs(P.radius_c - 5.0 * P.radius_c) / A
    ratio = abs(far[2]) / abs(at_limit[2])
    assert 0.5 * 8.0 / l_far < ratio < 2.0 * 8.0 / l_far  # M_O decays like 1/|l| beyond the clip


@settings(max_examples=200, deadline=None)
@given(v=st.one_of(st.just(0.0), st.floats(-1.0, 1.0)), w=st.one_of(st.just(0.0), st.floats(-5.0, 5.0)),
       c=st.floats(-8e-3, 8e-3), l_set=st.floats(-0.025, 0.025))
def test_loads_are_finite_and_bounded_for_any_state(v, w, c, l_set):
    """Hard cases 6, 7: zero, reversing and mismatched speeds give finite, bounded loads."""
    cp = point(l_set=l_set, c=c)
    f_x, f_y, m_o = cp.loads(v, w)[:, 0]
    bound = P.mu * 36.0
    assert abs(f_x) <= bound and abs(f_y) <= bound * 1.1
    assert math.isfinite(m_o) and abs(m_o) <= bound * A * 12.0


@settings(max_examples=150, deadline=None)
@given(v=st.one_of(st.just(0.0), st.floats(-1.0, 1.0)), w=st.one_of(st.just(0.0), st.floats(-5.0, 5.0)),
       c=st.floats(-8e-3, 8e-3), l_set=st.floats(-0.025, 0.025))
def test_scalar_loads_equal_the_vectorised_loads(v, w, c, l_set):
    cp = point(l_set=l_set, c=c)
    assert cp.loads_one(v, w) == pytest.approx(tuple(cp.loads(v, w)[:, 0]), rel=1e-12, abs=1e-15)


def test_a_disc_at_rest_clamps_alpha_to_the_laws_domain_to_the_last_ulp():
    """alpha (alpha_max/alpha) exceeds alpha_max by an ulp for some pairs (this one: a lab session at
    36 N, mu = 0.755): the clamp must still keep alpha' inside the table's domain."""
    alpha, alpha_max = 20.08117838819283, 106.38724133097631
    assert alpha * (alpha_max / alpha) > alpha_max
    seen = []

    def law(l, c, a):
        seen.append(np.max(a))
        return smooth_law(l, c, a)

    contact = dataclasses.replace(point(law=law), alpha=alpha, alpha_max=alpha_max)
    contact.loads(np.array([0.5]), np.array([0.0]))  # roller moving, disc at rest: |v/w| = inf
    contact.loads_one(0.5, 0.0)
    assert seen and max(seen) <= alpha_max
