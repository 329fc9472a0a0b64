"""The lab's session store: whole files or none, and nothing but session ids names a file."""

from __future__ import annotations

import json

import pytest

from rig.errors import ParameterError
from rig.lab.store import SessionStore

IDENT = "0123456789abcdef"


def test_a_state_is_replaced_whole_and_a_failed_write_leaves_the_old_one(tmp_path):
    store = SessionStore(tmp_path / "state")
    store.write({"id": IDENT, "points": [1]})
    assert store.read(IDENT) == {"id": IDENT, "points": [1]}
    with pytest.raises(ValueError):
        store.write({"id": IDENT, "points": [float("nan")]})  # fails while writing the temporary file
    assert store.read(IDENT) == {"id": IDENT, "points": [1]}
    assert [p.name for p in (tmp_path / "state").iterdir()] == [f"{IDENT}.json"]


@pytest.mark.parametrize("ident", ["../secret", "0123456789ABCDEF", "0123", "0123456789abcdef0", "", "a/b"])
def test_only_a_session_id_names_a_file(tmp_path, ident):
    store = SessionStore(tmp_path)
    assert store.path(ident) is None and store.read(ident) is None


def test_a_damaged_state_file_is_a_named_error(tmp_path):
    (tmp_path / f"{IDENT}.json").write_text('{"id": ')
    with pytest.raises(ParameterError) as caught:
        SessionStore(tmp_path).read(IDENT)
    assert caught.value.name == "session"
    json.loads((tmp_path / f"{IDENT}.json").read_text() + '""}')  # the file itself is left as it was


def test_a_state_folder_the_lab_cannot_write_is_a_named_400_and_the_server_goes_on(tmp_path):
    from rig.lab.app import Lab, create_app

    blocked = tmp_path / "a-file"
    blocked.write_text("not a folder")
    client = create_app(Lab(tmp_path / "out", state_dir=blocked)).test_client()
    response = client.post("/api/sessions", json={"stand": "disc_roller"})
    assert response.status_code == 400 and response.get_json()["field"] == "--state"
    assert client.get("/api/stands").status_code == 200
