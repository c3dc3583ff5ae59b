"""A fuzzer (tests/scripts/fuzz.py, in a child): random arguments to every public function raise
nothing but the documented exceptions."""

from __future__ import annotations

import pytest

from support.processes import passes

pytestmark = pytest.mark.subprocess

ROUNDS = 600


def test_random_arguments_raise_only_documented_exceptions() -> None:
    out = passes("fuzz", str(ROUNDS), timeout=300)
    assert "UNEXPECTED" not in out, out
    total = int(out.split()[0])
    assert total == ROUNDS * 13
