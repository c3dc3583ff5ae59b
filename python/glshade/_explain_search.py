"""The search behind `explain`: one render per candidate set of convention switches, and the
transfer, clamp, light and ambient scales fitted to each on sampled pixels. The scene is GL's,
glTF's or three.js', and the shading model is itself a switch (the scene converted by
`as_model`); the other models have no specular model, gate or shininess switch (those are
GL's equation's), and their lights are in the world whatever the camera does."""

from __future__ import annotations

import dataclasses
import functools
import math
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

from . import _glshade, gltf, threejs
from ._camera import Camera
from ._intake import colors_checked, real
from ._model_conversion import MODELS, as_model
from ._normals import crease_normals, vertex_normals
from ._render import render
from ._scene import Lights, Material, Scene
from ._transfer import apply_transfer, srgb_decode
from ._typing import Weighting

# The discrete switches a render is searched over, and what each value means.
SWITCHES: dict[str, tuple[Any, ...]] = {
    "shading_model": MODELS,
    "specular": ("blinn", "phong"),
    "specular_gate": (True, False),
    "lights_in": ("eye", "world"),
    "normals": ("angle", "area", "uniform", "crease"),
    "cull": (None, "back", "front"),
    # "cw": two corners of each face swapped, so its normal and its facing flip.
    "winding": ("ccw", "cw"),
    # Shininess conventions: 0-1000 (Wavefront's Ns) against GL's 0-128 (0.128 and 7.8125),
    # Blinn against Phong exponents (4 and 1/4), 0-1 against 0-128 (128 and 1/128).
    "shininess_scale": (1.0, 1 / 128, 0.128, 0.25, 4.0, 7.8125, 128.0),
}
# GL's equation's own switches: the other models have none of them, nor lights that move with
# the eye.
GL_ONLY = ("specular", "specular_gate", "shininess_scale", "lights_in")
# What PyTorch3D's Phong fixes of them: its scene is GL's, drawn with these.
FIXED: dict[str, dict[str, Any]] = {
    "pytorch3d": {
        "specular": "phong", "specular_gate": True, "shininess_scale": 1.0, "lights_in": "world",
    },
}  # fmt: skip
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
# Light scales searched: factors from 1/20 to 20 (a golden-section search on log k).
SCALE_RANGE = (math.log(0.05), math.log(20.0))
# Ambient scales searched: 0 (a renderer without the global ambient term) to 10.
AMBIENT_RANGE = (0.0, 10.0)
PIXELS_FOR_FITS = 10_000


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


AnyScene = Scene | gltf.Scene | threejs.Scene
# three.js' lights that make its ambient term (the global ambient's counterpart).
_THREE_AMBIENT = (threejs.AmbientLight, threejs.HemisphereLight)


def world_scene_with(
    scene: gltf.Scene | threejs.Scene, scale: float, ambient: float
) -> gltf.Scene | threejs.Scene:
    """A glTF or three.js scene with every direct light's intensity times `scale`, and its
    ambient term (glTF's ambient light, three.js' ambient and hemisphere lights) times
    `ambient`: both models are linear in them, as GL's is in its light colours."""
    fields = scene._fields()
    fields["lights"] = [
        dataclasses.replace(
            light,
            intensity=light.intensity * (ambient if isinstance(light, _THREE_AMBIENT) else scale),
        )
        for light in scene.lights
    ]
    if isinstance(scene, gltf.Scene):
        fields["ambient_light"] = tuple(ambient * x for x in fields["ambient_light"])
    with colors_checked():
        return type(scene)(**fields)


def scene_with(
    scene: AnyScene,
    scale: float,
    specular: str,
    gate: bool,
    *,
    shininess: float = 1.0,
    ambient: float = 1.0,
) -> AnyScene:
    """`scene` with every light's colours times `scale`, the specular model and gate, the
    materials' shininess times `shininess` and the global ambient's RGB times `ambient`; a
    world model's by `world_scene_with` (it has no specular model, gate or shininess)."""
    if not isinstance(scene, Scene):
        return world_scene_with(scene, scale, ambient)
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


