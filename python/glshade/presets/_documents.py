"""The models of glshade's four source documents: GL, DirectX 11, learnopengl, the lecture."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from .._intake import colors_checked
from .._params import color_array, real_array, rgb, scalar, vector3, warn_bytes
from .._scene import Light, Lights, Material, Scene
from ._preset import BLACK, Preset, model_matrix, one_light, world_kwargs


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
    xyz, w = one_light(light_vector, light_position, ("light_vector", "light_position"))
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
            emission=BLACK,
            shininess=shininess,
        )
        scene = Scene(
            lights=[light],
            material=material,
            global_ambient=BLACK,
            viewer=(*eye, 1.0),
            specular="phong",
        )
    warn_bytes(colors, "directx11")
    return Preset(scene, {"normalize": True})


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
    matrix = model_matrix(model)
    with colors_checked():
        scene = Scene(
            lights=[
                Light(
                    position=(*position, 1.0),
                    ambient=BLACK,
                    diffuse=light,
                    specular=strength * light,
                )
            ],
            material=Material(
                ambient=obj, diffuse=obj, specular=obj, emission=BLACK, shininess=exponent
            ),
            global_ambient=ambient * light,
            viewer=(*viewer, 1.0),
            specular="phong",
            specular_gate=False,
        )
    warn_bytes({"light_color": light, "object_color": obj}, "learnopengl")
    return Preset(scene, world_kwargs(matrix))


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
    xyz, w = one_light(light_direction, light_position, ("light_direction", "light_position"))
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
            ambient=BLACK,
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
            emission=BLACK,
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
