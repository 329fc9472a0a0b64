"""Effects a scene does not name are not built and never called (common brief: off = None)."""

from __future__ import annotations

from unittest import mock

import pytest

from rig.stands.disc_roller import instruments
from rig.stands.disc_roller.components import BearingFriction, ContactRelaxation, LoopCompliance
from rig.stands.disc_roller.swinging_drive import SwingingDrive
from sensors.noise import RandomWalkDrift, WhiteNoise
from tests.stands.disc_roller.conftest import make_stand, settings

PATCHED = [
    (BearingFriction, "disc"), (BearingFriction, "roller"), (ContactRelaxation, "rate"), (LoopCompliance, "torque"),
    (LoopCompliance, "deflection"), (SwingingDrive, "speed"), (WhiteNoise, "sample"), (RandomWalkDrift, "sample"),
]


def run_point(stand) -> None:
    stand.calibrate(5)
    point = stand.start_point(0, settings(), None, 5)
    point.settle(10.0)
    point.read(point.gate(0.2))


def test_no_effect_named_no_effect_called():
    stand = make_stand({})
    patches = [mock.patch.object(cls, name, side_effect=AssertionError(f"{cls.__name__}.{name} called"))
               for cls, name in PATCHED]
    rng = mock.patch.object(instruments, "effect_rng", side_effect=AssertionError("a random stream was drawn"))
    for p in patches + [rng]:
        p.start()
    try:
        run_point(stand)
    finally:
        mock.patch.stopall()


@pytest.mark.parametrize("effect, cls, name", [
    ({"bearing_friction": {}}, BearingFriction, "disc"),
    ({"loop_compliance": {}}, LoopCompliance, "torque"),
    ({"contact_relaxation": {}}, ContactRelaxation, "rate"),
    ({"recorder_noise": {}}, WhiteNoise, "sample"),
    ({"dynamometer_drift": {}}, RandomWalkDrift, "sample"),
])
def test_a_named_effect_is_called(effect, cls, name):
    stand = make_stand(effect)
    with mock.patch.object(cls, name, autospec=True, side_effect=getattr(cls, name)) as spy:
        run_point(stand)
    assert spy.call_count > 0


def test_weight_errors_only_when_named():
    calls = []
    real = instruments.effect_rng

    def spy(seed, instrument, effect):
        calls.append(effect)
        return real(seed, instrument, effect)

    with mock.patch.object(instruments, "effect_rng", side_effect=spy):
        make_stand({"recorder_noise": {}}).calibrate(1)
        assert "error" not in calls and "noise" in calls
        make_stand({"calibration_weight_errors": {}}).calibrate(1)
        assert calls.count("error") == 3
