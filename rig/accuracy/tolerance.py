"""The stands' integrator tolerances, scaled for one study run (a stop-gap, see below).

The stands do not take their ODE tolerances as an input: they are module constants of each
stand's integration module (stand A: ``RTOL`` = 1e-5 while settling, ``RTOL_GATE`` = 1e-4 over
the gate, rig.stands.yoke.integration; stand B: ``RTOL`` = 1e-7, rig.stands.disc_roller.integration),
read when the integrator is called. Until a stand exposes them (requested from the lead: an
integrator-tolerance input of the stand, e.g. a field of the scene's ``[scene]`` table), the
study multiplies those relative tolerances by a factor for the duration of one run and restores
them afterwards. The absolute tolerances stay the stand's own. A factor of 1 touches nothing.
This is process-global state: use it only around a run that nothing else in the process shares
(the study runs its settings one after another, or in worker processes).
"""

from __future__ import annotations

import importlib
from collections.abc import Iterator
from contextlib import contextmanager

from rig import validate

RELATIVE_TOLERANCES = {
    "yoke": ("rig.stands.yoke.integration", ("RTOL", "RTOL_GATE")),
    "disc_roller": ("rig.stands.disc_roller.integration", ("RTOL",)),
}
"""stand key -> (module, names of its relative-tolerance constants [1])."""


def tolerances(stand: str) -> dict[str, float]:
    """The stand's relative integrator tolerances now {name: value [1]}."""
    validate.choice("stand", stand, RELATIVE_TOLERANCES)
    module_name, names = RELATIVE_TOLERANCES[stand]
    module = importlib.import_module(module_name)
    return {name: float(getattr(module, name)) for name in names}


@contextmanager
def scaled_tolerances(stand: str, factor: float) -> Iterator[dict[str, float]]:
    """Within the block, the stand's relative tolerances times ``factor`` [1] (in (0, 1e6]);
    yields the values in force. Restored on exit, also after an error."""
    validate.choice("stand", stand, RELATIVE_TOLERANCES)
    factor = validate.number("tolerance_factor", factor, 0.0, 1e6, lo_open=True)
    original = tolerances(stand)
    if factor == 1.0:
        yield original
        return
    module = importlib.import_module(RELATIVE_TOLERANCES[stand][0])
    try:
        for name, value in original.items():
            setattr(module, name, value * factor)
        yield tolerances(stand)
    finally:
        for name, value in original.items():
            setattr(module, name, value)
