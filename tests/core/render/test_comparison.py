"""gs.compare on synthetic images whose every difference is known: statistics, labels and the
largest differences, uint8 and premultiplied images, arguments that name themselves."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs


def test_statistics_labels_and_largest_on_known_differences() -> None:
    reference = np.zeros((20, 30, 4))
    reference[4:16, 5:25] = (0.5, 0.25, 0.75, 1.0)
    image = reference.copy()
    image[10, 12, 1] += 0.01  # interior colour
    image[4, 10, 0] += 0.002  # colour on the silhouette's row
    image[16, 8] = (0.5, 0.25, 0.75, 1.0)  # one more pixel covered, below the edge
    depth = np.where(reference[..., 3] > 0, 0.5, 1.0)
    their_depth = depth.copy()
    depth[16, 8] = 0.5
    their_depth[8, 20] = 0.505  # another surface behind, closer than a silhouette step
    result = gs.compare(image, reference, depth=depth, reference_depth=their_depth)
    assert result.compared == 12 * 20
    assert result.counts == {
        "color, interior": 1,
        "color, edge": 1,
        "depth, interior": 1,
        "depth, edge": 0,
        "coverage, interior": 0,
        "coverage, edge": 1,
    }
    assert result.within_tolerance == (240 - 2) / 240
    np.testing.assert_allclose(result.max_error, [0.002, 0.01, 0, 0], atol=1e-15)
    np.testing.assert_allclose(result.mean_error, [0.002 / 240, 0.01 / 240, 0, 0], atol=1e-15)
    assert result.percentiles[50.0].tolist() == [0, 0, 0, 0]
    first, second = result.largest[:2]
    assert (first["row"], first["column"], first["kind"]) == (16, 8, "coverage, edge")
    assert (second["row"], second["column"], second["error"]) == (10, 12, pytest.approx(0.01))
    labels = result.labels
    assert gs.Comparison.KINDS[labels[8, 20]] == "depth, interior"
    assert isinstance(result.heatmap, gs.Image) and result.heatmap.shape == (20, 30, 4)
    assert result._repr_png_().startswith(b"\x89PNG")
    np.testing.assert_array_equal(result.heatmap[16, 8, :3], [1, 0, 1])  # magenta: edge coverage
    assert "coverage, edge" in str(result)


def test_uint8_and_premultiplied_images_compare_as_their_straight_colours() -> None:
    rng = np.random.default_rng(1)
    straight = rng.uniform(0, 1, (8, 9, 4))
    straight[..., 3] = rng.choice([0.0, 0.5, 1.0], (8, 9))
    straight[straight[..., 3] == 0, :3] = 0
    premultiplied = straight.copy()
    premultiplied[..., :3] *= straight[..., 3:]
    result = gs.compare(premultiplied, straight, alpha="premultiplied", reference_alpha="straight")
    assert result.max_error.max() < 1e-15 and result.within_tolerance == 1.0
    quantised = np.round(straight * 255).astype(np.uint8)
    result = gs.compare(quantised, straight, tolerance=0.5 / 255)
    assert result.within_tolerance == 1.0
    assert result.max_error.max() == pytest.approx(0.5 / 255, abs=2e-3 / 255)
    assert gs.compare(quantised, straight, tolerance=0.1 / 255).within_tolerance < 1.0


def test_bad_arguments_name_themselves() -> None:
    a = np.zeros((4, 4, 4))
    with pytest.raises(ValueError, match="image and reference must have one height and width"):
        gs.compare(a, np.zeros((4, 5, 4)))
    with pytest.raises(ValueError, match=r"image must have shape \(height, width, 3\)"):
        gs.compare(np.zeros((4, 4)), a)
    with pytest.raises(ValueError, match="alpha must be 'straight' or 'premultiplied'"):
        gs.compare(a, a, alpha="linear")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"reference_depth must have shape \(4, 4\)"):
        gs.compare(a, a, depth=np.ones((4, 4)), reference_depth=np.ones((3, 4)))
    with pytest.raises(TypeError, match="tolerance must be a number"):
        gs.compare(a, a, tolerance="1e-4")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="image must be real numbers"):
        gs.compare(np.zeros((4, 4, 4), complex), a)
