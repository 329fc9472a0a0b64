"""A student finishes the stand-A exercise from the page alone, in a real headless Chromium.

Every number the test enters it computes from what the page shows - the counters and marks, the
dynamometer and its calibration, the balance, the settings in the points table, the stand data
(symbols and units) and the page's nu lookup (b/a and nu_T, nu_v, nu_0 at the l/a, c/a, alpha' it
typed) - with the sheet's equations ([Koziarski] eqs. (21), (29)-(33), (35)), iterating mu in
alpha' as the method requires. No reduction is read, no log is saved; the final submission passes.
"""

from __future__ import annotations

import math

from selenium.webdriver.common.by import By

from tests.lab.conftest import JOIN_CODE
from tests.lab.test_lab_browser import _apply, _attr, _check, _open_exercise, _record, _type, _wait
from tests.lab.test_lab_browser_class import _speed_ratio, _submit

SHEET = ("i_k", "l_over_a", "c_over_a", "F_y_N", "alpha_prime", "nu_T", "nu_v", "nu_0", "mu_v", "mu_T")
UNITS = {"mm": 1e-3, "rad": 1.0, "m": 1.0}


def _stand_data(driver) -> dict[str, float]:
    """The stand data table: {code name (tooltip): SI value from the shown value and unit}."""
    data = {}
    for row in driver.find_elements(By.CSS_SELECTOR, "#stand-data tbody tr"):
        value, unit = row.find_elements(By.TAG_NAME, "td")[1].get_attribute("textContent").split()
        data[row.get_attribute("title")] = float(value) * UNITS[unit]
    return data


def _lookup(driver, l_over_a: float, c_over_a: float, alpha: float) -> dict[str, float]:
    for name, value in (("l_over_a", l_over_a), ("c_over_a", c_over_a), ("alpha_prime", alpha)):
        _type(driver, f"nu-{name}", repr(value))
    driver.execute_script("document.getElementById('nu-values').dataset.done = ''")
    driver.find_element(By.ID, "nu-lookup").click()
    _wait(driver, lambda d: _attr(d, "nu-values", "data-done") == "yes")
    shown = {name: float(driver.find_element(By.ID, f"nu-out-{name}").text) for name in ("nu_T", "nu_v", "nu_0")}
    return shown | {"b_over_a": float(driver.find_element(By.ID, "nu-b_over_a").text)}


def test_the_stand_a_exercise_finished_from_the_page_alone(lab_server, browser, screenshot):
    _open_exercise(browser, lab_server.url, "s-sheet", "A2", JOIN_CODE)
    _apply(browser, brake_setpoint_N_m="0.8")
    _record(browser, "4")
    _wait(browser, lambda d: d.find_element(By.ID, "counter-1").text not in ("", "0"))
    g = _stand_data(browser)
    i_k = _speed_ratio(browser)
    cells = browser.find_elements(By.CSS_SELECTOR, "#point-0 td")
    f_n, delta_h = float(cells[1].text), float(cells[2].text) * 1e-3  # F_N [N], Delta h [mm]
    mean = float(browser.find_element(By.ID, "dynamometer").text.split()[0])
    sensitivity, offset = (float(x) for x in browser.find_element(By.ID, "calibration").text.split(","))
    t2 = float(browser.find_element(By.ID, "balance").text.split()[0])

    sin_a1 = math.sin(g["alpha_1_rad"])
    l = (g["l1_m"] * sin_a1 + i_k * g["l2_m"]) / (sin_a1 + i_k)  # eqs. (29)-(32)
    c = i_k * delta_h / (sin_a1 + i_k)
    l_a, c_a = l / g["a_m"], c / g["a_m"]
    f_y = (mean - offset) / sensitivity * g["dynamometer_lever_m"] / g["yoke_lever_m"]  # eq. (33)
    v_over_spin = g["r1_m"] / (sin_a1 + i_k)
    mu, b_over_a = 0.4, None
    for _ in range(12):  # mu <-> alpha' (eq. 21): look up nu at alpha'(mu), mu = F_y/(F_N nu_v), again
        alpha = 10.0 * mu * (b_over_a or 1.0) * v_over_spin / g["radius_x_m"]
        nu = _lookup(browser, l_a, c_a, alpha)
        if b_over_a is None:  # the load's b/a, shown by the lookup: start again with it
            b_over_a = nu["b_over_a"]
            continue
        previous, mu = mu, f_y / (f_n * nu["nu_v"])
        if abs(mu - previous) < 1e-5 * mu:
            break
    alpha = 10.0 * mu * b_over_a * v_over_spin / g["radius_x_m"]
    nu = _lookup(browser, l_a, c_a, alpha)
    d = -(l - g["l2_m"]) * nu["nu_T"] - g["a_m"] * nu["nu_0"]
    answers = {"i_k": i_k, "l_over_a": l_a, "c_over_a": c_a, "F_y_N": f_y, "alpha_prime": alpha, "nu_T": nu["nu_T"],
               "nu_v": nu["nu_v"], "nu_0": nu["nu_0"], "mu_v": f_y / (f_n * nu["nu_v"]),
               "mu_T": (t2 + f_y * (delta_h - c)) / (f_n * d)}  # eq. (35)
    answers = {name: float(f"{value:.5g}") for name, value in answers.items()}
    assert _check(browser, 0, answers, SHEET) == "passed", browser.find_element(By.ID, "verdict").text
    assert all(row.get_attribute("data-ok") == "yes" for row in browser.find_elements(By.CSS_SELECTOR, "#steps tr"))
    screenshot(browser, "sheet-steps-passed", "sheet")
    assert _submit(browser, final=True) == "yes"
    graded = browser.find_element(By.ID, "graded-0").text
    assert graded.startswith("point 0: passed"), graded
