"""About 3 000 hostile requests across every endpoint of the lab (Flask's test client, in process):
deeply nested JSON, 400-digit numbers, bodies over the limit, unknown ids and tokens, path
traversal, bad UTF-8, oversized lists. None may be answered with a 5xx, an oversized body gets 413,
and the server answers a plain request after each burst."""

from __future__ import annotations

import json
import logging

import pytest

from rig.lab import requests as rq
from rig.lab.app import MAX_POINTS, Lab, create_app
from rig.lab.exercises import ClassFile
from tests.lab.conftest import EXAMPLE_CLASS

BIG = 10**400  # a 401-digit integer: beyond a float
NUMBER_TEXTS = ("1" + "0" * 400, "-" + "9" * 400, "1e400", "-1e999", "NaN", "Infinity", "1" * 5000)
NESTS = (5000, 50, 9)


def _nested(depth: int) -> bytes:
    return b'{"settings":' + b"[" * depth + b"]" * depth + b"}"


def _nested_object(depth: int) -> bytes:
    return b'{"a":' * depth + b"1" + b"}" * depth


@pytest.fixture(scope="module")
def app(tmp_path_factory):
    """A lab with the example class: a practice session of each stand and an exercise session of a
    listed student (one recorded point each); requests go without a token or with a wrong one."""
    lab = Lab(tmp_path_factory.mktemp("lab-hostile"), ClassFile.load(EXAMPLE_CLASS))
    client = create_app(lab).test_client()
    sids = []
    for stand in ("yoke", "disc_roller"):
        sid = client.post("/api/sessions", json={"stand": stand}).get_json()["id"]
        assert client.post(f"/api/sessions/{sid}/record", json={"gate_time_s": 0.5}).status_code == 200
        sids.append(sid)
    token = {"X-Lab-Token": lab.roster.token_of("s1001")}
    sid = client.post("/api/sessions", json={"stand": "yoke", "exercise": "A1"}, headers=token).get_json()["id"]
    assert client.post(f"/api/sessions/{sid}/record", json={"gate_time_s": 1.0}, headers=token).status_code == 200
    return client, sids + [sid]


def _bodies(field_names: tuple[str, ...]) -> list[bytes]:
    """Hostile bodies for a POST whose fields are ``field_names``."""
    out = [_nested(n) for n in NESTS] + [_nested_object(n) for n in NESTS]
    out += [b"\xff\xfe\x00", b"", b"{", b"[" * 20000, b'{"a": "' + b'\\"' * 5000 + b'"}', b"1" * 5000]
    for name in field_names:
        for text in NUMBER_TEXTS:
            out.append(f'{{"{name}": {text}}}'.encode())
        out.append(json.dumps({name: "x" * 30000}).encode())
        out.append(json.dumps({name: list(range(5000))}).encode())
        out.append(json.dumps({name: {str(k): 1 for k in range(2000)}}).encode())
    for outer in ("settings", "answers", "values"):
        for key in ("normal_force_N", "brake_setpoint_N_m", "l_m", "mu_v", "l_over_a", "point"):
            for text in NUMBER_TEXTS[:4]:
                out.append(f'{{"{outer}": {{"{key}": {text}}}}}'.encode())
    return out


