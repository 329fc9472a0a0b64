"""Oscillating contacts of [Oscillating] (issue 6, acceptance 2) with the FAG 7208 inner-ring contact."""

import numpy as np
import pandas as pd
import pytest

from rig.bearing.ball_raceway import Ring
from rig.bearing.fag7208 import FAG_7208
from rig.oscillation import OscillatingContact, amplitude_sweep, plateau_onset

STROKE_RATIOS = [0.5, 0.75, 0.9, 1.0, 1.2, 1.5, 2.0]


@pytest.fixture(scope="module")
def sweeps():
    return {mu: amplitude_sweep(OscillatingContact.ball_raceway(FAG_7208, Ring.INNER, 1270.0, mu),
                                STROKE_RATIOS if mu == 0.1 else [1.5, 2.0], n=16)
            for mu in (0.1, 0.2)}


def test_the_contact_of_seed_002_is_near_sliding():
    contact = OscillatingContact.ball_raceway(FAG_7208, Ring.INNER, 1270.0, 0.1)
    assert 0.5 < contact.alpha < 1.5, "alpha' = 40 mu p0 v/(a E w0) with v/w0 = r_i/sin(40 deg)"
    assert contact.amplitude_deg(1.0) == pytest.approx(1.42, abs=0.01), "e = 1 under K3 (Equations §5.1)"


def test_work_density_grows_below_e_1_then_plateaus(sweeps):
    table = sweeps[0.1]
    work = table.set_index("stroke_ratio")["max_work_J_m2"]
    assert np.all(np.diff(work.loc[[0.5, 0.75, 0.9, 1.0]].to_numpy()) > 0), "grows with the amplitude for e < 1"
    plateau = work.loc[[1.2, 1.5, 2.0]]
    assert plateau.max() - plateau.min() <= 0.05 * plateau.mean(), "constant within 5 % for e >= 1.2"
    assert plateau_onset(table) == pytest.approx(1.0, abs=0.15), "plateau onset within 15 % of e = 1"


def test_doubling_mu_doubles_the_work_and_barely_changes_the_slip_path(sweeps):
    low = sweeps[0.1].set_index("stroke_ratio").loc[[1.5, 2.0]]
    high = sweeps[0.2].set_index("stroke_ratio")
    ratio_work = high["max_work_J_m2"] / low["max_work_J_m2"]
    ratio_path = high["max_slip_path_m"] / low["max_slip_path_m"]
    assert np.all((ratio_work > 1.8) & (ratio_work < 2.2)), ratio_work.to_dict()
    assert np.all(np.abs(ratio_path - 1.0) < 0.10), ratio_path.to_dict()


def test_knee_of_an_ideal_ramp_and_plateau():
    table = pd.DataFrame({"stroke_ratio": [0.25, 0.5, 0.75, 1.2, 1.5], "max_work_J_m2": [1.0, 2.0, 3.0, 4.0, 4.0]})
    assert plateau_onset(table) == pytest.approx(1.0, abs=1e-3)
