"""Sessions outlive the server: ``rig lab --state DIR`` stopped and started again gives a student back
their session - its points, reduction and checked answers - in a real headless Chromium."""

from __future__ import annotations

import json
import re

from selenium.webdriver.common.by import By

from tests.lab.conftest import EXAMPLE_CLASS, start_server, warm_up
from tests.lab.test_lab_browser import _apply, _check, _open, _record, _settled, _significant, _wait
from tests.lab.test_lab_browser_stand_b import OUTPUTS_B

KEPT = ("stand", "settings", "readings", "reduced", "answers", "free", "exercise")


def _rows(driver) -> int:
    return len(driver.find_elements(By.CSS_SELECTOR, "#points tbody tr"))


def test_sessions_of_both_stands_survive_a_server_restart(tmp_path, browser):
    out, state_dir = tmp_path / "out", tmp_path / "state"
    out.mkdir()
    options = ("--state", str(state_dir), "--exercises", str(EXAMPLE_CLASS))
    server = start_server(out, *options)
    try:
        warm_up(server)
        _open(browser, server.url)
        browser.find_element(By.ID, "open-practice-b").click()
        _settled(browser)
        _apply(browser, b_l_mm="8", b_sigma_deg="-1")
        _record(browser, "4")
        sid_b = browser.current_url.split("session=")[1]
        reduced = server.request("GET", f"api/sessions/{sid_b}")[1]["reduced"][0]["values"]
        answers = {name: _significant(reduced[name]) for name in OUTPUTS_B}
        assert _check(browser, 0, answers, OUTPUTS_B) == "passed"
        token = server.join("s-restart")
        sid_a = server.request("POST", "api/sessions", {"stand": "yoke", "exercise": "A1"}, token=token)[1]["id"]
        assert server.request("POST", f"api/sessions/{sid_a}/record", {"gate_time_s": 1.0}, token=token)[0] == 200
        before = {sid: server.request("GET", f"api/sessions/{sid}", token=token)[1] for sid in (sid_a, sid_b)}
    finally:
        server.stop()
    files = sorted(p.name for p in state_dir.iterdir())
    assert {f"{sid_a}.json", f"{sid_b}.json"} <= set(files)
    class_files = {"class-secret", "teacher-token", "tokens.csv", "roster.json"}
    assert class_files <= set(files) and all(re.fullmatch(r"[0-9a-f]{16}\.json", n) for n in set(files) - class_files)
    assert json.loads((state_dir / f"{sid_b}.json").read_text())["answers"] == {"0": answers}

    server = start_server(out, *options)
    try:
        after_a = server.request("GET", f"api/sessions/{sid_a}", token=token)[1]
        assert {k: after_a[k] for k in KEPT} == {k: before[sid_a][k] for k in KEPT}
        _open(browser, f"{server.url}#session={sid_b}")
        _wait(browser, lambda d: _rows(d) == 1)
        _settled(browser)  # the restored session settles again at its settings
        assert [float(browser.find_element(By.ID, f"ans-{n}").get_attribute("value")) for n in ("l_over_a", "mu_v")] == \
            [answers["l_over_a"], answers["mu_v"]]  # the checked answers are back in the sheet
        after_b = server.request("GET", f"api/sessions/{sid_b}")[1]
        assert {k: after_b[k] for k in KEPT} == {k: before[sid_b][k] for k in KEPT}
        _record(browser, "4")  # and goes on
        assert _rows(browser) == 2
        assert len(server.request("GET", f"api/sessions/{sid_b}")[1]["reduced"]) == 2
    finally:
        server.stop()
