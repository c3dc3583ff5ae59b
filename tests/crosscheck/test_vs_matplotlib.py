"""`glshade.relief` against matplotlib itself: ``matplotlib.colors.LightSource`` (hillshade,
shade_normals, the hsv, soft and overlay blends, shade_rgb, shade) and mplot3d's
``_shade_colors``, on random terrain, normals and colours, within 1e-12 (float64 both)."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import require

import glshade as gs

mcolors = require("matplotlib.colors")
art3d = require("mpl_toolkits.mplot3d.art3d")
TOL = 1e-12


def terrain(seed: int, shape: tuple[int, int] = (60, 80)) -> np.ndarray:
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0 : shape[0], 0 : shape[1]] / 10
    return np.sin(x * rng.uniform(0.5, 2)) * np.cos(y * rng.uniform(0.5, 2)) * 50 + rng.normal(
        0, 1, shape
    )


LIGHTS = [(315, 45), (225, 19.4712), (90, 5), (0, 80), (137.5, 30)]


@pytest.mark.parametrize(("azdeg", "altdeg"), LIGHTS)
@pytest.mark.parametrize(
    ("vert_exag", "dx", "dy", "fraction"), [(1, 1, 1, 1.0), (0.05, 30, 30, 1.5), (3, 2, 0.5, 0.7)]
)
def test_hillshade(azdeg: float, altdeg: float, vert_exag: float, dx: float, dy: float,
                   fraction: float) -> None:  # fmt: skip
    z = terrain(int(azdeg))
    theirs = mcolors.LightSource(azdeg, altdeg).hillshade(z, vert_exag, dx, dy, fraction)
    ours = gs.relief.LightSource(azdeg, altdeg).hillshade(z, vert_exag, dx, dy, fraction)
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=TOL)
    assert fraction > 1 or theirs.std() > 0.05, "the terrain is shaded, not flat"


def test_shade_normals_and_a_flat_grid() -> None:
    rng = np.random.default_rng(4)
    n = rng.normal(size=(40, 50, 3))
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    for fraction in (1.0, 0.5, 2.0):
        theirs = mcolors.LightSource(20, 60).shade_normals(n.copy(), fraction)
        ours = gs.relief.LightSource(20, 60).shade_normals(n, fraction)
        np.testing.assert_allclose(ours, theirs, rtol=0, atol=TOL)
    flat = np.zeros((5, 6))  # one intensity: not stretched
    np.testing.assert_allclose(
        gs.relief.LightSource().hillshade(flat), mcolors.LightSource().hillshade(flat), atol=TOL
    )


@pytest.mark.parametrize("mode", ["hsv", "soft", "overlay"])
def test_blends(mode: str) -> None:
    rng = np.random.default_rng(7)
    rgb = rng.uniform(0, 1, (30, 40, 3))
    rgb[0, :5] = 0.5  # grey: no saturation
    rgb[1, :5] = [1.0, 1.0, 0.0]  # ties of the maximum
    intensity = rng.uniform(0, 1, (30, 40, 1))
    intensity[2, :5] = 0.5
    theirs_ls = mcolors.LightSource(hsv_min_val=0.1, hsv_max_val=0.9, hsv_min_sat=0.8,
                                    hsv_max_sat=0.2)  # fmt: skip
    ours_ls = gs.relief.LightSource(hsv_min_val=0.1, hsv_max_val=0.9, hsv_min_sat=0.8,
                                    hsv_max_sat=0.2)  # fmt: skip
    name = {"hsv": "blend_hsv", "soft": "blend_soft_light", "overlay": "blend_overlay"}[mode]
    theirs = getattr(theirs_ls, name)(rgb, intensity)
    ours = getattr(ours_ls, name)(rgb, intensity)
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=TOL)
    rgba = np.dstack([rgb, rng.uniform(0, 1, rgb.shape[:2])])  # an RGBA image too
    theirs = getattr(theirs_ls, name)(rgba, intensity)
    np.testing.assert_allclose(getattr(ours_ls, name)(rgba, intensity), theirs, rtol=0, atol=TOL)


@pytest.mark.parametrize("mode", ["hsv", "soft", "overlay"])
def test_shade_rgb_and_shade(mode: str) -> None:
    z = terrain(11)
    rng = np.random.default_rng(11)
    rgb = rng.uniform(0, 1, (*z.shape, 3))
    theirs = mcolors.LightSource(300, 40).shade_rgb(rgb, z, blend_mode=mode, vert_exag=0.1)
    ours = gs.relief.LightSource(300, 40).shade_rgb(rgb, z, blend_mode=mode, vert_exag=0.1)
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=TOL)
    cm = require("matplotlib").colormaps["viridis"]
    theirs = mcolors.LightSource(300, 40).shade(z, cm, blend_mode=mode, vert_exag=0.1)
    ours = gs.relief.LightSource(300, 40).shade(z, cm, blend_mode=mode, vert_exag=0.1)
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=TOL)


def test_mplot3d_shading() -> None:
    rng = np.random.default_rng(3)
    normals = rng.normal(size=(200, 3)) * rng.uniform(0.1, 10, (200, 1))
    normals[5] = 0  # no direction
    colors = rng.uniform(0, 1, (200, 4))
    np.testing.assert_allclose(
        gs.relief.shade_colors(colors, normals), art3d._shade_colors(colors, normals), atol=TOL
    )
    one = (0.2, 0.4, 0.6, 0.5)
    light = gs.relief.LightSource(30, 60)
    np.testing.assert_allclose(
        gs.relief.shade_colors(one, normals, light),
        art3d._shade_colors(one, normals, mcolors.LightSource(30, 60)),
        atol=TOL,
    )


def test_bad_inputs_name_themselves() -> None:
    ls = gs.relief.LightSource()
    with pytest.raises(ValueError, match="at least 2 rows and 2 columns"):
        ls.hillshade(np.zeros((1, 5)))
    with pytest.raises(TypeError, match="elevation is a masked array"):
        ls.hillshade(np.ma.masked_array(np.zeros((3, 3))))
    with pytest.raises(ValueError, match="rgb must be in \\[0, 1\\] for the hsv blend"):
        ls.blend_hsv(np.full((2, 2, 3), 1.5), np.full((2, 2, 1), 0.5))
    with pytest.raises(ValueError, match="blend_mode must be"):
        ls.shade_rgb(np.zeros((3, 3, 3)), np.zeros((3, 3)), blend_mode="multiply")
