"""A teacher's exercises for a class: the file, each student's hidden values, the grade book.

The teacher's file (TOML; example: rig/lab/examples/class.toml, described in docs/lab.md):

    title = "..."
    [[exercise]]
    id = "A1"                          # unique, letters/digits/-/_
    title = "..."
    stand = "yoke"                     # stand A; "disc_roller": stand B
    mu = [0.30, 0.50]                  # the hidden mu is drawn uniformly in this range [1]
                                       # (stand B: within [0.5, 1.0], the lab's contact tables)
    free = ["brake_setpoint_N_m"]      # controls the student may change
    [exercise.start]                   # settings of the stand when the exercise opens (SI)
    normal_force_N = 96.2
    [exercise.effects.bearing_friction]   # hidden effects besides the lab's own (parameters optional)

A student's instance draws mu and the run seed from SHA-256 of (exercise id, student id): the same
student always meets the same stand, two students (almost surely) different ones. The hidden
values stay on the server until the student submits. The grade book keeps every submitted value
with the twin's reduced value, its tolerance (rig.lab.sheet), the truth and pass/fail; it is
exported as CSV.
"""

from __future__ import annotations

import csv
import hashlib
import io
import os
import re
import threading
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from rig import validate
from rig.errors import ParameterError
from rig.lab.session import LAB_MU_RANGE_B, SESSIONS
from rig.stands.disc_roller.stand import DiscRollerStand
from rig.stands.yoke.stand import YokeStand

FILE_KEYS = ("title", "exercise")
EXERCISE_KEYS = ("id", "title", "stand", "mu", "free", "start", "effects")
STANDS = {"yoke": YokeStand, "disc_roller": DiscRollerStand}
"""Stands the lab operates: A (yoke) and B (disc_roller)."""
MU_RANGE = {"yoke": (YokeStand.PARAMETERS["mu"].lo, YokeStand.PARAMETERS["mu"].hi), "disc_roller": LAB_MU_RANGE_B}
"""Where an exercise's hidden mu may lie, per stand [1] (stand B: the lab's contact tables)."""
ID_PATTERN = re.compile(r"[A-Za-z0-9_-]{1,64}")
GRADE_COLUMNS = ("student", "exercise", "point", "quantity", "submitted", "reduced", "tolerance", "true", "pass")


@dataclass(frozen=True)
class Exercise:
    """One exercise: id, title, stand, the range of the hidden mu [1], free controls, start settings
    (SI) and the effects {name: {parameter: value}} (the lab's plus the teacher's)."""

    id: str
    title: str
    stand: str
    mu_range: tuple[float, float]
    free: tuple[str, ...]
    start: Mapping[str, float]
    effects: Mapping[str, Mapping[str, float]] = field(default_factory=dict)

    def draw(self, student: str) -> tuple[float, int]:
        """(mu [1], run seed) of ``student``'s instance: reproducible from (exercise id, student id)."""
        digest = hashlib.sha256(f"{self.id}\0{student}".encode()).digest()
        u = int.from_bytes(digest[:8], "big") / 2.0**64
        lo, hi = self.mu_range
        return lo + (hi - lo) * u, int.from_bytes(digest[8:15], "big")

    def public(self) -> dict:
        """What the page may know before submission (no mu, no effects)."""
        return {"id": self.id, "title": self.title, "stand": self.stand, "free": list(self.free),
                "start": dict(self.start)}


def student_id(value: object) -> str:
    """A student id: 1-64 letters, digits, '-' or '_' (it names rows of the grade book)."""
    if not isinstance(value, str) or not ID_PATTERN.fullmatch(value):
        raise ParameterError("student", value, "1-64 letters, digits, '-' or '_'")
    return value