def encoded_rgb(linear: NDArray[Any], clamp: bool, transfer: str) -> NDArray[Any]:
    """A linear render's RGB as `render` returns it with `clamp` and `transfer`."""
    rgb = np.clip(linear, 0.0, 1.0) if clamp else linear
    encoded: NDArray[Any] = apply_transfer(rgb, transfer)
    return encoded


def sampled_residual(
    unlit: NDArray[Any], lit: NDArray[Any], target: NDArray[Any], clamp: bool, transfer: str,
    log_k: float,
) -> float:  # fmt: skip
    """The mean |difference| of the pixels ``unlit + k lit`` (k = exp(log_k)), encoded, from
    `target`; inf where it is not finite (a render beyond float32's range)."""
    with np.errstate(over="ignore", invalid="ignore"):
        rgb = encoded_rgb(unlit + math.exp(log_k) * lit, clamp, transfer)
        residual = float(np.mean(np.abs(rgb - target)))
    return residual if math.isfinite(residual) else math.inf


def decoded_rgb(encoded: NDArray[Any], transfer: str) -> NDArray[Any]:
    """Linear values from `encoded` ones: `apply_transfer` undone."""
    if transfer == "linear":
        return encoded
    if transfer == "srgb":
        decoded: NDArray[Any] = srgb_decode(encoded)
        return decoded
    gamma: NDArray[Any] = np.sign(encoded) * np.abs(encoded) ** 2.2
    return gamma


def golden(f: Any, lo: float, hi: float, steps: int = 26) -> float:
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


# A candidate's fit: its full-image residual, its transfer, clamp and light scale, its picture.
Fit = tuple[float, dict[str, Any], NDArray[Any]]


