"""`explain`: which of the known convention switches make glshade's render of a mesh match a
user's image, found by search, with the residual before and after."""

from __future__ import annotations

import base64
import dataclasses
import functools
import html
import itertools
import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import gltf, threejs
from ._camera import Camera
from ._compare import coverage_edges, depth_steps
from ._compare import picture as picture_values
from ._explain_search import (
    AMBIENT_RANGE,
    FIXED,
    GL_ONLY,
    JOINT,
    MARGIN,
    PROVOKING,
    SCALE_RANGE,
    SWITCHES,
    Search,
)  # fmt: skip
from ._image import Image
from ._intake import colors_checked, one_of
from ._model_conversion import MODELS, model_of
from ._png import encode_png
from ._render_input import render_input
from ._scene import Scene

__all__ = ["Explanation", "explain"]

# What two float renderers of one convention differ by on average, away from silhouettes
# (float32 arithmetic, another rasteriser's sample positions inside a face).
FLOAT_NOISE = 2e-4
# Undoing a switch after the search is kept where it costs at most this (mean |difference|).
UNDO = 1e-6
# A step in distance between neighbouring pixels, relative, that makes an inner silhouette
# (a surface in front of another); smooth surfaces step by less unless seen edge on.
DEPTH_STEP = 0.02
# How many of the closest candidates an explanation keeps.
CANDIDATES = 3


def quantisation_step(values: NDArray[Any], step: float) -> float:
    """The step the picture's values were rounded to: `step` for an integer picture; for a
    float one, 1/255 or 1/65535 when every finite value is a multiple of it (an 8- or 16-bit
    picture divided), else 0."""
    if step:
        return step
    finite = values[np.isfinite(values)]
    for levels in (255.0, 65535.0):
        scaled = finite * levels
        if finite.size and np.abs(scaled - np.round(scaled)).max() < 1e-3:
            return 1.0 / levels
    return 0.0


@dataclasses.dataclass(frozen=True, eq=False)
class Explanation:
    """What `explain` found.

    Attributes
    ----------
    switches : dict
        The switches that explain the image, by name, where they differ from the render as
        given: ``shading_model`` (``"gl"``, ``"gltf"``, ``"threejs"`` or ``"pytorch3d"``: the
        scene converted to that model, as the guide page "Why does my renderer look
        different?" tabulates), ``specular``, ``specular_gate``, ``lights_in`` (these three
        and ``shininess_scale`` are GL's equation's own), ``normals`` (``"angle"``,
        ``"area"``, ``"uniform"``, or ``"crease"`` at 30 degrees), ``cull``, ``winding``
        (``"cw"``: the faces' vertices in the other order), ``shininess_scale``,
        ``provoking_vertex`` (flat shading), ``transfer`` and ``clamp``; ``light_scale``, the
        factor on every light's colours, and ``ambient_scale``, the factor on the global
        ambient term, where they are not 1. Empty when the image is not explained.
    closest : dict
        The same for the best render found, explained or not.
    residual_before : float
        The mean absolute difference of the RGB values, the image against the render as given
        (pixels with a NaN channel left out).
    residual_after : float
        The same against the best render found.
    residual_interior : float
        The same away from the best render's silhouettes, where other renderers antialias: a
        pixel with a neighbour of other coverage, or one more than 2% nearer or farther from
        the eye (a surface in front of another). What `explained` is decided on.
    noise : float
        What the picture's own rounding allows: half its quantisation step (0.5/255 for an
        8-bit picture, or a float picture whose values are multiples of 1/255) plus 2e-4 for
        float arithmetic.
    explained : bool
        Whether the best render is within `noise` away from the silhouettes, and its light and
        ambient scales inside their searched ranges (not stopped at an end): otherwise nothing
        explains the image (`switches` is empty; `closest` and `candidates` are what came
        closest, which is not an explanation).
    candidates : list of (dict, float)
        Distinct candidates with their switches and residual: the best render's first, then
        the closest others the search tried.
    ignored : int
        Pixels left out because a channel is NaN.
    image : Image
        The best render.
    target : Image
        The picture explained, as float values in [0, 1].
    renders : int
        How many renders the search made.

    Notes
    -----
    ``print(explanation)`` says in a sentence what explains the picture, or that nothing
    does, with the closest candidates; in a notebook it shows that beside the picture and the
    best render, small.
    """

    switches: dict[str, Any]
    closest: dict[str, Any]
    residual_before: float
    residual_after: float
    explained: bool
    image: Image = dataclasses.field(repr=False)
    renders: int
    residual_interior: float = 0.0
    noise: float = 0.0
    candidates: list[tuple[dict[str, Any], float]] = dataclasses.field(
        default_factory=list, repr=False
    )
    ignored: int = 0
    target: Image | None = dataclasses.field(default=None, repr=False)

    def __str__(self) -> str:
        shown = _switches_text(self.switches)
        if self.explained:
            head = (
                f"explained by {shown}: the residual goes from {self.residual_before:.3g} to "
                f"{self.residual_interior:.3g} away from the silhouettes, within the picture's "
                f"noise {self.noise:.3g}"
                if self.switches
                else f"explained as rendered: residual {self.residual_interior:.3g}, within "
                f"the picture's noise {self.noise:.3g}"
            )
            lines = [head]
        else:
            lines = [
                f"nothing explains it: the closest render, {_switches_text(self.closest)}, "
                f"leaves {self.residual_interior:.3g} away from the silhouettes, above the "
                f"picture's noise {self.noise:.3g} (from {self.residual_before:.3g} as "
                "rendered); the picture may come from conventions glshade does not search, "
                "or from another scene"
            ]
            for switches, residual in self.candidates[1:]:
                lines.append(f"  also close: {_switches_text(switches)}, residual {residual:.3g}")
        if self.ignored:
            lines.append(f"{self.ignored} pixels with NaN left out")
        lines.append(f"{self.renders} renders")
        return "\n".join(lines)

    def _repr_html_(self) -> str:
        """The sentence, the picture and the best render side by side, small."""
        cells = []
        for title, img in (("picture", self.target), ("best render", self.image)):
            if img is None:
                continue
            rgb = np.nan_to_num(np.clip(np.asarray(img, np.float64)[..., :3], 0.0, 1.0))
            data = base64.b64encode(encode_png(rgb)).decode("ascii")
            width = min(rgb.shape[1], 192)
            cells.append(
                f'<figure style="margin:0"><img src="data:image/png;base64,{data}" '
                f'width="{width}" alt="{title}"><figcaption>{title}</figcaption></figure>'
            )
        text = "".join(f"<div>{html.escape(line)}</div>" for line in str(self).splitlines())
        return (
            '<div style="font-family:sans-serif;font-size:12px">'
            f'<div>{text}</div><div style="display:flex;gap:12px">{"".join(cells)}</div></div>'
        )


