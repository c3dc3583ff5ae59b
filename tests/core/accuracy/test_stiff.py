"""The stiff and extreme cases of the table on the documentation's Accuracy page
(docs/pages/guide/accuracy.md, "The stiff cases"), each against the 50-digit mpmath oracle of
`mp_reference.py`, in both dtypes and both accuracy modes, with its bound written beside it.

Every case checks the clamped output against the clamped oracle and has a variant whose colours
keep the exact result inside (0, 1), so the unclamped value is compared too (`inside` counts
them). The bounds are those of the same page (its accuracy modes), per channel:

    fast, float64:   1e-12 * max(1, sum|terms|) + 16 u64 * sensitivity
    fast, float32:   2e-6  * max(1, sum|terms|) + 16 u32 * sensitivity + 4 u32 * powered
    exact, float32:  the float64 bound + 2^-24 (the one rounding of the float64 result)

where sensitivity is sum of (s tan(theta) + e tan(phi)) |term|, the condition numbers of the
specular and spot powers times their terms, and powered is sum of s |specular term| (the plain
float32 power of the fast mode's lean arithmetic errs by about s times its base's rounding). A
case that needs more states it beside the case.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import glshade as gs
from support.mp_reference import MpVertex, mp_vertex

U = {np.float32: 2.0**-24, np.float64: 2.0**-53}
MODES = [
    (np.float32, "fast"),
    (np.float64, "fast"),
    (np.float32, "exact"),
]
pytestmark = pytest.mark.parametrize(
    ("dtype", "accuracy"),
    MODES,
    ids=["f32-fast", "f64-fast", "f32-exact"],
)
BLACK = {"ambient": (0, 0, 0), "diffuse": (0, 0, 0), "specular": (0, 0, 0)}


def bound(dtype: type, accuracy: str, ref: MpVertex) -> float:
    """The Accuracy page's per-channel bound for one vertex."""
    if dtype is np.float32 and accuracy == "fast":
        u = U[np.float32]
        return 2e-6 * max(1.0, ref.magnitude) + 16 * u * ref.sensitivity + 4 * u * ref.powered
    wide = 1e-12 * max(1.0, ref.magnitude) + 16 * U[np.float64] * ref.sensitivity
    return wide + (2.0**-24 if dtype is np.float32 else 0.0)


def check(
    positions: Any,
    normals: Any,
    lights: list[dict[str, Any]],
    dtype: type,
    accuracy: str,
    material: dict[str, Any] | None = None,
    extra: float = 0.0,
    **scene: Any,
) -> list[MpVertex]:
    """Shades the rows with glshade and the oracle; asserts every channel within the bound
    (plus `extra`); returns the oracle's vertices."""
    normalize = scene.pop("normalize", False)
    gs_scene = gs.Scene(
        lights=[gs.Light(**light) for light in lights],
        material=gs.Material(**(material or {})),
        **scene,
    )
    p = np.asarray(positions, dtype=dtype).reshape(-1, 3)
    n = np.broadcast_to(np.asarray(normals, dtype=dtype).reshape(-1, 3), p.shape)
    got = gs.shade(p, n, gs_scene, normalize=normalize, accuracy=accuracy)
    assert got.dtype == dtype and np.isfinite(got).all()
    refs = []
    for i in range(len(p)):
        ref = mp_vertex(p[i], n[i], lights, material, normalize=normalize, **scene)
        expected = np.clip(ref.rgb, 0.0, 1.0)
        error = np.abs(got[i, :3].astype(np.float64) - expected).max()
        # Where the exact value is infinite (an unbounded attenuation) the clamp must give 1.
        limit = bound(dtype, accuracy, ref) + extra if np.isfinite(ref.magnitude) else 0.0
        assert error <= limit, (
            f"row {i}: p={p[i]}, n={n[i]}: got {got[i, :3]}, exact {ref.rgb}, "
            f"error {error:.3g} > bound {limit:.3g}"
        )
        refs.append(ref)
    return refs


