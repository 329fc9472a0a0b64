"""Class mode in process (Flask's test client): tokens bind every request to its student, the grade
book and the truth are the teacher's, Checks are counted and logged, attempts are counted with a
UTC time and the final one cannot be replaced, the hidden values are in no answer, saved file or
state file before the final submission, and a restarted server keeps all of it."""

from __future__ import annotations

import csv
import datetime as dt
import json

import pytest

from rig.lab.app import Lab, create_app
from rig.lab.exercises import ClassFile

CLASS = """title = "test class"
[class]
students = ["s1", "s2"]
join_code = "code-123"
attempts = 2
checks = 2
[[exercise]]
id = "A1"
title = "brake sweep"
stand = "yoke"
mu = [0.30, 0.50]
free = ["brake_setpoint_N_m"]
min_gate_s = 1.0
[exercise.tolerance]
mu_v = {relative = 0.02}
[exercise.start]
brake_setpoint_N_m = 0.5
[[exercise]]
id = "A0"
title = "closed"
stand = "yoke"
mu = [0.30, 0.50]
free = []
deadline = 2000-01-01T00:00:00Z
"""
# mu 0.15: half the least hidden mu of A1 (drawn in [0.30, 0.50] from the class's random secret), so mu_v and mu_T
# fail whatever the secret draws (0.4 passed when the secret drew a mu_v near 0.4: seen once in a full run)
WRONG = {"l_over_a": 0.1, "c_over_a": 0.0, "mu_v": 0.15, "mu_T": 0.15}


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    (folder / "class.toml").write_text(CLASS)
    classfile = ClassFile.load(folder / "class.toml")
    lab = Lab(folder / "out", classfile)
    client = create_app(lab).test_client()
    tokens = {s: lab.roster.token_of(s) for s in ("s1", "s2")} | {"teacher": lab.roster.teacher_token}
    return lab, client, tokens, folder


def _call(client, method, path, token=None, body=None):
    headers = {} if token is None else {"X-Lab-Token": token}
    response = client.open(path, method=method, json=body, headers=headers)
    return response.status_code, response


def _open(client, token, exercise="A1"):
    status, response = _call(client, "POST", "/api/sessions", token, {"stand": "yoke", "exercise": exercise})
    assert status == 201, response.get_json()
    return response.get_json()


def test_tokens_bind_sessions_grades_and_truth_to_their_owner(klass):
    lab, client, tokens, folder = klass
    state = _open(client, tokens["s1"])
    sid = state["id"]
    assert _open(client, tokens["s1"])["id"] == sid  # one session per student and exercise
    mu, _ = lab.classfile.get("A1").draw("s1", lab.secret)
    # without a token, with a wrong one, with another student's: 403 on every route of the session
    for token in (None, "0" * 32, tokens["s2"]):
        for method, path, body in (("GET", "", None), ("POST", "/controls", {"settings": {}}),
                                   ("POST", "/record", {"gate_time_s": 1.0}), ("GET", "/live", None),
                                   ("POST", "/check", {"point": 0, "answers": WRONG}),
                                   ("POST", "/submit", {"answers": [{"point": 0, "values": WRONG}]}),
                                   ("GET", "/log.h5", None), ("GET", "/readings.csv", None), ("POST", "/save", {})):
            status, response = _call(client, method, f"/api/sessions/{sid}{path}", token, body)
            assert status == 403 and response.get_json()["field"] == "token", (token, path)
        assert _call(client, "GET", "/api/grades.csv", token)[0] == 403
        assert _call(client, "GET", "/api/class", token)[0] == 403
    assert _call(client, "GET", "/api/grades.csv", tokens["s1"])[0] == 403
    # an exercise opens only with the student's own token, never by naming another student
    assert _call(client, "POST", "/api/sessions", tokens["s2"], {"stand": "yoke", "exercise": "A1",
                                                                 "student": "s1"})[0] == 403
    assert _call(client, "POST", "/api/sessions", None, {"stand": "yoke", "exercise": "A1", "student": "s1"})[0] == 403
    # the teacher reads the session, but does not work in it
    assert _call(client, "GET", f"/api/sessions/{sid}", tokens["teacher"])[0] == 200
    assert _call(client, "POST", f"/api/sessions/{sid}/record", tokens["teacher"], {"gate_time_s": 1.0})[0] == 403
    # a gate shorter than the exercise allows is refused by name
    status, response = _call(client, "POST", f"/api/sessions/{sid}/record", tokens["s1"], {"gate_time_s": 0.5})
    assert status == 400 and response.get_json()["field"] == "gate_time_s"
    status, response = _call(client, "POST", f"/api/sessions/{sid}/record", tokens["s1"], {"gate_time_s": 1.0})
    assert status == 200 and response.get_json()["reduced"] == []
    texts = [response.get_data(as_text=True), _call(client, "GET", f"/api/sessions/{sid}", tokens["s1"])[1].get_data(
        as_text=True), (lab.store.folder / f"{sid}.json").read_text(),
        _call(client, "GET", f"/api/sessions/{sid}/readings.csv", tokens["s1"])[1].get_data(as_text=True)]
    for text in texts:
        assert repr(mu) not in text and f"{mu:.5f}" not in text and '"mu": 0' not in text
    assert json.loads(texts[2])["mu"] is None
    # the log holds the truth: not before the final submission
    assert _call(client, "GET", f"/api/sessions/{sid}/log.h5", tokens["s1"])[0] == 403
    assert _call(client, "POST", f"/api/sessions/{sid}/save", tokens["s1"], {})[0] == 403


