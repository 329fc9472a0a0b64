"""The lab's JSON API on a real ``rig lab`` server: bad requests are 4xx naming the field; hidden
values stay hidden until submission; concurrent requests do not corrupt a session."""

from __future__ import annotations

import itertools
import json
import threading

import pytest

from rig.lab.exercises import ClassFile
from tests.lab.conftest import EXAMPLE_CLASS

GOOD_SETTINGS = {"brake_setpoint_N_m": 0.5, "normal_force_N": 96.2, "delta_h_m": 0.0, "omega_1_set_rad_s": 25.13}
GOOD_ANSWERS = {"l_over_a": 0.1, "c_over_a": 0.0, "mu_v": 0.4, "mu_T": 0.4}
GOOD_SETTINGS_B = {"normal_force_N": 36.0, "l_m": 0.01, "sigma_rad": 0.0, "speed_step": 1.0, "direction": 1.0}
GOOD_ANSWERS_B = {"l_over_a": 2.5, "c_over_a": 0.0, "mu_v": 0.7}
TOKENS: dict[str, str] = {}  # session id -> its student's token
BAD_VALUES = ("text", None, True, [1], {"x": 1}, float("nan"), float("inf"), -float("inf"), 1e300, -1e300)


@pytest.fixture(scope="module")
def session(lab_server) -> str:
    """A practice session with one recorded point."""
    status, state = lab_server.request("POST", "api/sessions", {"stand": "yoke"})
    assert status == 201
    assert lab_server.request("POST", f"api/sessions/{state['id']}/record", {"gate_time_s": 1.0})[0] == 200
    return state["id"]


@pytest.fixture(scope="module")
def session_b(lab_server) -> str:
    """A stand-B practice session with one recorded point."""
    status, state = lab_server.request("POST", "api/sessions", {"stand": "disc_roller"})
    assert status == 201 and state["settings"] == GOOD_SETTINGS_B
    assert lab_server.request("POST", f"api/sessions/{state['id']}/record", {"gate_time_s": 1.0})[0] == 200
    return state["id"]


@pytest.fixture(scope="module")
def exercise_session(lab_server) -> str:
    """A session of exercise A1 with one recorded point (its student's token: TOKENS[id])."""
    token = lab_server.join("s-bad")
    status, state = lab_server.request("POST", "api/sessions", {"stand": "yoke", "exercise": "A1"}, token=token)
    assert status == 201
    assert lab_server.request("POST", f"api/sessions/{state['id']}/record", {"gate_time_s": 1.0}, token=token)[0] == 200
    TOKENS[state["id"]] = token
    return state["id"]


