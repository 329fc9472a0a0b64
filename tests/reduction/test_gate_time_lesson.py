"""rig.teaching.gate_time (the lesson of docs/measurement-method.md; experiments/gate_time.py runs it) on short gates with the rigid law.

Independent numbers: the counting resolution of Equations §2, u(l) = |dl/di_k| u(i_k) with
u(i_k)/i_k = u_N sqrt(1/N1^2 + 1/N2^2), u_N = 1/sqrt(6) (counters' quantisation, docs/instruments.md),
falls as 1/T; u(mu_T) cannot fall below the pressing force's share mu u(F_N)/F_N (eq. 35 is
proportional to 1/F_N).
"""

from __future__ import annotations

import math

import pytest

from rig.teaching import gate_time
from rig.wheel_kinematics import dl_dratio


@pytest.fixture(scope="module")
def lesson():
    return gate_time


@pytest.fixture(scope="module")
def short_run(lesson, tmp_path_factory):
    out = tmp_path_factory.mktemp("gate_time")
    text, frame = lesson.run(out, lesson.MODELS["rigid"], gates=(2.0, 8.0))
    return out, text, frame


def test_the_script_writes_its_three_outputs(short_run):
    out, text, frame = short_run
    assert {p.name for p in out.iterdir()} == {"walkthrough.md", "gate_time.csv", "gate_time.png"}
    assert list(frame["gate_time_s"]) == [2.0, 8.0]
    assert "| (35) | mu_T |" in text and "tangent balance (scale step)" in text


def test_u_of_l_over_a_is_the_counting_resolution_and_falls_as_1_over_t(lesson, short_run):
    _, _, frame = short_run
    stand = lesson.make_stand(lesson.MODELS["rigid"])
    g = stand.params.geometry
    for _, row in frame.iterrows():
        m = lesson.measure(stand, row["gate_time_s"])
        n1, n2 = m.readings.counts_1, m.readings.counts_2
        i_k = n2 / n1
        u_l = abs(dl_dratio(i_k, g.alpha_1, g.l1, g.l2)) * i_k * math.sqrt(1 / n1**2 + 1 / n2**2) / math.sqrt(6)
        assert row["u_l_over_a"] == pytest.approx(u_l / g.a, rel=0.01)
    ratio = frame["u_l_over_a"].iloc[0] / frame["u_l_over_a"].iloc[1]
    assert ratio == pytest.approx(8.0 / 2.0, rel=0.02)


def test_u_of_mu_t_has_a_floor_that_no_gate_removes(lesson, short_run):
    _, _, frame = short_run
    f_n, u_f_n = lesson.SETTINGS["normal_force_N"], 0.5  # normal_force_u_N of stand A
    floor = frame["mu_T"].to_numpy() * u_f_n / f_n  # ~0.4 x 0.5/96.2 = 0.0021: mu_T ~ 1/F_N (eq. 35)
    assert frame["u_mu_T_from_pressing_force"].to_numpy() == pytest.approx(floor, rel=1e-3)
    assert all(frame["u_mu_T"] > floor)