def _switches_text(switches: dict[str, Any]) -> str:
    if not switches:
        return "no switch"
    return ", ".join(
        f"{k}={v:.3g}" if isinstance(v, float) else f"{k}={v!r}" for k, v in switches.items()
    )


def _at_an_end(post: dict[str, Any], config: dict[str, Any]) -> bool:
    """Whether a fitted scale stopped at the end of its searched range: the picture wants a
    value outside it, which is no convention's."""
    k = math.log(post["light_scale"])
    return (
        min(abs(k - end) for end in SCALE_RANGE) < 1e-3
        or config["ambient_scale"] >= AMBIENT_RANGE[1] - 1e-9
    )


def explain(
    image: ArrayLike,
    mesh: Any,
    scene: Scene | gltf.Scene | threejs.Scene | None = None,
    camera: Camera | None = None,
    **render_options: Any,
) -> Explanation:
    """Which known convention switches make glshade's render match `image`.

    The render of `mesh` with `scene`, `camera` and `render_options` (as `render` takes them)
    is compared with `image`; then the switches other renderers differ by are searched, one at
    a time, keeping the change that lowers the residual most, until none helps: the shading
    model (GL's, glTF's metallic-roughness as pyrender draws it, three.js' Phong, PyTorch3D's
    Phong, the scene converted to each), the output
    transfer (linear, sRGB, gamma 2.2) and GL's clamp, Blinn or Phong, the specular gate,
    lights in eye or world coordinates, the normals' weighting (angle, area, uniform) or
    creases at 30 degrees, culling (none, back, front), the faces' winding, shininess scales
    (0.128, 1/4, 4, 7.8125, 128) and, with flat shading, the provoking vertex (last, first,
    centroid); with each, the light intensity scale that fits best (from 1/20 to 20: a π or
    ``1/π`` convention shows as 3.14 or 0.32); and, as one more move, a scale of the global
    ambient term (0 to 10) fitted with it.

    The picture is explained when the best render matches it to within its own rounding (half
    its quantisation step, plus 2e-4 for float arithmetic) away from the render's silhouettes,
    with the fitted scales inside their ranges; otherwise `explain` says nothing explains it,
    with the closest candidates, rather than naming a convention that only comes near.

    Parameters
    ----------
    image : (height, width, 3) or (height, width, 4) array-like
        The picture to explain: float in [0, 1], uint8 (divided by 255) or uint16 (by 65535);
        its size is the render's. Pixels with a NaN channel are left out (and counted).
    mesh : mesh
        As for `render`: an object with ``.vertices`` and ``.faces``, or a ``(vertices,
        faces)`` tuple.
    scene : Scene, gltf.Scene or threejs.Scene, optional
        The scene the picture was meant to show; None: `render`'s default scene. The switches
        of GL's equation (``specular``, ``specular_gate``, ``shininess_scale``, ``lights_in``)
        are searched only while the search draws GL's model; in glTF's and three.js' the
        light scale multiplies the direct lights' intensities, the ambient scale the model's
        ambient term (glTF's ambient light, three.js' ambient and hemisphere lights).
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
        As `render` raises them, for an image that is not (height, width, 3 or 4), or (a
        TypeError) for a scene of none of glshade's models.
    """
    target, step = picture_values(image, "image", "explain")
    noise = quantisation_step(target[..., :3], step) / 2 + FLOAT_NOISE
    ignored = int((~np.isfinite(target[..., :3]).all(axis=2)).sum())
    if ignored == target.shape[0] * target.shape[1]:
        raise ValueError(
            f"image has a NaN channel in each of its {ignored} pixels: nothing to explain"
        )
    height, width = target.shape[:2]
    if scene is not None and not isinstance(scene, (Scene, gltf.Scene, threejs.Scene)):
        raise TypeError(
            f"scene must be a glshade.Scene, gltf.Scene, threejs.Scene or None, got {type(scene)!r}"
        )
    base: Scene | gltf.Scene | threejs.Scene
    if scene is None:
        from ._framing import default_scene

        # render's default scene: its lights belong to the world.
        base, lights_in0 = default_scene(), "world"
        render_options.pop("lights_in", None)
    elif isinstance(scene, Scene):
        base, lights_in0 = scene, render_options.pop("lights_in", "eye")
    else:  # the other models' lights are in the world
        base, lights_in0 = scene, "world"
        render_options.pop("lights_in", None)
    given = render_input(
        mesh, base, camera, None, shading=render_options.get("shading", "phong"), normals=None,
        colors=None, color_material=None, lights_in=lights_in0, model=render_options.get("model"),
        width=width, height=height, texture=False,
    )  # fmt: skip
    flat = str(render_options.get("shading", "phong")).lower() == "flat"
    start: dict[str, Any] = {
        "shading_model": model_of(base),
        "specular": base.specular if isinstance(base, Scene) else "blinn",
        "specular_gate": base.specular_gate if isinstance(base, Scene) else True,
        "lights_in": lights_in0,
        "normals": "angle",
        "cull": _cull(render_options.pop("cull", None), base),
        "winding": "ccw",
        "shininess_scale": 1.0,
        "provoking_vertex": one_of(
            render_options.pop("provoking_vertex", "last"), "provoking_vertex", PROVOKING
        ),
        "ambient_scale": 1.0,
    }
    transfer0 = render_options.pop("transfer", None) or "linear"
    clamp0 = render_options.pop("clamp", True)
    for option in ("normals", "width", "height", "depth"):
        render_options.pop(option, None)
    search = Search(
        given.vertices.astype(np.float64), given.faces, base, given.camera, target, flat,
        render_options, lights_in0,
    )  # fmt: skip
    models = tuple(m for m in MODELS if search.scene_for(m) is not None)
    searched = {model: _searched(models, model, flat) for model in models}
    moved = functools.partial(_moved, start)
    before = search.residual(start, clamp0, transfer0)
    config = dict(start)
    score, post, picture = search.fit(config)
    tried: list[tuple[float, dict[str, Any], dict[str, Any]]] = [(score, post, config)]
    while True:
        trials = []
        for name, values in searched[config["shading_model"]].items():
            for value in values:
                if value != config[name]:
                    candidate = moved(config, name, value)
                    trials.append((search.fit(candidate), candidate))
        for first, second in JOINT:
            for a, b in itertools.product(SWITCHES[first], SWITCHES[second]):
                if a != config[first] and b != config[second]:
                    candidate = {**config, first: a, second: b}
                    trials.append((search.fit(candidate), candidate))
        ambient_trial = search.fit_ambient(config, post)
        if ambient_trial is not None:
            trials.append(ambient_trial)
        tried.extend((fit[0], fit[1], candidate) for fit, candidate in trials)
        (new_score, new_post, new_picture), candidate = min(
            trials, key=functools.partial(_ranked, config["shading_model"])
        )
        if new_score >= score - MARGIN:
            break
        score, post, picture, config = new_score, new_post, new_picture, candidate
    # A switch taken early can be one the later ones make needless, yet undoing it gains less
    # than MARGIN: each is undone (the scales refitted) where that is no worse.
    for name in SWITCHES | {"provoking_vertex": PROVOKING}:
        if name not in searched[config["shading_model"]] or config[name] == start[name]:
            continue
        candidate = moved(config, name, start[name])
        undone = [(search.fit(candidate), candidate)]
        ambient_trial = search.fit_ambient(candidate, undone[0][0][1])
        if ambient_trial is not None:
            undone.append(ambient_trial)
        tried.extend((fit[0], fit[1], c) for fit, c in undone)
        (new_score, new_post, new_picture), candidate = min(undone, key=lambda t: t[0][0])
        if new_score <= score + UNDO:
            score, post, picture, config = new_score, new_post, new_picture, candidate
    named = functools.partial(_named, start, searched, transfer0, clamp0)
    switches = named(config, post)
    # Decided away from the silhouettes, outer and inner, where another renderer's
    # antialiasing differs.
    rows = np.asarray(picture)[..., :3].reshape(-1, 3)
    inside = np.flatnonzero(~_silhouettes(search.eye_distance(config)).reshape(-1))
    interior = search.mean_difference(rows, np.intersect1d(inside, search.valid))
    explained = interior <= noise and not _at_an_end(post, config)
    candidates: list[tuple[dict[str, Any], float]] = [(switches, score)]
    for residual, fit_post, fit_config in sorted(tried, key=lambda t: t[0]):
        found = named(fit_config, fit_post)
        if all(found != c for c, _ in candidates):
            candidates.append((found, residual))
        if len(candidates) == CANDIDATES:
            break
    with colors_checked():  # the picture was checked as `image`; the render is glshade's
        best, given_picture = Image(picture), Image(target)
    return Explanation(
        switches=switches if explained else {},
        closest=switches,
        residual_before=before,
        residual_after=score,
        explained=explained,
        image=best,
        renders=search.renders,
        residual_interior=interior,
        noise=noise,
        candidates=candidates,
        ignored=ignored,
        target=given_picture,
    )


