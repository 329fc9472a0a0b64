"""A teacher's exercises for a class: the file, each student's hidden values, the grade book.

The teacher's file (TOML; example: rig/lab/examples/class.toml, described in docs/lab.md):

    title = "..."
    [class]
    students = ["s1001", "s1002"]      # ids that get a token each (state folder, tokens.csv), and/or
    join_code = "..."                  # a code with which a student joins under an id of their own
    deadline = 2026-12-01T12:00:00Z    # default of every exercise (UTC; none: no deadline)
    attempts = 2                       # submissions counted per exercise; the last one is final
    checks = 3                         # Checks per exercise before submitting (0: no Check)
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
    [exercise.tolerance]               # per quantity: relative and/or absolute (default: rig.lab.sheet)
    mu_v = {relative = 0.02}
    mu_T = {relative = 0.01, uncertainty = 1.0}   # or within 1 x the U95 the student states
    # deadline, attempts, checks: as in [class], for this exercise; min_gate_s: shortest gate [s]

A student's instance draws mu and the run seed from HMAC-SHA-256 of (exercise id, student id)
keyed with the class's secret (kept in the state folder): the same student always meets the same
stand, two students (almost surely) different ones, and nobody without the secret can compute
another's. The hidden values stay on the server until the student's final submission. The grade
book keeps every attempt (UTC time, attempt number, final or not) with each submitted value, the
twin's reduced value, the tolerance, the truth and pass/fail; it is exported as CSV to the
teacher only.
"""

from __future__ import annotations

import csv
import datetime as dt
import hashlib
import hmac
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
from rig.lab.sheet import SHEETS, Tolerance, default_tolerances
from rig.stands.disc_roller.stand import DiscRollerStand
from rig.stands.yoke.stand import YokeStand

FILE_KEYS = ("title", "class", "exercise")
CLASS_KEYS = ("students", "join_code", "deadline", "attempts", "checks")
RULE_KEYS = ("deadline", "attempts", "checks")
EXERCISE_KEYS = ("id", "title", "stand", "mu", "free", "start", "effects", "tolerance", "min_gate_s") + RULE_KEYS
TOLERANCE_KEYS = ("relative", "absolute", "uncertainty")
MAX_ATTEMPTS = 20
MAX_CHECKS = 50
STANDS = {"yoke": YokeStand, "disc_roller": DiscRollerStand}
"""Stands the lab operates: A (yoke) and B (disc_roller)."""
MU_RANGE = {"yoke": (YokeStand.PARAMETERS["mu"].lo, YokeStand.PARAMETERS["mu"].hi), "disc_roller": LAB_MU_RANGE_B}
"""Where an exercise's hidden mu may lie, per stand [1] (stand B: the lab's contact tables)."""
ID_PATTERN = re.compile(r"[A-Za-z0-9_-]{1,64}")
GRADE_COLUMNS = ("student", "exercise", "attempt", "time_utc", "final", "point", "quantity", "submitted", "reduced",
                 "tolerance", "true", "pass")


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
    tolerances: Mapping[str, Tolerance] = field(default_factory=dict)
    deadline: dt.datetime | None = None
    attempts: int = 1
    checks: int = 3
    min_gate_s: float = 0.0

    def draw(self, student: str, secret: bytes = b"") -> tuple[float, int]:
        """(mu [1], run seed) of ``student``'s instance: reproducible from (exercise id, student id)
        and the class's ``secret`` (HMAC-SHA-256)."""
        digest = hmac.new(secret, f"{self.id}\0{student}".encode(), hashlib.sha256).digest()
        u = int.from_bytes(digest[:8], "big") / 2.0**64
        lo, hi = self.mu_range
        return lo + (hi - lo) * u, int.from_bytes(digest[8:15], "big")

    def closed(self, now: dt.datetime) -> bool:
        """Past the deadline (UTC)?"""
        return self.deadline is not None and now > self.deadline

    def public(self) -> dict:
        """What the page may know before submission (no mu, no effects): the rules and tolerances too."""
        return {"id": self.id, "title": self.title, "stand": self.stand, "free": list(self.free),
                "start": dict(self.start), "attempts": self.attempts, "checks": self.checks,
                "deadline": None if self.deadline is None else self.deadline.isoformat().replace("+00:00", "Z"),
                "min_gate_s": self.min_gate_s,
                "tolerance": {name: t.public() for name, t in self.tolerances.items()}}