def _malformed(sid: str, esid: str) -> list[tuple[str, str, object, bytes | None]]:
    """(method, path, JSON body, raw body) of requests a server must refuse with a 4xx."""
    s, e = f"api/sessions/{sid}", f"api/sessions/{esid}"
    cases: list[tuple[str, str, object, bytes | None]] = []
    # unknown stand, student, exercise; wrong body types
    for stand in ("disc", "Yoke", "", 3, None, "disc roller", ["yoke"]):
        cases.append(("POST", "api/sessions", {"stand": stand}, None))
    cases += [("POST", "api/sessions", {}, None), ("POST", "api/sessions", {"stand": "yoke", "colour": 1}, None),
              ("POST", "api/sessions", {"stand": "yoke", "exercise": "A9", "student": "s1"}, None),
              ("POST", "api/join", {"student": "no spaces", "join_code": "rolling-2026"}, None),
              ("POST", "api/join", {"student": "s9", "join_code": "wrong"}, None),
              ("POST", "api/sessions", {"stand": "yoke", "exercise": "A1"}, None),
              ("POST", "api/sessions", {"stand": "yoke", "exercise": "A1", "student": "no spaces"}, None),
              ("POST", "api/sessions", {"stand": "yoke", "exercise": "A1", "student": 7}, None)]
    for raw in (b"", b"{", b"[1, 2]", b"NaN", b"\xff\xfe", b'"yoke"', b"null"):
        for path in ("api/sessions", f"{s}/controls", f"{s}/record", f"{s}/check", f"{s}/submit"):
            cases.append(("POST", path, None, raw))
    # controls: each setting with every bad value, out of range, unknown names
    for name, bad in itertools.product(GOOD_SETTINGS, BAD_VALUES):
        cases.append(("POST", f"{s}/controls", {"settings": {name: bad}}, None))
    for name, value in (("brake_setpoint_N_m", 9.0), ("normal_force_N", 5.0), ("normal_force_N", 501.0),
                        ("delta_h_m", -1e-3), ("delta_h_m", 0.01), ("omega_1_set_rad_s", 0.0),
                        ("omega_1_set_rad_s", 100.0), ("brake_set_point", 0.1), ("mu", 0.3),
                        ("direction", -1.0), ("direction", 0.0), ("l_m", 0.01)):
        cases.append(("POST", f"{s}/controls", {"settings": {name: value}}, None))
    cases += [("POST", f"{s}/controls", {}, None), ("POST", f"{s}/controls", {"settings": [0.5]}, None),
              ("POST", f"{s}/controls", {"strobe_ratio": 0.0}, None),
              ("POST", f"{s}/controls", {"strobe_ratio": "1"}, None)]
    for bad in BAD_VALUES:
        cases.append(("POST", f"{s}/controls", {"strobe_ratio": bad}, None))
        cases.append(("POST", f"{e}/submit", {"answers": [{"point": bad, "values": GOOD_ANSWERS}]}, None))
        if bad is None or not isinstance(bad, float) or not abs(bad) < float("inf"):  # 1e300 is a (wrong) answer
            cases.append(("POST", f"{e}/submit", {"answers": [{"point": 0, "values": GOOD_ANSWERS | {"mu_v": bad}}]},
                          None))
    # record: gate time
    for bad in BAD_VALUES + (0.0, -1.0, 1e4):
        cases.append(("POST", f"{s}/record", {"gate_time_s": bad}, None))
    cases.append(("POST", f"{s}/record", {}, None))
    # check: point and answers
    for bad in BAD_VALUES + (-1, 5, 0.5):
        cases.append(("POST", f"{s}/check", {"point": bad, "answers": GOOD_ANSWERS}, None))
    for name, bad in itertools.product(GOOD_ANSWERS, ("x", True, [0.1], float("nan"), float("inf"))):
        cases.append(("POST", f"{s}/check", {"point": 0, "answers": GOOD_ANSWERS | {name: bad}}, None))
    for name in GOOD_ANSWERS:
        cases.append(("POST", f"{s}/check", {"point": 0, "answers": {k: v for k, v in GOOD_ANSWERS.items() if k != name}},
                      None))
    cases += [("POST", f"{s}/check", {"answers": GOOD_ANSWERS}, None),
              ("POST", f"{s}/check", {"point": 0}, None),
              ("POST", f"{s}/check", {"point": 0, "answers": GOOD_ANSWERS | {"mu": 0.4}}, None),
              ("POST", f"{s}/check", {"point": 0, "answers": [0.4]}, None)]
    # submit (a practice session, and malformed lists), save with fields, live with a bad ratio
    cases += [("POST", f"{e}/submit", {"answers": []}, None), ("POST", f"{e}/submit", {"answers": {}}, None),
              ("POST", f"{e}/submit", {"answers": [0]}, None), ("POST", f"{e}/submit", {"answers": [{"point": 0}]}, None),
              ("POST", f"{e}/controls", {"settings": {"normal_force_N": 200.0}}, None),
              ("POST", f"{s}/submit", {"answers": [{"point": 0, "values": GOOD_ANSWERS}]}, None),
              ("POST", f"{s}/save", {"path": "/etc"}, None)]
    for ratio in ("fast", "nan", "0", "-2", "1e9", "inf"):
        cases.append(("GET", f"{s}/live?ratio={ratio}", None, None))
    # unknown session, unknown route, wrong method
    cases += [("GET", "api/sessions/0000000000000000", None, None),
              ("POST", "api/sessions/0000000000000000/record", {"gate_time_s": 1.0}, None),
              ("GET", "api/nothing", None, None), ("DELETE", s, None, None), ("GET", f"{s}/record", None, None)]
    return cases