def test_checks_are_counted_logged_and_per_step_and_attempts_end_in_a_final_grade(klass):
    lab, client, tokens, folder = klass
    sid = _open(client, tokens["s2"])["id"]
    assert _call(client, "POST", f"/api/sessions/{sid}/record", tokens["s2"], {"gate_time_s": 1.0})[0] == 200
    for left in (1, 0):
        status, response = _call(client, "POST", f"/api/sessions/{sid}/check", tokens["s2"],
                                 {"point": 0, "answers": WRONG})
        verdict = response.get_json()
        assert status == 200 and verdict["checks_left"] == left and verdict["sent_back_to"]["step"]
        assert verdict["values"]["mu_v"] == {"entered": 0.15}  # no per-value verdict, no reduced value
    status, response = _call(client, "POST", f"/api/sessions/{sid}/check", tokens["s2"], {"point": 0, "answers": WRONG})
    assert status == 409 and response.get_json()["field"] == "check"
    checks = json.loads((lab.store.folder / f"{sid}.json").read_text())["checks"]
    assert [c["point"] for c in checks] == [0, 0] and all(c["time_utc"].endswith("Z") for c in checks)
    # attempt 1 (counted, not final): no truth, no reduction
    status, response = _call(client, "POST", f"/api/sessions/{sid}/submit", tokens["s2"],
                             {"answers": [{"point": 0, "values": WRONG}]})
    first = response.get_json()
    assert status == 200 and (first["attempt"], first["final"], first["attempts_left"]) == (1, False, 1)
    assert "truth" not in first["results"][0] and "values" not in first["results"][0]
    assert _call(client, "GET", f"/api/sessions/{sid}", tokens["s2"])[1].get_json()["reduced"] == []
    # attempt 2 is the last allowed: final, with the truth; then nothing changes the grade
    status, response = _call(client, "POST", f"/api/sessions/{sid}/submit", tokens["s2"],
                             {"answers": [{"point": 0, "values": WRONG}]})
    second = response.get_json()
    assert status == 200 and second["final"] is True and second["results"][0]["truth"]["mu"] > 0
    reduced = _call(client, "GET", f"/api/sessions/{sid}", tokens["s2"])[1].get_json()["reduced"][0]["values"]
    right = {name: reduced[name] for name in WRONG}
    status, response = _call(client, "POST", f"/api/sessions/{sid}/submit", tokens["s2"],
                             {"answers": [{"point": 0, "values": right}], "final": True})
    assert status == 409
    book = _call(client, "GET", "/api/grades.csv", tokens["teacher"])[1].get_data(as_text=True)
    rows = [r for r in csv.DictReader(book.splitlines()) if r["student"] == "s2"]
    assert {r["attempt"] for r in rows} == {"1", "2"} and {r["final"] for r in rows if r["attempt"] == "2"} == {"True"}
    assert all(r["pass"] == "False" for r in rows if r["quantity"] == "mu_v")
    stamps = {dt.datetime.fromisoformat(r["time_utc"].replace("Z", "+00:00")) for r in rows}
    assert all(abs((dt.datetime.now(dt.UTC) - t).total_seconds()) < 600 for t in stamps)
    assert _call(client, "GET", f"/api/sessions/{sid}/log.h5", tokens["s2"])[0] == 200
    summary = _call(client, "GET", "/api/class", tokens["teacher"])[1].get_json()
    assert {"student": "s2", "exercise": "A1", "attempts": 2, "final": True} .items() <= \
        next(g for g in summary["grades"] if g["student"] == "s2").items()
    # a restarted server: the same session (same hidden mu), the same attempts, still final
    lab2 = Lab(lab.out_dir, lab.classfile)
    client2 = create_app(lab2).test_client()
    assert lab2.roster.token_of("s2") == tokens["s2"]
    state = _call(client2, "GET", f"/api/sessions/{sid}", tokens["s2"])[1].get_json()
    assert state["exercise"]["final"] is True and state["exercise"]["attempts_used"] == 2
    assert _call(client2, "POST", f"/api/sessions/{sid}/submit", tokens["s2"],
                 {"answers": [{"point": 0, "values": right}]})[0] == 409
    assert lab2.sessions[sid].truth(0)["mu"] == second["results"][0]["truth"]["mu"]


