"""A fuzzer (tests/scripts/fuzz.py, in a child): random arguments to every public function and
scene type (GL's, glTF's, three.js', pyrender's; relief, textures, `Image`, `compare`,
`explain`) raise nothing but the documented exceptions."""

from __future__ import annotations

import importlib.util

import pytest
from conftest import unavailable

from support.processes import passes

pytestmark = pytest.mark.subprocess

ROUNDS = 600
CALLS = 44  # a round's calls, pyrender's render among them
EXPLAIN_EVERY = 10


def test_random_arguments_raise_only_documented_exceptions() -> None:
    # pyrender's scenes are fuzzed too (no GL needed to read them); the child imports it, so
    # that this process keeps the GL platform the GL tests choose.
    if importlib.util.find_spec("pyrender") is None:
        unavailable("pyrender is not installed (pip install '.[test]')")
    out = passes("fuzz", str(ROUNDS), timeout=300)
    assert "UNEXPECTED" not in out, out
    total = int(out.split()[0])
    assert total == ROUNDS * CALLS + -(-ROUNDS // EXPLAIN_EVERY), out
    assert out.rstrip().endswith("pyrender=True"), out
