"""Stand B of [Koziarski] (Figs. 12-13, section 3.2): the disc-roller stand as a digital twin.

A PMMA disc 1 on the vertical shaft 3 is rolled on by the rubber-lined roller 2 (d = 125 mm,
2a = 8 mm) at the rolling-point radius R_c = 166.3 mm. The roller shaft 16 is driven by the
motor 23 through the worm gear 22 (self-locking: assumed, the seed does not say), and the
disc is driven from the same shaft through the gear loop 17/13/11, the clutch 9 and the
momentometer 8, with the fixed ratio R_c/R_r = 2.661: the rolling point is kinematic and l is
set by the screw 19, c by the twist screw 15 (eq. 36). Dead weights load the contact (9, 21,
36, 144 N); dynamometers 5 read F_T and F_V on the disc bearing 4, the momentometer the torque
T_Mo in the disc shaft.

Modules: ``parameters`` (the one place for constants, effects and settings), ``contact``
(the contact loads on the disc from the drive-train state, signed and regularised),
``drive_train`` (the ODE), ``swinging_drive`` (the earlier oscillating drive),
``steady_state`` (quasi-static operating point), ``instruments`` (dynamometers 5,
momentometer 8, recorder, calibrations), ``stand`` (DiscRollerStand), ``reduction`` (log ->
rig.reduction.stand_b). Sign conventions: docs/stand-b.md and ``contact``.
"""