def _requests(sids: list[str]) -> list[tuple[str, str, bytes | None]]:
    """(method, path, raw body) of every hostile request."""
    cases: list[tuple[str, str, bytes | None]] = []
    posts = {"/api/sessions": ("stand", "student", "exercise", "token"), "/api/join": ("student", "join_code")}
    for sid in sids + ["0" * 16, "f" * 16, "../../etc/passwd", "x" * 3000, "%00", "..%2f..%2fstate"]:
        base = f"/api/sessions/{sid}"
        posts |= {f"{base}/controls": ("settings", "strobe_ratio"), f"{base}/record": ("gate_time_s",),
                  f"{base}/check": ("point", "answers"), f"{base}/save": ("x",),
                  f"{base}/submit": ("answers", "final"),
                  f"{base}/nu": ("point", "l_over_a", "c_over_a", "alpha_prime")}
        for query in ("", "?ratio=" + "9" * 400, "?ratio=nan", "?ratio=-1", "?ratio=1e999", "?token=" + "a" * 5000,
                      "?token=../../state/class-secret"):
            for tail in ("", "/live", "/log.h5", "/readings.csv"):
                cases.append(("GET", f"{base}{tail}{query}", None))
    for path, names in posts.items():
        for raw in _bodies(names):
            cases.append(("POST", path, raw))
    for sid in sids:  # oversized lists in a submission and in a check
        entries = [{"point": 0, "values": {"l_over_a": 0.1}}] * (MAX_POINTS + 1)
        cases.append(("POST", f"/api/sessions/{sid}/submit", json.dumps({"answers": entries}).encode()))
        cases.append(("POST", f"/api/sessions/{sid}/submit", json.dumps({"answers": [{"point": 0}] * 3000}).encode()))
        cases.append(("POST", f"/api/sessions/{sid}/check",
                      json.dumps({"point": BIG, "answers": {"l_over_a": 1}}, default=str).encode()))
        for values in ({"l_over_a": 1e308, "c_over_a": -1e308, "alpha_prime": 1e-308}, {"l_over_a": 0.3, "c_over_a": 0.0,
                       "alpha_prime": 1e6}, {"l_over_a": "x", "c_over_a": None, "alpha_prime": []}):
            cases.append(("POST", f"/api/sessions/{sid}/nu", json.dumps({"point": 0} | values).encode()))
    for path in ("/static/../app.py", "/static/..%2f..%2fapp.py", "/static/%2e%2e/%2e%2e/state",
                 "/static/vendor/../../x",
                 "/../../etc/passwd", "/api/grades.csv?token=" + "z" * 100, "/api/grades.csv", "/api/exercises",
                 "/api/stands", "/api/class", "/api/me", "/api/me?token=" + "f" * 32, "/api/class?token=x",
                 "/api/sessions", "/static/" + "a/" * 2000, "/static/vendor/katex/../../../app.py"):
        cases.append(("GET", path, None))
    return cases


def test_three_thousand_hostile_requests_get_no_5xx_and_the_server_keeps_answering(app, caplog):
    client, sids = app
    cases = _requests(sids)
    assert len(cases) >= 3000
    statuses: dict[int, int] = {}
    failures = []
    with caplog.at_level(logging.ERROR, logger="rig.lab"):
        for k, (method, path, raw) in enumerate(cases):
            response = client.open(path, method=method, data=raw, content_type="application/json")
            statuses[response.status_code] = statuses.get(response.status_code, 0) + 1
            if response.status_code >= 500:
                failures.append((method, path[:80], (raw or b"")[:80], response.get_data(as_text=True)[:200]))
            if k % 200 == 0:  # after each burst the server still answers a plain request
                assert client.get("/api/stands").status_code == 200
    assert not failures, failures[:5]
    assert not caplog.records, [r.getMessage() for r in caplog.records][:3]  # no defect reached the last resort
    assert client.get(f"/api/sessions/{sids[0]}").status_code == 200


def test_a_body_over_the_limit_is_refused_with_413_unread(app):
    client, sids = app
    big = b'{"gate_time_s": 1, "x": "' + b"a" * (20 * 1024 * 1024) + b'"}'
    for path in ("/api/sessions", f"/api/sessions/{sids[0]}/record", f"/api/sessions/{sids[0]}/submit"):
        response = client.post(path, data=big, content_type="application/json")
        assert response.status_code == 413
        assert response.get_json()["field"] == "body" and len(response.get_data()) < 500  # not echoed back


@pytest.mark.parametrize("raw, field", [
    (_nested(5000), "body"), (_nested_object(5000), "body"),
    (b'{"gate_time_s": 1' + b"0" * 400 + b"}", "gate_time_s"),
    (b'{"gate_time_s": 1e400}', "gate_time_s"),
])
def test_deep_nesting_and_overflowing_numbers_are_400_naming_the_field(app, raw, field):
    client, sids = app
    response = client.post(f"/api/sessions/{sids[0]}/record", data=raw, content_type="application/json")
    assert response.status_code == 400 and response.get_json()["field"] == field


def test_the_json_depth_is_measured_outside_strings_only():
    assert rq.depth(b'{"a": [[1, "[[[{{"], {"b": "]]]"}]}') == 3
    assert rq.depth(b'{"a": "\\"[["}') == 1
    assert rq.depth(b"[" * 5000) == 5000


def test_an_integer_beyond_a_float_is_a_named_parameter_error():
    from rig import validate
    from rig.errors import ParameterError

    with pytest.raises(ParameterError, match="^x ="):
        validate.number("x", BIG)
