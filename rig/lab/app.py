"""The lab's web server: the page, a small JSON API and a stream of live values (Flask; docs/lab.md).

Thin by design: each route reads its request (rig.lab.requests), calls the session
(rig.lab.session), the sheet's judge (rig.lab.sheet) or the exercises (rig.lab.exercises), and
returns JSON. Bad requests get 400 with ``{"error": message, "field": name}`` (404 for an
unknown session, 422 for settings at which the stand does not settle), never a 500. Every change
of a session is written to the state folder (rig.lab.store), and a session not in memory - the
server restarted - is rebuilt from there on its first request.

    GET  /                               the page (assets under /static, all from this server)
    GET  /api/stands                     the controls of each stand (names, units, ranges, choices)
    GET  /api/exercises                  the teacher's exercises (public part only)
    POST /api/sessions                   {stand, student?, exercise?} -> a new session
    GET  /api/sessions/<id>              the session's state (settings, readings, reduction)
    POST /api/sessions/<id>/controls     {settings?: {name: SI value}, strobe_ratio?} -> settle
    GET  /api/sessions/<id>/live?ratio=r the settling transient, streamed (server-sent events)
    POST /api/sessions/<id>/record       {gate_time_s} -> the gate's readings and the reduction
    POST /api/sessions/<id>/check        {point, answers: {output: value}} -> verdicts
    POST /api/sessions/<id>/nu           {point, l_over_a, c_over_a, alpha_prime} -> nu_T, nu_v, nu_0 at the
                                         point's b/a, and their curves over alpha' (the sheet's nu chart)
    POST /api/sessions/<id>/save         {} -> the path of the saved log.h5
    GET  /api/sessions/<id>/log.h5       the session's log, downloaded (rig reduce reads it)
    GET  /api/sessions/<id>/readings.csv the recorded points' readings as CSV
    POST /api/sessions/<id>/submit       {answers: [{point, values}], final?} -> an attempt's grades
    POST /api/join                       {student, join_code} -> the student's token (class mode)
    GET  /api/me                         the token's role, student and exercises (class mode)
    GET  /api/class                      teacher: students, tokens, attempts and grades
    GET  /api/grades.csv                 teacher: every attempt's values with reduced, true and pass/fail

Class mode (``rig lab --class FILE``): every request about an exercise carries a token (header
``X-Lab-Token`` or query ``token``; rig.lab.roster); a student's token opens only that student's
sessions, the grade book and the truth need the teacher's (403 otherwise). Before a student's
final submission the twin's reduction, the truth and the log file are not sent, Checks are
counted (the exercise's ``checks``; 409 when used up) and answered per step only. Practice
sessions stay open to anyone, as without a class.
"""

from __future__ import annotations

import csv
import datetime as dt
import io
import json
import logging
import secrets
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
from flask import Flask, Response, jsonify, request
from werkzeug.exceptions import HTTPException

from rig import validate
from rig.errors import ConvergenceError, ParameterError
from rig.lab import requests as rq
from rig.lab.exercises import ClassFile, Exercise, GradeBook, utc_now
from rig.lab.roster import Forbidden, Roster
from rig.lab.scene_text import GATE_TIME_S
from rig.lab.session import GATE_LIMITS_S, SESSIONS, STROBE_RATIO_LIMITS, LabSession, restore
from rig.lab.sheet import EQUATIONS, SHEETS, SYMBOLS, Sheet, judge
from rig.lab.store import SessionStore
from rig.stands.disc_roller.parameters import PARAMETERS as STAND_B_PARAMETERS
from rig.stands.yoke.parameters import GEOMETRY_FIELDS, PARAMETERS

