"""gs.compare on pictures from other renderers' conventions: 8- and 16-bit references (the
default tolerance grows by half a quantisation step, and says so), opaque backgrounds
(`background=` makes their silhouettes edges, as alpha does), depths given as eye distances
(`depth_convention="linear"`, converted with the clip planes) and depths given in the wrong
convention (refused, naming the right one), RGB against RGBA, and empty pictures."""

from __future__ import annotations

import numpy as np
import pytest

import glshade as gs

HEIGHT, WIDTH = 40, 50
NEAR, FAR = 0.5, 20.0
GREY = (0.1, 0.1, 0.1)


def _picture() -> tuple[np.ndarray, np.ndarray]:
    """A lit disc on transparent black (RGBA) and its eye distances (0 where nothing)."""
    y, x = np.mgrid[0:HEIGHT, 0:WIDTH]
    inside = (x - 24.3) ** 2 + (y - 19.6) ** 2 < 14.2**2
    rgba = np.zeros((HEIGHT, WIDTH, 4))
    rgba[inside] = np.c_[0.2 + 0.6 * x[inside] / WIDTH, 0.5 + 0 * x[inside],
                         0.8 - 0.5 * y[inside] / HEIGHT, 1 + 0 * x[inside]]  # fmt: skip
    distance = np.where(inside, 3.0 + 0.02 * x + 0.01 * y, 0.0)
    return rgba, distance


def _window(distance: np.ndarray, near: float, far: float) -> np.ndarray:
    """GL's window depth of eye distances through a perspective projection (glFrustum's third
    row: z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) d)), 1 where nothing is drawn."""
    with np.errstate(divide="ignore"):
        z_ndc = (far + near) / (far - near) - 2 * far * near / ((far - near) * distance)
    return np.where(distance > 0, (z_ndc + 1) / 2, 1.0)


def test_an_8_bit_copy_of_a_picture_is_within_the_default_tolerance() -> None:
    rgba, _ = _picture()
    eight = np.round(rgba * 255).astype(np.uint8)
    result = gs.compare(rgba, eight)
    assert result.tolerance == pytest.approx(0.5 / 255 + 1e-4, rel=1e-12)
    assert result.within_tolerance == 1.0 and sum(result.counts.values()) == 0
    assert result.notes == (
        "tolerance 0.00206: half a step of the 8-bit image (0.5/255) plus 0.0001",
    )
    assert "note: tolerance 0.00206" in str(result) and "tolerance 0.00206" in result._repr_html_()
    sixteen = np.round(rgba * 65535).astype(np.uint16)
    result = gs.compare(sixteen, rgba)
    assert result.tolerance == pytest.approx(0.5 / 65535 + 1e-4, rel=1e-12)
    assert result.within_tolerance == 1.0
    # Between floats the tolerance stays 1e-4, and an 8-bit copy is beyond it: a given
    # tolerance is kept as given.
    assert gs.compare(rgba, rgba).tolerance == 1e-4 and gs.compare(rgba, rgba).notes == ()
    assert gs.compare(rgba, eight / 255).within_tolerance < 1.0
    assert gs.compare(rgba, eight, tolerance=1e-4).within_tolerance < 1.0


def test_an_opaque_background_given_makes_its_silhouettes_edges() -> None:
    """The same picture cleared to an opaque grey (as pyrender with bg_color alpha 1 and a
    framebuffer without alpha give it) compares as the transparent one does."""
    rgba, _ = _picture()
    shifted = np.roll(rgba, 1, axis=1)  # another renderer, a pixel off
    opaque = shifted.copy()
    opaque[opaque[..., 3] == 0] = (*GREY, 1.0)
    as_alpha = gs.compare(rgba, shifted)
    for reference in (opaque, opaque[..., :3], np.round(opaque * 255).astype(np.uint8)):
        given = gs.compare(rgba, reference, background=GREY, tolerance=as_alpha.tolerance + 0.002)
        np.testing.assert_array_equal(given.labels, as_alpha.labels)
        assert given.counts["coverage, interior"] == 0 and given.counts["coverage, edge"] > 20
    # Without it, the opaque picture counts as covered everywhere: every pixel of the
    # transparent one's background differs in coverage, and the note says what to pass.
    wrong = gs.compare(rgba, opaque)
    assert wrong.counts["coverage, interior"] > 100
    assert any("its border is one colour, (0.1, 0.1, 0.1)" in note and
               "pass background=(0.1, 0.1, 0.1)" in note for note in wrong.notes)  # fmt: skip
    # Both opaque, 8-bit, the background in bytes as well: coverage from the background in
    # each, said in the notes.
    both = opaque.copy()
    both[..., :3] = np.where(rgba[..., 3:] > 0, rgba[..., :3], GREY)
    eight = [np.round(x * 255).astype(np.uint8) for x in (both, opaque)]
    result = gs.compare(*eight, background=np.array([26, 26, 26], np.uint8))
    np.testing.assert_array_equal(result.labels, as_alpha.labels)
    assert "image: covered where its colour is not the background" in result.notes
    # Float pictures cleared to 0.1, the background given in bytes (26, 0.00196 away).
    result = gs.compare(both, opaque, background=np.array([26, 26, 26], np.uint8))
    np.testing.assert_array_equal(result.labels, as_alpha.labels)


def test_rgb_against_rgba_compares_rgb() -> None:
    rgba, _ = _picture()
    result = gs.compare(rgba, rgba[..., :3], background=(0, 0, 0))
    assert result.max_error.shape == (3,) and result.within_tolerance == 1.0
    assert "one image has alpha and the other none: RGB compared" in result.notes
    assert sum(result.counts.values()) == 0


