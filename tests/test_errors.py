"""Errors keep their type, message and attributes across processes (pickling)."""

import pickle

import pytest

from rig.errors import ConvergenceError, LogFormatError, ParameterError, UnknownNameError
from rig.stands.base import SettleTimeoutError


@pytest.mark.parametrize(
    "error",
    [
        ParameterError("alpha", -1.0, "[0, inf]", hint="a hint"),
        UnknownNameError("model", "kinematc", ["rigid", "kinematic"]),
        ConvergenceError("did not converge"),
        LogFormatError("log.h5: truncated"),
        SettleTimeoutError({"brake_setpoint_N_m": 1.0}, 5.0, 0.3, "|d omega/dt|"),
    ],
)
def test_errors_survive_pickling(error):
    copy = pickle.loads(pickle.dumps(error))
    assert type(copy) is type(error) and str(copy) == str(error)
    assert copy.__dict__ == error.__dict__
    assert isinstance(copy, ValueError) == isinstance(error, ValueError)


def test_unknown_name_suggests_the_closest_and_lists_the_choices():
    error = UnknownNameError("shape", "elipse", ["ellipse", "line"])
    assert "did you mean 'ellipse'?" in str(error) and "ellipse, line" in str(error)
    assert error.name == "shape" and error.value == "elipse" and error.choices == ["ellipse", "line"]
