"""`explain`: which of the known convention switches make glshade's render of a mesh match a
user's image, found by search, with the residual before and after."""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _glshade
from ._camera import Camera
from ._image import Image
from ._intake import colors_checked, real
from ._normals import crease_normals, vertex_normals
from ._render import render
from ._render_input import render_input
from ._scene import Lights, Scene
from ._transfer import apply_transfer
from ._typing import Weighting

__all__ = ["Explanation", "explain"]

# The discrete switches a render is searched over, and what each value means.
SWITCHES: dict[str, tuple[Any, ...]] = {
    "specular": ("blinn", "phong"),
    "specular_gate": (True, False),
    "lights_in": ("eye", "world"),
    "normals": ("angle", "area", "uniform", "crease"),
    "cull": (None, "back", "front"),
}
# Applied to a render after it is made (no new render): the output transfer and GL's clamp.
TRANSFERS = ("linear", "srgb", "gamma2.2")
CLAMPS = (True, False)
# The crease angle tried, degrees (Blender's default auto smooth angle).
CREASE_ANGLE = 30.0
# A change is kept only if it lowers the residual by more than this (mean |difference|).
MARGIN = 1e-4
# A residual above this (2/255 on average) is not an explanation.
EXPLAINED = 2.0 / 255
# Light scales searched: factors from 1/20 to 20 (a golden-section search on log k).
SCALE_RANGE = (math.log(0.05), math.log(20.0))
PIXELS_FOR_FITS = 40_000


@dataclasses.dataclass(frozen=True, eq=False)
class Explanation:
    """What `explain` found.

    Attributes
    ----------
    switches : dict
        The switches that explain the image, by name, where they differ from the render as
        given: ``specular``, ``specular_gate``, ``lights_in``, ``normals`` (``"angle"``,
        ``"area"``, ``"uniform"``, or ``"crease"`` at 30 degrees), ``cull``, ``transfer`` and
        ``clamp``; and ``light_scale``, the factor on every light's colours, where it is not 1.
        Empty when the image is not explained.
    closest : dict
        The same for the best render found, explained or not.
    residual_before : float
        The mean absolute difference of the RGB values, the image against the render as given.
    residual_after : float
        The same against the best render found.
    explained : bool
        Whether the best render is within 2/255 on average: otherwise no known convention
        explains the image (`switches` is empty; `closest` is what came closest).
    image : Image
        The best render.
    renders : int
        How many renders the search made.
    """

    switches: dict[str, Any]
    closest: dict[str, Any]
    residual_before: float
    residual_after: float
    explained: bool
    image: Image
    renders: int


def _with(scene: Scene, scale: float, specular: str, gate: bool) -> Scene:
    """`scene` with every light's colours times `scale`, and the specular model and gate."""
    lights = scene.lights
    columns: dict[str, Any] = {n: lights._column(n) for n in _glshade.Lights.PARAMETERS}
    count = len(lights)
    for name in ("ambient", "diffuse", "specular"):
        rgba = columns[name].reshape(count, 4).copy()
        rgba[:, :3] *= scale
        columns[name] = rgba
    columns["position"] = columns["position"].reshape(count, 4)
    columns["spot_direction"] = columns["spot_direction"].reshape(count, 3)
    parameters = [real(columns[n], n) for n in _glshade.Lights.PARAMETERS]
    scaled = Lights._wrap(_glshade.Lights(parameters, None)) if count else Lights(count=0)
    with colors_checked():
        return Scene(
            lights=scaled,
            material=scene.material,
            back_material=None if scene.back_material is scene.material else scene.back_material,
            global_ambient=scene.global_ambient,
            viewer=scene.viewer,
            two_side=scene.two_side,
            separate_specular=scene.separate_specular,
            specular=specular,  # type: ignore[arg-type]
            specular_gate=gate,
        )


def _encoded(linear: NDArray[Any], clamp: bool, transfer: str) -> NDArray[Any]:
    """A linear render's RGB as `render` returns it with `clamp` and `transfer`."""
    rgb = np.clip(linear, 0.0, 1.0) if clamp else linear
    encoded: NDArray[Any] = apply_transfer(rgb, transfer)
    return encoded