PRACTICE_MU = {"yoke": (0.3, 0.5), "disc_roller": (0.6, 0.9)}  # range of the hidden mu of a practice session [1]
STAND_B_GEOMETRY = ("radius_c_m", "roller_radius_m", "pivot_distance_m", "half_length_m")
STAND_DATA_SYMBOLS = {
    "yoke": {"l1_m": ("l_1", "mm", 1e3), "l2_m": ("l_2", "mm", 1e3), "alpha_1_rad": (r"\alpha_1", "rad", 1.0),
             "a_m": ("a", "mm", 1e3), "r1_m": ("r_1", "mm", 1e3), "radius_x_m": ("R_x", "mm", 1e3),
             "dynamometer_lever_m": (r"l_\mathrm{dyn}", "mm", 1e3), "yoke_lever_m": ("R_v", "mm", 1e3),
             "balance_arm_m": (r"l_\mathrm{bal}", "mm", 1e3)},
    "disc_roller": {"radius_c_m": ("R_c", "mm", 1e3), "roller_radius_m": ("R_r", "mm", 1e3),
                    "pivot_distance_m": ("e", "mm", 1e3), "half_length_m": ("a", "mm", 1e3)},
}
"""The stand data as the sheet shows it: symbol (TeX), unit and the factor from SI to it."""
FRAME_S = 0.05  # real time between two frames of the live stream [s]
RATIO_LIMITS = (0.1, 100.0)  # simulated time / real time of the live stream [1]
MAX_SESSIONS = 1000
SIMULATION_SLOTS = 2  # simulations (settle, gate, reduction) run at once; the others queue [1]
MAX_POINTS = 200  # recorded points a session may hold (a submission lists each at most once)
LOG = logging.getLogger("rig.lab")
ERROR_CHARS = 400  # longest error text sent back
GRADES_CSV = "grades.csv"  # the grade book, rewritten in the output folder after every submission


class UnknownSession(LookupError):
    """No session with this id (the server restarted, or a wrong link)."""


class Refused(ParameterError):
    """A valid request the exercise's rules refuse now (no Checks left, final already, past the
    deadline): the server answers 409, naming the field."""


