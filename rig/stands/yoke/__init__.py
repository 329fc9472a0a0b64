"""Stand A of [Koziarski] (the yoke/spring stand, Figs. 8-9): ``rig.stands.yoke.stand.YokeStand``.

Modules: parameters (every parameter, effect and setting with its source), contact_forces (the
contact at the instantaneous wheel speeds), drive_train (the ODE), brake (feedback loop and its
stability limit), steady_state (quasi-static operating point), integration (implicit solver,
settle detection, gate), instruments (sensors chain), point (one operating point), laws (contact
laws and their domain), reduction (log -> eqs. 29-35), stand (the Stand). See docs/stand-a.md.
"""
