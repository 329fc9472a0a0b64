"""Transient rolling (issue 6): steady limit, reversal and standstill, frictional work."""

from unittest import mock

import numpy as np
import pytest

from rig.contact import transient
from rig.contact.grid import make_grid
from rig.contact.kinematics import Creepage
from rig.contact.solve import solve
from rig.contact.transient import RollingPath, solve_transient
from rig.errors import ParameterError


@pytest.mark.parametrize(
    "shape, b, alpha, c, l, effects",
    [("ellipse", 1.0, 10.0, 0.0, 0.0, {}), ("line", 1.0, 25.0, 0.4, 0.5, {}), ("ellipse", 2.0, 5.0, 0.2, -0.3, {"psi": 2.0})],
)
def test_constant_rolling_reaches_the_steady_model_to_first_order(shape, b, alpha, c, l, effects):
    """The transient step carries the displacement by linear interpolation (first-order transport);
    the steady model's transport is of second order. At n = 16 they differ by at most 0.032
    (measured; nu_v, circle, alpha' = 10: transient 0.5705, steady 0.6023, the steady model's own
    converged value 0.6005); the difference halves with the cell size
    (test_constant_rolling_converges_at_first_order)."""
    result, steady = _transient_and_steady(shape, b, alpha, c, l, effects, 16)
    for name in ("nu_T", "nu_v", "nu_Mo"):
        got, want = getattr(result, name)[-1], getattr(steady, name)
        assert got == pytest.approx(want, abs=0.035), name


def _transient_and_steady(shape, b, alpha, c, l, effects, n):
    grid = make_grid(shape, b, n)
    path = RollingPath.rolling(Creepage.from_rolling_point(alpha, c, l, 0.28), np.full(4 * grid.nx, grid.hx))
    result = solve_transient(shape=shape, b_over_a=b, poisson=0.28, n=n, path=path, **effects)
    steady = solve("kinematic", shape=shape, b_over_a=b, alpha=alpha, c_over_a=c, l_over_a=l, poisson=0.28, n=n, **effects)
    return result, steady


def test_constant_rolling_converges_at_first_order():
    """Circle, pure spin, alpha' = 10: |nu_v(transient) - nu_v(steady)| at n = 12 and 24 falls by a
    factor >= 1.6 (first order: 2; measured 0.0287 -> 0.0136 from n = 16 to 32)."""
    gaps = []
    for n in (12, 24):
        result, steady = _transient_and_steady("ellipse", 1.0, 10.0, 0.0, 0.0, {}, n)
        gaps.append(abs(result.nu_v[-1] - steady.nu_v))
    assert gaps[0] > 1.6 * gaps[1] > 0.0, gaps


def test_reversed_rolling_reaches_the_mirrored_steady_state():
    """Rolling and spin reversed together = the x-mirror of forward rolling with c -> -c:
    nu_T changes sign, nu_v does not (docs/contact-model.md, transient section)."""
    n, c, l = 12, 0.2, 0.3
    grid = make_grid("line", 1.0, n)
    creepage = Creepage.from_rolling_point(20.0, c, l, 0.5)
    distances = np.concatenate([np.full(3 * grid.nx, grid.hx), np.zeros(5), np.full(4 * grid.nx, -grid.hx)])
    r = solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=n, path=RollingPath.rolling(creepage, distances))
    mirrored = solve("kinematic", shape="line", b_over_a=1.0, alpha=20.0, c_over_a=-c, l_over_a=l, poisson=0.5, n=n)
    assert r.nu_T[-1] == pytest.approx(-mirrored.nu_T, abs=0.03)  # first- vs second-order transport
    assert r.nu_v[-1] == pytest.approx(mirrored.nu_v, abs=0.03)
    standstill = slice(3 * grid.nx, 3 * grid.nx + 5)
    assert np.ptp(r.nu_T[standstill]) < 1e-9 and np.ptp(r.nu_v[standstill]) < 1e-9, "nothing moves at standstill"


def test_tiny_strokes_and_vanishing_steps_stay_finite():
    grid = make_grid("line", 1.0, 12)
    creepage = Creepage.from_rolling_point(20.0, 0.2, 0.3, 0.5)
    distances = np.concatenate([np.full(3, 1e-12), np.full(5, -1e-9), np.full(4, grid.hx / 3)])
    r = solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=12, path=RollingPath.rolling(creepage, distances))
    values = np.stack([r.nu_T, r.nu_v, r.nu_Mo, r.stick_fraction])
    assert np.all(np.isfinite(values)) and np.all(np.abs(values[:2]) <= 1 + 1e-9)
    tiny = solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=12, frictional_work=True,
                           path=RollingPath.oscillation(creepage, stroke=1e-6, cycles=1, step=grid.hx))
    assert np.all(np.isfinite(tiny.work.work)) and tiny.work.work.max() < 1e-6


def test_a_step_longer_than_a_cell_and_unknown_effects_are_named_errors():
    grid = make_grid("line", 1.0, 12)
    creepage = Creepage(0.0, 0.0, 1.0)
    with pytest.raises(ParameterError, match=r"path.distance\[1\]"):
        solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=12,
                        path=RollingPath.rolling(creepage, [grid.hx, 2 * grid.hx]))
    with pytest.raises(ParameterError, match="did you mean 'psi'"):
        solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=12, path=RollingPath.rolling(creepage, [0.0]), pis=2)
    with pytest.raises(ParameterError, match="inertia_number"):
        solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=12, path=RollingPath.rolling(creepage, [0.0]),
                        inertia_number=0.1)


def test_frictional_work_off_is_not_computed():
    grid = make_grid("line", 1.0, 12)
    path = RollingPath.rolling(Creepage(0.0, 0.0, 1.0), np.full(10, grid.hx))
    with mock.patch.object(transient._WorkAccumulator, "add") as add:
        r = solve_transient(shape="line", b_over_a=1.0, poisson=0.5, n=12, path=path)
    add.assert_not_called()
    assert r.work is None
