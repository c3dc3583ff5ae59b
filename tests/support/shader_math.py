"""The GLSL and HLSL built-ins that the shader transcriptions use, in numpy over rows of
vectors (the last axis): one definition for every transcription, none from glshade."""

from __future__ import annotations

from typing import Any

import numpy as np


def normalize(v: np.ndarray) -> np.ndarray:
    """GLSL's ``normalize``, row by row."""
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """GLSL's ``dot``, row by row, keeping the axis so that it broadcasts against vectors."""
    return np.sum(a * b, axis=-1, keepdims=True)


def reflect(I: np.ndarray, N: np.ndarray) -> np.ndarray:  # noqa: E741 (GLSL's names)
    """GLSL's and HLSL's ``reflect(I, N) = I - 2 dot(N, I) N``."""
    return I - 2.0 * dot(N, I) * N


def clamp(x: Any, lo: float, hi: float) -> Any:
    """GLSL's ``clamp``."""
    return np.minimum(np.maximum(x, lo), hi)


def saturate(x: Any) -> Any:
    """HLSL's and Cg's ``saturate``: clamp to [0, 1]."""
    return clamp(x, 0.0, 1.0)