def inside(refs: list[MpVertex]) -> int:
    """How many oracle results lie strictly inside (0, 1) in every channel: compared before
    the clamp could hide an error."""
    return sum(all(0 < c < 1 for c in r.rgb) for r in refs)


def around(axis: Any, angles: Any) -> np.ndarray:
    """Unit vectors at `angles` (radians) from the unit `axis` = +z, tilted towards +x."""
    a = np.asarray(angles, dtype=np.float64)
    return np.c_[np.sin(a), np.zeros_like(a), np.cos(a)]


# --- the specular power near the highlight ------------------------------------------------


@pytest.mark.parametrize("shininess", [0.0, 1.0, 128.0, 1e3, 1e4, 1e6])
@pytest.mark.parametrize("normalize", [False, True], ids=["as-given", "normalize"])
def test_shininess_near_the_highlight(
    dtype: type, accuracy: str, shininess: float, normalize: bool
) -> None:
    # Angles from the highlight where cos^s runs from 1 down to 1e-3, and the highlight itself.
    q = np.geomspace(1.0, 1e-3, 24)
    theta = np.sqrt(-2.0 * np.log(q) / max(shininess, 1.0))
    normals = around((0, 0, 1), np.r_[0.0, theta, theta[::3] * 1.0001])
    light = {"position": (0.0, 0.0, 1.0, 0.0), "diffuse": (0.2, 0.2, 0.2), "specular": (1,) * 3}
    material = {"diffuse": (0.5, 0.5, 0.5), "specular": (0.6, 0.5, 0.4), "shininess": shininess}
    refs = check(
        np.zeros_like(normals), normals, [light], dtype, accuracy, material, normalize=normalize
    )
    assert inside(refs) == len(refs)


def test_shininess_with_a_local_viewer_and_a_point_light(dtype: type, accuracy: str) -> None:
    # h per vertex (not a constant): the normal's tilt sweeps the highlight of s = 10^4.
    theta = np.r_[0.0, np.sqrt(-2.0 * np.log(np.geomspace(1.0, 1e-3, 12)) / 1e4)]
    light = {"position": (0.0, 0.0, 3.0, 1.0), "diffuse": (0.2,) * 3, "specular": (1,) * 3}
    material = {"specular": (0.7,) * 3, "shininess": 1e4}
    refs = check(
        np.zeros((len(theta), 3)),
        around((0, 0, 1), theta),
        [light],
        dtype,
        accuracy,
        material,
        viewer=(0.0, 0.0, 3.0, 1.0),
    )
    assert inside(refs) == len(refs)


# --- degenerate geometry --------------------------------------------------------------------


@pytest.mark.parametrize("k", [(1.0, 0.0, 0.0), (0.0, 0.0, 1.0)], ids=["k0=1", "k0=0"])
def test_light_at_the_vertex(dtype: type, accuracy: str, k: tuple[float, ...]) -> None:
    # VP = 0: no diffuse, no specular; the ambient term is attenuated (1/(k0 + 0) or, at
    # k0 = 0, saturated and clamped to 1).
    light = {
        "position": (0.5, -0.25, 2.0, 1.0),
        "ambient": (0.3, 0.2, 0.1),
        "constant_attenuation": k[0],
        "quadratic_attenuation": k[2],
    }
    material = {"specular": (1, 1, 1), "shininess": 5.0}
    refs = check([0.5, -0.25, 2.0], [0, 0, 1], [light], dtype, accuracy, material)
    assert inside(refs) == (k[0] == 1.0)


@pytest.mark.parametrize("shininess", [0.0, 10.0])
def test_light_opposite_the_viewer(dtype: type, accuracy: str, shininess: float) -> None:
    # L + V = 0: no halfway vector, so no specular for s > 0 and 0^0 = 1 for s = 0; then the
    # light a little off the opposite direction (h well defined: its constant is float64).
    material = {"specular": (0.5,) * 3, "shininess": shininess, "diffuse": (0.4,) * 3}
    normal = [0.6, 0.0, -0.8]
    for position in [(0.0, 0.0, -1.0, 0.0), (1e-3, 0.0, -1.0, 0.0), (0.0, 1e-6, -1.0, 0.0)]:
        light = {"position": position}
        refs = check([0, 0, 0], normal, [light], dtype, accuracy, material)
        assert inside(refs) == 1
    # A positional light behind the vertex and a local viewer in front, on one line.
    light = {"position": (0.0, 0.0, -2.0, 1.0)}
    refs = check([0, 0, 0], normal, [light], dtype, accuracy, material, viewer=(0, 0, 2, 1))
    assert inside(refs) == 1


