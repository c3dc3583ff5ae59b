"""PyTorch3D's Phong shading as a preset."""

from __future__ import annotations

from numpy.typing import ArrayLike

from .._intake import colors_checked
from .._params import rgb, scalar, vector3, warn_bytes
from .._scene import Light, Material, Scene
from ._preset import BLACK, Preset, one_light


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
    light_vector, w = one_light(direction, location, ("direction", "location"))
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
                emission=BLACK, shininess=exponent,
            ),
            global_ambient=BLACK,
            viewer=(*camera, 1.0),
            specular="phong",
        )  # fmt: skip
    warn_bytes(colors, "pytorch3d")
    return Preset(scene, {"normalize": True, "clamp": False}, weighting="area")
