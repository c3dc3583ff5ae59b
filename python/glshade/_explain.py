"""`explain`: which of the known convention switches make glshade's render of a mesh match a
user's image, found by search, with the residual before and after."""

from __future__ import annotations

import dataclasses
import functools
import itertools
import math
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _glshade
from ._camera import Camera
from ._image import Image
from ._intake import colors_checked, one_of, real
from ._normals import crease_normals, vertex_normals
from ._render import render
from ._render_input import render_input
from ._scene import Lights, Material, Scene
from ._transfer import apply_transfer, srgb_decode
from ._typing import Weighting

__all__ = ["Explanation", "explain"]

# The discrete switches a render is searched over, and what each value means.
SWITCHES: dict[str, tuple[Any, ...]] = {
    "specular": ("blinn", "phong"),
    "specular_gate": (True, False),
    "lights_in": ("eye", "world"),
    "normals": ("angle", "area", "uniform", "crease"),
    "cull": (None, "back", "front"),
    # "cw": the faces' vertices in the other order, so their normals and facing flip.
    "winding": ("ccw", "cw"),
    # Shininess conventions: 0-1000 (Wavefront's Ns) against GL's 0-128 (0.128 and 7.8125),
    # Blinn against Phong exponents (4 and 1/4), 0-1 against 0-128 (128 and 1/128).
    "shininess_scale": (1.0, 1 / 128, 0.128, 0.25, 4.0, 7.8125, 128.0),
}
# Searched with flat shading only.
PROVOKING = ("last", "first", "centroid")
# Switches also tried together: clockwise faces culled as back faces are the counter-clockwise
# ones culled as front faces, which neither change alone brings closer.
JOINT = (("winding", "cull"),)
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
# Ambient scales searched: 0 (a renderer without the global ambient term) to 10.
AMBIENT_RANGE = (0.0, 10.0)
PIXELS_FOR_FITS = 10_000


