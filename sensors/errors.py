"""Exceptions raised by the instrument package ``sensors``.

``sensors`` is a stand-alone package beside ``rig`` and does not import it, so it carries its own
small error type. :class:`InstrumentParameterError` is a :class:`ValueError` whose message names
the parameter, the value given and the valid range, like ``rig.errors.ParameterError``.
"""

from __future__ import annotations


class InstrumentParameterError(ValueError):
    """An instrument parameter or input is outside its valid range.

    Attributes ``name`` (the parameter), ``value`` (what was given) and ``valid`` (the valid
    range, in words) are kept for callers that want to re-raise with more context.
    """

    def __init__(self, name: str, value: object, valid: str, *, hint: str = "") -> None:
        self.name = name
        self.value = value
        self.valid = valid
        message = f"{name} = {value!r} is not valid; valid: {valid}"
        if hint:
            message += f" ({hint})"
        super().__init__(message)
