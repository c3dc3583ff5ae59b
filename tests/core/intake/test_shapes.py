"""The intake's shapes: a G-buffer shades as an image, one normal or colour broadcasts, shapes and
colour widths that do not fit are named."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs
from support.boundary import MIXED, SUN, rows


def test_a_g_buffer_shades_as_an_image(rng: np.random.Generator) -> None:
    p, n = rows(rng, 6 * 5, np.float32)
    image = gs.shade(p.reshape(6, 5, 3), n.reshape(6, 5, 3), MIXED)
    assert image.shape == (6, 5, 4)
    np.testing.assert_array_equal(image.reshape(-1, 4), gs.shade(p, n, MIXED))
    two = gs.Scene(lights=MIXED.lights, two_side=True)
    assert gs.shade(p.reshape(6, 5, 3), n.reshape(6, 5, 3), two).shape == (2, 6, 5, 4)


def test_one_normal_or_one_colour_broadcasts_over_all_positions(rng: np.random.Generator) -> None:
    p, _ = rows(rng, 12)
    normal = np.array([0.0, 0.6, 0.8])
    expected = gs.shade(p, np.tile(normal, (12, 1)), MIXED)
    np.testing.assert_array_equal(gs.shade(p, normal, MIXED), expected)
    np.testing.assert_array_equal(gs.shade(p, normal[None], MIXED), expected)
    colour = np.array([0.3, 0.2, 0.9])
    np.testing.assert_array_equal(
        gs.shade(p, normal, MIXED, colors=colour),
        gs.shade(p, np.tile(normal, (12, 1)), MIXED, colors=np.tile(colour, (12, 1))),
    )
    grid = gs.shade(p.reshape(3, 4, 3), normal.reshape(1, 1, 3), MIXED)
    assert grid.shape == (3, 4, 4)


@pytest.mark.parametrize(
    ("positions", "normals", "words"),
    [
        (np.zeros((4, 3)), np.zeros((5, 3)), ["broadcast", "positions (4, 3)", "normals (5, 3)"]),
        (np.zeros((4, 2)), np.zeros((4, 3)), ["positions", "(..., 3)", "(4, 2)"]),
        (np.zeros((4, 3)), np.zeros(()), ["normals", "(..., 3)", "()"]),
        (np.zeros(3), np.zeros((2, 4)), ["normals", "(2, 4)"]),
    ],
)
def test_shapes_that_do_not_fit_are_named(
    positions: np.ndarray, normals: np.ndarray, words: list[str]
) -> None:
    with pytest.raises(ValueError) as info:
        gs.shade(positions, normals, SUN)
    for word in words:
        assert word in str(info.value)


def test_colours_of_the_wrong_width_are_named() -> None:
    with pytest.raises(ValueError, match=r"colors must have shape \(\.\.\., 3\) or \(\.\.\., 4\)"):
        gs.shade(np.zeros((2, 3)), np.zeros((2, 3)), SUN, colors=np.zeros((2, 5)))
