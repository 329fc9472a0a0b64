"""Reduction of the measurements, eqs. (29)-(36) of [Koziarski] with uncertainties (docs/reduction.md).

Modules: ``equations`` (pure functions of eqs. 21, 29-36; the kinematics come from
rig.wheel_kinematics), ``geometry`` (stand constants with provenance), ``readings`` (measured
inputs; the mean of an instrument's readings with its resolution and noise), ``coefficients`` (the
contact-model callable and its domain error), ``uncertainty`` (first-order and Monte-Carlo
propagation), ``coverage`` (the 95 % half width U95), ``budget`` (per-input variance terms),
``iteration`` (mu <-> alpha' fixed point and settings), ``drivers`` (which estimate drives alpha'),
``result`` (evaluate, propagate, guard, budget), ``stand_a`` and ``stand_b`` (the per-stand
chains), ``table`` (the reduced table).
"""

__all__ = ["budget", "coefficients", "coverage", "drivers", "equations", "geometry", "iteration", "readings", "result",
           "stand_a", "stand_b", "table", "uncertainty"]