def _silhouettes(distance: NDArray[Any]) -> NDArray[np.bool_]:
    """Pixels at the edge of what is drawn (`distance` from the eye's plane, inf where nothing
    is), or beside a neighbour more than `DEPTH_STEP` nearer or farther: where one surface
    passes in front of another."""
    covered = np.isfinite(distance)
    with np.errstate(divide="ignore"):
        log_distance = np.log(np.where(covered, distance, 1.0))
    return coverage_edges(covered) | depth_steps(log_distance, covered, math.log1p(DEPTH_STEP))


def _searched(models: tuple[str, ...], model: str, flat: bool) -> dict[str, tuple[Any, ...]]:
    """The switches searched, and their values, while the search is at `model`: the `models`
    the scene converts to; GL's equation's own only for GL's model; the provoking vertex
    instead of the normals with flat shading (which lights with the face normals)."""
    switches = {k: v for k, v in SWITCHES.items() if model == "gl" or k not in GL_ONLY}
    switches["shading_model"] = models
    if flat:
        del switches["normals"]
        switches["provoking_vertex"] = PROVOKING
    return switches


def _moved(start: dict[str, Any], config: dict[str, Any], name: str, value: Any) -> dict[str, Any]:
    """`config` with switch `name` at `value`. Moving to another model puts GL's equation's
    own switches back where the render as meant has them, and at what the model fixes
    (PyTorch3D's Phong reflection, say)."""
    if name != "shading_model":
        return {**config, name: value}
    return {**config, name: value, **{k: start[k] for k in GL_ONLY}, **FIXED.get(value, {})}


