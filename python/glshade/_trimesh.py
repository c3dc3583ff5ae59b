"""Meshes as they come: a ``trimesh.Trimesh`` (or anything with ``.vertices`` and ``.faces``), a
``trimesh.Scene`` flattened into one mesh (and its own camera), the colours a mesh carries, the
(vertices, faces) arrays of a mesh or of arrays given as they are, and a file's mesh. trimesh
is imported only to load a file: its objects are read through their attributes."""

from __future__ import annotations

import importlib
import os
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._intake import indices, rows
from ._typing import FloatArray, Per


def is_mesh(obj: Any) -> bool:
    """True for anything with ``.vertices`` and ``.faces``, or a ``trimesh.Scene``."""
    return (hasattr(obj, "vertices") and hasattr(obj, "faces")) or _is_scene(obj)


def _is_scene(obj: Any) -> bool:
    return hasattr(obj, "geometry") and hasattr(obj, "graph") and hasattr(obj, "dump")


def has_own_camera(obj: Any) -> bool:
    """A ``trimesh.Scene`` whose camera was set (loaded from a file, or ``scene.camera``
    asked for): not one its ``camera`` property would make up on first reading."""
    return _is_scene(obj) and bool(getattr(obj, "has_camera", False))


def load(path: str | os.PathLike[str]) -> Any:
    """The mesh or scene ``trimesh.load`` reads from `path` (glTF, OBJ, PLY, STL, OFF and the
    other formats trimesh reads)."""
    try:
        trimesh = importlib.import_module("trimesh")
    except ImportError:
        raise ImportError(
            f"rendering a file ({os.fspath(path)!r}) needs trimesh to read it: pip install trimesh"
        ) from None
    if not os.path.isfile(path):
        raise FileNotFoundError(f"vertices names a file that does not exist: {os.fspath(path)!r}")
    loaded = trimesh.load(path)
    if not is_mesh(loaded):
        raise TypeError(
            f"{os.fspath(path)!r} holds a {type(loaded).__name__}, not a triangle mesh: "
            "glshade renders triangles"
        )
    return loaded


def as_mesh(obj: Any) -> Any:
    """`obj`, or for a ``trimesh.Scene`` one mesh of all its geometry placed by the scene graph
    (``scene.to_mesh()``: every node's transform applied, colours kept where they concatenate)."""
    if not _is_scene(obj):
        return obj
    if not obj.geometry:
        raise ValueError("the trimesh.Scene holds no geometry")
    flatten = getattr(obj, "to_mesh", None)
    mesh = flatten() if flatten is not None else obj.dump(concatenate=True)
    if not (hasattr(mesh, "vertices") and hasattr(mesh, "faces")):
        raise TypeError(
            f"the trimesh.Scene did not flatten into a triangle mesh (got {type(mesh)!r}): "
            "it holds paths or point clouds; pass its Trimesh geometry"
        )
    return mesh


def mesh_arrays(vertices: Any, faces: ArrayLike | None) -> tuple[FloatArray, Any]:
    """(vertices, faces), taken from a mesh object (trimesh.Trimesh or anything with `.vertices`
    and `.faces`, or a trimesh.Scene flattened by its graph) when `faces` is None."""
    if faces is None:
        if not is_mesh(vertices):
            raise TypeError(
                "faces is required unless the first argument is a mesh with .vertices and .faces, "
                f"got {type(vertices)!r}"
            )
        mesh = as_mesh(vertices)
        vertices, faces = mesh.vertices, mesh.faces
    return rows(vertices, "vertices"), indices(faces, "faces")


def mesh_colors(mesh: Any) -> tuple[NDArray[Any], Per] | None:
    """The colours `mesh` defines (``mesh.visual`` of kind "vertex" or "face", uint8 RGBA as
    trimesh stores them), or None for a mesh without colours of its own (trimesh's default
    grey, textures, or no ``visual``)."""
    visual = getattr(mesh, "visual", None)
    kind = getattr(visual, "kind", None)
    if kind == "vertex":
        return np.asarray(visual.vertex_colors), "vertex"  # type: ignore[union-attr]
    if kind == "face":
        return np.asarray(visual.face_colors), "face"  # type: ignore[union-attr]
    return None


def mesh_texture(mesh: Any) -> tuple[NDArray[Any], Any] | None:
    """The texture coordinates (n, 2) and base-colour image of a mesh whose ``visual`` is of
    kind "texture" (trimesh's ``TextureVisuals``: a ``PBRMaterial``'s ``baseColorTexture`` or a
    ``SimpleMaterial``'s ``image``, PIL images), or None."""
    visual = getattr(mesh, "visual", None)
    if getattr(visual, "kind", None) != "texture" or getattr(visual, "uv", None) is None:
        return None
    material = getattr(visual, "material", None)
    image = getattr(material, "baseColorTexture", None)
    if image is None:
        image = getattr(material, "image", None)
    if image is None:
        return None
    return np.asarray(visual.uv), image  # type: ignore[union-attr]
