"""`Preset`, a lighting model as glshade state, and what the presets share."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from .._params import real_array
from .._records import ValueRecord
from .._scene import Scene
from .._shade import shade
from .._shade_mesh import shade_mesh
from .._typing import FloatArray, Per, Weighting

BLACK = (0.0, 0.0, 0.0, 1.0)


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


def one_light(
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


def model_matrix(model: ArrayLike | None, name: str = "model") -> FloatArray | None:
    """A model (world) matrix as numpy prints it: (4, 4), affine and invertible; None stays."""
    if model is None:
        return None
    m = real_array(model, name)
    if m.shape != (4, 4):
        raise ValueError(f"{name} must have shape (4, 4), got {m.shape}")
    if not np.array_equal(m[3], (0.0, 0.0, 0.0, 1.0)):
        raise ValueError(f"{name} must be affine (last row (0, 0, 0, 1)), got last row {m[3]}")
    det = float(np.linalg.det(m[:3, :3]))
    if det == 0.0 or not np.isfinite(det):
        raise ValueError(
            f"{name} must be invertible (its normal matrix is its inverse transpose), "
            f"got determinant {det:g} for the upper-left 3x3"
        )
    return m


def world_kwargs(model: FloatArray | None) -> dict[str, Any]:
    """The `shade` keywords of a model lit in world space: unit normals, and the positions'
    model matrix when there is one (a shader's ``model`` or ``gWorld``)."""
    kwargs: dict[str, Any] = {"normalize": True}
    if model is not None:
        kwargs["modelview"] = model
    return kwargs