class Lab:
    """The server's state: sessions by id, the teacher's exercises (or None), the grade book, the
    folder saved logs go to and the folder sessions are kept in (default ``out_dir/state``)."""

    def __init__(self, out_dir: Path, classfile: ClassFile | None = None, state_dir: Path | None = None) -> None:
        self.out_dir = Path(out_dir)
        self.classfile = classfile
        self.grades = GradeBook(self.out_dir / GRADES_CSV)
        self.store = SessionStore(self.out_dir / "state" if state_dir is None else Path(state_dir))
        self.sessions: dict[str, LabSession] = {}
        self.assigned: dict[str, tuple[str, Exercise]] = {}  # session id -> (student id, exercise)
        self.roster = None if classfile is None else Roster(self.store.folder, classfile)
        # CPU-bound simulations beyond the cores only slow every request down (one interpreter
        # lock): at most SIMULATION_SLOTS run at once, so that the quick requests keep their pace
        self.simulations = threading.BoundedSemaphore(SIMULATION_SLOTS)
        self._lock = threading.Lock()
        self._loading = threading.Lock()

    def prepare(self, say=lambda line: None) -> None:
        """Build (or load from the cache) the contact tables the class's exercises need, one
        exercise at a time, saying how long each took: a student's first Apply then finds them."""
        for exercise in self.classfile.exercises.values():
            start = time.monotonic()
            say(f"preparing exercise {exercise.id} ({exercise.stand}): contact tables ...")
            try:
                lo, hi = exercise.mu_range
                session = SESSIONS[exercise.stand]("0" * 16, seed=1, mu=0.5 * (lo + hi), effects=exercise.effects,
                                                   free=exercise.free, start=exercise.start)
                session.set_controls({})
                session.record(max(exercise.min_gate_s, GATE_LIMITS_S[0]))
                session.reduced()
            except (ValueError, ConvergenceError) as error:  # the exercise itself reports it to the student
                say(f"exercise {exercise.id}: not prepared ({error})")
                continue
            say(f"exercise {exercise.id} ready ({time.monotonic() - start:.1f} s)")
        say("every exercise ready")

    @property
    def secret(self) -> bytes:
        return b"" if self.roster is None else self.roster.secret

    def who(self, token: object) -> tuple[str, str | None]:
        """The token's (role, student); Forbidden without a class or with a wrong token."""
        if self.roster is None:
            raise Forbidden("token", "this server has no class (rig lab --class FILE)")
        return self.roster.who(token)

    def final(self, session: LabSession) -> bool:
        """Has the student of exercise session ``session`` made the final submission?"""
        student, exercise = self.assigned[session.id]
        return self.grades.final(student, exercise.id)

    def authorize(self, session: LabSession, token: object, *, write: bool = True) -> None:
        """Forbidden unless ``token`` may use ``session``: a practice session anyone; an exercise
        session its student, and the teacher to read it."""
        assigned = self.assigned.get(session.id)
        if assigned is None:
            return
        role, student = self.who(token)
        if role == "teacher" and not write:
            return
        if student != assigned[0]:
            raise Forbidden("token", "this session belongs to another student")

    def open(self, data: dict, token: object = None) -> LabSession:
        stand = rq.required(data, "stand")
        if not isinstance(stand, str) or stand not in SESSIONS:
            raise ParameterError("stand", stand, f"one of {', '.join(SESSIONS)} (stand A: yoke, stand B: disc_roller)")
        kind = SESSIONS[stand]
        ident = secrets.token_hex(8)
        if "exercise" in data:
            if self.classfile is None:
                raise ParameterError("exercise", data["exercise"], "no exercise: the server has no teacher's file "
                                     "(rig lab --exercises FILE)")
            exercise = self.classfile.get(data["exercise"])
            role, student = self.who(token)
            if role != "student" or data.get("student", student) != student:
                raise Forbidden("token", "an exercise opens with the student's own token")
            if exercise.stand != stand:
                raise ParameterError("stand", stand, f"{exercise.stand!r}, the stand of exercise {exercise.id!r}")
            earlier = self.roster.session_of(student, exercise.id)
            if earlier is not None:  # one session per student and exercise: the same one again
                return self.get(earlier)
            mu, seed = exercise.draw(student, self.secret)
            session = kind(ident, seed=seed, mu=mu, effects=exercise.effects, free=exercise.free,
                           start=exercise.start, description=f"rig lab: exercise {exercise.id}, {student}")
        else:
            rng = np.random.default_rng()
            session = kind(ident, seed=int(rng.integers(2**62)), mu=float(rng.uniform(*PRACTICE_MU[stand])))
            student = exercise = None
        self._keep(session, None if exercise is None else (student, exercise))
        self.persist(session)
        if exercise is not None:
            self.roster.keep_session(student, exercise.id, ident)
        return session

    def _keep(self, session: LabSession, assigned: tuple[str, Exercise] | None) -> None:
        with self._lock:
            if len(self.sessions) >= MAX_SESSIONS:  # the oldest leaves memory (its state stays on disk)
                self.assigned.pop(self.sessions.pop(next(iter(self.sessions))).id, None)
            self.sessions[session.id] = session
            if assigned is not None:
                self.assigned[session.id] = assigned

    def persist(self, session: LabSession) -> None:
        """Write the session's state (call with the session's lock held, after every change)."""
        state = session.state()
        assigned = self.assigned.get(session.id)
        state["student"], state["exercise"] = (None, None) if assigned is None else (assigned[0], assigned[1].id)
        if assigned is not None:  # the hidden values are not stored: they derive from the class's secret
            state["mu"] = state["seed"] = None
            state["description"] = ""
        self.store.write(state)

    def _load(self, ident: str) -> LabSession:
        """Rebuild session ``ident`` from the state folder (the server restarted): UnknownSession if absent."""
        state = self.store.read(ident)
        if state is None:
            raise UnknownSession(ident)
        assigned = None
        if state["exercise"] is not None:
            if self.classfile is None or state["exercise"] not in self.classfile.exercises:
                raise ParameterError("session", ident, f"a server with the teacher's file of exercise "
                                     f"{state['exercise']!r} (rig lab --exercises FILE)")
            assigned = (state["student"], self.classfile.exercises[state["exercise"]])
            mu, seed = assigned[1].draw(assigned[0], self.secret)
            state = state | {"mu": mu, "seed": seed,
                             "description": f"rig lab: exercise {assigned[1].id}, {assigned[0]}"}
        try:
            session = restore(state)
        except (KeyError, TypeError, ValueError, AttributeError) as error:
            if isinstance(error, ParameterError) and error.name != "state.format":
                raise
            raise ParameterError("session", ident, f"a readable state file in {self.store.folder} "
                                 f"({type(error).__name__}: {error})") from None
        self._keep(session, assigned)
        return session

    def exercise_of(self, session: LabSession) -> Exercise | None:
        assigned = self.assigned.get(session.id)
        return None if assigned is None else assigned[1]

    def reduced(self, session: LabSession) -> list[dict]:
        """The twin's reduction as the page may see it: in an exercise, only after submission."""
        if session.id in self.assigned and not self.final(session):
            return []
        return session.reduced()

    def get(self, ident: str) -> LabSession:
        with self._lock:
            if ident in self.sessions:
                return self.sessions[ident]
        with self._loading:  # one rebuild at a time (a second request for it waits, then finds it)
            with self._lock:
                if ident in self.sessions:
                    return self.sessions[ident]
            with self.simulations:  # a restored session replays its points
                return self._load(ident)


