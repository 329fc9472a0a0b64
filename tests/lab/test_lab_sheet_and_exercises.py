"""The lab sheet's judge and the teacher's exercise file (no server, no browser)."""

from __future__ import annotations

import pytest

from rig.errors import ParameterError
from rig.lab.exercises import ClassFile, GradeBook, student_id
from rig.lab.sheet import ROUNDING, STAND_A, Tolerance, default_tolerances, judge
from tests.lab.conftest import EXAMPLE_CLASS

REDUCED = {"i_k": 0.8, "U95_i_k": 0.001, "l_over_a": 0.25, "U95_l_over_a": 0.02, "c_over_a": 0.0, "U95_c_over_a": 0.0,
           "nu_T": -0.5, "U95_nu_T": 0.02, "nu_v": 0.05, "U95_nu_v": 0.002, "mu_v": 0.4, "U95_mu_v": 0.016,
           "mu_T": 0.38, "U95_mu_T": 0.015}
RIGHT = {"i_k": 0.8005, "l_over_a": 0.255, "c_over_a": 0.0, "nu_T": -0.503, "nu_v": 0.0505, "mu_v": 0.403,
         "mu_T": 0.382}


def test_values_within_tolerance_pass_and_the_first_wrong_step_is_named():
    assert judge(RIGHT, REDUCED)["passed"] is True
    for name, step in (("i_k", "speed_ratio"), ("l_over_a", "rolling_point"), ("c_over_a", "rolling_point"),
                       ("nu_T", "nu_lookup"), ("nu_v", "nu_lookup"), ("mu_v", "friction"), ("mu_T", "friction")):
        wrong = RIGHT | {name: RIGHT[name] + 0.1}
        verdict = judge(wrong, REDUCED)
        assert verdict["sent_back_to"]["step"] == step and verdict["values"][name]["ok"] is False
    # an error in i_k carried through every later value: sent back to the first step, not the last
    assert judge({k: v * 1.1 for k, v in RIGHT.items()}, REDUCED)["sent_back_to"]["step"] == "speed_ratio"


def test_the_tolerance_is_stated_not_the_reductions_u95():
    assert Tolerance(0.02).band(0.4) == pytest.approx(0.008)
    assert Tolerance(0.0, 0.01).band(0.001) == 0.01
    assert Tolerance(0.0, 0.0).band(0.8) == pytest.approx(ROUNDING * 0.8)
    # a wide U95 (a short gate) does not widen the band: 30 % off fails whatever the gate
    lax = REDUCED | {"U95_mu_T": 0.5}
    assert not judge(RIGHT | {"mu_T": 0.38 * 1.3}, lax)["passed"]
    tolerances = default_tolerances(STAND_A) | {"mu_v": Tolerance(0.05)}
    edge = REDUCED["mu_v"] * 1.05
    assert judge(RIGHT | {"mu_v": edge * (1 - 1e-9)}, REDUCED, STAND_A, tolerances)["passed"]
    assert not judge(RIGHT | {"mu_v": edge * (1 + 1e-6)}, REDUCED, STAND_A, tolerances)["passed"]


@pytest.mark.parametrize("name, entered, kind", [
    ("mu_v", -0.4, "sign"), ("mu_T", 380.0, "units"), ("l_over_a", 0.25e-3, "units"), ("i_k", 1 / 0.8, "inverted"),
])
def test_a_wrong_value_is_named_by_its_kind_of_slip(name, entered, kind):
    verdict = judge(RIGHT | {name: entered}, REDUCED)
    assert verdict["sent_back_to"]["slips"] == [{"quantity": name, "kind": kind}]
    assert verdict["steps"][verdict["sent_back_to"]["step"]] is False
    assert judge(RIGHT | {name: RIGHT[name] * 1.3}, REDUCED)["sent_back_to"]["slips"] == []


def test_an_output_the_reduction_could_not_give_is_not_passed():
    verdict = judge(RIGHT, REDUCED | {"mu_T": None})
    assert verdict["values"]["mu_T"] == {"entered": 0.382, "reduced": None, "tolerance": None, "ok": False}


def test_a_students_hidden_mu_is_reproducible_and_inside_the_range():
    exercise = ClassFile.load(EXAMPLE_CLASS).get("A1")
    draws = [exercise.draw(f"s{k}", b"secret") for k in range(200)]
    assert exercise.draw("s7", b"secret") == draws[7]
    assert exercise.draw("s7", b"another") != draws[7]  # without the class's secret, not computable
    mus = [mu for mu, _ in draws]
    assert all(0.30 <= mu <= 0.50 for mu in mus) and max(mus) - min(mus) > 0.15
    assert len({seed for _, seed in draws}) == 200
    assert "mu" not in exercise.public() and "effects" not in exercise.public()


