"""Stroboscope disc (stand A's discs 13 and 14): which instants a mark passes the light path.

A disc on a wheel carries ``marks`` equally spaced marks; mark k sits at the wheel angle
phase + 2 pi k/marks, where the wheel angle theta is measured from the photocell's light path
(so ``phase_rad`` is where mark 0 is when theta = 0). In the mark coordinate
u = (theta - phase) marks/(2 pi), a mark crosses the light path whenever u passes an integer -
in either direction, so a reversing wheel produces a pulse at each crossing and a stalled
wheel produces none.

The true angle trajectory comes as samples (t [s], theta [rad]) and is taken as linear between
samples; crossing k of segment i happens where floor(u) changes, at the interpolated instant
t_i + (n - u_i)/(u_{i+1} - u_i) (t_{i+1} - t_i). Computed for all segments at once (numpy).
Touching an integer and turning back counts as two crossings (the mark entered the light path
and left it again): exact reversal points on a mark have measure zero in a simulation. A mark
lying exactly at the first sample is not seen (its crossing happened before the samples began).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sensors import validate

DEFAULT_MARKS = 60
"""Marks per disc [1] (assumed, Equations §2: 60 marks at 240 rpm give 240 pulses/s; the paper
does not give the number)."""


@dataclass(frozen=True)
class StrobeDisc:
    """A stroboscope disc: number of marks [1] and the angle of mark 0 [rad]."""

    marks: int = DEFAULT_MARKS
    phase_rad: float = 0.0

    def __post_init__(self) -> None:
        validate.integer("marks", self.marks, 1, 100_000)
        validate.number("phase_rad", self.phase_rad, -1.0e6, 1.0e6)

    def mark_coordinate(self, theta_rad: np.ndarray) -> np.ndarray:
        """u = (theta - phase) marks/(2 pi) [1]: integer values are marks on the light path."""
        return (np.asarray(theta_rad, dtype=float) - self.phase_rad) * (self.marks / (2.0 * np.pi))

    def crossing_times(self, t_s: np.ndarray, theta_rad: np.ndarray) -> np.ndarray:
        """Sorted instants [s] at which a mark crosses the light path, for samples (t [s], theta [rad])."""
        t, theta = validate.time_series("t_s", t_s, "theta_rad", theta_rad)
        u = self.mark_coordinate(theta)
        k = np.floor(u)
        dk = np.diff(k)
        n_per_segment = np.abs(dk).astype(np.int64)
        total = int(n_per_segment.sum())
        seg = np.repeat(np.arange(dk.size), n_per_segment)
        first = np.cumsum(n_per_segment) - n_per_segment
        j = np.arange(total) - np.repeat(first, n_per_segment)
        forward = dk[seg] > 0
        n = np.where(forward, k[seg] + 1.0 + j, k[seg] - j)
        u0, u1 = u[seg], u[seg + 1]
        frac = (n - u0) / (u1 - u0)
        times = t[seg] + frac * (t[seg + 1] - t[seg])
        if u[0] == k[0] and u[1] > u[0]:  # a mark in the light path at the first sample, moving on: it crosses there
            times = np.concatenate([t[:1], times])
        return times
