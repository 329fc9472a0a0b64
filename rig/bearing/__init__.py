"""Ball-raceway contacts of an oscillating angular-contact ball bearing ([Oscillating], Schwack et al. 2021).

* ``ball_raceway``: bearing geometry and the Hertz point contact of a ball on either raceway;
* ``kinematics``: ring, cage and ball speeds and the spin at the contacts, eqs. (S4)-(S11);
* ``amplitude``: Harris' critical amplitudes (S1)-(S3) and the stroke ratio e = x/2b (S15);
* ``fag7208``: the FAG 7208 bearing of [Oscillating] Table 1 and the published Table 2.
"""