def test_joining_with_the_code_issues_one_token_per_id(klass):
    lab, client, tokens, folder = klass
    status, response = _call(client, "POST", "/api/join", None, {"student": "new-1", "join_code": "nope"})
    assert status == 403 and response.get_json()["field"] == "join_code"
    status, response = _call(client, "POST", "/api/join", None, {"student": "new-1", "join_code": "code-123"})
    assert status == 201
    token = response.get_json()["token"]
    assert _call(client, "GET", "/api/me", token)[1].get_json()["student"] == "new-1"
    for student in ("new-1", "s1"):  # an id already in the class cannot be taken over
        assert _call(client, "POST", "/api/join", None, {"student": student, "join_code": "code-123"})[0] == 403
    assert "new-1," + token in (lab.store.folder / "tokens.csv").read_text()


def test_past_the_deadline_a_submission_is_refused(klass):
    lab, client, tokens, folder = klass
    sid = _open(client, tokens["s1"], "A0")["id"]
    assert _call(client, "POST", f"/api/sessions/{sid}/record", tokens["s1"], {"gate_time_s": 0.5})[0] == 200
    status, response = _call(client, "POST", f"/api/sessions/{sid}/submit", tokens["s1"],
                             {"answers": [{"point": 0, "values": WRONG}]})
    assert status == 409 and response.get_json()["field"] == "deadline"


def test_practice_stays_open_without_a_token(klass):
    lab, client, tokens, folder = klass
    status, response = _call(client, "POST", "/api/sessions", None, {"stand": "yoke"})
    assert status == 201
    assert _call(client, "GET", f"/api/sessions/{response.get_json()['id']}")[0] == 200


def test_a_stated_uncertainty_is_a_positive_number_named_when_not(klass):
    lab, client, tokens, folder = klass
    status, response = _call(client, "POST", "/api/sessions", None, {"stand": "yoke"})
    sid = response.get_json()["id"]
    assert _call(client, "POST", f"/api/sessions/{sid}/record", None, {"gate_time_s": 0.5})[0] == 200
    for bad in (-0.01, 0.0, "x"):
        status, response = _call(client, "POST", f"/api/sessions/{sid}/check", None,
                                 {"point": 0, "answers": WRONG | {"U95_mu_T": bad}})
        assert status == 400 and response.get_json()["field"] == "answers.U95_mu_T"
    status, response = _call(client, "POST", f"/api/sessions/{sid}/check", None,
                             {"point": 0, "answers": WRONG | {"U95_mu_T": 0.01}})
    assert status == 200 and "U95_mu_T" not in response.get_json()["values"]
