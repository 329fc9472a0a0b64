"""A class in a real headless Chromium: two students and the teacher on the example class.

Student s1001 (a listed student, with the token the teacher hands out) and a student who joins
with the class's code each run exercise A1; a wrong value is located to its step and the kind
of slip; attempts are counted, the final one carries a UTC time and shows the answers, and a
resubmission after that is refused with the grade unchanged; s1001's token opens neither the
other's session nor the grade book (403); the teacher's page lists both.
"""

from __future__ import annotations

import csv
import datetime as dt

from selenium.webdriver.common.by import By

from tests.lab.test_lab_browser import _apply, _attr, _check, _open, _open_exercise, _record, _wait

FINALS = ("l_over_a", "c_over_a", "mu_v", "mu_T")


def _tokens(server) -> dict[str, str]:
    text = (server.state_dir / "tokens.csv").read_text()
    return {row["student"]: row["token"] for row in csv.DictReader(text.splitlines())}


def _submit(driver, final: bool) -> str:
    box = driver.find_element(By.ID, "final")
    if box.is_selected() != final:
        box.click()
    driver.execute_script("document.getElementById('submitted').dataset.done = ''")
    driver.find_element(By.ID, "submit").click()
    _wait(driver, lambda d: _attr(d, "submitted", "data-done") not in ("", None))
    return _attr(driver, "submitted", "data-done")


def _speed_ratio(driver) -> float:
    """i_k = N2 z1 / (N1 z2) from the counters and marks the page shows."""
    n1, n2 = (int(driver.find_element(By.ID, f"counter-{k}").text) for k in (1, 2))
    z1, z2 = (int(z) for z in driver.find_element(By.ID, "marks").text.split(","))
    return n2 * z1 / (n1 * z2)


def test_a_class_two_students_and_the_teacher(lab_server, browser, screenshot):
    tokens = _tokens(lab_server)
    # student 1: a wrong speed ratio (upside down) is located to its step and named
    _open_exercise(browser, lab_server.url, "s1001", "A1", tokens["s1001"])
    sid_1 = browser.current_url.split("session=")[1]
    _apply(browser, brake_setpoint_N_m="0.8")
    _record(browser, "2")
    _wait(browser, lambda d: d.find_element(By.ID, "counter-1").text not in ("", "0"))
    i_k = _speed_ratio(browser)
    # mu 0.15: half the least hidden mu of A1 (drawn in [0.30, 0.50] from the class's random secret), so the
    # final attempt fails mu_v whatever the secret (0.3 passed when the secret drew mu near 0.30)
    guesses = {"i_k": 1 / i_k, "l_over_a": 0.5, "c_over_a": 0.0, "mu_v": 0.15, "mu_T": 0.15}
    assert _check(browser, 0, guesses) == "back:speed_ratio"
    assert "inverse" in browser.find_element(By.ID, "verdict-text").text
    assert browser.find_element(By.ID, "checks-left").text == "2"
    assert not browser.find_elements(By.CSS_SELECTOR, "#verdict [id^=v-]")  # per step, not per value
    screenshot(browser, "class-check-located", "sheet")
    assert _check(browser, 0, guesses | {"i_k": i_k}) in ("back:rolling_point", "passed")
    # a counted attempt, then the final one: timestamped, with the answers shown
    assert _submit(browser, final=False) == "yes"
    assert _attr(browser, "attempt", "data-final") == "false"
    assert not browser.find_element(By.ID, "reduction").is_displayed()
    assert _submit(browser, final=True) == "yes"
    attempt = browser.find_element(By.ID, "attempt").text
    assert attempt.startswith("attempt 2 at ") and "final" in attempt
    stamp = dt.datetime.fromisoformat(attempt.split(" at ")[1][:20].replace("Z", "+00:00"))
    assert abs((dt.datetime.now(dt.UTC) - stamp).total_seconds()) < 600
    assert "true μ" in browser.find_element(By.ID, "graded-0").text
    _wait(browser, lambda d: d.find_element(By.ID, "reduction").is_displayed())
    screenshot(browser, "class-final-submission", "sheet")
    # the answers are shown now: resubmitting them changes nothing
    shown = {name: float(browser.find_element(By.CSS_SELECTOR, f"#reduction td.red-{name}").get_attribute("data-value"))
             for name in FINALS}
    assert not browser.find_element(By.ID, "submit").is_enabled()
    status, answer = lab_server.request("POST", f"api/sessions/{sid_1}/submit",
                                        {"answers": [{"point": 0, "values": shown}], "final": True},
                                        token=tokens["s1001"])
    assert status == 409 and answer["field"] == "answers"
    teacher = lab_server.teacher_token()
    book = lab_server.request("GET", "api/grades.csv", token=teacher)[1]
    rows = [r for r in csv.DictReader(book.splitlines()) if r["student"] == "s1001"]
    assert {r["attempt"] for r in rows} == {"1", "2"}
    assert [r["pass"] for r in rows if r["attempt"] == "2" and r["quantity"] == "mu_v"] == ["False"]

    # student 2 joins with the class's code
    _open_exercise(browser, lab_server.url, "s-join-2", "A1", "rolling-2026")
    sid_2 = browser.current_url.split("session=")[1]
    token_2 = browser.execute_script("return lab.token")
    assert sid_2 != sid_1 and len(token_2) == 32
    _record(browser, "2")
    _check(browser, 0, {"l_over_a": 0.2, "c_over_a": 0.0, "mu_v": 0.4, "mu_T": 0.4})
    assert _submit(browser, final=True) == "yes"

    # student 1 cannot open, read or submit student 2's work, nor read the grade book
    _open(browser, f"{lab_server.url}#session={sid_2}")
    browser.execute_script("sessionStorage.setItem('rig-lab-token', arguments[0])", tokens["s1001"])
    browser.refresh()
    _wait(browser, lambda d: "token" in d.find_element(By.ID, "session-info").text)
    assert "another student" in browser.find_element(By.ID, "session-info").text
    mine = tokens["s1001"]
    assert lab_server.request("GET", f"api/sessions/{sid_2}", token=mine)[0] == 403
    assert lab_server.request("POST", f"api/sessions/{sid_2}/submit",
                              {"answers": [{"point": 0, "values": dict.fromkeys(FINALS, 0.1)}]}, token=mine)[0] == 403
    assert lab_server.request("GET", "api/grades.csv", token=mine)[0] == 403
    assert lab_server.request("GET", "api/class", token=mine)[0] == 403

    # the teacher's page: both students' final submissions
    browser.execute_script("sessionStorage.clear()")
    browser.get("about:blank")  # a new page load, not a change of the hash only
    _open(browser, f"{lab_server.url}#teacher={teacher}")
    _wait(browser, lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-teacher") == "yes")
    rows = [r.text for r in browser.find_elements(By.CSS_SELECTOR, "#gradebook tbody tr")]
    assert any(r.startswith("s1001 A1 2") and "final" in r for r in rows)
    assert any(r.startswith("s-join-2 A1 1") and "final" in r for r in rows)
    screenshot(browser, "class-teacher")