def student_id(value: object) -> str:
    """A student id: 1-64 letters, digits, '-' or '_' (it names rows of the grade book)."""
    if not isinstance(value, str) or not ID_PATTERN.fullmatch(value):
        raise ParameterError("student", value, "1-64 letters, digits, '-' or '_'")
    return value


def _deadline(value: object, where: str) -> dt.datetime | None:
    """A TOML date-time or ISO text, with a zone (read as UTC) or without (taken as UTC)."""
    if value is None:
        return None
    if isinstance(value, str):
        try:
            value = dt.datetime.fromisoformat(value.replace("Z", "+00:00"))
        except ValueError:
            raise ParameterError(where, value, "a date-time such as 2026-12-01T12:00:00Z") from None
    if not isinstance(value, dt.datetime):
        raise ParameterError(where, value, "a date-time such as 2026-12-01T12:00:00Z")
    return value.replace(tzinfo=dt.UTC) if value.tzinfo is None else value.astimezone(dt.UTC)


def _rules(entry: dict, where: str, default: Mapping[str, object]) -> dict:
    """deadline, attempts, checks of an exercise (or of [class], the default)."""
    deadline = _deadline(entry["deadline"], f"{where}.deadline") if "deadline" in entry else default.get("deadline")
    attempts = validate.integer(f"{where}.attempts", entry.get("attempts", default.get("attempts", 1)), 1, MAX_ATTEMPTS)
    checks = validate.integer(f"{where}.checks", entry.get("checks", default.get("checks", 3)), 0, MAX_CHECKS)
    return {"deadline": deadline, "attempts": attempts, "checks": checks}


def _tolerances(value: object, where: str, stand: str) -> dict[str, Tolerance]:
    sheet = SHEETS[stand]
    tolerances = dict(default_tolerances(sheet))
    if not isinstance(value, dict):
        raise ParameterError(where, value, "a table [exercise.tolerance] of {relative, absolute} per quantity")
    validate.known_keys(f"{where} quantity", value, sheet.required + sheet.optional)
    for name, spec in value.items():
        if not isinstance(spec, dict) or not spec:
            raise ParameterError(f"{where}.{name}", spec, "{relative = r}, {absolute = a} and/or {uncertainty = k}")
        validate.known_keys(f"{where}.{name} key", spec, TOLERANCE_KEYS)
        tolerances[name] = Tolerance(
            validate.number(f"{where}.{name}.relative", spec.get("relative", 0.0), 0.0, 1.0),
            validate.number(f"{where}.{name}.absolute", spec.get("absolute", 0.0), 0.0, 1e3),
            validate.number(f"{where}.{name}.uncertainty", spec.get("uncertainty", 0.0), 0.0, 10.0))
    return tolerances


def _exercise(entry: object, where: str, rules: Mapping[str, object] | None = None) -> Exercise:
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
    tolerances = _tolerances(entry.get("tolerance", {}), f"{where}.tolerance", stand)
    min_gate = validate.number(f"{where}.min_gate_s", entry.get("min_gate_s", 0.0), 0.0, 60.0)
    return Exercise(ident, title, stand, (lo, hi), tuple(free), start, effects, tolerances,
                    **_rules(entry, where, rules or {}), min_gate_s=min_gate)


@dataclass(frozen=True)
class ClassFile:
    """A teacher's file: its title and the exercises by id."""

    title: str
    exercises: Mapping[str, Exercise]
    students: tuple[str, ...] = ()
    join_code: str | None = None

    @classmethod
    def load(cls, path: Path) -> ClassFile:
        """Read and check a teacher's file (named errors naming the key)."""
        try:
            data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
        except (OSError, tomllib.TOMLDecodeError) as error:
            raise ParameterError("exercises", str(path), f"a readable TOML file ({error})") from None
        validate.known_keys("exercise file key", data, FILE_KEYS)
        klass = data.get("class", {})
        if not isinstance(klass, dict):
            raise ParameterError("class", klass, "a table [class]")
        validate.known_keys("class key", klass, CLASS_KEYS)
        students = klass.get("students", [])
        if not isinstance(students, list):
            raise ParameterError("class.students", students, "a list of student ids")
        students = tuple(student_id(s) for s in students)
        if len(set(students)) != len(students):
            raise ParameterError("class.students", "a repeated id", "each student once")
        join_code = klass.get("join_code")
        if join_code is not None and (not isinstance(join_code, str) or not 6 <= len(join_code) <= 64):
            raise ParameterError("class.join_code", join_code, "a text of 6-64 characters")
        rules = _rules(klass, "class", {})
        entries = data.get("exercise", [])
        if not isinstance(entries, list) or not entries:
            raise ParameterError("exercise", entries, "at least one [[exercise]] table")
        exercises = {}
        for k, entry in enumerate(entries):
            exercise = _exercise(entry, f"exercise[{k}]", rules)
            if exercise.id in exercises:
                raise ParameterError(f"exercise[{k}].id", exercise.id, "an id not used by another exercise")
            exercises[exercise.id] = exercise
        if not students and join_code is None:
            raise ParameterError("class", "neither students nor join_code",
                                 "[class] with students = [...] and/or join_code = \"...\"")
        return cls(str(data.get("title", Path(path).stem)), exercises, students, join_code)

    def get(self, ident: object) -> Exercise:
        validate.choice("exercise", ident, self.exercises)
        return self.exercises[ident]


