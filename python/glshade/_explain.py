"""`explain`: which of the known convention switches make glshade's render of a mesh match a
user's image, found by search, with the residual before and after."""

from __future__ import annotations

import dataclasses
import itertools
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ._camera import Camera
from ._explain_search import JOINT, MARGIN, PROVOKING, SWITCHES, Search
from ._image import Image
from ._intake import one_of
from ._render_input import render_input
from ._scene import Scene

__all__ = ["Explanation", "explain"]

# A residual above this (2/255 on average) is not an explanation.
EXPLAINED = 2.0 / 255


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
        The scene the picture was meant to show (GL's model); None: `render`'s default scene.
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
        TypeError) for a scene that is not a `glshade.Scene` (the glTF and three.js models
        have no switches here).
    """
    target = np.asarray(image)
    if target.ndim != 3 or target.shape[2] not in (3, 4):
        raise ValueError(f"image must have shape (height, width, 3 or 4), got {target.shape}")
    target = target / 255.0 if target.dtype == np.uint8 else target.astype(np.float64)
    height, width = target.shape[:2]
    if scene is not None and not isinstance(scene, Scene):
        raise TypeError(
            f"scene must be a glshade.Scene or None: explain searches the switches of GL's "
            f"equation (a glTF or three.js model has conventions of its own), got {type(scene)!r}"
        )
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
    search = Search(
        given.vertices.astype(np.float64), given.faces, base, given.camera, target, flat,
        render_options,
    )  # fmt: skip
    before = search.residual(start, clamp0, transfer0)
    config = dict(start)
    score, post, picture = search.fit(config)
    while True:
        trials = []
        for name, values in switches_searched.items():
            for value in values:
                if value != config[name]:
                    candidate = {**config, name: value}
                    trials.append((search.fit(candidate), candidate))
        for first, second in JOINT:
            for a, b in itertools.product(SWITCHES[first], SWITCHES[second]):
                if a != config[first] and b != config[second]:
                    candidate = {**config, first: a, second: b}
                    trials.append((search.fit(candidate), candidate))
        ambient_trial = search.fit_ambient(config, post)
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
        renders=search.renders,
    )
