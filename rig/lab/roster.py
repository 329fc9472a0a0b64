"""Who is who in a class: the class's secret, the teacher's token, each student's token and session.

Files in the state folder (created on the first start with a class, read back on a restart;
owner-only permissions):

- ``class-secret``: 32 random bytes (hex). Every token and every student's hidden mu derive from
  it (HMAC-SHA-256), so whoever has it can act as anyone: it never leaves the server.
- ``teacher-token``: the teacher's token (also printed at start as the teacher's link).
- ``tokens.csv``: ``student,token`` of every student of the class file and every student who
  joined with the join code - what the teacher hands out.
- ``roster.json``: the students who joined, and each student's session of each exercise (one
  per student and exercise: opening the exercise again returns it, Checks used and all).
"""

from __future__ import annotations

import contextlib
import hashlib
import hmac
import json
import os
import secrets
import threading
from pathlib import Path

from rig.errors import ParameterError
from rig.lab.exercises import ClassFile, student_id

SECRET_FILE, TEACHER_FILE, TOKENS_FILE, ROSTER_FILE = "class-secret", "teacher-token", "tokens.csv", "roster.json"
TOKEN_HEX = 32  # hex digits of a token (128 bits)


class Forbidden(PermissionError):
    """A request without the token the resource needs (the server answers 403, naming the field)."""

    def __init__(self, field: str, message: str) -> None:
        super().__init__(f"{field}: {message}")
        self.field = field


def _write_private(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` whole (temporary file + rename), readable by the owner only."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}-{threading.get_ident()}.tmp")
    try:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, path)
    finally:
        with contextlib.suppress(OSError):
            tmp.unlink(missing_ok=True)


class Roster:
    """The class's secret and tokens in ``folder`` (the lab's state folder) for ``classfile``."""

    def __init__(self, folder: Path, classfile: ClassFile) -> None:
        self.folder = Path(folder)
        self.classfile = classfile
        self._lock = threading.Lock()
        secret_path = self.folder / SECRET_FILE
        try:
            if secret_path.is_file():
                self.secret = bytes.fromhex(secret_path.read_text(encoding="utf-8").strip())
            else:
                self.secret = secrets.token_bytes(32)
                _write_private(secret_path, self.secret.hex())
        except (OSError, ValueError) as error:
            raise ParameterError("--state", str(self.folder),
                                 f"a folder the lab can read and write ({error})") from None
        self.teacher_token = self._derive("teacher")
        roster, path = {}, self.folder / ROSTER_FILE
        if path.is_file():
            try:
                roster = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError) as error:
                raise ParameterError("--state", str(path), f"a roster this lab wrote ({error})") from None
        self.joined: list[str] = list(roster.get("joined", []))
        self.sessions: dict[str, str] = dict(roster.get("sessions", {}))  # "student/exercise" -> session id
        self._tokens = {self.token_of(s): s for s in self.students()}
        _write_private(self.folder / TEACHER_FILE, self.teacher_token + "\n")
        self._write()

    def _derive(self, what: str) -> str:
        return hmac.new(self.secret, what.encode(), hashlib.sha256).hexdigest()[:TOKEN_HEX]

    def students(self) -> list[str]:
        """The class file's students, then those who joined."""
        return list(self.classfile.students) + [s for s in self.joined if s not in self.classfile.students]

    def token_of(self, student: str) -> str:
        return self._derive(f"student\0{student}")

    def who(self, token: object) -> tuple[str, str | None]:
        """("teacher", None) or ("student", id) of ``token``; Forbidden for any other."""
        if not isinstance(token, str) or not token:
            raise Forbidden("token", "this needs your token (the teacher gave it, or join with the class's code)")
        if hmac.compare_digest(token.encode(), self.teacher_token.encode()):
            return "teacher", None
        student = self._tokens.get(token)
        if student is None:
            raise Forbidden("token", "unknown token")
        return "student", student

    def join(self, student: object, code: object) -> str:
        """A new student's token for the class's join code; Forbidden for a wrong code or a taken id."""
        student = student_id(student)
        if self.classfile.join_code is None:
            raise Forbidden("join_code", "this class has no join code: ask the teacher for your token")
        if not isinstance(code, str) or not hmac.compare_digest(code.encode(), self.classfile.join_code.encode()):
            raise Forbidden("join_code", "wrong join code")
        with self._lock:
            if student in self.classfile.students or student in self.joined:
                raise Forbidden("student", f"{student!r} has joined already: ask the teacher for that token")
            self.joined.append(student)
            self._tokens[self.token_of(student)] = student
            self._write()
        return self.token_of(student)

    def session_of(self, student: str, exercise: str) -> str | None:
        with self._lock:
            return self.sessions.get(f"{student}/{exercise}")

    def keep_session(self, student: str, exercise: str, ident: str) -> None:
        with self._lock:
            self.sessions[f"{student}/{exercise}"] = ident
            self._write()

    def _write(self) -> None:
        _write_private(self.folder / ROSTER_FILE, json.dumps({"joined": self.joined, "sessions": self.sessions}))
        rows = "".join(f"{s},{self.token_of(s)}\n" for s in self.students())
        _write_private(self.folder / TOKENS_FILE, "student,token\n" + rows)