@dataclasses.dataclass(frozen=True, eq=False)
class Explanation:
    """What `explain` found.

    Attributes
    ----------
    switches : dict
        The switches that explain the image, by name, where they differ from the render as
        given: ``specular``, ``specular_gate``, ``lights_in``, ``normals`` (``"angle"``,
        ``"area"``, ``"uniform"``, or ``"crease"`` at 30 degrees), ``cull``, ``winding``
        (``"cw"``: the faces' vertices in the other order), ``shininess_scale``,
        ``provoking_vertex`` (flat shading), ``transfer`` and ``clamp``; ``light_scale``, the
        factor on every light's colours, and ``ambient_scale``, the factor on the global
        ambient term, where they are not 1. Empty when the image is not explained.
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


def _shinier(material: Material, factor: float) -> Material:
    if factor == 1.0:
        return material
    return Material(
        ambient=material.ambient,
        diffuse=material.diffuse,
        specular=material.specular,
        emission=material.emission,
        shininess=material.shininess * factor,
    )


def _with(
    scene: Scene,
    scale: float,
    specular: str,
    gate: bool,
    *,
    shininess: float = 1.0,
    ambient: float = 1.0,
) -> Scene:
    """`scene` with every light's colours times `scale`, the specular model and gate, the
    materials' shininess times `shininess` and the global ambient's RGB times `ambient`."""
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
    back = None if scene.back_material is scene.material else scene.back_material
    global_ambient = scene.global_ambient.copy()
    global_ambient[:3] *= ambient
    with colors_checked():
        return Scene(
            lights=scaled,
            material=_shinier(scene.material, shininess),
            back_material=None if back is None else _shinier(back, shininess),
            global_ambient=global_ambient,
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


def _decoded(encoded: NDArray[Any], transfer: str) -> NDArray[Any]:
    """Linear values from `encoded` ones: `apply_transfer` undone."""
    if transfer == "linear":
        return encoded
    if transfer == "srgb":
        decoded: NDArray[Any] = srgb_decode(encoded)
        return decoded
    gamma: NDArray[Any] = np.sign(encoded) * np.abs(encoded) ** 2.2
    return gamma


def _golden(f: Any, lo: float, hi: float, steps: int = 26) -> float:
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
    creases at 30 degrees, culling (none, back, front), the faces' winding, shininess scales
    (0.128, 1/4, 4, 7.8125, 128) and, with flat shading, the provoking vertex (last, first,
    centroid); with each, the light intensity scale that fits best (from 1/20 to 20: a π or
    ``1/π`` convention shows as 3.14 or 0.32); and, as one more move, a scale of the global
    ambient term (0 to 10) fitted with it.

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
        searched ones (``transfer``, ``clamp``, ``cull``, ``lights_in``, ``normals``,
        ``provoking_vertex``) start from the values given.

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
    flat = str(render_options.get("shading", "phong")).lower() == "flat"
    switches_searched = dict(SWITCHES)
    if flat:  # flat shading lights with the face normals: the vertex normals do not matter
        del switches_searched["normals"]
        switches_searched["provoking_vertex"] = PROVOKING
    start: dict[str, Any] = {
        "specular": base.specular,
        "specular_gate": base.specular_gate,
        "lights_in": lights_in0,
        "normals": "angle",
        "cull": render_options.pop("cull", None),
        "winding": "ccw",
        "shininess_scale": 1.0,
        "provoking_vertex": one_of(
            render_options.pop("provoking_vertex", "last"), "provoking_vertex", PROVOKING
        ),
        "ambient_scale": 1.0,
    }
    transfer0 = render_options.pop("transfer", None) or "linear"
    clamp0 = render_options.pop("clamp", True)
    for searched in ("normals", "width", "height", "depth"):
        render_options.pop(searched, None)
    renders = 0
    rng = np.random.default_rng(0)
    sample = rng.choice(height * width, min(PIXELS_FOR_FITS, height * width), replace=False)
    flat_target = target[..., :3].reshape(-1, 3)

    def faces_of(config: dict[str, Any]) -> NDArray[Any]:
        """The faces in the winding of `config`: clockwise swaps two corners, keeping the
        provoking one (the first or the last) where it is."""
        if config["winding"] == "ccw":
            return f
        order = [0, 2, 1] if config["provoking_vertex"] == "first" else [1, 0, 2]
        return np.ascontiguousarray(f[:, order])

    def normals_of(config: dict[str, Any]) -> NDArray[Any]:
        faces = faces_of(config)
        if config["normals"] == "crease":
            return crease_normals(v, faces, angle=CREASE_ANGLE)
        return vertex_normals(v, faces, weighting=cast(Weighting, config["normals"]))

    def draw(config: dict[str, Any], scale: float, ambient: float = 1.0) -> NDArray[Any]:
        nonlocal renders
        renders += 1
        lit = _with(
            base, scale, config["specular"], config["specular_gate"],
            shininess=config["shininess_scale"], ambient=ambient,
        )  # fmt: skip
        extra = {"provoking_vertex": config["provoking_vertex"]} if flat else {}
        return np.asarray(render(
            v, faces_of(config), lit, lens, width=width, height=height,
            normals=None if flat else normals_of(config), cull=config["cull"],
            lights_in=config["lights_in"], transfer="linear", clamp=False, **extra,
            **render_options,
        ))  # fmt: skip

    # Renders without light: emission and global ambient (`unlit`), emission alone (`dark`),
    # RGB rows. Only what is drawn (culling, winding) and, with flat shading, the vertex whose
    # colour a face takes change them: one of each per drawing.
    unlit: dict[Any, NDArray[Any]] = {}
    dark: dict[Any, NDArray[Any]] = {}

    def drawing(config: dict[str, Any]) -> tuple[Any, ...]:
        return (config["cull"], config["winding"], flat and config["provoking_vertex"])

    def unlit_rows(config: dict[str, Any]) -> tuple[NDArray[Any], NDArray[Any] | None]:
        """Emission + a·ambient, and the ambient term (None when `a` is 1: not needed)."""
        key = drawing(config)
        if key not in unlit:
            unlit[key] = draw(config, 0.0)[..., :3].reshape(-1, 3)
        if config["ambient_scale"] == 1.0:
            return unlit[key], None
        if key not in dark:
            dark[key] = draw(config, 0.0, ambient=0.0)[..., :3].reshape(-1, 3)
        ambient = unlit[key] - dark[key]
        return dark[key] + config["ambient_scale"] * ambient, ambient

    def fit(config: dict[str, Any], post: dict[str, Any] | None = None) -> tuple[
        float, dict[str, Any], NDArray[Any]
    ]:  # fmt: skip
        """The full-image residual of a structure with the transfer, clamp and light scale
        that fit it best on the sampled pixels (or those of `post`), and its picture."""
        one = draw(config, 1.0, ambient=config["ambient_scale"])
        lit1 = one[..., :3].reshape(-1, 3)
        lit0, _ = unlit_rows(config)
        if post is None:
            s1, s0, st = lit1[sample], lit0[sample], flat_target[sample]
            best: tuple[float, dict[str, Any]] = (math.inf, {})
            for transfer in TRANSFERS:
                for clamp in CLAMPS:
                    residual = functools.partial(
                        _sampled_residual, s0, s1 - s0, st, clamp, transfer
                    )
                    at_one = residual(0.0)
                    log_k = _golden(residual, *SCALE_RANGE)
                    k = 1.0 if at_one <= residual(log_k) + MARGIN else math.exp(log_k)
                    r = residual(math.log(k))
                    if r < best[0] - 1e-12:
                        best = (r, {"transfer": transfer, "clamp": clamp, "light_scale": k})
            post = best[1]
        linear = lit0 + post["light_scale"] * (lit1 - lit0)
        encoded = _encoded(linear, post["clamp"], post["transfer"])
        full = float(np.mean(np.abs(encoded - flat_target)))
        picture = np.concatenate([encoded.reshape(height, width, 3), one[..., 3:]], axis=-1)
        return full, post, picture

    def fit_ambient(
        config: dict[str, Any], post: dict[str, Any]
    ) -> tuple[tuple[float, dict[str, Any], NDArray[Any]], dict[str, Any]] | None:
        """The global ambient's scale and the light scale fitted together for `config` with
        `post`'s transfer and clamp; None when the scene has no global ambient term."""
        _, ambient_rows = unlit_rows({**config, "ambient_scale": 0.0})
        key = drawing(config)
        if ambient_rows is None or not ambient_rows[sample].any():
            return None
        lights = draw(config, 1.0, ambient=0.0)[..., :3].reshape(-1, 3)[sample]
        emission, ambient = dark[key][sample], ambient_rows[sample]
        lights = lights - emission
        # Least squares in linear values, on the pixels the transfer can be undone at (inside
        # (0, 1) when clamped: a clipped value says only that the sum is beyond the clip).
        st, clamp = flat_target[sample], post["clamp"]
        target = _decoded(st, post["transfer"])
        usable = ((st > 1e-6) & (st < 1 - 1e-6)) if clamp else np.isfinite(target)
        basis = np.stack([ambient[usable], lights[usable]], axis=1)
        rhs = target[usable] - emission[usable]
        if len(rhs) < 2 or np.linalg.matrix_rank(basis) < 2:
            return None
        (a, k), *_ = np.linalg.lstsq(basis, rhs, rcond=None)
        a = float(np.clip(a, *AMBIENT_RANGE))
        k = float(np.clip(k, *np.exp(SCALE_RANGE)))
        candidate = {**config, "ambient_scale": a}
        return fit(candidate, {**post, "light_scale": k}), candidate

    def residual_as_given() -> float:
        picture = draw(start, 1.0)[..., :3].reshape(-1, 3)
        encoded = _encoded(picture, clamp0, transfer0)
        return float(np.mean(np.abs(encoded - flat_target)))

    before = residual_as_given()
    config = dict(start)
    score, post, picture = fit(config)
    while True:
        trials = []
        for name, values in switches_searched.items():
            for value in values:
                if value != config[name]:
                    candidate = {**config, name: value}
                    trials.append((fit(candidate), candidate))
        for first, second in JOINT:
            for a, b in itertools.product(SWITCHES[first], SWITCHES[second]):
                if a != config[first] and b != config[second]:
                    candidate = {**config, first: a, second: b}
                    trials.append((fit(candidate), candidate))
        ambient_trial = fit_ambient(config, post)
        if ambient_trial is not None:
            trials.append(ambient_trial)
        (new_score, new_post, new_picture), candidate = min(trials, key=lambda t: t[0][0])
        if new_score >= score - MARGIN:
            break
        score, post, picture, config = new_score, new_post, new_picture, candidate
    switches = {k: config[k] for k in switches_searched if config[k] != start[k]}
    if post["transfer"] != transfer0:
        switches["transfer"] = post["transfer"]
    if post["clamp"] != clamp0:
        switches["clamp"] = post["clamp"]
    if abs(post["light_scale"] - 1.0) > 1e-3:
        switches["light_scale"] = post["light_scale"]
    if abs(config["ambient_scale"] - 1.0) > 1e-3:
        switches["ambient_scale"] = config["ambient_scale"]
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