def _malformed_stand_b(sid: str) -> list[tuple[str, str, object, bytes | None]]:
    """Requests to a stand-B session a server must refuse with a 4xx."""
    s = f"api/sessions/{sid}"
    cases: list[tuple[str, str, object, bytes | None]] = []
    for name, bad in itertools.product(GOOD_SETTINGS_B, BAD_VALUES):
        cases.append(("POST", f"{s}/controls", {"settings": {name: bad}}, None))
    for name, value in (("normal_force_N", 30.0), ("normal_force_N", 0.0), ("normal_force_N", 200.0),
                        ("l_m", 0.03), ("l_m", -0.021), ("sigma_rad", 0.2), ("sigma_rad", -0.16), ("speed_step", 0.0),
                        ("speed_step", 2.5), ("speed_step", 4.0), ("direction", 0.0), ("direction", 2.0),
                        ("direction", -0.5), ("delta_h_m", 0.0), ("brake_setpoint_N_m", 0.5), ("sigma", 0.1)):
        cases.append(("POST", f"{s}/controls", {"settings": {name: value}}, None))
    cases += [("POST", f"{s}/controls", {"strobe_ratio": 1.0}, None),
              ("POST", f"{s}/controls", {"settings": GOOD_SETTINGS_B, "strobe_ratio": 2.0}, None)]
    for name, bad in itertools.product(GOOD_ANSWERS_B, ("x", True, [0.1], float("nan"), float("inf"))):
        cases.append(("POST", f"{s}/check", {"point": 0, "answers": GOOD_ANSWERS_B | {name: bad}}, None))
    for name in GOOD_ANSWERS_B:
        cases.append(("POST", f"{s}/check", {"point": 0, "answers": {k: v for k, v in GOOD_ANSWERS_B.items() if k != name}},
                      None))
    cases += [("POST", f"{s}/check", {"point": 0, "answers": GOOD_ANSWERS_B | {"i_k": 0.8}}, None),
              ("POST", f"{s}/check", {"point": 1, "answers": GOOD_ANSWERS_B}, None),
              ("POST", f"{s}/record", {"gate_time_s": 100.0}, None)]
    return cases


def test_200_malformed_requests_get_4xx_naming_the_field_and_the_server_still_answers(lab_server, session, exercise_session,
                                                                                      session_b):
    cases = _malformed(session, exercise_session)
    assert len(cases) >= 200
    cases_b = _malformed_stand_b(session_b)
    assert len(cases_b) >= 80
    cases += cases_b
    for method, path, body, raw in cases:
        data = raw if raw is not None else (None if body is None else json.dumps(body).encode())  # NaN as Python writes it
        status, answer = lab_server.request(method, path, raw=data)
        where = f"{method} {path} {body if raw is None else raw!r}"
        assert 400 <= status < 500, (where, status, answer)
        assert isinstance(answer, dict) and answer["field"] and answer["error"], where
        assert answer["field"].split(".")[-1].split("[")[0] in answer["error"] or answer["field"] in ("url", "body",
                                                                                                      "session"), where
    status, state = lab_server.request("GET", f"api/sessions/{session}")
    assert status == 200 and len(state["readings"]) == 1
    assert lab_server.request("GET", f"api/sessions/{exercise_session}", token=TOKENS[exercise_session])[0] == 200
    status, state = lab_server.request("GET", f"api/sessions/{session_b}")
    assert status == 200 and len(state["readings"]) == 1 and state["settings"] == GOOD_SETTINGS_B
    assert lab_server.request("GET", "")[0] == 200
    assert lab_server.process.poll() is None


def test_errors_name_the_exact_field(lab_server, session):
    named = {
        ("POST", "api/sessions", json.dumps({"stand": "disc"})): "stand",
        ("POST", f"api/sessions/{session}/controls", json.dumps({"settings": {"direction": -1}})): "settings.direction",
        ("POST", f"api/sessions/{session}/controls", json.dumps({"settings": {"normal_force_N": 1e6}})):
            "settings.normal_force_N",
        ("POST", f"api/sessions/{session}/controls", '{"settings": {"delta_h_m": NaN}}'): "settings.delta_h_m",
        ("POST", f"api/sessions/{session}/record", json.dumps({"gate_time_s": "4"})): "gate_time_s",
        ("POST", f"api/sessions/{session}/check", json.dumps({"point": 0, "answers": {"l_over_a": 0.1}})):
            "answers.c_over_a",
        ("POST", f"api/sessions/{session}/controls", json.dumps({"setings": {}})): "setings",
    }
    for (method, path, text), field in named.items():
        status, answer = lab_server.request(method, path, raw=text.encode())
        assert (status, answer["field"]) == (400, field), answer


