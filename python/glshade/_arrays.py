"""Coercion of user arrays to what the native module reads: C-contiguous float32/float64 rows
and int64 indices, with errors that name the argument."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.floating[Any]]


def float_dtype(value: ArrayLike, name: str) -> np.dtype[Any]:
    """The dtype `value` computes in: float32 or float64 (float16 widens to float32); Python
    sequences count as float64."""
    if not isinstance(value, np.ndarray):
        return np.dtype(np.float64)
    kind, size = value.dtype.kind, value.dtype.itemsize
    if kind == "f" and size <= 4:
        return np.dtype(np.float32)
    if kind == "f" and size == 8:
        return np.dtype(np.float64)
    raise TypeError(f"{name} must be a float32 or float64 array, got dtype {value.dtype}")


def rows(value: ArrayLike, name: str, dtype: np.dtype[Any], width: str = "3") -> FloatArray:
    """`value` as a C-contiguous 2-d array of `dtype` (a copy only where needed)."""
    if not isinstance(value, np.ndarray):
        value = np.asarray(value)
        if value.dtype.kind not in "fiu":
            raise TypeError(f"{name} must be real numbers, got dtype {value.dtype}")
    elif value.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be real numbers, got dtype {value.dtype}")
    if value.ndim != 2:
        raise ValueError(
            f"{name} must be a 2-d array of shape (n, {width}), got shape {value.shape}"
        )
    return np.ascontiguousarray(value, dtype=dtype)


def indices(value: ArrayLike, name: str) -> NDArray[np.int64]:
    """Integer rows of any integer dtype as C-contiguous int64."""
    a = np.asarray(value)
    if a.dtype.kind not in "iu" and not (a.size == 0 and a.dtype.kind == "f"):
        raise TypeError(f"{name} must be an integer array, got dtype {a.dtype}")
    if a.ndim != 2:
        raise ValueError(f"{name} must be a 2-d array of shape (m, 3), got shape {a.shape}")
    if a.dtype.kind == "u" and a.size and a.max() > np.iinfo(np.int64).max:
        raise IndexError(f"{name} holds index {a.max()}, beyond any vertex count")
    return np.ascontiguousarray(a, dtype=np.int64)


def matrix(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """A (4, 4) matrix of real numbers as a C-contiguous float64 array."""
    m = np.asarray(value)
    if m.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be real numbers, got dtype {m.dtype}")
    if m.shape != (4, 4):
        raise ValueError(f"{name} must have shape (4, 4), got {m.shape}")
    return np.ascontiguousarray(m, dtype=np.float64)


def choice(value: object, name: str) -> str:
    """`value` checked to be a string before the native module parses it."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, got {value!r}")
    return value


def optional_choice(value: object, name: str) -> str | None:
    """`value` checked to be a string or None."""
    return None if value is None else choice(value, name)
