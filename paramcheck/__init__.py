"""Named errors and argument checks shared by ``rig`` and ``sensors``.

The one home both packages depend on (``sensors`` does not import ``rig``, and ``rig.contact``
does not import ``sensors``): :mod:`paramcheck.errors` holds the error types raised on purpose,
:mod:`paramcheck.validate` the checks that raise them with the parameter's name, the value given
and the valid range.
"""
