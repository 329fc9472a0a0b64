"""Stand B (the disc-roller stand) in a real headless Chromium: controls, recorder, sheet, log, exercise.

The correct answers come from ``rig reduce`` run on the log the page saved; l/a and c/a are also
computed by hand from the page's settings and stand data (eq. 36: c = e sin sigma, mirrored in
reverse running), and mu_v from the page's recorder readings and calibration.
"""

from __future__ import annotations

import math

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

from tests.lab.test_lab_browser import _apply, _check, _open, _record, _rig_reduce, _save, _settled, \
    _significant, _wait

OUTPUTS_B = ("l_over_a", "c_over_a", "M_C_N_m", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T", "mu_M")


def _shown_reduction_b(driver) -> dict[int, dict[str, str]]:
    driver.find_element(By.ID, "show-reduction").click()
    _wait(driver, lambda d: d.find_element(By.ID, "reduction").is_displayed())
    return {int(row.find_element(By.CSS_SELECTOR, "td").text):
            {name: row.find_element(By.CSS_SELECTOR, f"td.red-{name}").get_attribute("data-value")
             for name in OUTPUTS_B}
            for row in driver.find_elements(By.CSS_SELECTOR, "#reduction tbody tr")}


def _stand_data(driver) -> dict[str, float]:
    """The stand data as shown (symbol, value, unit): {code name (tooltip): SI value}."""
    units = {"mm": 1e-3, "m": 1.0}
    data = {}
    for row in driver.find_elements(By.CSS_SELECTOR, "#stand-b-data tbody tr"):
        value, unit = row.find_elements(By.TAG_NAME, "td")[1].get_attribute("textContent").split()
        data[row.get_attribute("title")] = float(value) * units[unit]
    return data


def _choose(driver, element_id: str, value: str) -> None:
    Select(driver.find_element(By.ID, element_id)).select_by_value(value)


def test_a_stand_b_session_reduced_by_rig_reduce_equals_the_page_and_the_sheet_judges(lab_server, browser, screenshot):
    _open(browser, lab_server.url)
    browser.find_element(By.ID, "open-practice-b").click()
    _settled(browser)
    assert browser.find_element(By.TAG_NAME, "body").get_attribute("data-stand") == "disc_roller"
    assert not browser.find_element(By.ID, "strobe-figure").is_displayed()
    assert [o.get_attribute("value") for o in Select(browser.find_element(By.ID, "b_normal_force_N")).options] == \
        ["9", "21", "36", "144"]
    _apply(browser, b_l_mm="-5", b_sigma_deg="2")
    forward = _record(browser, "10")
    screenshot(browser, "stand-b-recorded")
    _choose(browser, "b_direction", "-1")
    _apply(browser)
    assert browser.find_element(By.ID, "sch-b-direction").text.startswith("reverse")
    reverse = _record(browser, "10")

    reduced = _rig_reduce(_save(browser))
    shown = _shown_reduction_b(browser)
    for point in (forward, reverse):  # to the last digit
        for name in OUTPUTS_B:
            assert float(shown[point][name]) == float(reduced[point][name]), (point, name)

    # by hand from what the page shows: l/a, c/a (eq. 36, the reverse point mirrored), mu_v from the recorder
    data = _stand_data(browser)
    e, a = data["pivot_distance_m"], data["half_length_m"]
    sigma = math.radians(2.0)
    assert float(reduced[forward]["l_over_a"]) == float(reduced[reverse]["l_over_a"]) == -0.005 / a
    assert float(reduced[forward]["c_over_a"]) == -float(reduced[reverse]["c_over_a"])
    assert float(reduced[forward]["c_over_a"]) == _approx(e * math.sin(sigma) / a)
    state = lab_server.request("GET", "api/sessions/" + browser.current_url.split("session=")[1])[1]
    for point in (forward, reverse):
        channel = state["readings"][point]["recorder_V"]["F_V"]
        f_v = (channel["mean"] - channel["offset"]) / channel["sensitivity"]
        assert float(reduced[point]["mu_v"]) == _approx(f_v / (36.0 * float(reduced[point]["nu_v"])), 2e-3)

    correct = {point: {name: _significant(float(reduced[point][name])) for name in OUTPUTS_B} for point in (0, 1)}
    for point in (forward, reverse):
        assert _check_b(browser, point, correct[point]) == "passed"
    screenshot(browser, "sheet-b-passed", "sheet")
    wrong_sign = correct[reverse] | {"c_over_a": -correct[reverse]["c_over_a"]}  # the mirror forgotten
    assert _check_b(browser, reverse, wrong_sign) == "back:rolling_point"
    assert "c_over_a: its sign is wrong" in browser.find_element(By.ID, "verdict-text").text
    screenshot(browser, "sheet-b-sent-back", "answer-and-verdict")
    assert _check_b(browser, reverse, correct[reverse] | {"M_C_N_m": correct[reverse]["M_C_N_m"] * 2}) == \
        "back:pivoting_moment"
    assert _check_b(browser, forward, correct[forward] | {"nu_v": correct[forward]["nu_v"] * 1.5}) == "back:nu_lookup"
    assert _check_b(browser, forward, correct[forward] | {"mu_v": correct[forward]["mu_v"] + 0.1}) == "back:friction"
    finals = {name: correct[forward][name] for name in ("l_over_a", "c_over_a", "mu_v")}
    assert _check_b(browser, forward, finals | {"l_over_a": -finals["l_over_a"]}) == "back:rolling_point"


def _approx(x: float, rel: float = 1e-12):
    return pytest.approx(x, rel=rel)


def _check_b(driver, point: int, answers: dict[str, float]) -> str:
    return _check(driver, point, answers, OUTPUTS_B)


def test_stand_a_offers_no_reverse_and_the_server_refuses_it_by_name(lab_server, browser):
    _open(browser, lab_server.url)
    browser.find_element(By.ID, "open-practice").click()
    _settled(browser)
    assert not browser.find_elements(By.ID, "direction_a")  # the model runs forward only: not offered
    sid = browser.current_url.split("session=")[1]
    status, answer = lab_server.request("POST", f"api/sessions/{sid}/controls", {"settings": {"direction": -1}})
    assert status == 400 and answer["field"] == "settings.direction" and "forward only" in answer["error"]
    state = lab_server.request("GET", f"api/sessions/{sid}")[1]
    assert state["version"] == 1 and "direction" not in state["settings"]