@pytest.mark.parametrize("normalize", [False, True], ids=["as-given", "normalize"])
def test_zero_denormal_and_non_unit_normals(dtype: type, accuracy: str, normalize: bool) -> None:
    tiny = np.finfo(dtype).smallest_subnormal * 3
    normals = [
        [0.0, 0.0, 0.0],
        [0.0, tiny, tiny],  # subnormal: ~0 as given, unit with normalize
        [0.0, 0.6e-3, 0.8e-3],
        [0.0, 0.3, 0.4],
        [0.0, 1.8, 2.4],
        [0.0, 600.0, 800.0],
    ]
    light = {"position": (0.0, 0.5, 1.0, 0.0), "diffuse": (0.3,) * 3, "specular": (0.2,) * 3}
    material = {"specular": (1, 1, 1), "shininess": 10.0, "diffuse": (0.5,) * 3}
    refs = check(np.zeros((6, 3)), normals, [light], dtype, accuracy, material, normalize=normalize)
    assert inside(refs) >= 4


SCALES = [2.0**100, 2.0**-100, 1e30, 1e-30]


@pytest.mark.parametrize("scale", SCALES, ids=["2^100", "2^-100", "1e30", "1e-30"])
def test_scenes_scaled_far_from_one(dtype: type, accuracy: str, scale: float) -> None:
    # Positions, lights and viewer times `scale`, the linear attenuation over it: the exact
    # colours do not change. Squared lengths overflow or underflow float32 at these scales.
    rng = np.random.default_rng(5)
    p = rng.uniform(-1, 1, (16, 3)) * scale
    n = rng.normal(size=(16, 3)) + np.array([0, 0, 2])
    lights = [
        {
            "position": (1.0 * scale, 2.0 * scale, 3.0 * scale, 1.0),
            "linear_attenuation": 0.2 / scale,
            "diffuse": (0.4,) * 3,
            "specular": (0.3,) * 3,
        },
        {
            "position": (0.0, 0.0, 4.0 * scale, 1.0),
            "spot_direction": (0.0, 0.0, -1.0),
            "spot_cutoff": 60.0,
            "spot_exponent": 4.0,
            "diffuse": (0.3,) * 3,
        },
    ]
    material = {"specular": (0.5,) * 3, "shininess": 20.0}
    viewer = (0.0, 0.0, 5.0 * scale, 1.0)
    refs = check(p, n, lights, dtype, accuracy, material, viewer=viewer, normalize=True)
    assert inside(refs) >= 8


@pytest.mark.parametrize("distance", [1e-3, 1e-10, 1e-20, 1e-30, 0.0])
def test_k0_zero_at_tiny_distance(dtype: type, accuracy: str, distance: float) -> None:
    # att = 1/(k2 d^2) reaches 1e60 and beyond: saturated, never inf * 0; with the light's
    # colour scaled by d^2 (where the dtype holds it) the product is an ordinary 0.4.
    # The vertex at the origin, so the light's position (and d) is exact in both dtypes.
    p = np.zeros(3)
    position = (0.0, 0.0, distance, 1.0)
    base = {"position": position, "constant_attenuation": 0.0, "quadratic_attenuation": 1.0}
    lights = [{**base, "ambient": (0.5,) * 3, "diffuse": (0.3,) * 3}]
    material = {"ambient": (1, 1, 1), "diffuse": (1, 1, 1)}
    check(p, [0, 0, 1], lights, dtype, accuracy, material, global_ambient=(0, 0, 0))
    # Weights (att * spot * n.VP) saturate at 2^64 in float32 and 2^240 in float64, so that a
    # weight times a colour (saturated at 2^60 and 2^240) stays finite: beyond, only the clamped
    # value is defined. Below, the unclamped value is compared.
    saturation = 2.0**64 if dtype is np.float32 and accuracy != "exact" else 2.0**240
    small = distance**2 * 0.4
    if distance > 0 and distance**-2 <= saturation:
        scaled = [{**base, "ambient": (small,) * 3, "diffuse": (0.0,) * 3}]
        refs = check(p, [0, 0, 1], scaled, dtype, accuracy, material, global_ambient=(0, 0, 0))
        assert inside(refs) == 1


