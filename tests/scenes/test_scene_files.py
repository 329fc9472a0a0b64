"""Built-in scenes: shipped as package data (never by importing experiments), RIG_SCENES_DIR, names,
paths; the shipped scenes validate; the characteristics scene kind."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

import rig
from rig.errors import ParameterError, UnknownNameError
from rig.characteristics import sweep
from rig.scenes import CharacteristicsScene, builtin_scenes, load_scene, parse_scene, resolve_scene, scenes_dir
from rig.scenes.locate import ENV_VAR
from tests.runner.fake_stand import register, scene_text

SOURCE_SCENES = Path(rig.__file__).resolve().parent / "scenes" / "builtin"
TINY_CHARACTERISTICS = """\
# Tiny characteristics scene for tests: the rigid model only.
[scene]
kind = "contact_characteristics"
description = "rigid pure spin, three alpha'"

[characteristics]
models = ["rigid"]
poisson = 0.3
n = 64
alpha = { start = 0.1, stop = 10, num = 3, spacing = "log" }

[[characteristics.cases]]
shape = "ellipse"
b_over_a = 1.0
c_over_a = 0.0
l_over_a = 0.0
"""


@pytest.fixture
def scene_folder(tmp_path, monkeypatch):
    register(monkeypatch)
    (tmp_path / "fake.toml").write_text(scene_text())
    (tmp_path / "tiny.toml").write_text(TINY_CHARACTERISTICS)
    monkeypatch.setenv(ENV_VAR, str(tmp_path))
    return tmp_path


def test_default_folder_is_the_packages_builtin_scenes(monkeypatch):
    monkeypatch.delenv(ENV_VAR, raising=False)
    assert scenes_dir() == SOURCE_SCENES
    assert {"contact_characteristics", "default"} <= {s.name for s in builtin_scenes()}
    assert "experiments" not in sys.modules and "experiments.scenes" not in sys.modules


def test_every_builtin_scene_starts_with_a_comment_block(monkeypatch):
    monkeypatch.delenv(ENV_VAR, raising=False)
    for scene in builtin_scenes():
        assert scene.path.read_text().startswith("# "), scene.name


def test_every_builtin_scene_validates(monkeypatch):
    monkeypatch.delenv(ENV_VAR, raising=False)
    scenes = {scene.name: load_scene(scene.name) for scene in builtin_scenes()}
    assert isinstance(scenes["contact_characteristics"], CharacteristicsScene)
    assert scenes["default"].stand == "yoke"


def test_override_lists_names_with_descriptions(scene_folder):
    assert [(s.name, s.description) for s in builtin_scenes()] == [
        ("fake", "fake stand load sweep"), ("tiny", "rigid pure spin, three alpha'")]


def test_unknown_builtin_name_suggests_the_closest(scene_folder):
    with pytest.raises(UnknownNameError, match="did you mean 'tiny'"):
        load_scene("tinny")


def test_path_and_name_give_the_same_scene(scene_folder):
    by_name, by_path = load_scene("fake"), load_scene(scene_folder / "fake.toml")
    assert by_name == by_path and by_name.name == "fake"
    assert resolve_scene(str(scene_folder / "fake.toml")) == scene_folder / "fake.toml"


def test_missing_folder_or_file_is_a_clear_error(tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(tmp_path / "nowhere"))
    with pytest.raises(ParameterError, match=ENV_VAR):
        scenes_dir()
    with pytest.raises(ParameterError, match="existing scene file"):
        load_scene(tmp_path / "absent.toml")


def test_characteristics_scene_is_read_and_checked():
    scene = parse_scene(TINY_CHARACTERISTICS, name="tiny")
    assert scene.models == ("rigid",) and scene.n == 64 and scene.poisson == 0.3
    assert scene.alphas == pytest.approx((0.1, 1.0, 10.0), rel=1e-12)
    assert scene.cases[0].label == "ellipse b/a=1, C=(0, 0)a"
    with pytest.raises(UnknownNameError, match="did you mean 'fastsim'"):
        parse_scene(TINY_CHARACTERISTICS.replace('["rigid"]', '["fastsm"]'), name="tiny")
    with pytest.raises(ParameterError) as info:
        parse_scene(TINY_CHARACTERISTICS.replace("b_over_a = 1.0", "b_over_a = 20.0"), name="tiny")
    assert info.value.name == "characteristics.cases[0].b_over_a" and info.value.valid == "[0.1, 10]"
    with pytest.raises(ParameterError) as info:
        parse_scene(TINY_CHARACTERISTICS.replace("n = 64\n", ""), name="tiny")
    assert info.value.name == "characteristics.n" and info.value.value == "missing"
    with pytest.raises(ParameterError, match="> 0 for spacing = 'log'"):
        parse_scene(TINY_CHARACTERISTICS.replace("start = 0.1", "start = 0"), name="tiny")


def _doc_examples() -> list[str]:
    text = (REPO_DOCS / "scenes.md").read_text()
    return [block.split("```", 1)[0] for block in text.split("```toml\n")[1:]]


REPO_DOCS = Path(__file__).resolve().parents[2] / "docs"


def test_the_annotated_examples_of_docs_scenes_md_validate():
    stand_example, characteristics_example = _doc_examples()
    scene = parse_scene(characteristics_example, name="doc")
    assert isinstance(scene, CharacteristicsScene) and len(scene.alphas) == 25
    scene = parse_scene(stand_example, name="doc")
    assert scene.stand == "yoke" and scene.procedure.n_points == 8
    assert scene.contact.effects == {"psi": 1.2} and scene.effects["dynamometer_noise"] == {"std_V": 2e-6}


def test_characteristics_variants_run_the_kinematic_model_with_their_effects(tmp_path):
    document = TINY_CHARACTERISTICS.replace("n = 64", "n = 8") + '\n[characteristics.variants]\n"psi = 2" = { psi = 2.0 }\n'
    scene = parse_scene(document, name="variants")
    assert scene.variants == {"psi = 2": {"psi": 2.0}}
    table = sweep(scene.cases, scene.models, scene.alphas, poisson=scene.poisson, n=scene.n, variants=scene.variants)
    assert sorted(set(zip(table["model"], table["variant"]))) == [("kinematic", "psi = 2"), ("rigid", "")]
    with pytest.raises(UnknownNameError, match="did you mean 'psi'"):
        parse_scene(document.replace("psi = 2.0", "pzi = 2.0"), name="bad")


def test_an_effect_parameter_out_of_range_fails_when_the_scene_is_read(monkeypatch):
    """Range checks of effect parameters run at load, not only when the stand is built."""
    monkeypatch.delenv(ENV_VAR, raising=False)
    text = load_scene("fig10").text
    bad = text.replace("[effects.brake_dynamics]", "[effects.brake_dynamics]\nloop_gain = -5.0", 1)
    assert bad != text
    with pytest.raises(ParameterError, match="loop_gain"):
        parse_scene(bad, name="bad")