@pytest.mark.parametrize("far", [FAR, None, np.inf])
def test_eye_distances_compare_with_window_depths(far: float | None) -> None:
    """pyrender's depth (eye distance, 0 where nothing) against GL's window depth of the same
    surface: no depth or coverage difference once the convention is named."""
    rgba, distance = _picture()
    window = _window(distance, NEAR, FAR) if far == FAR else np.where(
        distance > 0, 1 - NEAR / np.where(distance > 0, distance, 1), 1.0
    )  # fmt: skip
    result = gs.compare(rgba, rgba, depth=window, reference_depth=distance,
                        reference_depth_convention="linear", near=NEAR, far=far)  # fmt: skip
    assert sum(result.counts.values()) == 0 and result.compared == (distance > 0).sum()
    assert any(note.startswith("reference_depth: eye distances") for note in result.notes)
    both = gs.compare(rgba, rgba, depth=distance, reference_depth=distance,
                      depth_convention="LINEAR", near=NEAR, far=far)  # fmt: skip
    assert sum(both.counts.values()) == 0
    # A surface 1% farther away in the reference is a depth difference.
    farther = np.where(distance > 0, distance * 1.01, 0.0)
    moved = gs.compare(rgba, rgba, depth=window, reference_depth=farther,
                       reference_depth_convention="linear", near=NEAR, far=far)  # fmt: skip
    assert moved.counts["depth, interior"] > 0.5 * moved.compared


def test_a_depth_in_the_wrong_convention_is_refused_naming_the_right_one() -> None:
    rgba, distance = _picture()
    window = _window(distance, NEAR, FAR)
    outside = r"reference_depth has values in \[0, 3\.9.*outside GL window depth's \[0, 1\]"
    with pytest.raises(ValueError, match=outside + r".*reference_depth_convention='linear'"):
        gs.compare(rgba, rgba, depth=window, reference_depth=distance)
    small = distance / 10  # eye distances below 1, 0 where nothing: not window depths either
    with pytest.raises(ValueError, match=r"depth is 0 at some pixels and 1 at none.*"
                       r"depth_convention='linear'"):  # fmt: skip
        gs.compare(rgba, rgba, depth=small)
    with pytest.raises(ValueError, match=r"depth is 1 at some pixels and 0 at none.*"
                       r"depth_convention='window'"):  # fmt: skip
        gs.compare(rgba, rgba, depth=window, depth_convention="linear", near=NEAR, far=FAR)
    with pytest.raises(ValueError, match=r"depth_convention='linear' needs near="):
        gs.compare(rgba, rgba, depth=distance, depth_convention="linear")
    with pytest.raises(ValueError, match=r"depth_convention must be 'window' or 'linear'"):
        gs.compare(rgba, rgba, depth=window, depth_convention="eye")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"far must be greater than near \(0.5\), got 0.1"):
        gs.compare(rgba, rgba, depth=distance, depth_convention="linear", near=NEAR, far=0.1)
    with pytest.raises(ValueError, match=r"far is given without near"):
        gs.compare(rgba, rgba, far=FAR)
    with pytest.raises(ValueError, match=r"near must be a finite number > 0, got 0"):
        gs.compare(rgba, rgba, depth=distance, depth_convention="linear", near=0, far=FAR)
    with pytest.raises(ValueError, match=r"depth as linear eye distances must be >= 0"):
        gs.compare(rgba, rgba, depth=-distance, depth_convention="linear", near=NEAR, far=FAR)


@pytest.mark.parametrize(
    ("image", "reference", "words"),
    [
        (np.zeros((0, 0, 4)), np.zeros((0, 0, 4)), "image must have at least one pixel"),
        (np.zeros((3, 3, 4)), np.zeros((3, 0, 4)), "reference must have at least one pixel"),
        (np.zeros((3, 3, 4)), np.zeros((3, 3, 4), bool), "reference must be float"),
        (np.zeros((3, 3, 4)), np.zeros((3, 4, 3)), "must have one height and width"),
    ],
)
def test_bad_pictures_name_the_argument(
    image: np.ndarray, reference: np.ndarray, words: str
) -> None:
    with pytest.raises((ValueError, TypeError), match=words):
        gs.compare(image, reference)


def test_a_bad_background_names_itself() -> None:
    rgba, _ = _picture()
    with pytest.raises(ValueError, match=r"background must have shape \(3,\) or \(4,\)"):
        gs.compare(rgba, rgba, background=(0.1, 0.1))
    with pytest.raises(ValueError, match="background must be finite"):
        gs.compare(rgba, rgba, background=(np.nan, 0, 0))
    with pytest.raises(TypeError, match="background takes numbers, not a colour name"):
        gs.compare(rgba, rgba, background="black")  # type: ignore[arg-type]


def test_a_nan_pixel_is_a_difference_and_stays_out_of_the_statistics() -> None:
    rgba, _ = _picture()
    broken = rgba.copy()
    broken[20, 25, 1] = np.nan  # inside the disc
    result = gs.compare(broken, rgba)
    assert result.counts["color, interior"] == 1 and result.within_tolerance < 1.0
    assert np.isfinite(result.max_error).all() and result.max_error.max() == 0.0
    assert result.largest[0]["row"] == 20 and result.largest[0]["error"] == np.inf
    assert "1 pixels both cover are NaN in a picture" in result.notes[0]
    np.testing.assert_allclose(result.heatmap[20, 25, :3], (0.7, 0.0, 0.0), atol=1e-7)
