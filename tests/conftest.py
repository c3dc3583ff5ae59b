"""Shared test configuration: hypothesis profiles (HYPOTHESIS_PROFILE=ci|dev|thorough), the
references' availability (`unavailable`, `require`), the seeded `rng` fixture, and the skip of
the `shapes` tests where the build runs the general kernel alone."""

import importlib
import os
from typing import NoReturn

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

# Every failure prints the blob that reproduces it (@reproduce_failure); under CI the examples
# are derived from each test's name, so a run repeats exactly and a failure is the same on rerun.
settings.register_profile("dev", max_examples=50, print_blob=True)
settings.register_profile(
    "ci",
    max_examples=200,
    derandomize=True,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow],
)
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


def _general_kernel_only() -> bool:
    """This build runs the general kernel alone: built with the `single-kernel` feature (the
    inner loop of kernel work), or on the baseline instruction set, which has no shape kernels.
    The plan of a scene of the directional shape (one directional light and a specular
    material, under GL's infinite viewer) then names the general kernel."""
    import glshade as gs

    material = gs.Material(specular=(0.5, 0.5, 0.5, 1.0), shininess=32)
    directional = gs.Scene(lights=[gs.Light(position=(0, 0, 1, 0))], material=material)
    return "general kernel" in directional.plan("float32")


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    shapes = [item for item in items if item.get_closest_marker("shapes")]
    if shapes and _general_kernel_only():
        skip = pytest.mark.skip(reason="this build runs the general kernel alone (single-kernel)")
        for item in shapes:
            item.add_marker(skip)
