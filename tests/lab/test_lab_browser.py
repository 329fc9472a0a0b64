"""The lab in a real headless Chromium: a student's session from the controls to ``rig reduce``.

The correct answers come from ``rig reduce`` run on the log the page saved (a separate process
reading the file), and i_k also from the counts the page shows, by hand: N2 z1/(N1 z2).
"""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from selenium.common.exceptions import TimeoutException
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

import rig.cli
from tests.lab.conftest import START_LIMIT_S

OUTPUTS = ("i_k", "l_over_a", "c_over_a", "nu_T", "nu_v", "mu_v", "mu_T")
WAIT_S = 30.0
POLL_S = 0.05  # WebDriverWait polls every 0.5 s by default: each wait for the server then cost up to 0.5 s idle


def _wait(driver, condition, timeout: float = WAIT_S):
    return WebDriverWait(driver, timeout, poll_frequency=POLL_S).until(condition)


def _attr(driver, element_id: str, name: str) -> str | None:
    return driver.find_element(By.ID, element_id).get_attribute(name)


def _type(driver, element_id: str, text: str) -> None:
    element = driver.find_element(By.ID, element_id)
    element.clear()
    element.send_keys(text)


def _open(driver, url: str) -> None:
    driver.get(url)
    _wait(driver, lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "yes")
    driver.execute_script("document.getElementById('ratio').value = '20'")  # hidden until a session opens


def _open_exercise(driver, url: str, student: str, exercise: str, key: str) -> None:
    """Open the page, enter the student's id and token (or the join code), open the exercise and
    wait until the stand settles."""
    _open(driver, url)
    driver.execute_script("sessionStorage.clear(); lab.token = ''")
    _type(driver, "student", student)
    _type(driver, "token", key)
    Select(driver.find_element(By.ID, "exercise")).select_by_value(exercise)
    driver.find_element(By.ID, "open-exercise").click()
    _settled(driver)


def _settled(driver) -> None:
    try:
        _wait(driver, lambda d: _attr(d, "status", "data-state") == "settled")
    except TimeoutException:
        shown = {i: driver.find_element(By.ID, i).text for i in ("status", "control-error", "exercise-info", "session-info")}
        raise AssertionError(f"not settled within {WAIT_S:g} s: {shown}") from None


def _apply(driver, **values: str) -> None:
    for element_id, text in values.items():
        _type(driver, element_id, text)
    stand_b = driver.find_element(By.TAG_NAME, "body").get_attribute("data-stand") == "disc_roller"
    driver.find_element(By.ID, "apply-b" if stand_b else "apply").click()
    _wait(driver, lambda d: _attr(d, "status", "data-state") == "settling")
    _settled(driver)


def _record(driver, gate_s: str = "4") -> int:
    before = int(driver.find_element(By.TAG_NAME, "body").get_attribute("data-recorded") or 0)
    _type(driver, "gate_time", gate_s)
    driver.find_element(By.ID, "record").click()
    _wait(driver, lambda d: int(d.find_element(By.TAG_NAME, "body").get_attribute("data-recorded") or 0) == before + 1)
    return before


def _check(driver, point: int, answers: dict[str, float | None], outputs: tuple[str, ...] = OUTPUTS) -> str:
    Select(driver.find_element(By.ID, "answer-point")).select_by_value(str(point))
    values = {f"ans-{name}": "" if answers.get(name) is None else repr(answers[name]) for name in outputs}
    driver.execute_script("for (const [id, v] of Object.entries(arguments[0])) document.getElementById(id).value = v",
                          values)  # typed at once: send_keys, key by key, costs seconds per check
    driver.execute_script("document.getElementById('verdict').dataset.result = ''")
    driver.find_element(By.ID, "check").click()
    _wait(driver, lambda d: _attr(d, "verdict", "data-result") != "")
    return _attr(driver, "verdict", "data-result")


def _shown_reduction(driver) -> dict[int, dict[str, float]]:
    driver.find_element(By.ID, "show-reduction").click()
    _wait(driver, lambda d: d.find_element(By.ID, "reduction").is_displayed())
    rows = {}
    for row in driver.find_elements(By.CSS_SELECTOR, "#reduction tbody tr"):
        point = int(row.find_element(By.CSS_SELECTOR, "td").text)
        rows[point] = {name: row.find_element(By.CSS_SELECTOR, f"td.red-{name}").get_attribute("data-value")
                       for name in OUTPUTS}
    return rows