@pytest.mark.parametrize("text, field", [
    ('title = "x"\n', "exercise"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "disc"\nmu = [0.3, 0.4]\nfree = []\n', "exercise[0].stand"),
    # stand B: the hidden mu within the lab's tables (0.5-1.0), loads among the dead weights
    ('[[exercise]]\nid = "B"\ntitle = "t"\nstand = "disc_roller"\nmu = [0.3, 0.6]\nfree = []\n', "exercise[0].mu[0]"),
    ('[[exercise]]\nid = "B"\ntitle = "t"\nstand = "disc_roller"\nmu = [0.6, 0.8]\nfree = ["delta_h_m"]\n',
     "exercise[0].free control"),
    ('[[exercise]]\nid = "B"\ntitle = "t"\nstand = "disc_roller"\nmu = [0.6, 0.8]\nfree = []\n'
     '[exercise.start]\nnormal_force_N = 30.0\n', "exercise[0].start.normal_force_N"),
    ('[[exercise]]\nid = "B"\ntitle = "t"\nstand = "disc_roller"\nmu = [0.6, 0.8]\nfree = []\n'
     '[exercise.start]\ndirection = 0.0\n', "exercise[0].start.direction"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.5, 0.4]\nfree = []\n', "exercise[0].mu[1]"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = ["brake"]\n', "exercise[0].free control"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\n', "exercise[0].free"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = [1]\n', "exercise[0].free"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\nstart = 3\n',
     "exercise[0].start"),
    ('[[exercise]]\nid = "A b"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n', "exercise[0].id"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n'
     '[exercise.start]\nnormal_force_N = 1.0\n', "exercise[0].start.normal_force_N"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n'
     '[exercise.effects.bearing_friction]\nmoment_1_N_m = 5.0\n', "effects.bearing_friction.moment_1_N_m"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\nhidden = 1\n',
     "exercise[0] key"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n'
     '[exercise.tolerance]\nmu = {relative = 0.1}\n', "exercise[0].tolerance quantity"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n'
     '[exercise.tolerance]\nmu_v = {relative = -0.1}\n', "exercise[0].tolerance.mu_v.relative"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\nattempts = 0\n',
     "exercise[0].attempts"),
    ('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\ndeadline = "soon"\n',
     "exercise[0].deadline"),
    ('[class]\nstudents = ["a b"]\n[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n',
     "student"),
    ('[class]\nattempts = 2\n[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n',
     "class"),
])
def test_a_bad_exercise_file_is_a_named_error(tmp_path, text, field):
    path = tmp_path / "class.toml"
    path.write_text(text + '\n[class]\njoin_code = "abcdef"\n' if "[class]" not in text else text)
    with pytest.raises(ParameterError) as caught:
        ClassFile.load(path)
    assert caught.value.name == field


def test_student_ids_and_the_grade_book():
    with pytest.raises(ParameterError):
        student_id("a b")
    book = GradeBook()
    row = dict(point=0, quantity="mu_v", submitted=0.4, reduced=0.41, tolerance=0.02, true=0.405, **{"pass": True})
    t = "2026-01-01T00:00:00Z"
    book.submit("s2", "A1", [row], time_utc=t)
    book.submit("s1", "A1", [row | {"pass": False}], final=False, time_utc=t)
    book.submit("s1", "A1", [row], time_utc=t)  # a second attempt is added, not a replacement
    with pytest.raises(ParameterError):  # after the final attempt, nothing
        book.submit("s1", "A1", [row | {"pass": False}], time_utc=t)
    assert (book.attempts("s1", "A1"), book.final("s1", "A1"), book.attempts("s3", "A1")) == (2, True, 0)
    lines = book.csv().splitlines()
    assert lines[0] == "student,exercise,attempt,time_utc,final,point,quantity,submitted,reduced,tolerance,true,pass"
    assert lines[1:] == [f"s1,A1,1,{t},False,0,mu_v,0.4,0.41,0.02,0.405,False",
                         f"s1,A1,2,{t},True,0,mu_v,0.4,0.41,0.02,0.405,True",
                         f"s2,A1,1,{t},True,0,mu_v,0.4,0.41,0.02,0.405,True"]


def test_a_tolerance_of_k_times_the_students_stated_uncertainty_counts_only_when_the_claim_is_plausible():
    tolerances = default_tolerances(STAND_A) | {"mu_T": Tolerance(0.01, 0.0, 2.0)}
    off = RIGHT | {"mu_T": REDUCED["mu_T"] + 0.02}  # 5 % off: outside 1 %
    assert not judge(off, REDUCED, STAND_A, tolerances)["passed"]
    # stated U95 = 0.012 (the reduction's 0.015 within a factor 3): band 2 x 0.012 = 0.024 holds 0.02
    assert judge(off | {"U95_mu_T": 0.012}, REDUCED, STAND_A, tolerances)["passed"]
    # a claim of 0.2 (13 x the reduction's U95) widens nothing: the value fails
    assert not judge(off | {"U95_mu_T": 0.2}, REDUCED, STAND_A, tolerances)["passed"]
    # without k in the exercise, a stated U95 changes nothing
    assert not judge(off | {"U95_mu_T": 0.012}, REDUCED)["passed"]
