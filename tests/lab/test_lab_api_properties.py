"""Any JSON a client sends to the lab's API gets an answer, never a server error (hypothesis).

In-process (Flask's test client) on one practice session of each stand with one recorded point;
a 4xx answer names a field, a 2xx one is a valid request that happened to be generated.
"""

from __future__ import annotations

import json

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rig.lab.app import Lab, create_app

KEYS = st.sampled_from(["stand", "settings", "strobe_ratio", "gate_time_s", "point", "answers", "values",
                        "normal_force_N", "brake_setpoint_N_m", "l_over_a", "mu_v", "student", "exercise", "x",
                        "l_m", "sigma_rad", "speed_step", "direction", "M_C_N_m"])
SCALARS = st.none() | st.booleans() | st.integers(-10**20, 10**20) | st.floats() | st.text(max_size=8)
JSON = st.recursive(SCALARS, lambda inner: st.lists(inner, max_size=3) | st.dictionaries(KEYS, inner, max_size=4),
                    max_leaves=12)
ROUTES = st.sampled_from(["api/sessions", "controls", "check", "save", "submit"])  # not record: a valid gate is slow


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    app = create_app(Lab(tmp_path_factory.mktemp("lab")))
    test_client = app.test_client()
    sids = []
    for stand in ("yoke", "disc_roller"):
        sid = test_client.post("/api/sessions", json={"stand": stand}).get_json()["id"]
        assert test_client.post(f"/api/sessions/{sid}/record", json={"gate_time_s": 0.5}).status_code == 200
        sids.append(sid)
    return test_client, sids


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(route=ROUTES, body=JSON, which=st.integers(0, 1))
def test_any_json_body_gets_an_answer_naming_the_field_of_a_refusal(client, route, body, which):
    test_client, sids = client
    sid = sids[which]
    path = "/api/sessions" if route == "api/sessions" else f"/api/sessions/{sid}/{route}"
    response = test_client.post(path, data=json.dumps(body), content_type="application/json")
    assert response.status_code < 500, response.get_data(as_text=True)
    if response.status_code >= 400:
        answer = response.get_json()
        assert answer["field"] and answer["error"]