def _rig_reduce(log: Path) -> dict[int, dict[str, str]]:
    """``rig reduce LOG`` (the command's entry point, in this process): reduced.csv by point."""
    assert rig.cli.main(["reduce", str(log)]) == 0
    with open(log.parent / "reduced.csv", newline="") as handle:
        return {int(row["point"]): row for row in csv.DictReader(handle)}


def _save(driver) -> Path:
    driver.execute_script("delete document.getElementById('saved').dataset.path")
    driver.find_element(By.ID, "save").click()
    _wait(driver, lambda d: _attr(d, "saved", "data-path"))
    return Path(_attr(driver, "saved", "data-path"))


def _significant(x: float, digits: int = 4) -> float:
    return float(f"{x:.{digits - 1}e}")


def test_page_and_every_asset_come_from_this_server_within_10_s(lab_server, browser):
    assert lab_server.start_s < START_LIMIT_S
    _open(browser, lab_server.url)
    loaded = browser.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
    assert any(name.endswith("/static/lab.js") for name in loaded) and any(n.endswith("/static/lab.css") for n in loaded)
    linked = browser.execute_script(
        "return [...document.querySelectorAll('[src],[href]')].map(e => e.src || e.href)")
    for address in loaded + linked:
        assert address.startswith(lab_server.url) or address.startswith("data:"), address
    assert lab_server.url.startswith("http://127.0.0.1:")
    rows = browser.find_elements(By.CSS_SELECTOR, "#stand-data tbody tr")
    assert len(rows) == 9  # with symbols and units, not code names; equations rendered by the vendored KaTeX
    a = next(r for r in rows if r.get_attribute("data-name") == "a_m")
    assert a.find_elements(By.TAG_NAME, "td")[1].get_attribute("textContent") == "1.215 mm"
    assert a.find_element(By.CSS_SELECTOR, ".katex") and "a_m" not in a.find_elements(By.TAG_NAME, "td")[0].text
    assert any(name.endswith("/static/vendor/katex/katex.min.js") for name in loaded)


def test_a_recorded_point_reduced_by_rig_reduce_equals_the_page_and_the_sheet_judges(lab_server, browser, screenshot):
    _open(browser, lab_server.url)
    browser.find_element(By.ID, "open-practice").click()
    _settled(browser)
    _apply(browser, brake_setpoint_N_m="0.8", delta_h_mm="1.06")
    assert "settled after" in browser.find_element(By.ID, "status").text
    assert "20× real time" in browser.find_element(By.ID, "ratio-shown").text
    point = _record(browser)
    screenshot(browser, "stand-a-recorded")

    counts = [int(browser.find_element(By.ID, f"counter-{k}").text) for k in (1, 2)]
    z1, z2 = (int(z) for z in browser.find_element(By.ID, "marks").text.split(","))
    reduced = _rig_reduce(_save(browser))[point]
    shown = _shown_reduction(browser)[point]
    for name in OUTPUTS:  # acceptance 2: to the last digit
        assert float(shown[name]) == float(reduced[name]), name
    assert float(reduced["i_k"]) == pytest.approx(counts[1] * z1 / (counts[0] * z2), rel=1e-12)
    assert float(reduced["c_over_a"]) != 0.0  # Delta h = 1.06 mm: the yoke shift gives spin

    correct = {name: _significant(float(reduced[name])) for name in OUTPUTS}
    assert _check(browser, point, correct) == "passed"
    assert len(browser.find_elements(By.CSS_SELECTOR, "#verdict .ok")) == len(OUTPUTS) + 1
    assert len(browser.find_elements(By.CSS_SELECTOR, "#results circle.student")) == 2
    assert len(browser.find_elements(By.CSS_SELECTOR, "#results circle.twin")) == 2
    screenshot(browser, "sheet-passed", "sheet")

    wrong_ratio = correct | {"i_k": correct["i_k"] * 1.02}
    assert _check(browser, point, wrong_ratio) == "back:speed_ratio"
    assert "speed ratio" in browser.find_element(By.ID, "verdict-text").text
    screenshot(browser, "sheet-sent-back", "answer-and-verdict")
    assert _check(browser, point, correct | {"nu_v": correct["nu_v"] * 1.5}) == "back:nu_lookup"
    assert _check(browser, point, correct | {"mu_T": correct["mu_T"] + 0.1}) == "back:friction"
    only_finals = {name: correct[name] for name in ("l_over_a", "c_over_a", "mu_v", "mu_T")}
    assert _check(browser, point, only_finals | {"l_over_a": only_finals["l_over_a"] + 0.3}) == "back:rolling_point"