class Search:
    """The renders and fits of one `explain` call: a mesh, the scene and camera as meant, and
    the target picture (float64, (height, width, 3 or 4)).

    A configuration is a dict of every switch of `start` (the render as meant); `fit` scores
    one, `fit_ambient` refits the global ambient's scale with the light scale."""

    def __init__(
        self,
        vertices: NDArray[Any],
        faces: NDArray[Any],
        scene: AnyScene,
        camera: Camera,
        target: NDArray[Any],
        flat: bool,
        render_options: dict[str, Any],
        lights_in: str,
    ) -> None:
        self.v, self.f, self.scene, self.camera = vertices, faces, scene, camera
        # The scene as each model's, made when first asked for (`lights_in`: where a GL
        # scene's lights are given, for the conversion into world coordinates); None for a
        # model whose ranges the converted values leave.
        self.scenes: dict[str, AnyScene | None] = {}
        self.lights_in = lights_in
        self.height, self.width = target.shape[:2]
        self.flat = flat
        self.render_options = render_options
        # Rows of RGB; pixels with a NaN channel say nothing: every residual and fit leaves
        # them out (`valid`, the others' row numbers; `sample`, row numbers of valid pixels).
        self.target = target[..., :3].reshape(-1, 3)
        self.valid = np.flatnonzero(np.isfinite(self.target).all(axis=1))
        rng = np.random.default_rng(0)
        count = len(self.valid)
        self.sample = self.valid[rng.choice(count, min(PIXELS_FOR_FITS, count), replace=False)]
        self.renders = 0
        # Renders without light, RGB rows: emission and global ambient (`unlit`), emission
        # alone (`dark`): one of each per `drawing`.
        self.unlit: dict[Any, NDArray[Any]] = {}
        self.dark: dict[Any, NDArray[Any]] = {}

    def scene_for(self, model: str) -> AnyScene | None:
        """The scene as `model`'s, or None where it cannot be (an attenuation of 1e-320 is no
        three.js intensity): that model is not a candidate."""
        if model not in self.scenes:
            try:
                self.scenes[model] = as_model(
                    self.scene, model, view=self.camera.view, lights_in=self.lights_in
                )
            except (ValueError, OverflowError):
                self.scenes[model] = None
        return self.scenes[model]

    def drawn(self, config: dict[str, Any]) -> AnyScene:
        """The scene `config` draws (its model's)."""
        scene = self.scene_for(config["shading_model"])
        assert scene is not None, "only the models with a scene are searched"
        return scene

    def drawing(self, config: dict[str, Any]) -> tuple[Any, ...]:
        """What the renders without light depend on: the model, what is drawn (culling,
        winding) and, with flat shading, the vertex whose colour a face takes."""
        return (
            config["shading_model"], config["cull"], config["winding"],
            self.flat and config["provoking_vertex"],
        )  # fmt: skip

    def faces(self, config: dict[str, Any]) -> NDArray[Any]:
        """The faces in the winding of `config`: clockwise swaps two corners, keeping the
        provoking one (the first or the last) where it is."""
        if config["winding"] == "ccw":
            return self.f
        order = [0, 2, 1] if config["provoking_vertex"] == "first" else [1, 0, 2]
        return np.ascontiguousarray(self.f[:, order])

    def normals(self, config: dict[str, Any]) -> NDArray[Any]:
        faces = self.faces(config)
        if config["normals"] == "crease":
            return crease_normals(self.v, faces, angle=CREASE_ANGLE)
        return vertex_normals(self.v, faces, weighting=cast(Weighting, config["normals"]))

    def draw(self, config: dict[str, Any], scale: float, ambient: float = 1.0) -> NDArray[Any]:
        """The linear, unclamped render of `config` with the lights' colours times `scale` and
        the global ambient's times `ambient`."""
        self.renders += 1
        lit = scene_with(
            self.drawn(config), scale, config["specular"], config["specular_gate"],
            shininess=config["shininess_scale"], ambient=ambient,
        )  # fmt: skip
        extra = {"provoking_vertex": config["provoking_vertex"]} if self.flat else {}
        return np.asarray(render(
            self.v, self.faces(config), lit, self.camera, width=self.width, height=self.height,
            normals=None if self.flat else self.normals(config),
            # "none", render's own name for no culling: None would be a scene's default.
            cull=cast(Any, "none" if config["cull"] is None else config["cull"]),
            lights_in=config["lights_in"], transfer="linear", clamp=False, **extra,
            **self.render_options,
        ))  # fmt: skip

    def eye_distance(self, config: dict[str, Any]) -> NDArray[Any]:
        """The distance from the eye's plane of what `config` draws at each pixel, (height,
        width) (inf where nothing is): GL's window depth through the projection undone."""
        self.renders += 1
        _, window = render(
            self.v, self.faces(config), self.drawn(config), self.camera,
            width=self.width, height=self.height,
            cull=cast(Any, "none" if config["cull"] is None else config["cull"]), depth=True,
            **self.render_options,
        )  # fmt: skip
        p = self.camera.projection_matrix(self.width, self.height)
        ndc = 2.0 * np.asarray(window) - 1.0
        # z_ndc = (p22 z + p23) / (p32 z + p33), solved for the eye's z.
        with np.errstate(divide="ignore", invalid="ignore"):
            z = (p[2, 3] - ndc * p[3, 3]) / (ndc * p[3, 2] - p[2, 2])
        distance: NDArray[Any] = np.where(np.asarray(window) < 1.0, np.abs(z), np.inf)
        return distance

    def rows(self, config: dict[str, Any], scale: float, ambient: float = 1.0) -> NDArray[Any]:
        """`draw`'s RGB as rows."""
        return self.draw(config, scale, ambient)[..., :3].reshape(-1, 3)

    def unlit_rows(self, config: dict[str, Any]) -> tuple[NDArray[Any], NDArray[Any] | None]:
        """Emission + a·ambient, and the ambient term (None when `a` is 1: not needed)."""
        key = self.drawing(config)
        if key not in self.unlit:
            self.unlit[key] = self.rows(config, 0.0)
        if config["ambient_scale"] == 1.0:
            return self.unlit[key], None
        if key not in self.dark:
            self.dark[key] = self.rows(config, 0.0, ambient=0.0)
        ambient = self.unlit[key] - self.dark[key]
        return self.dark[key] + config["ambient_scale"] * ambient, ambient

    def residual(self, config: dict[str, Any], clamp: bool, transfer: str) -> float:
        """The full-image residual of `config` as drawn, with `clamp` and `transfer`."""
        return self.mean_difference(encoded_rgb(self.rows(config, 1.0), clamp, transfer))

    def mean_difference(self, rows: NDArray[Any], where: NDArray[Any] | None = None) -> float:
        """The mean |difference| of RGB `rows` from the target's over its valid pixels (or
        the row numbers `where`); 0 where there are none, inf where it is not finite."""
        where = self.valid if where is None else where
        if len(where) == 0:
            return 0.0
        with np.errstate(invalid="ignore"):
            residual = float(np.mean(np.abs(rows[where] - self.target[where])))
        return residual if math.isfinite(residual) else math.inf

    def fit(self, config: dict[str, Any], post: dict[str, Any] | None = None) -> Fit:
        """The full-image residual of `config` with the transfer, clamp and light scale that fit
        it best on the sampled pixels (or those of `post`), and its picture."""
        one = self.draw(config, 1.0, ambient=config["ambient_scale"])
        lit1 = one[..., :3].reshape(-1, 3)
        lit0, _ = self.unlit_rows(config)
        if post is None:
            # The search runs in float32: the transfer's powers are most of its time, and the
            # full-image residual below decides in float64.
            with np.errstate(over="ignore"):  # beyond float32's range: inf, no fit
                s1, s0, st = (x[self.sample].astype(np.float32) for x in (lit1, lit0, self.target))
            best: tuple[float, dict[str, Any]] = (
                math.inf, {"transfer": "linear", "clamp": True, "light_scale": 1.0}
            )  # fmt: skip
            for transfer in TRANSFERS:
                for clamp in CLAMPS:
                    residual = functools.partial(sampled_residual, s0, s1 - s0, st, clamp, transfer)
                    at_one = residual(0.0)
                    log_k = golden(residual, *SCALE_RANGE)
                    k = 1.0 if at_one <= residual(log_k) + MARGIN else math.exp(log_k)
                    r = residual(math.log(k))
                    if r < best[0] - 1e-12:
                        best = (r, {"transfer": transfer, "clamp": clamp, "light_scale": k})
            post = best[1]
        linear = lit0 + post["light_scale"] * (lit1 - lit0)
        encoded = encoded_rgb(linear, post["clamp"], post["transfer"])
        full = self.mean_difference(encoded)
        picture = np.concatenate(
            [encoded.reshape(self.height, self.width, 3), one[..., 3:]], axis=-1
        )
        return full, post, picture

    def fit_ambient(
        self, config: dict[str, Any], post: dict[str, Any]
    ) -> tuple[Fit, dict[str, Any]] | None:
        """The global ambient's scale and the light scale fitted together for `config` with
        `post`'s transfer and clamp; None when the scene has no global ambient term."""
        _, ambient_rows = self.unlit_rows({**config, "ambient_scale": 0.0})
        key = self.drawing(config)
        if ambient_rows is None or not ambient_rows[self.sample].any():
            return None
        emission, ambient = self.dark[key][self.sample], ambient_rows[self.sample]
        lights = self.rows(config, 1.0, ambient=0.0)[self.sample] - emission
        # Least squares in linear values, on the pixels the transfer can be undone at (inside
        # (0, 1) when clamped: a clipped value says only that the sum is beyond the clip).
        st, clamp = self.target[self.sample], post["clamp"]
        target = decoded_rgb(st, post["transfer"])
        usable = ((st > 1e-6) & (st < 1 - 1e-6)) if clamp else np.isfinite(target)
        basis = np.stack([ambient[usable], lights[usable]], axis=1)
        rhs = target[usable] - emission[usable]
        if len(rhs) < 2 or np.linalg.matrix_rank(basis) < 2:
            return None
        (a, k), *_ = np.linalg.lstsq(basis, rhs, rcond=None)
        a = float(np.clip(a, *AMBIENT_RANGE))
        k = float(np.clip(k, *np.exp(SCALE_RANGE)))
        candidate = {**config, "ambient_scale": a}
        return self.fit(candidate, {**post, "light_scale": k}), candidate