class GradeBook:
    """Every attempt of every student (thread-safe): attempts are added, never replaced; once an
    attempt is final, :meth:`submit` refuses more (the grade stays). With a ``path``, the CSV is
    rewritten there after every attempt (temporary file + rename), so the grades outlive the
    server; a restarted server reads it back (attempt counts and finality included)."""

    def __init__(self, path: Path | None = None) -> None:
        self.path = path
        self._rows: dict[tuple[str, str], list[dict]] = {}
        self._lock = threading.Lock()
        if path is not None and path.is_file():
            try:
                with open(path, newline="", encoding="utf-8") as handle:
                    for row in csv.DictReader(handle):
                        self._rows.setdefault((row["student"], row["exercise"]), []).append(row)
                        int(row["attempt"])
            except (OSError, KeyError, ValueError, csv.Error) as error:
                raise ParameterError("grades", str(path), f"a grade book this lab wrote ({error})") from None

    def attempts(self, student: str, exercise: str) -> int:
        """Attempts ``student`` has made at ``exercise``."""
        with self._lock:
            return max((int(r["attempt"]) for r in self._rows.get((student, exercise), [])), default=0)

    def final(self, student: str, exercise: str) -> bool:
        """Has ``student`` made the final submission of ``exercise``?"""
        with self._lock:
            return any(str(r["final"]) == "True" for r in self._rows.get((student, exercise), []))

    def submit(self, student: str, exercise: str, rows: list[dict], *, final: bool = True,
               time_utc: str | None = None) -> int:
        """Add an attempt (its rows: point, quantity, submitted, reduced, tolerance, true, pass) at
        ``time_utc`` (default now); returns its number. A ValueError after the final attempt."""
        time_utc = time_utc or utc_now()
        with self._lock:
            earlier = self._rows.setdefault((student, exercise), [])
            if any(str(r["final"]) == "True" for r in earlier):
                raise ParameterError("answers", "a further submission", "none: the final submission is graded")
            attempt = max((int(r["attempt"]) for r in earlier), default=0) + 1
            earlier.extend(dict(student=student, exercise=exercise, attempt=attempt, time_utc=time_utc, final=final)
                           | row for row in rows)
        if self.path is not None:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}-{threading.get_ident()}.tmp")
            tmp.write_text(self.csv(), encoding="utf-8")
            os.replace(tmp, self.path)
        return attempt

    def summary(self) -> list[dict]:
        """Per (student, exercise): attempts, the last attempt's time, final, points passed/graded."""
        out = []
        with self._lock:
            for (student, exercise), rows in sorted(self._rows.items()):
                last = max(int(r["attempt"]) for r in rows)
                mine = [r for r in rows if int(r["attempt"]) == last]
                points = {}
                for r in mine:
                    points[str(r["point"])] = points.get(str(r["point"]), True) and str(r["pass"]) == "True"
                out.append({"student": student, "exercise": exercise, "attempts": last, "time_utc": mine[0]["time_utc"],
                            "final": str(mine[0]["final"]) == "True", "points": len(points),
                            "passed": sum(points.values())})
        return out

    def csv(self) -> str:
        """The grade book as CSV (columns GRADE_COLUMNS), by student, exercise, attempt, point."""
        out = io.StringIO()
        writer = csv.DictWriter(out, fieldnames=GRADE_COLUMNS, lineterminator="\n")
        writer.writeheader()
        with self._lock:
            for key in sorted(self._rows):
                writer.writerows(self._rows[key])
        return out.getvalue()


def utc_now() -> str:
    """The time now, UTC, ISO 8601 to the second (``2026-11-29T04:05:06Z``)."""
    return dt.datetime.now(dt.UTC).replace(microsecond=0).isoformat().replace("+00:00", "Z")
