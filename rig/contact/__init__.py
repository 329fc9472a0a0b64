"""Contact-force model of [Koziarski], section 2 (knows nothing of test stands).

``solve(model, ...)`` returns a :class:`ContactResult` for the models "rigid", "linear",
"fastsim" and "kinematic"; ``solve_creepage`` states the same problem in creepages (zero spin
included). See rig.contact.solve.
"""

from rig.contact.result import ContactResult
from rig.contact.solve import solve, solve_creepage

__all__ = ["ContactResult", "solve", "solve_creepage"]