def test_hidden_values_are_not_sent_before_submission(lab_server):
    student = "s-hidden"
    token = lab_server.join(student)
    mu, _ = ClassFile.load(EXAMPLE_CLASS).get("A2").draw(student, lab_server.secret())
    status, state = lab_server.request("POST", "api/sessions", {"stand": "yoke", "exercise": "A2"}, token=token)
    assert status == 201
    sid = state["id"]
    lab_server.request("POST", f"api/sessions/{sid}/controls", {"settings": {"brake_setpoint_N_m": 0.6}}, token=token)
    texts = [json.dumps(state), json.dumps(lab_server.request("POST", f"api/sessions/{sid}/record",
                                                              {"gate_time_s": 1.0}, token=token)[1]),
             json.dumps(lab_server.request("POST", f"api/sessions/{sid}/check", {"point": 0, "answers": GOOD_ANSWERS},
                                           token=token)[1]),
             json.dumps(lab_server.request("GET", f"api/sessions/{sid}", token=token)[1]),
             json.dumps(lab_server.request("GET", "api/exercises")[1]),
             lab_server.request("GET", f"api/sessions/{sid}/live?ratio=100", token=token)[1],
             (lab_server.state_dir / f"{sid}.json").read_text()]
    for text in texts:
        assert repr(mu) not in text and f"{mu:.6f}"[:7] not in text
        assert "true_" not in text and '"mu": 0' not in text
    for text in texts[:-1]:
        assert "bearing_friction" not in text and '"mu"' not in text
    assert lab_server.request("GET", f"api/sessions/{sid}", token=token)[1]["reduced"] == []
    verdict = json.loads(texts[2])
    assert all(set(v) == {"entered"} for v in verdict["values"].values()) and verdict["sent_back_to"]
    status, answer = lab_server.request("POST", f"api/sessions/{sid}/submit",
                                        {"answers": [{"point": 0, "values": GOOD_ANSWERS}], "final": True}, token=token)
    assert status == 200 and answer["results"][0]["truth"]["mu"] == mu
    assert [row["point"] for row in lab_server.request("GET", f"api/sessions/{sid}", token=token)[1]["reduced"]] == [0]


def test_stand_b_hidden_values_are_not_sent_before_submission(lab_server):
    student = "s-hidden-b"
    token = lab_server.join(student)
    mu, _ = ClassFile.load(EXAMPLE_CLASS).get("B1").draw(student, lab_server.secret())
    status, state = lab_server.request("POST", "api/sessions", {"stand": "disc_roller", "exercise": "B1"}, token=token)
    assert status == 201
    sid = state["id"]

    def ask(method, path, body=None):
        return lab_server.request(method, path, body, token=token)[1]

    texts = [json.dumps(state),
             json.dumps(ask("POST", f"api/sessions/{sid}/controls", {"settings": {"l_m": -0.01}})),
             json.dumps(ask("POST", f"api/sessions/{sid}/record", {"gate_time_s": 1.0})),
             json.dumps(ask("POST", f"api/sessions/{sid}/check", {"point": 0, "answers": GOOD_ANSWERS_B})),
             json.dumps(ask("GET", f"api/sessions/{sid}")),
             ask("GET", f"api/sessions/{sid}/live?ratio=100")]
    for text in texts:
        assert repr(mu) not in text and f"{mu:.6f}"[:7] not in text
        assert "law_mu_range" not in text and "true_" not in text and '"mu"' not in text
    assert ask("GET", f"api/sessions/{sid}")["reduced"] == []


def test_concurrent_requests_on_one_session_keep_it_consistent(lab_server):
    sid = lab_server.request("POST", "api/sessions", {"stand": "yoke"})[1]["id"]
    statuses = []

    def record():
        statuses.append(lab_server.request("POST", f"api/sessions/{sid}/record", {"gate_time_s": 0.5})[0])

    def control():
        statuses.append(lab_server.request("POST", f"api/sessions/{sid}/controls",
                                           {"settings": {"brake_setpoint_N_m": 0.4}})[0])

    threads = [threading.Thread(target=f) for f in (record, control, record, record)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert statuses.count(200) == 4
    state = lab_server.request("GET", f"api/sessions/{sid}")[1]
    assert [r["point"] for r in state["readings"]] == [0, 1, 2]
    assert [r["point"] for r in state["reduced"]] == [0, 1, 2]
