"""Rolling resistance ([Zhao] slides 32-36): u = f_v r, moment N u, power f_v N v, f_v = F/N."""

from __future__ import annotations

import pytest

from rig.errors import ParameterError
from rig.teaching.rolling_resistance import (
    ROLLING_COEFFICIENTS,
    coefficient_from_pull,
    dissipated_power,
    normal_reaction_shift,
    resisting_moment,
    steady_pull,
)


def test_worked_values():
    assert normal_reaction_shift(0.015, 0.3) == pytest.approx(4.5e-3)
    assert resisting_moment(3000.0, 0.015, 0.3) == pytest.approx(13.5)
    v, r = 20.0, 0.3
    assert dissipated_power(3000.0, 0.015, v) == pytest.approx(resisting_moment(3000.0, 0.015, r) * v / r)  # N u omega
    assert dissipated_power(3000.0, 0.015, v) == pytest.approx(900.0)
    assert coefficient_from_pull(steady_pull(3000.0, 0.004), 3000.0) == pytest.approx(0.004)


def test_slide_36_values():
    table = {c.pair: (c.low, c.high) for c in ROLLING_COEFFICIENTS}
    assert table == {"tyre-road": (1e-2, 2e-2), "steel-steel": (1e-3, 5e-3)}
    assert all("slide 36" in c.source for c in ROLLING_COEFFICIENTS)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: normal_reaction_shift(-0.01, 0.3), "f_v"),
        (lambda: normal_reaction_shift(0.01, 0.0), "radius"),
        (lambda: dissipated_power(10.0, 0.01, -1.0), "speed"),
        (lambda: coefficient_from_pull(1.0, 0.0), "normal_force"),
    ],
)
def test_bad_input(call, name):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == name
