"""
A first virtual experiment
==========================

The shape of every experiment script: load a scene, change it, run it, look at the result. Here stand A
([Koziarski] Figs. 8-9) sweeps its brake set-point with a friction coefficient of 0.45 instead of the built-in
0.4; the measurement log is reduced with [Koziarski] eqs. (29)-(35), and the reduced coefficients mu_T and mu_v
are held against the value the simulation used.

Run it from the repository root (about ten seconds; the first run on a machine also builds the contact table)::

    python experiments/first_virtual_experiment.py
"""

import tempfile

import matplotlib.pyplot as plt

import rig

# %%
# Load a built-in scene and change it
# -----------------------------------
# ``rig.list_scenes()`` names the built-in scenes (``rig scenes`` on the command line). ``with_`` returns a changed
# copy; every change is checked like the same key in a scene file.

scene = rig.load_scene("default").with_(mu=0.45)
print(scene)
print("mu =", scene["parameters.mu"], "| points:", scene["procedure.sweep.brake_setpoint_N_m"])

# %%
# A change outside the stand's range is refused with a named error (a ``ValueError``) that says the valid range:

try:
    scene.with_(mu=5.0)
except ValueError as error:
    print(error)

# %%
# Run it
# ------
# ``rig.run`` simulates the stand, writes the measurement log and reduces it, exactly as ``rig run`` does, into
# the folder given (here a temporary one). The result reads the folder back as pandas objects.

folder = tempfile.mkdtemp(prefix="first-virtual-experiment-")
result = rig.run(scene, folder)
reduced = result.reduced
print(reduced[["l_over_a", "mu_T", "u_mu_T", "mu_v", "u_mu_v", "true_mu_T"]].round(4))

# %%
# Reduced against truth
# ---------------------
# Each point's reduced coefficient with twice its standard uncertainty, and the friction coefficient the virtual
# stand was built with. Near l/a = 0, eq. (35)'s denominator is small and mu_T's uncertainty large (hard case 8).

fig, ax = plt.subplots(figsize=(7, 4), layout="constrained")
ax.errorbar(reduced["l_over_a"], reduced["mu_T"], yerr=2 * reduced["u_mu_T"], fmt="o", capsize=3,
            label="mu_T, eq. (35), +-2u")
ax.errorbar(reduced["l_over_a"] + 0.02, reduced["mu_v"], yerr=2 * reduced["u_mu_v"], fmt="s", capsize=3,
            label="mu_v, eq. (33), +-2u")
ax.axhline(0.45, color="grey", ls="--", label="mu of the simulation")
ax.set(xlabel="rolling point l/a [1]", ylabel="friction coefficient [1]", title="stand A, mu = 0.45")
ax.legend()
plt.show()

# %%
# The same run later
# ------------------
# ``rig.open_run`` reopens a run folder; ``log`` holds the measurement groups as DataFrames, ``truth`` what the
# simulation knew at each point.

again = rig.open_run(folder)
print(sorted(again.log))
print(again.truth.columns.tolist()[:6])