def _sampled_residual(
    unlit: NDArray[Any], lit: NDArray[Any], target: NDArray[Any], clamp: bool, transfer: str,
    log_k: float,
) -> float:  # fmt: skip
    """The mean |difference| of the pixels ``unlit + k lit`` (k = exp(log_k)), encoded, from
    `target`."""
    return float(np.mean(np.abs(_encoded(unlit + math.exp(log_k) * lit, clamp, transfer) - target)))


def _golden(f: Any, lo: float, hi: float, steps: int = 40) -> float:
    """The minimiser of a unimodal `f` on [lo, hi], by golden-section search."""
    ratio = (math.sqrt(5) - 1) / 2
    a, b = lo, hi
    c, d = b - ratio * (b - a), a + ratio * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(steps):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - ratio * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + ratio * (b - a)
            fd = f(d)
    return (a + b) / 2


def explain(
    image: ArrayLike,
    mesh: Any,
    scene: Scene | None = None,
    camera: Camera | None = None,
    **render_options: Any,
) -> Explanation:
    """Which known convention switches make glshade's render match `image`.

    The render of `mesh` with `scene`, `camera` and `render_options` (as `render` takes them)
    is compared with `image`; then the switches other renderers differ by are searched, one at
    a time, keeping the change that lowers the residual most, until none helps: the output
    transfer (linear, sRGB, gamma 2.2) and GL's clamp, Blinn or Phong, the specular gate,
    lights in eye or world coordinates, the normals' weighting (angle, area, uniform) or
    creases at 30 degrees, and culling (none, back, front); with each, the light intensity
    scale that fits best (from 1/20 to 20: a π or ``1/π`` convention shows as 3.14 or 0.32).

    Parameters
    ----------
    image : (height, width, 3) or (height, width, 4) array-like
        The picture to explain: float in [0, 1] or uint8; its size is the render's.
    mesh : mesh
        As for `render`: an object with ``.vertices`` and ``.faces``, or a ``(vertices,
        faces)`` tuple.
    scene : Scene, optional
        The scene the picture was meant to show; None: `render`'s default scene.
    camera : Camera, optional
        As for `render`.
    **render_options
        `render`'s other keywords (``shading``, ``model``, ``background``...), as meant. The
        searched ones (``transfer``, ``clamp``, ``cull``, ``lights_in``, ``normals``) start
        from the values given.

    Returns
    -------
    Explanation
        The switches that differ, the residuals before and after, whether that explains the
        image, and the matching render.

    Raises
    ------
    ValueError, TypeError
        As `render` raises them, or for an image that is not (height, width, 3 or 4).
    """
    target = np.asarray(image)
    if target.ndim != 3 or target.shape[2] not in (3, 4):
        raise ValueError(f"image must have shape (height, width, 3 or 4), got {target.shape}")
    target = target / 255.0 if target.dtype == np.uint8 else target.astype(np.float64)
    height, width = target.shape[:2]
    if scene is None:
        from ._framing import default_scene

        # render's default scene: its lights belong to the world.
        base, lights_in0 = default_scene(), "world"
        render_options.pop("lights_in", None)
    else:
        base, lights_in0 = scene, render_options.pop("lights_in", "eye")
    given = render_input(
        mesh, base, camera, None, shading=render_options.get("shading", "phong"), normals=None,
        colors=None, color_material=None, lights_in=lights_in0, model=render_options.get("model"),
        width=width, height=height, texture=False,
    )  # fmt: skip
    v, f, lens = given.vertices.astype(np.float64), given.faces, given.camera
    start = {
        "specular": base.specular,
        "specular_gate": base.specular_gate,
        "lights_in": lights_in0,
        "normals": "angle",
        "cull": render_options.pop("cull", None),
    }
    transfer0 = render_options.pop("transfer", None) or "linear"
    clamp0 = render_options.pop("clamp", True)
    for searched in ("normals", "width", "height", "depth"):
        render_options.pop(searched, None)
    renders = 0
    rng = np.random.default_rng(0)
    sample = rng.choice(height * width, min(PIXELS_FOR_FITS, height * width), replace=False)
    flat_target = target[..., :3].reshape(-1, 3)

    def normals_of(kind: str) -> NDArray[Any]:
        if kind == "crease":
            return crease_normals(v, f, angle=CREASE_ANGLE)
        return vertex_normals(v, f, weighting=cast(Weighting, kind))

    def draw(config: dict[str, Any], scale: float) -> NDArray[Any]:
        nonlocal renders
        renders += 1
        lit = _with(base, scale, config["specular"], config["specular_gate"])
        shading = render_options.get("shading", "phong")
        normals = None if shading == "flat" else normals_of(config["normals"])
        return np.asarray(render(
            v, f, lit, lens, width=width, height=height, normals=normals, cull=config["cull"],
            lights_in=config["lights_in"], transfer="linear", clamp=False, **render_options,
        ))  # fmt: skip

    unlit: dict[Any, NDArray[Any]] = {}

    def fit(config: dict[str, Any]) -> tuple[float, dict[str, Any], NDArray[Any]]:
        """The best transfer, clamp and light scale for a structure: residual, switches, image."""
        one = draw(config, 1.0)
        # Without light (scale 0) a render is emission and global ambient: only what is drawn
        # (the culling) changes it, so one per culling.
        if config["cull"] not in unlit:
            unlit[config["cull"]] = draw(config, 0.0)
        zero = unlit[config["cull"]]
        lit1, lit0 = one[..., :3].reshape(-1, 3), zero[..., :3].reshape(-1, 3)
        s1, s0, st = lit1[sample], lit0[sample], flat_target[sample]
        best: tuple[float, dict[str, Any]] = (math.inf, {})
        for transfer in TRANSFERS:
            for clamp in CLAMPS:
                residual = functools.partial(_sampled_residual, s0, s1 - s0, st, clamp, transfer)

                at_one = residual(0.0)
                log_k = _golden(residual, *SCALE_RANGE)
                k = 1.0 if at_one <= residual(log_k) + MARGIN else math.exp(log_k)
                r = residual(math.log(k))
                if r < best[0] - 1e-12:
                    best = (r, {"transfer": transfer, "clamp": clamp, "light_scale": k})
        post = best[1]
        k = post["light_scale"]
        linear = lit0 + k * (lit1 - lit0)
        encoded = _encoded(linear, post["clamp"], post["transfer"])
        full = float(np.mean(np.abs(encoded - flat_target)))
        picture = np.concatenate([encoded.reshape(height, width, 3), one[..., 3:]], axis=-1)
        return full, post, picture

    def residual_as_given() -> float:
        picture = draw(start, 1.0)[..., :3].reshape(-1, 3)
        encoded = _encoded(picture, clamp0, transfer0)
        return float(np.mean(np.abs(encoded - flat_target)))

    before = residual_as_given()
    config = dict(start)
    score, post, picture = fit(config)
    while True:
        trials = []
        for name, values in SWITCHES.items():
            for value in values:
                if value != config[name]:
                    candidate = {**config, name: value}
                    trials.append((fit(candidate), candidate))
        (new_score, new_post, new_picture), candidate = min(trials, key=lambda t: t[0][0])
        if new_score >= score - MARGIN:
            break
        score, post, picture, config = new_score, new_post, new_picture, candidate
    switches = {k: config[k] for k in SWITCHES if config[k] != start[k]}
    if post["transfer"] != transfer0:
        switches["transfer"] = post["transfer"]
    if post["clamp"] != clamp0:
        switches["clamp"] = post["clamp"]
    if abs(post["light_scale"] - 1.0) > 1e-3:
        switches["light_scale"] = post["light_scale"]
    explained = score <= EXPLAINED
    return Explanation(
        switches=switches if explained else {},
        closest=switches,
        residual_before=before,
        residual_after=score,
        explained=explained,
        image=Image(picture),
        renders=renders,
    )
