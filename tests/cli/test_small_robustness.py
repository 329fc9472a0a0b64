"""Small hostile inputs, each one named line: a scene with a byte-order mark, the gate time's one
range, a 100 000-character value, Ctrl-C while the command starts."""

from __future__ import annotations

import pytest

import rig.cli
from rig.errors import ParameterError
from rig.scenes import load_scene
from rig.scenes.locate import BUILTIN_DIR
from tests.runner.fake_stand import NO_FIGURES, register, scene_text


def test_a_scene_saved_with_a_byte_order_mark_runs(tmp_path, monkeypatch, capsys):
    register(monkeypatch)
    scene = tmp_path / "bom.toml"
    scene.write_bytes(b"\xef\xbb\xbf" + scene_text(NO_FIGURES).encode())
    assert rig.cli.main(["run", str(scene), "-o", str(tmp_path / "out")]) == 0, capsys.readouterr().err
    assert (tmp_path / "out" / "reduced.csv").is_file()


def _gate_error(tmp_path, gate: str) -> ParameterError:
    text = (BUILTIN_DIR / "default.toml").read_text().replace("gate_time_s = 4.0", f"gate_time_s = {gate}")
    scene = tmp_path / f"gate_{gate}.toml"
    scene.write_text(text)
    with pytest.raises(ParameterError) as caught:
        load_scene(str(scene))
    return caught.value


def test_the_gate_time_has_one_stated_range(tmp_path):
    """The range a refused gate time states is the range enforced: too short and too long say the same."""
    short, long = _gate_error(tmp_path, "-1.0"), _gate_error(tmp_path, "1e6")
    assert short.name == long.name == "procedure.gate_time_s"
    assert short.valid == long.valid and short.valid.startswith("(0, ") and "inf" not in short.valid, short.valid
    limit = float(short.valid[4:short.valid.index("]")])
    load_scene_ok = (BUILTIN_DIR / "default.toml").read_text().replace("gate_time_s = 4.0", f"gate_time_s = {limit!r}")
    (tmp_path / "at_limit.toml").write_text(load_scene_ok)
    assert load_scene(str(tmp_path / "at_limit.toml")).procedure.gate_time_s == limit


def test_a_100000_character_value_is_cut_in_the_error(tmp_path, capsys):
    text = (BUILTIN_DIR / "default.toml").read_text().replace('drive = "quasi_static"', f'drive = "{"x" * 100_000}"')
    (tmp_path / "long.toml").write_text(text)
    assert rig.cli.main(["run", str(tmp_path / "long.toml"), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and len(err) < 1000 and "(100002 characters)" in err, err[:300]


def test_ctrl_c_while_the_command_starts_names_the_command(monkeypatch, capsys):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt
    monkeypatch.setattr(rig.cli, "build_parser", interrupted)
    assert rig.cli.main(["run", "default"]) == rig.cli.EXIT_INTERRUPTED
    assert capsys.readouterr().err == "rig run: interrupted\n"