def _state(lab: Lab, session: LabSession) -> dict:
    exercise = lab.exercise_of(session)
    return {
        "id": session.id, "version": session.version, "stand": session.scene.stand,
        "settings": session.settings, "free": list(session.free), "strobe_ratio": session.strobe_ratio,
        "settle_s": None if session.transient is None else session.transient.settle_s,
        "readings": [session.readings(k) for k in range(len(session.outcomes))],
        "reduced": lab.reduced(session), "answers": {str(k): v for k, v in session.answers.items()},
        "exercise": None if exercise is None else exercise.public() | _progress(lab, session, exercise),
    }


def _progress(lab: Lab, session: LabSession, exercise: Exercise) -> dict:
    """An exercise session's use of its rules: Checks left, attempts made, final or not."""
    student = lab.assigned[session.id][0]
    return {"student": student, "checks_left": max(0, exercise.checks - len(session.checks)),
            "attempts_used": lab.grades.attempts(student, exercise.id), "final": lab.final(session)}


def _controls(session: type[LabSession]) -> dict:
    return {name: {"unit": c.unit, "lo": c.lo, "hi": c.hi, "description": c.description, "choices": list(c.choices)}
            for name, c in session.CONTROLS.items()}


def _controls_spec() -> dict:
    common = {"gate_time_s": {"lo": GATE_LIMITS_S[0], "hi": GATE_LIMITS_S[1]}}
    spec = {}
    for stand, session in SESSIONS.items():
        sheet = SHEETS[stand]
        steps = [{"key": key, "text": text, "tex": EQUATIONS[stand][key],
                  "quantities": [{"name": n, "symbol": SYMBOLS[n][0], "unit": SYMBOLS[n][1]} for n in names]}
                 for key, text, names in sheet.steps]
        spec[stand] = common | {"settings": _controls(session), "outputs": list(session.SHOWN), "steps": steps,
                                "required": list(sheet.required), "optional": list(sheet.optional),
                                "traces": dict(session.TRACES)}
        spec[stand]["gate_time_s"] = common["gate_time_s"] | {"default": GATE_TIME_S[stand]}
    spec["yoke"] |= {"strobe_ratio": {"lo": STROBE_RATIO_LIMITS[0], "hi": STROBE_RATIO_LIMITS[1]},
                     "marks": {"wheel_1": PARAMETERS["marks_1"].default, "wheel_2": PARAMETERS["marks_2"].default},
                     "geometry": {name: {"value": PARAMETERS[name].default, "unit": PARAMETERS[name].unit,
                                         "source": PARAMETERS[name].source} for name in GEOMETRY_FIELDS}}
    spec["disc_roller"]["geometry"] = {
        name: {"value": STAND_B_PARAMETERS[name].default, "unit": STAND_B_PARAMETERS[name].unit,
               "source": STAND_B_PARAMETERS[name].source} for name in STAND_B_GEOMETRY}
    for stand, names in STAND_DATA_SYMBOLS.items():
        for name, (symbol, unit, scale) in names.items():
            entry = spec[stand]["geometry"][name]
            entry |= {"symbol": symbol, "shown_unit": unit, "shown_value": entry["value"] * scale}
    return spec


