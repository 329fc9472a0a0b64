"""Argument checks of the instruments: paramcheck's checks raising :class:`InstrumentParameterError`."""

from __future__ import annotations

from functools import partial

from paramcheck import validate as _checks
from sensors.errors import InstrumentParameterError

number = partial(_checks.number, error=InstrumentParameterError)
integer = partial(_checks.integer, error=InstrumentParameterError)
finite_array = partial(_checks.finite_array, error=InstrumentParameterError)
time_series = partial(_checks.time_series, error=InstrumentParameterError)