def _exercise(entry: object, where: str) -> Exercise:
    if not isinstance(entry, dict):
        raise ParameterError(where, entry, "a table [[exercise]]")
    validate.known_keys(f"{where} key", entry, EXERCISE_KEYS)
    for key in ("id", "title", "stand", "mu", "free"):
        if key not in entry:
            raise ParameterError(f"{where}.{key}", "missing", "given (see docs/lab.md)")
    ident = entry["id"]
    if not isinstance(ident, str) or not ID_PATTERN.fullmatch(ident):
        raise ParameterError(f"{where}.id", ident, "1-64 letters, digits, '-' or '_'")
    stand = validate.choice(f"{where}.stand", entry["stand"], STANDS)
    session = SESSIONS[stand]
    mu = entry["mu"]
    if not isinstance(mu, list) or len(mu) != 2:
        raise ParameterError(f"{where}.mu", mu, "[lo, hi]: the range of the hidden mu")
    lo = validate.number(f"{where}.mu[0]", mu[0], *MU_RANGE[stand])
    hi = validate.number(f"{where}.mu[1]", mu[1], lo, MU_RANGE[stand][1])
    free = entry["free"]
    if not isinstance(free, list) or not all(isinstance(name, str) for name in free):
        raise ParameterError(f"{where}.free", free, "a list of control names")
    settings = STANDS[stand].SETTINGS
    validate.known_keys(f"{where}.free control", free, settings)
    start = entry.get("start", {})
    if not isinstance(start, dict):
        raise ParameterError(f"{where}.start", start, "a table [exercise.start] of settings")
    validate.known_keys(f"{where}.start setting", start, settings)
    start = session.check_controls(start, f"{where}.start")
    extra = entry.get("effects", {})
    if not isinstance(extra, dict) or not all(isinstance(v, dict) for v in extra.values()):
        raise ParameterError(f"{where}.effects", extra, "tables [exercise.effects.<name>]")
    effects = STANDS[stand].resolve_effects(dict(session.EFFECTS) | extra)
    title = entry["title"]
    if not isinstance(title, str):
        raise ParameterError(f"{where}.title", title, "a string")
    return Exercise(ident, title, stand, (lo, hi), tuple(free), start, effects)


@dataclass(frozen=True)
class ClassFile:
    """A teacher's file: its title and the exercises by id."""

    title: str
    exercises: Mapping[str, Exercise]

    @classmethod
    def load(cls, path: Path) -> ClassFile:
        """Read and check a teacher's file (named errors naming the key)."""
        try:
            data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
        except (OSError, tomllib.TOMLDecodeError) as error:
            raise ParameterError("exercises", str(path), f"a readable TOML file ({error})") from None
        validate.known_keys("exercise file key", data, FILE_KEYS)
        entries = data.get("exercise", [])
        if not isinstance(entries, list) or not entries:
            raise ParameterError("exercise", entries, "at least one [[exercise]] table")
        exercises = {}
        for k, entry in enumerate(entries):
            exercise = _exercise(entry, f"exercise[{k}]")
            if exercise.id in exercises:
                raise ParameterError(f"exercise[{k}].id", exercise.id, "an id not used by another exercise")
            exercises[exercise.id] = exercise
        return cls(str(data.get("title", Path(path).stem)), exercises)

    def get(self, ident: object) -> Exercise:
        validate.choice("exercise", ident, self.exercises)
        return self.exercises[ident]


class GradeBook:
    """Every submitted value of every student (thread-safe); a resubmission replaces the earlier one.
    With a ``path``, the CSV is rewritten there after every submission (temporary file + rename), so
    the grades outlive the server; a restarted server reads it back and keeps adding to it."""

    def __init__(self, path: Path | None = None) -> None:
        self.path = path
        self._rows: dict[tuple[str, str], list[dict]] = {}
        self._lock = threading.Lock()
        if path is not None and path.is_file():
            try:
                with open(path, newline="", encoding="utf-8") as handle:
                    for row in csv.DictReader(handle):
                        self._rows.setdefault((row["student"], row["exercise"]), []).append(row)
            except (OSError, KeyError, csv.Error) as error:
                raise ParameterError("grades", str(path), f"a grade book this lab wrote ({error})") from None

    def submit(self, student: str, exercise: str, rows: list[dict]) -> None:
        with self._lock:
            self._rows[(student, exercise)] = [dict(student=student, exercise=exercise) | row for row in rows]
        if self.path is not None:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}-{threading.get_ident()}.tmp")
            tmp.write_text(self.csv(), encoding="utf-8")
            os.replace(tmp, self.path)

    def csv(self) -> str:
        """The grade book as CSV (columns GRADE_COLUMNS), sorted by student, exercise, point."""
        out = io.StringIO()
        writer = csv.DictWriter(out, fieldnames=GRADE_COLUMNS, lineterminator="\n")
        writer.writeheader()
        with self._lock:
            for key in sorted(self._rows):
                writer.writerows(self._rows[key])
        return out.getvalue()