@pytest.mark.parametrize("exponent", [0.0, 3.0])
def test_spot_cutoff_90_180_and_the_cone_edge(dtype: type, accuracy: str, exponent: float) -> None:
    # Light at the origin pointing down -z; vertices in front, on the plane z = 0 (cutoff 90:
    # cos 90 = 0 exactly, on the cone's surface) and behind; a cone of 30 deg with vertices a
    # hair inside and outside its edge (exactly on it the inputs' rounding decides).
    edge = np.radians(30.0)
    points = np.r_[
        around((0, 0, 1), [0.3, np.pi / 2, 2.0]) * (1, 1, -1),
        around((0, 0, 1), [edge - 1e-6, edge + 1e-6]) * (1, 1, -1),
    ]
    material = {"diffuse": (0.5,) * 3}
    for cutoff in (180.0, 90.0, 30.0):
        light = {
            "position": (0.0, 0.0, 0.0, 1.0),
            "spot_direction": (0.0, 0.0, -1.0),
            "spot_cutoff": cutoff,
            "spot_exponent": exponent,
        }
        check(points, [0, 0, 1], [light], dtype, accuracy, material, global_ambient=(0, 0, 0))
    # The edge vertices straddle the cone: lit inside, dark outside.
    out = gs.shade(
        points[3:].astype(dtype),
        np.array([[0, 0, 1]] * 2, dtype),
        gs.Scene([gs.Light(**light)], material=gs.Material(**material), global_ambient=(0, 0, 0)),
        accuracy=accuracy,
    )
    assert out[0, 0] > 0 and out[1, 0] == 0


@pytest.mark.parametrize("t", [1e-30, 1e-7, 0.0, -1e-7, -1e-30])
def test_grazing_light(dtype: type, accuracy: str, t: float) -> None:
    # n . VP = t exactly (n = z, VP = (1, 0, t)/|.|): diffuse t, and the specular gate opens
    # for t > 0 only, with (n . h)^s = cos(45 deg)^s of ordinary size.
    light = {"position": (1.0, 0.0, t, 0.0), "diffuse": (0.5,) * 3}
    material = {"specular": (0.5,) * 3, "shininess": 2.0}
    refs = check([0, 0, 0], [0, 0, 1], [light], dtype, accuracy, material)
    out = gs.shade(
        np.zeros((1, 3), dtype),
        np.array([[0, 0, 1]], dtype),
        gs.Scene([gs.Light(**light)], material=gs.Material(**material)),
        accuracy=accuracy,
    )
    assert (out[0, 0] > 0.2) == (t > 0), "the gate follows the sign of n . VP"
    assert inside(refs) == 1


# --- many lights ----------------------------------------------------------------------------

ORDERS = ["ascending", "descending", "alternating", "big-small-big"]


