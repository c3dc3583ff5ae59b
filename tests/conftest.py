"""Shared test configuration: hypothesis profiles (HYPOTHESIS_PROFILE=ci|dev|thorough), the
references' availability (`unavailable`, `require`) and the seeded `rng` fixture."""

import importlib
import os
from typing import NoReturn

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

settings.register_profile("dev", max_examples=50)
settings.register_profile("ci", max_examples=200, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("thorough", max_examples=5000)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))


def unavailable(reason: str) -> NoReturn:
    """A reference the test needs (a library, a GL context) cannot be used: under CI=true the
    test fails with the reason, elsewhere it is skipped with it."""
    if os.environ.get("CI"):
        pytest.fail(f"{reason} (CI=true: references are mandatory)", pytrace=False)
    pytest.skip(reason)


def require(module: str) -> object:
    """Imports a reference library: under CI=true a missing one fails the run, elsewhere the
    test is skipped with the reason."""
    if os.environ.get("CI"):
        return importlib.import_module(module)
    return pytest.importorskip(module, reason=f"{module} is not installed (pip install '.[test]')")


@pytest.fixture
def rng() -> np.random.Generator:
    """A generator of fixed seed, new for each test: a test's data does not depend on which tests
    ran before it, or in what order."""
    return np.random.default_rng(13)
