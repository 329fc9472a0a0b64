"""Reduction of the measurements, eqs. (29)-(36) of seed 000 with uncertainties (docs/reduction.md).

Modules: ``equations`` (pure functions of eqs. 21, 29-36; the kinematics come from
rig.wheel_kinematics), ``geometry`` (stand constants with provenance), ``readings`` (measured
inputs), ``uncertainty`` (first-order and Monte-Carlo propagation), ``budget`` (per-input
variance terms), ``iteration`` (mu <-> alpha' fixed point and settings), ``stand_a`` and
``stand_b`` (the per-stand chains), ``table`` (the reduced table).
"""