@pytest.mark.parametrize("order", ORDERS)
def test_a_thousand_lights_in_adversarial_order(dtype: type, accuracy: str, order: str) -> None:
    # 1,000 directional lights straight on (n . VP = 1), whose diffuse colours are the terms.
    # Bound: 8 u sum|terms| + 2 u |sum|, the same for any count: float32 terms are summed in
    # float64, float64 ones in blocks of 8 added with a compensated sum. A running sum's
    # bound is 999 u sum|terms|.
    rng = np.random.default_rng(1)
    if order == "big-small-big":
        terms = np.r_[1e4, np.full(998, 4e-4), -1e4]  # the small ones vanish from a naive sum
    else:
        terms = rng.uniform(0, 1.5e-4, 1000) * rng.choice([1, 1, 1, 20], 1000)
        terms = np.sort(terms)[:: -1 if order == "descending" else 1]
        if order == "alternating":
            terms = np.ravel(np.c_[terms[::2] * 50, -terms[::2] * 50 + terms[1::2]])
    lights = gs.Lights(position=(0, 0, 1, 0), diffuse=np.c_[terms, terms, terms], specular=(0,) * 3)
    scene = gs.Scene(lights, material=gs.Material(diffuse=(1, 1, 1)), global_ambient=(0, 0, 0))
    got = gs.shade(np.zeros((1, 3), dtype), np.array([[0, 0, 1]], dtype), scene, accuracy=accuracy)
    exact = float(sum(map(__import__("fractions").Fraction, terms)))
    assert 0 < exact < 1
    u = U[np.float64] if accuracy == "exact" else U[dtype]
    limit = 8 * u * np.abs(terms).sum() + 2 * U[dtype] * exact
    assert abs(float(got[0, 0]) - exact) <= limit, (got[0, 0], exact, limit)
    if dtype is np.float32 and order == "big-small-big" and accuracy == "fast":
        naive = np.float32(0)
        for t in terms.astype(np.float32):
            naive += t
        assert abs(float(naive) - exact) > 10 * limit, "the case is adversarial"


# --- NaN and inf rows -------------------------------------------------------------------------


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_nan_and_inf_rows_stay_in_their_rows(dtype: type, accuracy: str, bad: float) -> None:
    rng = np.random.default_rng(2)
    p = rng.uniform(-1, 1, (40, 3)).astype(dtype)
    n = (rng.normal(size=(40, 3)) + np.array([0, 0, 2])).astype(dtype)
    colors = rng.uniform(0, 1, (40, 4)).astype(dtype)
    point = gs.Scene(
        [gs.Light(position=(1, 2, 3, 1), linear_attenuation=0.5)],
        material=gs.Material(specular=(0.5,) * 3, shininess=30.0),
    )
    directional = gs.Scene([gs.Light()], material=gs.Material(specular=(0.5,) * 3, shininess=30))
    clean = {
        name: gs.shade(p, n, s, colors=colors, accuracy=accuracy)
        for name, s in (("point", point), ("directional", directional))
    }
    for array, row in (("positions", 3), ("normals", 17), ("colors", 31)):
        inputs = {"positions": p.copy(), "normals": n.copy(), "colors": colors.copy()}
        inputs[array][row, 1] = bad
        for name, s in (("point", point), ("directional", directional)):
            got = gs.shade(
                inputs["positions"],
                inputs["normals"],
                s,
                colors=inputs["colors"],
                accuracy=accuracy,
            )
            others = np.arange(40) != row
            assert np.array_equal(got[others], clean[name][others]), "other rows unchanged"
            # Positions are not read for directional lights and an infinite viewer.
            if array == "positions" and name == "directional":
                assert np.array_equal(got[row], clean[name][row])
            else:
                assert np.isnan(got[row]).all(), (array, name)


# --- exponents beyond GL's range ----------------------------------------------------------------


def test_strict_rejects_exponents_above_128_and_the_default_allows_them(
    dtype: type, accuracy: str
) -> None:
    p, n = np.zeros((1, 3), dtype), np.array([[0, 0, 1]], dtype)
    high = gs.Scene([gs.Light()], material=gs.Material(specular=(1, 1, 1), shininess=1e4))
    spot = gs.Scene([gs.Light(position=(0, 0, 1, 1), spot_cutoff=30, spot_exponent=200)])
    for scene, name in ((high, "shininess"), (spot, "spot_exponent")):
        with pytest.raises(ValueError, match=name):
            gs.shade(p, n, scene, accuracy=accuracy, strict=True)
        assert np.isfinite(gs.shade(p, n, scene, accuracy=accuracy)).all()
    edge = gs.Scene([gs.Light()], material=gs.Material(specular=(1, 1, 1), shininess=128))
    assert np.isfinite(gs.shade(p, n, edge, accuracy=accuracy, strict=True)).all()
