"""The virtual lab (``rig lab``): stand A operated from a web page, over the same rig.stands code.

The server (rig.lab.app, Flask) is thin: it validates requests (rig.lab.requests) and calls a
:class:`rig.lab.session.LabSession`, which builds the stand from a scene text exactly as
``rig run`` does, steps it point by point (settle -> gate -> read), reduces the recorded points
with the stand's own ``reduce_log`` and saves them as a ``log.h5`` through rig.logbook's writer.
The lab sheet's checks are in rig.lab.sheet, the teacher's exercises and grades in
rig.lab.exercises. The page (``static/``) only draws what the server sends. docs/lab.md.
"""
