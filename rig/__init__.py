"""friction-rig: a virtual test rig of C. Koziarski's friction-wheel experiments.

Sub-packages: ``rig.contact`` (contact-force model, knows nothing of stands), ``rig.stands``
(the two test stands), ``rig.reduction`` (eqs. (29)-(36) of the main paper); instruments live
in the separate package ``sensors``.
"""

__version__ = "0.1.0"
