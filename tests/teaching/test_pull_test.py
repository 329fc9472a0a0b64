"""The slowly increasing force ([Zhao] slides 13, 17): stick until mu_s N, drop to mu_k N, then slide."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rig.errors import ParameterError
from rig.teaching.coulomb import STANDARD_GRAVITY as G
from rig.teaching.pull_test import pull_test


def test_breakaway_and_drop():
    times = np.linspace(0.0, 12.0, 1201)
    trace = pull_test(2.0, 0.8, 0.6, 2.0, times)
    n = 2.0 * G
    assert trace.breakaway_time_s == pytest.approx(0.8 * n / 2.0)
    stick = times <= trace.breakaway_time_s
    np.testing.assert_allclose(trace.friction_N[stick], trace.pull_N[stick])  # T = F while at rest
    np.testing.assert_allclose(trace.friction_N[~stick], 0.6 * n)  # T = mu_k N while sliding
    assert np.all(trace.speed_m_s[stick] == 0.0)
    drop = trace.pull_N[~stick][0] - trace.friction_N[~stick][0]
    step = 2.0 * (times[1] - times[0])  # F grows by k dt between samples [N]
    assert (0.8 - 0.6) * n <= drop <= (0.8 - 0.6) * n + step


def test_speed_agrees_with_a_numerical_integration_of_newton():
    m, mu_s, mu_k, k = 3.0, 0.5, 0.2, 1.5
    trace = pull_test(m, mu_s, mu_k, k, np.array([0.0, 5.0, 11.0, 15.0]))
    t_star = trace.breakaway_time_s
    ode = solve_ivp(lambda t, v: [(k * t - mu_k * m * G) / m], (t_star, 15.0), [0.0], t_eval=[t_star, 11.0, 15.0],
                    rtol=1e-10, atol=1e-12)
    assert t_star == pytest.approx(mu_s * m * G / k)
    assert trace.speed_m_s[1] == 0.0  # 5 s < t* = 9.8 s
    np.testing.assert_allclose(trace.speed_m_s[2:], ode.y[0][1:], rtol=1e-8)


def test_equal_coefficients_give_no_drop():
    trace = pull_test(1.0, 0.4, 0.4, 1.0, np.linspace(0.0, 10.0, 101))
    assert np.all(np.diff(trace.friction_N) >= 0.0)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        (dict(mu_k=0.9), "mu_k"),
        (dict(force_rate=0.0), "force_rate"),
        (dict(mass=-1.0), "mass"),
        (dict(times=np.array([-1.0, 1.0])), "times"),
    ],
)
def test_bad_input(kwargs, name):
    args = dict(mass=1.0, mu_s=0.8, mu_k=0.6, force_rate=1.0, times=np.linspace(0, 1, 3)) | kwargs
    with pytest.raises(ParameterError) as info:
        pull_test(**args)
    assert info.value.name == name
