"""The study design: which settings each axis runs, the references, the shortened procedure."""

from __future__ import annotations

import dataclasses

import pytest

from rig.accuracy.design import Axis, StudyOptions, scaled_nodes, shorten, study_design
from rig.errors import ParameterError, UnknownNameError
from rig.scenes import load_scene
from rig.stands.base import DriveMode


@pytest.fixture(scope="module")
def scene():
    return load_scene("default")  # stand A, quasi-static, kinematic n = 16, table 25 x 3 x 7, gate 4 s, 9 set-points


def test_node_scaling_and_subsets_by_hand():
    assert scaled_nodes((25, 3, 7), 0.5) == (13, 2, 4)      # 24*0.5+1, 2*0.5+1, 6*0.5+1
    assert scaled_nodes((25, 4, 7), 1.25) == (31, 5, 9)     # 24*1.25+1, round(3.75)+1, round(7.5)+1
    assert scaled_nodes((3, 3, 7), 1.25) == (4, 4, 9)       # halves round up: 2.5 -> 3
    assert scaled_nodes((3, 2, 2), 0.1) == (2, 2, 2)        # never below 2 nodes


def test_shortened_procedure_keeps_ends_and_one_repeat(scene):
    short = shorten(dataclasses.replace(scene.procedure, repeats=3), 4)
    ((name, values),) = short.sweep
    # 9 set-points -1.6 .. 1.6 in steps of 0.4; indices 0, 8/3, 16/3, 8 rounded: 0, 3, 5, 8
    assert name == "brake_setpoint_N_m" and values == pytest.approx((-1.6, -0.4, 0.4, 1.6), abs=1e-12)
    assert short.repeats == 1 and short.n_points == 4
    assert short.gate_time_s == scene.procedure.gate_time_s and short.fixed == scene.procedure.fixed


def test_axes_references_and_scene_choice(scene):
    design = study_design(scene, StudyOptions())
    plans = {plan.axis: plan for plan in design.axes}
    assert list(plans) == [Axis.CONTACT, Axis.TABLE, Axis.DRIVE, Axis.GATE]
    contact = plans[Axis.CONTACT]
    assert len(contact.entries) == 3 * 4 + 1  # kinematic n = 6 added: the reference extrapolates 6 / 12 / 24
    assert contact.entries[contact.reference].label == "kinematic n=24"
    assert [contact.entries[i].label for i in contact.extrapolated] == ["kinematic n=6", "kinematic n=12",
                                                                        "kinematic n=24"]
    assert contact.entries[contact.scene_choice].setting == design.scene_setting
    table = plans[Axis.TABLE]
    assert [e.setting.contact.table_points for e in table.entries] == [(13, 2, 4), (19, 3, 6), (25, 3, 7),
                                                                       (31, 4, 9)]
    assert table.reference == 3 and table.scene_choice == 2
    drive = plans[Axis.DRIVE]
    assert drive.entries[drive.scene_choice].setting.drive is DriveMode.QUASI_STATIC
    assert drive.entries[drive.reference].setting.tolerance_factor == 0.1
    gate = plans[Axis.GATE]
    assert [e.setting.gate_time_s for e in gate.entries] == [1.0, 2.0, 4.0, 8.0] and gate.reference is None
    # the scene's own setting appears on every axis but runs once
    keys = [s.key() for s in design.settings()]
    assert len(keys) == len(set(keys)) == 13 + 3 + 4 + 3


def test_scene_grid_and_model_are_added_and_unsupported_effects_dropped(scene):
    own = dataclasses.replace(scene.contact, n=20, effects={"psi": 1.2})
    design = study_design(dataclasses.replace(scene, contact=own), StudyOptions(models=("fastsim",), grids=(8,)))
    contact = next(p for p in design.axes if p.axis is Axis.CONTACT)
    labels = [e.label for e in contact.entries]
    # kinematic n = 5 and 10 added for the reference's extrapolation (5 / 10 / 20)
    assert labels == ["fastsim n=8 (without psi)", "fastsim n=20 (without psi)", "kinematic n=5", "kinematic n=8",
                      "kinematic n=10", "kinematic n=20"]
    assert contact.entries[contact.scene_choice].setting.contact is own


def test_direct_law_scene_has_no_table_axis_and_dynamic_scene_choice(scene):
    direct = dataclasses.replace(scene, contact=dataclasses.replace(scene.contact, surrogate=False),
                                 drive=DriveMode.DYNAMIC)
    design = study_design(direct, StudyOptions())
    assert Axis.TABLE not in [p.axis for p in design.axes]
    drive = next(p for p in design.axes if p.axis is Axis.DRIVE)
    assert drive.entries[drive.scene_choice].label == "dynamic, stand's tolerances"


def test_bad_options_and_scene_kind_are_named_errors():
    with pytest.raises(UnknownNameError, match="contact model"):
        StudyOptions(models=("kinematik",))
    with pytest.raises(ParameterError, match="grid n"):
        StudyOptions(grids=(2,))
    with pytest.raises(ParameterError, match="gate_factors"):
        StudyOptions(gate_factors=(0.0,))
    with pytest.raises(ParameterError, match="repeats"):
        StudyOptions(repeats=0)
    with pytest.raises(ParameterError, match="stand scene"):
        study_design(load_scene("contact_characteristics"), StudyOptions())


def test_quasi_static_entry_drops_the_effects_the_stand_refuses_without_dynamics(scene):
    from rig.stands.yoke.stand import YokeStand

    brake = {k: v[0] for k, v in YokeStand.EFFECTS["brake_dynamics"].parameters.items()}
    dynamic = dataclasses.replace(scene, drive=DriveMode.DYNAMIC, effects=dict(scene.effects, brake_dynamics=brake))
    design = study_design(dynamic, StudyOptions())
    drive = next(p for p in design.axes if p.axis is Axis.DRIVE)
    assert drive.entries[0].label == "quasi-static (without brake_dynamics)"
    assert drive.entries[0].setting.dropped_effects == ("brake_dynamics",)
    assert all(e.setting.dropped_effects == () for e in drive.entries[1:])


def test_a_setting_the_stand_refuses_fails_before_any_run(scene):
    bad = dataclasses.replace(scene, parameters={"mu": 1.5})  # outside the contact tables' a-priori range
    with pytest.raises(ParameterError, match="mu"):
        study_design(bad, StudyOptions())


def test_procedure_text_names_each_series_and_the_values_kept():
    from rig.accuracy.study import procedure_text
    from rig.scenes import parse_scene

    text = load_scene("default").text.replace("[procedure.fixed]\nnormal_force_N = 96.2", "[procedure.fixed]")
    sweep = text[text.index("[procedure.sweep]"):]
    text = text.replace(sweep, """[[procedure.series]]
fixed = { normal_force_N = 96.2 }
sweep = { brake_setpoint_N_m = [-1.6, -0.8, 0.0, 0.8, 1.6] }
[[procedure.series]]
fixed = { normal_force_N = 385.0 }
sweep = { brake_setpoint_N_m = [-5.0, 5.0] }
""")
    scene = parse_scene(text, name="two_series")
    assert procedure_text(scene.procedure, shorten(scene.procedure, 3)) == (
        "series 1 (normal_force_N = 96.2): brake_setpoint_N_m 3 of 5 values (-1.6, 0, 1.6) / "
        "series 2 (normal_force_N = 385): brake_setpoint_N_m 2 of 2 values (-5, 5)")