def _answers(value: object, name: str, sheet: Sheet) -> dict[str, float]:
    if not isinstance(value, dict):
        raise ParameterError(name, rq.short(value), "a JSON object {output: number}")
    given = {key: v for key, v in value.items() if v is not None}  # an optional value left empty
    quantities = sheet.required + sheet.optional
    checked = rq.numbers({name: given}, name, quantities + tuple(f"U95_{q}" for q in quantities))
    for key, stated in checked.items():
        if key.startswith("U95_") and not stated > 0.0:
            raise ParameterError(f"{name}.{key}", stated, "a stated uncertainty > 0")
    for key in sheet.required:
        if key not in checked:
            raise ParameterError(f"{name}.{key}", "missing", "a number")
    return checked


def _point(data: dict, session: LabSession, where: str = "") -> int:
    """The recorded point ``data["point"]`` (errors name ``where`` + "point")."""
    value, n = data.get("point"), len(session.outcomes)
    if "point" not in data:
        raise ParameterError(f"{where}point", "missing", "the index of a recorded point")
    if n == 0:
        raise ParameterError(f"{where}point", value, "a recorded point (none recorded yet)")
    return validate.integer(f"{where}point", value, 0, n - 1)


def _reduced_row(session: LabSession, point: int) -> dict:
    return next(row["values"] for row in session.reduced() if row["point"] == point)


