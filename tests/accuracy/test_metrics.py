"""Error measures of the study, against numbers worked out by hand."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from rig.accuracy.metrics import (common_points, lab_time, median_uncertainty, rms_difference,
                                  weighted_truth_error)


def test_rms_difference_matches_points_by_index_and_skips_nan():
    a = pd.Series([1.0, 2.0, np.nan, 4.0], index=[0, 1, 2, 3])
    b = pd.Series([1.5, 2.0, 3.0, 3.0, 9.0], index=[0, 1, 2, 3, 4])
    # common finite points 0, 1, 3: differences -0.5, 0, 1 -> sqrt((0.25 + 0 + 1)/3)
    assert math.isclose(rms_difference(a, b), math.sqrt(1.25 / 3.0), rel_tol=1e-12)
    assert common_points(a, b) == 3
    assert math.isnan(rms_difference(pd.Series([np.nan]), pd.Series([1.0])))


def test_weighted_truth_error_gives_an_ill_conditioned_point_little_weight():
    x = pd.Series([0.41, 0.39, 0.0])
    t = pd.Series([0.40, 0.40, 0.40])
    u = pd.Series([0.01, 0.01, 0.2])  # mu_T at l = 0: undetermined, u ~ 0.2
    # w = 1e4, 1e4, 25: sqrt((1e4 * 1e-4 * 2 + 25 * 0.16)/(2e4 + 25)) = sqrt(6/20025)
    assert math.isclose(weighted_truth_error(x, t, u), math.sqrt(6.0 / 20025.0), rel_tol=1e-12)
    # equal u: the plain RMS
    assert math.isclose(weighted_truth_error(x, t, pd.Series([0.1] * 3)), math.sqrt((2e-4 + 0.16) / 3.0))
    assert math.isnan(weighted_truth_error(x, t, pd.Series([0.0, np.nan, -1.0])))


def test_median_uncertainty_and_lab_time():
    assert median_uncertainty(pd.Series([0.3, np.nan, 0.1, 0.2])) == 0.2
    assert math.isnan(median_uncertainty(pd.Series([np.nan])))
    # two settled points (0.4 s and 0.6 s) with 20 s gates, one point that timed out at 30 s
    assert lab_time(np.array([0.4, 0.6]), 20.0, 1, 30.0) == 0.4 + 0.6 + 40.0 + 30.0
