"""The lighting models of glshade's source documents, each one call in that model's own terms.

Each function takes the parameters a document names (``l_a``, ``m_d`` and ``p`` for the
DirectX 11 tutorial; ``ambientStrength``, ``objectColor`` and ``viewPos`` for learnopengl; ``k_a``,
``I_l`` and ``n`` for the lecture's Phong model) and returns a `Preset`: the `Scene` and the
`shade` keywords that make glshade compute exactly that model. Nothing here is a new equation:
each model is GL state (lights, materials, global ambient, viewer, ``specular="phong"``,
``specular_gate``, ``normalize``, ``modelview``), so it runs in the same kernel as everything else.

>>> import numpy as np, glshade as gs
>>> model = gs.presets.learnopengl(light_pos=(1.2, 1.0, 2.0), view_pos=(0.0, 0.0, 3.0))
>>> model.shade(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]])).round(4)
array([[0.8884, 0.4442, 0.2754, 1.    ]])
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from ._intake import colors_checked
from ._params import color_array, real_array, rgb, scalar, vector3, warn_bytes
from ._records import ValueRecord
from ._scene import Light, Lights, Material, Scene
from ._shade import shade
from ._shade_mesh import shade_mesh
from ._typing import FloatArray, Per, Weighting

__all__ = ["Preset", "directx11", "learnopengl", "opengl", "phong_illumination", "pytorch3d"]

_BLACK = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True, eq=False)
class Preset(ValueRecord):
    """A lighting model as glshade state.

    Presets pickle and deepcopy to equal presets, and compare equal when their scenes are equal
    and their keywords hold equal values (arrays compared element by element).

    Attributes
    ----------
    scene : Scene
        Lights, material and light model.
    shade_kwargs : Mapping[str, Any]
        The `shade` keywords the model needs (``normalize``, ``modelview``), read-only.
    weighting : {"angle", "area", "uniform"}
        The vertex normals the model's renderer makes, `shade_mesh`'s default (``"angle"``,
        trimesh's, unless the model's renderer weighs otherwise).
    """

    scene: Scene
    shade_kwargs: Mapping[str, Any] = field(default_factory=dict)
    weighting: Weighting = "angle"

    def __post_init__(self) -> None:
        # A read-only view of a private copy: the caller's dict cannot change the preset.
        object.__setattr__(self, "shade_kwargs", MappingProxyType(dict(self.shade_kwargs)))

    def shade(self, positions: ArrayLike, normals: ArrayLike, **extra: Any) -> FloatArray:
        """``gs.shade(positions, normals, self.scene, **self.shade_kwargs, **extra)``.

        Parameters
        ----------
        positions : (..., 3) array-like
            As for `shade`.
        normals : (..., 3) array-like
            As for `shade`.
        **extra
            Further `shade` keywords; they override the preset's `shade_kwargs`.

        Returns
        -------
        (..., 4) or (k, ..., 4) ndarray
            As `shade` returns it.
        """
        return shade(positions, normals, self.scene, **{**self.shade_kwargs, **extra})

    def shade_mesh(
        self,
        vertices: Any,
        faces: ArrayLike | None = None,
        *,
        per: Per = "vertex",
        weighting: Weighting | None = None,
        **extra: Any,
    ) -> FloatArray:
        """`shade_mesh` with this model: per vertex (smooth) or per face (flat).

        Parameters
        ----------
        vertices : (n, 3) float32 or float64, or a mesh
            As for `shade_mesh`.
        faces : (m, 3) int, optional
            As for `shade_mesh`.
        per : {"vertex", "face"}
            As for `shade_mesh`.
        weighting : str or None
            ``"angle"``, ``"area"`` or ``"uniform"``, as for `shade_mesh`; None (the default)
            is the preset's `weighting`.
        **extra
            Further `shade` keywords; they override the preset's `shade_kwargs`.

        Returns
        -------
        (n, 4) or (m, 4) ndarray, or (k, n, 4) / (k, m, 4) for scenes with several outputs
            As `shade_mesh` returns it.
        """
        kwargs = {**self.shade_kwargs, **extra}
        weights = self.weighting if weighting is None else weighting
        return shade_mesh(vertices, faces, scene=self.scene, per=per, weighting=weights, **kwargs)


def _one_light(
    light_vector: ArrayLike | None, light_position: ArrayLike | None, names: tuple[str, str]
) -> tuple[ArrayLike, float]:
    """The light's (x, y, z) and GL's w: 0 for a direction towards the light, 1 for a point."""
    if (light_vector is None) == (light_position is None):
        given = "both" if light_vector is not None else "neither"
        raise TypeError(
            f"give exactly one of {names[0]} (a directional light) and {names[1]} "
            f"(a point light), got {given}"
        )
    if light_vector is not None:
        return light_vector, 0.0
    assert light_position is not None
    return light_position, 1.0


def opengl(
    lights: Lights | Iterable[Lights] = (),
    material: Material | None = None,
    *,
    global_ambient: ArrayLike = (0.2, 0.2, 0.2, 1.0),
    local_viewer: bool = False,
) -> Preset:
    """The OpenGL 2.1 lighting equation (document 000): glshade's default `Scene`.

    ``c = e_cm + a_cm*a_cs + sum_i att_i spot_i [a_cm*a_cli + (n . VP) d_cm*d_cli
    + f_i (n . h)^s_rm s_cm*s_cli]``, with GL's lights (`Light`) and material (`Material`).

    Parameters
    ----------
    lights : Lights, Light, or a sequence of them
        The lights (eye coordinates), with GL's parameters P_pli, a_cli, d_cli, s_cli, k0..k2,
        s_dli, s_rli, c_rli.
    material : Material, optional
        e_cm, a_cm, d_cm, s_cm, s_rm (default: GL's).
    global_ambient : (3,) or (4,) float
        a_cs, ``GL_LIGHT_MODEL_AMBIENT`` (GL's default).
    local_viewer : bool
        v_bs, ``GL_LIGHT_MODEL_LOCAL_VIEWER``: h = VP + VP_e (viewer at the eye) instead of
        VP + (0, 0, 1).

    Returns
    -------
    Preset
        The scene; no `shade` keywords (GL does not normalize normals by default).
    """
    if not isinstance(local_viewer, (bool, np.bool_)):
        raise TypeError(f"local_viewer must be True or False, got {local_viewer!r}")
    viewer = (0.0, 0.0, 0.0, 1.0) if local_viewer else (0.0, 0.0, 1.0, 0.0)
    return Preset(
        Scene(lights=lights, material=material, global_ambient=global_ambient, viewer=viewer)
    )


def directx11(
    *,
    l_a: ArrayLike,
    l_d: ArrayLike,
    l_s: ArrayLike,
    m_a: ArrayLike,
    m_d: ArrayLike,
    m_s: ArrayLike,
    p: float,
    eye_position: ArrayLike,
    light_vector: ArrayLike | None = None,
    light_position: ArrayLike | None = None,
) -> Preset:
    """The DirectX 11 tutorial's lighting (document 001, Luna's model as taught by Chili).

    ``LitColor = l_a (x) m_a + k_d l_d (x) m_d + k_s l_s (x) m_s = A + k_d D + k_s S`` with
    ``k_d = max(L . n, 0)`` and ``k_s = max(v . r, 0)^p`` where ``L . n > 0``, else 0: the
    reflection vector ``r`` of the light about the unit normal, ``v`` the unit vector to the eye.

    Parameters
    ----------
    l_a : (3,) or (4,) float
        The light's ambient colour. Colours are numbers in [0, 1] (uint8 is divided by 255).
    l_d : (3,) or (4,) float
        The light's diffuse colour.
    l_s : (3,) or (4,) float
        The light's specular colour.
    m_a : (3,) or (4,) float
        The material's ambient colour.
    m_d : (3,) or (4,) float
        The material's diffuse colour; the output alpha is m_d's (1 for an RGB m_d).
    m_s : (3,) or (4,) float
        The material's specular colour.
    p : float
        The specular exponent, >= 0.
    eye_position : (3,) float
        The eye, in the space of the positions: ``v = normalize(eye_position - position)``.
    light_vector : (3,) float, optional
        L for a directional light: the direction towards the light (normalised here).
    light_position : (3,) float, optional
        A point light: ``L = normalize(light_position - position)``, no attenuation (the
        document has none). Give exactly one of `light_vector` and `light_position`.

    Returns
    -------
    Preset
        A scene with one light whose ambient is not attenuated (GL's att = 1 here), no global
        ambient or emission, ``specular="phong"`` with GL's gate; and ``normalize=True``, since
        the document takes n as a unit vector.

    Raises
    ------
    TypeError
        For a colour given by name (``l_d="white"``): the message gives its numbers; for
        neither or both of `light_vector` and `light_position`.
    ValueError
        For a wrong shape, a negative `p`, or a zero `light_vector`, naming the argument.

    Warns
    -----
    ColorRangeWarning
        For a colour that looks like 0-255 bytes (every value a whole number in [0, 255], the
        largest 16 or more), naming it: colours are in [0, 1], and uint8 is divided by 255.
    """
    colors = {
        name: rgb(value, name, alpha=True)
        for name, value in (
            ("l_a", l_a),
            ("l_d", l_d),
            ("l_s", l_s),
            ("m_a", m_a),
            ("m_d", m_d),
            ("m_s", m_s),
        )
    }
    shininess = scalar(p, "p", minimum=0.0)
    eye = vector3(eye_position, "eye_position")
    xyz, w = _one_light(light_vector, light_position, ("light_vector", "light_position"))
    where = vector3(xyz, "light_vector" if w == 0 else "light_position", nonzero=w == 0)
    with colors_checked():
        light = Light(
            position=(*where, w),
            ambient=colors["l_a"],
            diffuse=colors["l_d"],
            specular=colors["l_s"],
        )
        material = Material(
            ambient=colors["m_a"],
            diffuse=colors["m_d"],
            specular=colors["m_s"],
            emission=_BLACK,
            shininess=shininess,
        )
        scene = Scene(
            lights=[light],
            material=material,
            global_ambient=_BLACK,
            viewer=(*eye, 1.0),
            specular="phong",
        )
    warn_bytes(colors, "directx11")
    return Preset(scene, {"normalize": True})


def _model_matrix(model: ArrayLike | None) -> FloatArray | None:
    if model is None:
        return None
    m = real_array(model, "model")
    if m.shape != (4, 4):
        raise ValueError(f"model must have shape (4, 4), got {m.shape}")
    if not np.array_equal(m[3], (0.0, 0.0, 0.0, 1.0)):
        raise ValueError(f"model must be affine (last row (0, 0, 0, 1)), got last row {m[3]}")
    det = float(np.linalg.det(m[:3, :3]))
    if det == 0.0 or not np.isfinite(det):
        raise ValueError(
            "model must be invertible (its normal matrix is its inverse transpose), "
            f"got determinant {det:g} for the upper-left 3x3"
        )
    return m


def learnopengl(
    *,
    light_pos: ArrayLike = (1.2, 1.0, 2.0),
    view_pos: ArrayLike = (0.0, 0.0, 3.0),
    light_color: ArrayLike = (1.0, 1.0, 1.0),
    object_color: ArrayLike = (1.0, 0.5, 0.31),
    ambient_strength: float = 0.1,
    specular_strength: float = 0.5,
    shininess: float = 32.0,
    model: ArrayLike | None = None,
) -> Preset:
    """learnopengl's Basic Lighting shader (document 002), per vertex, in world space.

    ``result = (ambientStrength * lightColor + diff * lightColor
    + specularStrength * spec * lightColor) * objectColor`` with
    ``diff = max(dot(norm, lightDir), 0)``, ``spec = pow(max(dot(viewDir, reflectDir), 0), 32)``,
    ``reflectDir = reflect(-lightDir, norm)``, ``norm = normalize(mat3(transpose(inverse(model)))
    * aNormal)``, ``FragPos = vec3(model * vec4(aPos, 1))``; alpha 1. There is no gate: a
    highlight may appear where ``dot(norm, lightDir) <= 0``, as in the shader.

    Parameters
    ----------
    light_pos : (3,) float
        ``lightPos``, world space. The default is the tutorial's ``lightPos(1.2, 1.0, 2.0)``.
    view_pos : (3,) float
        ``viewPos``, world space. The default is the tutorial's camera, at (0, 0, 3).
    light_color : (3,) float
        ``lightColor``; the default is the tutorial's (1, 1, 1). Colours are numbers in
        [0, 1] (uint8 is divided by 255).
    object_color : (3,) float
        ``objectColor``; the default is the tutorial's (1, 0.5, 0.31).
    ambient_strength : float
        ``ambientStrength``; the default is the tutorial's 0.1.
    specular_strength : float
        ``specularStrength``; the default is the tutorial's 0.5.
    shininess : float
        The exponent the shader writes as 32, >= 0.
    model : (4, 4) float, optional
        The model matrix, as numpy prints it (``model @ (x, y, z, 1)``; a flat glm array is its
        transpose). Affine and invertible. Default: the identity (positions are world space).

    Returns
    -------
    Preset
        Ambient as the global ambient ``ambientStrength * lightColor`` on material ambient
        ``objectColor``; one unattenuated point light with diffuse ``lightColor`` and specular
        ``specularStrength * lightColor``; every material colour ``objectColor``; a viewer at
        ``viewPos``; ``specular="phong"``, ``specular_gate=False``; and ``normalize=True``,
        ``modelview=model``.

    Raises
    ------
    TypeError
        For a colour given by name (``object_color="orange"``): the message gives its numbers.
    ValueError
        For a wrong shape, a negative `shininess`, or a `model` that is not affine and
        invertible, naming the argument.

    Warns
    -----
    ColorRangeWarning
        For `light_color` or `object_color` looking like 0-255 bytes (every value a whole
        number in [0, 255], the largest 16 or more): colours are in [0, 1], and uint8 is
        divided by 255.
    """
    light = rgb(light_color, "light_color")
    obj = rgb(object_color, "object_color")
    ambient = scalar(ambient_strength, "ambient_strength")
    strength = scalar(specular_strength, "specular_strength")
    exponent = scalar(shininess, "shininess", minimum=0.0)
    position = vector3(light_pos, "light_pos")
    viewer = vector3(view_pos, "view_pos")
    matrix = _model_matrix(model)
    with colors_checked():
        scene = Scene(
            lights=[
                Light(
                    position=(*position, 1.0),
                    ambient=_BLACK,
                    diffuse=light,
                    specular=strength * light,
                )
            ],
            material=Material(
                ambient=obj, diffuse=obj, specular=obj, emission=_BLACK, shininess=exponent
            ),
            global_ambient=ambient * light,
            viewer=(*viewer, 1.0),
            specular="phong",
            specular_gate=False,
        )
    warn_bytes({"light_color": light, "object_color": obj}, "learnopengl")
    kwargs: dict[str, Any] = {"normalize": True}
    if matrix is not None:
        kwargs["modelview"] = matrix
    return Preset(scene, kwargs)


def _attenuation(value: Any) -> tuple[float, float, float]:
    if value is None:
        return (1.0, 0.0, 0.0)
    if isinstance(value, str):
        if value.lower() != "inverse_square":
            raise ValueError(
                f"attenuation must be None, 'inverse_square' or (a0, a1, a2), got {value!r}"
            )
        return (0.0, 0.0, 1.0)
    a = real_array(value, "attenuation")
    if a.shape != (3,) or (a < 0).any() or not a.any():
        raise ValueError(
            f"attenuation must be (a0, a1, a2) with every a >= 0 and not all 0, got {value!r}"
        )
    return (float(a[0]), float(a[1]), float(a[2]))


def phong_illumination(
    *,
    k_a: float,
    k_d: float,
    k_s: float,
    n: float,
    I_a: ArrayLike,
    I_l: ArrayLike,
    viewer_position: ArrayLike,
    light_position: ArrayLike | None = None,
    light_direction: ArrayLike | None = None,
    attenuation: Literal["inverse_square"] | ArrayLike | None = None,
    spot_direction: ArrayLike | None = None,
    spot_cutoff: float | None = None,
    spot_exponent: float | None = None,
) -> Preset:
    """The lecture's Phong illumination model (document 004), with its attenuations.

    ``I = k_a I_a + sum_l f_rad(d_l) f_ang [k_d I_l (N . L) + k_s I_l (R . V)^n]`` with
    ``R = 2 (N . L) N - L``; the diffuse and specular terms only where ``N . L > 0`` and
    ``(R . V)`` taken as ``max(R . V, 0)`` (the angle limited to [0, 90] degrees). N, L, R, V
    are unit vectors. Each RGB channel is computed alike.

    Parameters
    ----------
    k_a : float
        The ambient reflection coefficient (a scalar), >= 0.
    k_d : float
        The diffuse reflection coefficient (a scalar), >= 0.
    k_s : float
        The specular reflection coefficient (a scalar), >= 0.
    n : float
        The glossiness exponent, >= 0.
    I_a : float or (3,) float
        The ambient light's intensity (a number is grey); uint8 is divided by 255.
    I_l : float, (3,) or (L, 3) float
        The intensity of the light, or one row per light; uint8 is divided by 255.
    viewer_position : (3,) float
        The viewer: ``V = normalize(viewer_position - position)``.
    light_position : (3,) or (L, 3) float, optional
        Point lights: ``L = normalize(light_position - position)``.
    light_direction : (3,) or (L, 3) float, optional
        Infinitely distant lights: L, the direction towards the light (normalised here); never
        attenuated. Give exactly one of `light_position` and `light_direction`.
    attenuation : None, "inverse_square" or (a0, a1, a2)
        Radial attenuation of point lights: none, ``1 / d^2`` (the name in any case), or
        ``1 / (a0 + a1 d + a2 d^2)``.
    spot_direction : (3,) or (L, 3) float, optional
        Angular attenuation: the cone's axis (from the light outwards). A point inside the cone
        gets ``(V_obj . V_light)^a_l``, V_obj the unit vector from the light to the point;
        outside it gets 0. Default: no angular attenuation.
    spot_cutoff : float or (L,) float, optional
        θ_l, the cone's half-angle in degrees, in [0, 90]; None (the default) is 90. Needs
        `spot_direction`.
    spot_exponent : float or (L,) float, optional
        a_l, >= 0; None (the default) is 0. Needs `spot_direction`.

    Returns
    -------
    Preset
        Material ambient, diffuse and specular ``k_a``, ``k_d``, ``k_s`` (grey), global
        ambient ``I_a``, lights of diffuse and specular ``I_l``, a viewer at `viewer_position`,
        ``specular="phong"`` with GL's gate; and ``normalize=True``.

    Raises
    ------
    TypeError
        For `I_a` or `I_l` given by a colour name (the message gives its numbers); for
        neither or both of `light_position` and `light_direction`.
    ValueError
        For a wrong shape, a negative coefficient or exponent, a spot cone outside [0, 90]
        degrees, or an unknown `attenuation`, naming the argument.

    Warns
    -----
    ColorRangeWarning
        For `I_a`, or an unattenuated `I_l`, looking like 0-255 bytes (every value a whole
        number in [0, 255], the largest 16 or more): with attenuation, `I_l` is an intensity,
        which may be large.
    """
    ka, kd, ks = (
        scalar(v, name, minimum=0.0) for v, name in ((k_a, "k_a"), (k_d, "k_d"), (k_s, "k_s"))
    )
    exponent = scalar(n, "n", minimum=0.0)
    ambient = rgb(I_a, "I_a", grey=True)
    intensity = color_array(I_l, "I_l")
    if intensity.ndim == 0:
        intensity = np.full(3, float(intensity))
    elif intensity.shape[-1:] != (3,) or intensity.ndim > 2:
        raise ValueError(
            f"I_l must be a number or have shape (3,) or (L, 3), got {intensity.shape}"
        )
    viewer = vector3(viewer_position, "viewer_position")
    xyz, w = _one_light(light_direction, light_position, ("light_direction", "light_position"))
    name = "light_direction" if w == 0 else "light_position"
    where = vector3(xyz, name, rows=True, nonzero=w == 0)
    if intensity.ndim == 2 and (where.ndim != 2 or len(where) != len(intensity)):
        raise ValueError(
            f"I_l has {len(intensity)} rows, so {name} must have shape ({len(intensity)}, 3), "
            f"got {where.shape}"
        )
    k0, k1, k2 = _attenuation(attenuation)
    spot: dict[str, Any] = {}
    if spot_direction is None:
        if spot_cutoff is not None or spot_exponent is not None:
            raise TypeError("spot_cutoff and spot_exponent need a spot_direction")
    else:
        cutoff = real_array(90.0 if spot_cutoff is None else spot_cutoff, "spot_cutoff")
        if cutoff.ndim > 1 or ((cutoff < 0) | (cutoff > 90)).any():
            raise ValueError(
                f"spot_cutoff must be in [0, 90] degrees (a number or (L,)), got {spot_cutoff!r}"
            )
        exp = real_array(0.0 if spot_exponent is None else spot_exponent, "spot_exponent")
        if exp.ndim > 1 or (exp < 0).any():
            raise ValueError(
                f"spot_exponent must be >= 0 (a number or (L,)), got {spot_exponent!r}"
            )
        spot = {
            "spot_direction": vector3(spot_direction, "spot_direction", rows=True, nonzero=True),
            "spot_cutoff": cutoff,
            "spot_exponent": exp,
        }
    homogeneous = np.concatenate([where, np.full((*where.shape[:-1], 1), w)], axis=-1)
    # k_a, k_d and k_s are coefficients, not colours: their grey material is not checked.
    with colors_checked():
        lights = Lights(
            position=homogeneous,
            ambient=_BLACK,
            diffuse=intensity,
            specular=intensity,
            constant_attenuation=k0,
            linear_attenuation=k1,
            quadratic_attenuation=k2,
            **spot,
        )
        material = Material(
            ambient=(ka, ka, ka),
            diffuse=(kd, kd, kd),
            specular=(ks, ks, ks),
            emission=_BLACK,
            shininess=exponent,
        )
        scene = Scene(
            lights=lights,
            material=material,
            global_ambient=ambient,
            viewer=(*viewer, 1.0),
            specular="phong",
        )
    colors = {"I_a": ambient}
    # I_l is a colour where nothing attenuates it (directions never are); else an intensity.
    if w == 0 or (k0, k1, k2) == (1.0, 0.0, 0.0):
        colors["I_l"] = intensity
    warn_bytes(colors, "phong_illumination")
    return Preset(scene, {"normalize": True})


def pytorch3d(
    *,
    location: ArrayLike | None = (0.0, 1.0, 0.0),
    direction: ArrayLike | None = None,
    ambient_color: ArrayLike = (0.5, 0.5, 0.5),
    diffuse_color: ArrayLike = (0.3, 0.3, 0.3),
    specular_color: ArrayLike = (0.2, 0.2, 0.2),
    material_ambient_color: ArrayLike = (1.0, 1.0, 1.0),
    material_diffuse_color: ArrayLike = (1.0, 1.0, 1.0),
    material_specular_color: ArrayLike = (1.0, 1.0, 1.0),
    shininess: float = 64.0,
    camera_position: ArrayLike = (0.0, 0.0, 0.0),
) -> Preset:
    """PyTorch3D's Phong shading: its ``PointLights`` or ``DirectionalLights``, ``Materials``
    and ``phong_shading`` / ``gouraud_shading`` / ``flat_shading``, in world space.

    Read from pytorch3d/renderer/lighting.py (``diffuse``, ``specular``, commit 04d318d8) and
    pytorch3d/renderer/mesh/shading.py (``_apply_lighting``, the three shadings, commit
    17ce7d7b)::

        colors = (ambient + diffuse) * texels + specular
        ambient = material.ambient_color * light.ambient_color
        diffuse = material.diffuse_color * light.diffuse_color * relu(n . l)
        specular = material.specular_color * light.specular_color
                   * (relu(v . r) * (n . l > 0)) ** shininess,   r = -l + 2 (n . l) n

    with n, l = normalize(location - p) (or normalize(direction), towards the light) and
    v = normalize(camera_position - p), no attenuation and no clamp. In GL's terms: one
    unattenuated light whose colours are the products of the light's and the material's, a
    white material whose ambient and diffuse colours the texels (vertex colours) replace
    (``color_material="ambient_and_diffuse"``, the default with `colors`), no global ambient,
    a viewer at the camera, ``specular="phong"`` with GL's gate, ``normalize=True`` and
    ``clamp=False``. `Preset.shade_mesh` weighs vertex normals by area, as PyTorch3D's
    ``verts_normals`` does, and ``per="face"`` lights each face at its centroid with its face
    normal, as ``flat_shading`` does.

    Parameters
    ----------
    location : (3,) float or None, default: (0.0, 1.0, 0.0)
        ``PointLights.location`` (its default); None with `direction`.
    direction : (3,) float, optional
        ``DirectionalLights.direction``, pointing towards the light; give it with
        ``location=None``.
    ambient_color : (3,) float, default: (0.5, 0.5, 0.5)
        The light's ``ambient_color`` (PyTorch3D's default).
    diffuse_color : (3,) float, default: (0.3, 0.3, 0.3)
        The light's ``diffuse_color``.
    specular_color : (3,) float, default: (0.2, 0.2, 0.2)
        The light's ``specular_color``.
    material_ambient_color : (3,) float, default: (1.0, 1.0, 1.0)
        ``Materials.ambient_color``.
    material_diffuse_color : (3,) float, default: (1.0, 1.0, 1.0)
        ``Materials.diffuse_color``.
    material_specular_color : (3,) float, default: (1.0, 1.0, 1.0)
        ``Materials.specular_color``.
    shininess : float, default: 64.0
        ``Materials.shininess``, > 0. (At 0 PyTorch3D raises its gated zero to the power 0 and
        adds the whole specular colour behind the light, where GL's gate adds none.)
    camera_position : (3,) float, default: (0.0, 0.0, 0.0)
        ``cameras.get_camera_center()``, world space.

    Returns
    -------
    Preset
        The scene, ``normalize=True`` and ``clamp=False``, and area-weighted vertex normals.

    Raises
    ------
    TypeError
        For both or neither of `location` and `direction`, or a colour given by name.
    ValueError
        For a wrong shape or a `shininess` that is not positive.

    Notes
    -----
    PyTorch3D normalises with ``F.normalize(x, eps=1e-6)``, which divides vectors shorter than
    1e-6 by 1e-6 instead of their length; glshade normalises them exactly.
    """
    light_vector, w = _one_light(direction, location, ("direction", "location"))
    colors = {
        name: rgb(value, name)
        for name, value in (
            ("ambient_color", ambient_color), ("diffuse_color", diffuse_color),
            ("specular_color", specular_color), ("material_ambient_color", material_ambient_color),
            ("material_diffuse_color", material_diffuse_color),
            ("material_specular_color", material_specular_color),
        )
    }  # fmt: skip
    exponent = scalar(shininess, "shininess", minimum=0.0)
    if exponent == 0:
        raise ValueError("shininess must be > 0 (PyTorch3D's specular at 0 is ungated), got 0")
    where = vector3(light_vector, "direction" if w == 0 else "location", nonzero=w == 0)
    camera = vector3(camera_position, "camera_position")
    with colors_checked():
        scene = Scene(
            lights=[
                Light(
                    position=(*where, w),
                    ambient=colors["ambient_color"] * colors["material_ambient_color"],
                    diffuse=colors["diffuse_color"] * colors["material_diffuse_color"],
                    specular=colors["specular_color"] * colors["material_specular_color"],
                )
            ],
            material=Material(
                ambient=(1.0, 1.0, 1.0), diffuse=(1.0, 1.0, 1.0), specular=(1.0, 1.0, 1.0),
                emission=_BLACK, shininess=exponent,
            ),
            global_ambient=_BLACK,
            viewer=(*camera, 1.0),
            specular="phong",
        )  # fmt: skip
    warn_bytes(colors, "pytorch3d")
    return Preset(scene, {"normalize": True, "clamp": False}, weighting="area")