def _ranked(model: str, trial: tuple[Any, dict[str, Any]]) -> float:
    """A trial's rank: its residual, and half a margin more for a change of model, so a picture
    the current model's own switches explain as well is not put down to another model (where
    two models draw the same picture: PyTorch3D's Phong is GL's with Phong's reflection when
    the scene has no attenuation, spot or emission)."""
    (residual, _, _), candidate = trial
    return float(residual) + (MARGIN / 2 if candidate["shading_model"] != model else 0.0)


def _cull(given: Any, scene: Any) -> str | None:
    """The culling the render as meant does, as the search names it (None: no culling): as
    `render` reads `cull`, None being the scene's default (three.js': by its material's
    side)."""
    cull = scene._default_cull() if given is None else given
    return None if cull in (None, "none") else str(cull).lower()


def _named(
    start: dict[str, Any],
    searched: dict[str, Any],
    transfer0: str,
    clamp0: bool,
    config: dict[str, Any],
    post: dict[str, Any],
) -> dict[str, Any]:
    """The switches of `config` and its fitted `post` that differ from the render as meant (of
    those its model has)."""
    switches = {k: config[k] for k in searched[config["shading_model"]] if config[k] != start[k]}
    if post["transfer"] != transfer0:
        switches["transfer"] = post["transfer"]
    if post["clamp"] != clamp0:
        switches["clamp"] = post["clamp"]
    if abs(post["light_scale"] - 1.0) > 1e-3:
        switches["light_scale"] = post["light_scale"]
    if abs(config["ambient_scale"] - 1.0) > 1e-3:
        switches["ambient_scale"] = config["ambient_scale"]
    return switches