def test_a_bad_control_is_named_and_leaves_the_stand_as_it_was(lab_server, browser):
    _open(browser, lab_server.url)
    browser.find_element(By.ID, "open-practice").click()
    _settled(browser)
    _type(browser, "normal_force_N", "5000")
    browser.find_element(By.ID, "apply").click()
    _wait(browser, lambda d: d.find_element(By.ID, "control-error").text != "")
    assert "normal_force_N" in browser.find_element(By.ID, "control-error").text
    state = lab_server.request("GET", "api/sessions/" + browser.current_url.split("session=")[1])[1]
    assert state["settings"]["normal_force_N"] == 96.2


def test_a_reload_and_a_second_tab_share_one_uncorrupted_session(lab_server, browser):
    _open(browser, lab_server.url)
    browser.find_element(By.ID, "open-practice").click()
    _settled(browser)
    _record(browser, "2")
    url = browser.current_url
    first = browser.current_window_handle
    browser.switch_to.new_window("tab")
    _open(browser, url)
    _settled(browser)
    _apply(browser, brake_setpoint_N_m="0.6")
    _record(browser, "2")
    browser.close()
    browser.switch_to.window(first)
    _wait(browser, lambda d: len(d.find_elements(By.CSS_SELECTOR, "#points tbody tr")) == 2)  # synced
    assert browser.find_element(By.ID, "brake_setpoint_N_m").get_attribute("value") == "0.6"
    browser.refresh()
    _wait(browser, lambda d: len(d.find_elements(By.CSS_SELECTOR, "#points tbody tr")) == 2)
    rows = [r.text.split() for r in browser.find_elements(By.CSS_SELECTOR, "#points tbody tr")]
    assert [r[0] for r in rows] == ["0", "1"] and [r[3] for r in rows] == ["0", "0.6"]
    reduced = _rig_reduce(_save(browser))
    assert sorted(reduced) == [0, 1]


def test_the_page_before_a_session_a_wild_entry_a_dropped_point_and_a_dead_server(lab_server, browser):
    _open(browser, lab_server.url)
    assert not browser.find_element(By.ID, "bench").is_displayed()  # no bench before a session
    browser.find_element(By.ID, "open-practice").click()
    _settled(browser)
    point = _record(browser, "1")
    _check(browser, point, {"l_over_a": 0.3, "c_over_a": 0.1, "mu_v": 1000.0, "mu_T": 0.4})
    browser.find_element(By.ID, "show-reduction").click()
    _wait(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#results circle.twin"))
    assert len(browser.find_elements(By.CSS_SELECTOR, "#results path.off-scale")) == 1  # mu_v = 1000: at the edge
    twin_y = [float(c.get_attribute("cy")) for c in browser.find_elements(By.CSS_SELECTOR, "#results circle.twin")]
    assert all(15 < cy < 185 for cy in twin_y)  # the twin's points keep the plot
    assert len(browser.find_elements(By.CSS_SELECTOR, "#results text")) > 6  # ticks with their values
    shown = browser.find_element(By.CSS_SELECTOR, "#reduction td.red-mu_v").text
    assert len(shown.replace("-", "").replace(".", "").lstrip("0")) <= 5  # five significant digits
    browser.find_element(By.ID, f"drop-{point}").click()
    assert not browser.find_elements(By.CSS_SELECTOR, "#results .student, #results circle.twin")
    browser.execute_script("window.fetch = () => Promise.reject(new TypeError('network'))")  # the server is gone
    browser.find_element(By.ID, "apply").click()
    _wait(browser, lambda d: d.find_element(By.ID, "offline").is_displayed())
    assert _attr(browser, "status", "data-state") == "offline"
