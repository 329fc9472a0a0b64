"""Where the time goes: a stack sampler that attributes a run's CPU time to parts of the rig.

How (and why not cProfile): a background thread looks at the profiled thread's Python stack every
INTERVAL_S (sys._current_frames) and files the sample under the highest-priority Part found
anywhere on the stack, by module name (``classify_stack``). So numpy or scipy code counts for
the part that called it (a contact solve's array work is a contact solve), and a contact-law
call made by the ODE or by the reduction counts as contact. Each sample is weighted by the CPU
time the profiled thread used since the previous sample (its own CPU clock,
time.pthread_getcpuclockid), so time spent waiting (disk, sleep) weighs nothing; where that clock
does not exist, every sample weighs the same (wall-clock sampling). cProfile was not used: its
per-call overhead (~1 us) inflates the Python-call-heavy parts (a table look-up costs ~15 us) and
its caller graph is one level deep, so time in numpy cannot be attributed to the part that called
it. The sampler costs one short look at the stack per sample (while Python code runs, at most one
per GIL switch, ~5 ms); its result is a share per part, which the study applies to the median
CPU time of the timed runs. The profiled run is not one of the timed repeats.
"""

from __future__ import annotations

import enum
import re
import sys
import threading
import time
from collections.abc import Iterable
from dataclasses import dataclass
from types import FrameType

from rig.errors import ParameterError

INTERVAL_S = 0.001  # time between two samples [s] (at most one per GIL switch, ~5 ms, while Python runs)


class Part(enum.Enum):
    """A part of the rig a sample is filed under (listed in priority order, highest first)."""

    TABLE = "contact table build / load"
    CONTACT = "contact solves and table look-ups"
    INSTRUMENTS = "instruments"
    IO = "I/O (log, HDF5, CSV)"
    REDUCTION = "reduction"
    DRIVE = "drive train (ODE, steady state)"
    OTHER = "other (operator, set-up)"


RULES: tuple[tuple[Part, re.Pattern], ...] = (
    (Part.TABLE, re.compile(r"rig\.contact\.surrogate_cache$")),
    (Part.CONTACT, re.compile(r"rig\.contact(\..*)?$|rig\.stands\.contact_law$"
                              r"|rig\.stands\.yoke\.(contact_forces|laws)$|rig\.stands\.disc_roller\.contact$")),
    (Part.INSTRUMENTS, re.compile(r"sensors(\..*)?$|rig\.stands\.\w+\.instruments$")),
    (Part.IO, re.compile(r"rig\.logbook(\..*)?$|h5py(\..*)?$|pandas\.io(\..*)?$")),
    (Part.REDUCTION, re.compile(r"rig\.reduction(\..*)?$|rig\.stands\.\w+\.reduction$|rig\.runner\.reduction$")),
    (Part.DRIVE, re.compile(r"scipy\.integrate(\..*)?$|rig\.stands\.\w+\.(drive_train|integration|steady_state|brake"
                            r"|point|simulation|components|swinging_drive)$")),
)
"""Module-name rules, in priority order; a module matching none is OTHER."""
PRIORITY = {part: rank for rank, part in enumerate(Part)}


def categorize(module: str) -> Part:
    """The Part a module name belongs to (OTHER when no rule matches)."""
    for part, pattern in RULES:
        if pattern.match(module):
            return part
    return Part.OTHER


def classify_stack(modules: Iterable[str]) -> Part:
    """The highest-priority Part among the modules of one stack's frames (OTHER if none)."""
    best = Part.OTHER
    for module in modules:
        part = categorize(module)
        if PRIORITY[part] < PRIORITY[best]:
            best = part
    return best


def _stack_modules(frame: FrameType | None) -> list[str]:
    modules = []
    while frame is not None:
        modules.append(frame.f_globals.get("__name__", ""))
        frame = frame.f_back
    return modules


@dataclass(frozen=True)
class Profile:
    """Weight per Part (CPU seconds of the profiled thread, or sample counts without a thread CPU
    clock), the number of samples, and whether the weights are CPU time."""

    weights: dict[Part, float]
    samples: int
    cpu_weighted: bool

    def fractions(self) -> dict[Part, float]:
        """Share per Part [1] (every Part, zero when unseen; an empty profile gives all zero)."""
        total = sum(self.weights.values())
        return {part: (self.weights.get(part, 0.0) / total if total > 0 else 0.0) for part in Part}


def _thread_cpu_clock(ident: int):
    """A function returning the CPU time [s] of thread ``ident``, or None where there is none."""
    try:
        clock = time.pthread_getcpuclockid(ident)
        time.clock_gettime(clock)
    except (AttributeError, OSError):
        return None
    return lambda: time.clock_gettime(clock)


class StackSampler:
    """Context manager: samples the stack of the thread that enters it until it exits.

    ``with StackSampler() as sampler: work()`` then ``sampler.profile()``. interval_s: time
    between samples [s] (> 0).
    """

    def __init__(self, interval_s: float = INTERVAL_S) -> None:
        if not interval_s > 0.0:
            raise ParameterError("interval_s", interval_s, "(0, inf) s")
        self.interval_s = interval_s
        self._weights: dict[Part, float] = {}
        self._samples = 0
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._target = 0
        self._clock = None

    def _run(self) -> None:
        last = self._clock() if self._clock is not None else 0.0
        while not self._stop.is_set():
            frame = sys._current_frames().get(self._target)
            if frame is not None:
                part = classify_stack(_stack_modules(frame))
                if self._clock is None:
                    weight = 1.0
                else:
                    now = self._clock()
                    weight, last = now - last, now
                self._weights[part] = self._weights.get(part, 0.0) + weight
                self._samples += 1
            del frame
            time.sleep(self.interval_s)

    def __enter__(self) -> StackSampler:
        self._target = threading.get_ident()
        self._clock = _thread_cpu_clock(self._target)
        self._thread = threading.Thread(target=self._run, name="rig-accuracy-sampler", daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()

    def profile(self) -> Profile:
        """The samples taken so far."""
        return Profile(dict(self._weights), self._samples, self._clock is not None)