def create_app(lab: Lab) -> Flask:
    """The Flask application of ``lab``."""
    app = Flask(__name__, static_folder="static", static_url_path="/static")
    app.json.sort_keys = False
    app.config["MAX_CONTENT_LENGTH"] = rq.MAX_BODY_BYTES  # werkzeug answers 413 above it, unread

    @app.errorhandler(ParameterError)
    def bad_request(error: ParameterError):
        return jsonify(error=str(error)[:ERROR_CHARS], field=str(error.name)[:ERROR_CHARS]), 400

    @app.errorhandler(UnknownSession)
    def unknown_session(error: UnknownSession):
        return jsonify(error=f"no session {error.args[0]!r} (none in this server's state folder): open a new one",
                       field="session"), 404

    @app.errorhandler(Refused)
    def refused(error: Refused):
        return jsonify(error=str(error)[:ERROR_CHARS], field=error.name), 409

    @app.errorhandler(Forbidden)
    def forbidden(error: Forbidden):
        return jsonify(error=str(error), field=error.field), 403

    @app.errorhandler(ConvergenceError)
    def not_settled(error: ConvergenceError):
        return jsonify(error=str(error), field="settings"), 422

    @app.errorhandler(HTTPException)
    def http_error(error: HTTPException):
        if error.code == 413:
            return jsonify(error=f"the request body is larger than {rq.MAX_BODY_BYTES} bytes", field="body"), 413
        return jsonify(error=error.description, field="body" if error.code == 400 else "url"), error.code

    @app.errorhandler(Exception)
    def last_resort(error: Exception):  # a defect: logged with its traceback, the server keeps serving
        LOG.exception("rig lab: unexpected error on %s %s", request.method, request.path)
        return jsonify(error=f"internal error ({type(error).__name__}); the server logged it", field="server"), 500

    def body(allowed) -> dict:
        return dict(rq.body(rq.parse_json(request.get_data(cache=True)), allowed))

    def token() -> str | None:
        return request.headers.get("X-Lab-Token") or request.args.get("token")

    def session_for(ident: str, *, write: bool = True) -> LabSession:
        """Session ``ident`` if the request's token may use it (403 otherwise, 404 if unknown)."""
        session = lab.get(ident)
        lab.authorize(session, token(), write=write)
        return session

    @app.get("/")
    def page():
        return app.send_static_file("index.html")

    @app.get("/api/stands")
    def stands():
        return jsonify(_controls_spec())

    @app.get("/api/exercises")
    def exercises():
        if lab.classfile is None:
            return jsonify(title=None, exercises=[])
        return jsonify(title=lab.classfile.title, exercises=[e.public() for e in lab.classfile.exercises.values()])

    @app.post("/api/sessions")
    def open_session():
        session = lab.open(body(("stand", "student", "exercise")), token())
        with session.lock:
            return jsonify(_state(lab, session)), 201

    @app.get("/api/sessions/<ident>")
    def state(ident: str):
        session = session_for(ident, write=False)
        with session.lock:
            return jsonify(_state(lab, session))

    @app.post("/api/sessions/<ident>/controls")
    def controls(ident: str):
        session = session_for(ident)
        data = body(("settings", "strobe_ratio"))
        if not data:
            raise ParameterError("settings", "missing", "settings and/or strobe_ratio")
        settings = rq.numbers(data, "settings", session.CONTROLS) if "settings" in data else None
        with session.lock, lab.simulations:
            if "strobe_ratio" in data:
                if session.strobe() is None:
                    raise ParameterError("strobe_ratio", data["strobe_ratio"], "absent: this stand has no stroboscope")
                session.set_strobe_ratio(rq.number(data, "strobe_ratio"))
            if settings is not None:
                session.set_controls(settings)  # errors name settings.<name>
            elif session.transient is None:
                session.set_controls({})
            lab.persist(session)
            return jsonify(version=session.version, settings=session.settings, settle_s=session.transient.settle_s)

    @app.get("/api/sessions/<ident>/live")
    def live(ident: str):
        session = session_for(ident, write=False)
        ratio = rq.number({"ratio": _query_number(request.args.get("ratio", "1"))}, "ratio", *RATIO_LIMITS)
        with session.lock:
            transient, strobe, version = session.transient, session.strobe(), session.version
        if transient is None:
            raise ParameterError("settings", "not set", "POST controls before opening the live stream")
        return Response(_stream(transient, strobe, version, ratio), mimetype="text/event-stream",
                        headers={"Cache-Control": "no-store"})

    @app.post("/api/sessions/<ident>/record")
    def record(ident: str):
        session = session_for(ident)
        gate = rq.number(body(("gate_time_s",)), "gate_time_s", *GATE_LIMITS_S)
        exercise = lab.exercise_of(session)
        if exercise is not None and gate < exercise.min_gate_s:
            raise ParameterError("gate_time_s", gate, f"at least {exercise.min_gate_s:g} s in exercise {exercise.id}")
        with session.lock, lab.simulations:
            if len(session.outcomes) >= MAX_POINTS:
                raise ParameterError("point", len(session.outcomes), f"at most {MAX_POINTS} recorded points a session")
            readings = session.record(gate)
            lab.persist(session)
            return jsonify(readings=readings, reduced=lab.reduced(session), version=session.version)

    @app.post("/api/sessions/<ident>/check")
    def check(ident: str):
        session = session_for(ident)
        data = body(("point", "answers"))
        exercise = lab.exercise_of(session)
        with session.lock:
            point = _point(data, session)
            sheet = SHEETS[session.STAND]
            answers = _answers(rq.required(data, "answers"), "answers", sheet)
            hidden = exercise is not None and not lab.final(session)
            if hidden and len(session.checks) >= exercise.checks:
                raise Refused("check", f"{len(session.checks)} used", f"at most {exercise.checks} Checks in exercise "
                              f"{exercise.id}" + ("" if exercise.checks else " (it has no Check: submit)"))
            verdict = judge(answers, _reduced_row(session, point), sheet,
                            None if exercise is None else exercise.tolerances)
            session.answers[point] = answers
            if exercise is not None:
                session.checks.append({"time_utc": utc_now(), "point": point, "passed": verdict["passed"],
                                       "step": None if verdict["passed"] else verdict["sent_back_to"]["step"]})
            lab.persist(session)
            if hidden:  # an exercise before the final submission: per step, not the values' verdicts
                verdict["values"] = {name: {"entered": v["entered"]} for name, v in verdict["values"].items()}
                verdict["checks_left"] = exercise.checks - len(session.checks)
            return jsonify(point=point, **verdict)

    @app.post("/api/sessions/<ident>/nu")
    def nu(ident: str):
        session = session_for(ident, write=False)
        data = body(("point", "l_over_a", "c_over_a", "alpha_prime"))
        values = {name: rq.number(data, name) for name in ("l_over_a", "c_over_a", "alpha_prime")}
        with session.lock:
            point = _point(data, session)
            return jsonify(point=point, **session.nu_lookup(point, **values))

    @app.post("/api/sessions/<ident>/save")
    def save(ident: str):
        session = session_for(ident)
        body(())
        hide_truth(session)
        with session.lock:
            path = session.save(lab.out_dir / session.id)
        return jsonify(path=str(path))

    def hide_truth(session: LabSession) -> None:
        if session.id in lab.assigned and not lab.final(session):
            raise Forbidden("session", "the log holds the hidden values: it is offered after your final submission "
                            "(the readings are: readings.csv)")

    @app.get("/api/sessions/<ident>/log.h5")
    def download_log(ident: str):
        session = session_for(ident, write=False)
        hide_truth(session)
        with session.lock, tempfile.TemporaryDirectory(prefix="rig-lab-") as folder:
            data = session.save(Path(folder)).read_bytes()
        return Response(data, mimetype="application/x-hdf5",
                        headers={"Content-Disposition": f"attachment; filename=lab-{session.id}-log.h5"})

    @app.get("/api/sessions/<ident>/readings.csv")
    def download_readings(ident: str):
        session = session_for(ident, write=False)
        with session.lock:
            text = readings_csv([session.readings(k) for k in range(len(session.outcomes))])
        return Response(text, mimetype="text/csv",
                        headers={"Content-Disposition": f"attachment; filename=lab-{session.id}-readings.csv"})

    @app.post("/api/sessions/<ident>/submit")
    def submit(ident: str):
        session = session_for(ident)
        data = body(("answers", "final"))
        entries = rq.required(data, "answers")
        if not isinstance(entries, list) or not entries:
            raise ParameterError("answers", rq.short(entries), "a non-empty list of {point, values}")
        if len(entries) > MAX_POINTS:
            raise ParameterError("answers", f"{len(entries)} entries", "at most one entry per recorded point")
        asked_final = data.get("final", False)
        if not isinstance(asked_final, bool):
            raise ParameterError("final", rq.short(asked_final), "true or false")
        with session.lock:
            if session.id not in lab.assigned:
                raise ParameterError("session", session.id, "a session of an exercise (practice is not graded)")
            student, exercise = lab.assigned[session.id]
            now = utc_now()
            if exercise.closed(dt.datetime.fromisoformat(now.replace("Z", "+00:00"))):
                raise Refused("deadline", exercise.public()["deadline"], "a submission before the deadline")
            if lab.grades.final(student, exercise.id):
                raise Refused("answers", "a further submission", "none: the final submission is graded")
            sheet = SHEETS[session.STAND]
            results, rows = [], []
            for k, entry in enumerate(entries):
                where = f"answers[{k}]"
                entry = rq.body(entry, ("point", "values"), where)
                point = _point(dict(entry), session, f"{where}.")
                if any(result["point"] == point for result in results):
                    raise ParameterError(f"{where}.point", point, "a point not listed before in this submission")
                if "values" not in entry:
                    raise ParameterError(f"{where}.values", "missing", "a JSON object {output: number}")
                answers = _answers(entry["values"], f"{where}.values", sheet)
                verdict = judge(answers, _reduced_row(session, point), sheet, exercise.tolerances)
                truth = session.truth(point)
                results.append({"point": point, **verdict, "truth": truth})
                for name, v in verdict["values"].items():
                    true = truth.get("mu") if name.startswith("mu_") else truth.get({"M_C_N_m": "M_C"}.get(name, name))
                    rows.append(dict(point=point, quantity=name, submitted=v["entered"], reduced=v["reduced"],
                                     tolerance=v["tolerance"], true=true, **{"pass": v["ok"]}))
            final = asked_final or lab.grades.attempts(student, exercise.id) + 1 >= exercise.attempts
            attempt = lab.grades.submit(student, exercise.id, rows, final=final, time_utc=now)
            lab.persist(session)
            if not final:  # a counted attempt: per point and step, nothing of the truth
                results = [{"point": r["point"], "passed": r["passed"], "steps": r["steps"],
                            "sent_back_to": r["sent_back_to"]} for r in results]
            return jsonify(attempt=attempt, attempts_left=exercise.attempts - attempt, final=final, time_utc=now,
                           results=results)

    @app.post("/api/join")
    def join():
        data = body(("student", "join_code"))
        if lab.roster is None:
            raise ParameterError("join_code", "given", "none: this server has no class (rig lab --class FILE)")
        student = rq.required(data, "student")
        issued = lab.roster.join(student, rq.required(data, "join_code"))
        return jsonify(student=student, token=issued), 201

    @app.get("/api/me")
    def me():
        role, student = lab.who(token())
        exercises = []
        for exercise in lab.classfile.exercises.values():
            entry = exercise.public()
            if student is not None:
                entry |= {"session": lab.roster.session_of(student, exercise.id),
                          "attempts_used": lab.grades.attempts(student, exercise.id),
                          "final": lab.grades.final(student, exercise.id)}
            exercises.append(entry)
        return jsonify(role=role, student=student, title=lab.classfile.title, exercises=exercises)

    @app.get("/api/class")
    def klass():
        if lab.who(token())[0] != "teacher":
            raise Forbidden("token", "the class's grade book is the teacher's")
        return jsonify(title=lab.classfile.title,
                       students=[{"student": s, "token": lab.roster.token_of(s)} for s in lab.roster.students()],
                       grades=lab.grades.summary())

    @app.get("/api/grades.csv")
    def grades():
        if lab.who(token())[0] != "teacher":
            raise Forbidden("token", "the grade book is the teacher's")
        return Response(lab.grades.csv(), mimetype="text/csv",
                        headers={"Content-Disposition": "attachment; filename=grades.csv"})

    return app


