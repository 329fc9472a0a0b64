"""Scaled integrator tolerances: applied for one block, restored after it, untouched at factor 1."""

from __future__ import annotations

from types import SimpleNamespace
from unittest import mock

import numpy as np
import pytest

from rig.accuracy.tolerance import scaled_tolerances, tolerances
from rig.errors import ParameterError, UnknownNameError
from rig.stands.yoke import integration


def test_yoke_tolerances_are_scaled_in_the_block_and_restored():
    before = tolerances("yoke")
    assert before == {"RTOL": 1e-5, "RTOL_GATE": 1e-4}  # rig.stands.yoke.integration (stand A)
    with scaled_tolerances("yoke", 10.0) as now:
        assert now == pytest.approx({"RTOL": 1e-4, "RTOL_GATE": 1e-3}, rel=1e-12)
        assert integration.RTOL == pytest.approx(1e-4)
    assert tolerances("yoke") == before


def test_restored_after_an_error():
    with pytest.raises(RuntimeError), scaled_tolerances("disc_roller", 0.1):
        raise RuntimeError("inside")
    assert tolerances("disc_roller") == {"RTOL": 1e-7}


def test_factor_one_touches_nothing():
    with mock.patch("rig.accuracy.tolerance.setattr", create=True) as patched, scaled_tolerances("yoke", 1.0):
        pass
    patched.assert_not_called()


def test_the_integrator_receives_the_scaled_tolerance():
    seen = {}

    class Stop(Exception):
        pass

    def fake_radau(*args, rtol, **kwargs):
        seen["rtol"] = rtol
        raise Stop

    train = SimpleNamespace(rhs=None, jacobian=None, names=["psi_1", "psi_2", "omega_2"])
    target = integration.Target(1.0, 1.0, 0.0, 1.0)
    with mock.patch.object(integration, "Radau", fake_radau), scaled_tolerances("yoke", 0.1):
        with pytest.raises(Stop):
            integration.settle(train, np.zeros(3), target, 1.0)
    assert seen["rtol"] == pytest.approx(1e-6)


def test_bad_input_is_named():
    with pytest.raises(UnknownNameError, match="stand"):
        tolerances("yokee")
    with pytest.raises(ParameterError, match="tolerance_factor"):
        with scaled_tolerances("yoke", 0.0):
            pass
