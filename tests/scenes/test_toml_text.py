"""rig.scenes.toml_text.dump_toml: what it writes, tomllib reads back unchanged (the round trip of
rig.Scene.to_toml / from_dict), for every built-in scene and for hostile keys and values."""

from __future__ import annotations

import math
import tomllib

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.scenes.locate import builtin_scenes
from rig.scenes.toml_text import dump_toml


@pytest.mark.parametrize("path", [scene.path for scene in builtin_scenes()], ids=lambda p: p.stem)
def test_every_builtin_scene_round_trips(path):
    document = tomllib.loads(path.read_text(encoding="utf-8"))
    assert tomllib.loads(dump_toml(document)) == document


keys = st.text(min_size=1, max_size=12)  # quotes, backslashes, dots, spaces, control characters, non-ASCII
scalars = (st.booleans() | st.integers(min_value=-2**63, max_value=2**63 - 1)
           | st.floats(allow_nan=False) | st.text(max_size=20))
values = st.recursive(scalars, lambda inner: st.lists(inner, max_size=3) | st.dictionaries(keys, inner, max_size=3),
                      max_leaves=8)
tables = st.recursive(st.dictionaries(keys, values, max_size=4),
                      lambda inner: st.dictionaries(keys, inner | values | st.lists(inner, min_size=1, max_size=2),
                                                    max_size=3),
                      max_leaves=6)


@settings(max_examples=150, deadline=None)
@given(tables)
@example({"0": {}, "0\n": [{}]})  # a key ending in a newline: a bare-key pattern with "$" let it through unquoted
def test_any_document_round_trips(document):
    assert tomllib.loads(dump_toml(document)) == document


def test_nan_and_infinity_are_written_as_toml_floats():
    back = tomllib.loads(dump_toml({"t": {"a": math.inf, "b": -math.inf, "c": math.nan}}))["t"]
    assert back["a"] == math.inf and back["b"] == -math.inf and math.isnan(back["c"])


@pytest.mark.parametrize("bad", [None, object(), {1, 2}])
def test_a_value_toml_cannot_hold_is_named(bad):
    with pytest.raises(ParameterError, match=r"contact\.n"):
        dump_toml({"contact": {"n": bad}})
