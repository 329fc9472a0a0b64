"""Contact-force model of seed 000, section 2 (knows nothing of test stands).

``solve(model, ...)`` returns a :class:`ContactResult` for the models "rigid", "linear",
"fastsim" and "kinematic"; see rig.contact.solve.
"""