def readings_csv(readings: list[dict]) -> str:
    """The recorded points' readings as CSV: one row per point, nested fields as dotted columns."""
    def flat(prefix: str, value: object, out: dict) -> dict:
        if isinstance(value, dict):
            for key, inner in value.items():
                flat(f"{prefix}.{key}" if prefix else str(key), inner, out)
        elif isinstance(value, list):
            out[prefix] = " ".join(repr(v) for v in value)
        else:
            out[prefix] = value
        return out

    rows = [flat("", r, {}) for r in readings]
    columns = list(dict.fromkeys(key for row in rows for key in row))
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=columns, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    return out.getvalue()


def _query_number(text: str) -> float | str:
    """A query parameter as a number if it reads as one (else the text, which the check rejects)."""
    try:
        return float(text)
    except ValueError:
        return text


def _stream(transient, strobe: dict | None, version: int, ratio: float):
    """Server-sent events: frames of the transient paced at ``ratio`` x real time, then 'settled'."""
    t = transient.t
    strobe = strobe or {"t": [], "phase": [], "drift_marks_s": None}
    flash_t, flash_phase = np.asarray(strobe["t"]), np.asarray(strobe["phase"])
    start = time.monotonic()
    k = 0
    while k < t.size:
        sim_now = (time.monotonic() - start) * ratio
        j = max(int(np.searchsorted(t, sim_now, side="right")), k + 1)
        f = int(np.searchsorted(flash_t, t[j - 1], side="right")) - 1
        frame = {"version": version, "ratio": ratio, "settle_s": transient.settle_s,
                 "t": t[k:j].tolist(), "series": {name: v[k:j].tolist() for name, v in transient.series.items()},
                 "strobe_phase": float(flash_phase[f]) if f >= 0 else None}
        yield f"event: frame\ndata: {json.dumps(frame)}\n\n"
        k = j
        time.sleep(FRAME_S)
    settled = {"version": version, "settle_s": transient.settle_s, "strobe_drift_marks_s": strobe["drift_marks_s"]}
    yield f"event: settled\ndata: {json.dumps(settled)}\n\n"
