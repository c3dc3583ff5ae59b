"""The one intake of every array argument of every public function.

The rules (the table of the documentation's Arrays and dtypes page, docs/pages/guide/arrays.md):

- Anything numpy turns into an array is accepted: ndarrays of any byte order, alignment and
  memory order, lists, tuples, memoryviews, xarray and other array-likes.
- Real numbers only: floats, integers and bools (True is 1); complex, strings, objects and long
  doubles raise ``TypeError`` naming the argument.
- The computation dtype of vertex data is float32 when every vertex array is float32 or float16,
  and float64 otherwise (float64, any integer or bool, a Python sequence), as numpy promotes.
  Results have that dtype. Scene parameters and matrices are float64.
- What the native module reads is a C-contiguous, aligned, native-order array: an argument that
  already is one is used as it is, anything else is copied.
- Vertex colours of dtype uint8 (trimesh's, PNG's, PIL's 0-255) are scaled to [0, 1] by 1/255;
  any other dtype is taken as the colour values themselves.
- Colours are numbers: a colour name (``"red"``) raises ``TypeError`` saying so, with the numbers
  to write instead (three.js' colours also take its hex integers and '#rrggbb' strings); a
  colour of any surface whose every value lies in [0, 255], the largest 16 or more, warns
  (`ColorRangeWarning`, `looks_like_bytes`: bytes written where glshade takes [0, 1]), or
  raises ``ValueError`` where values above 1 are not allowed.
- Names of options are case-insensitive (``"Phong"`` is ``"phong"``).
- ``out=`` is never copied: it must be exactly right, and it must not share memory with an input
  (checked exactly by the native module, and here for two maps of one file).
"""

from __future__ import annotations

import mmap
import os
import sys
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._typing import Float64Array, FloatArray

_FLOAT32 = np.dtype(np.float32)
_FLOAT64 = np.dtype(np.float64)


class ColorRangeWarning(UserWarning):
    """A colour that looks written in bytes (0-255) where glshade takes [0, 1].

    Every colour glshade takes (material, light and background colours of every model, vertex
    colours, textures, `Image` and `compare` pictures) is checked by one rule: every value lies
    in [0, 255] and the largest is 16 or more, (255, 128, 0) rather than (1, 0.5, 0), or an
    image times 255. Smaller values, (2, 2, 2) or (5, 5, 5), are how a bright light is written,
    and as bytes they would be a near-black colour, so they do not warn; nor does a GL light
    with attenuation, whose colour is an intensity, or uint8 data, which is divided by 255.
    Colours above 1 are allowed (high dynamic range), so this is a warning, not an error;
    silence it with ``warnings.filterwarnings("ignore", category=glshade.ColorRangeWarning)``.
    Where values above 1 are not allowed (glTF's base colour factor), the same finding raises
    ``ValueError`` with the same message.
    """


def array(value: ArrayLike, name: str) -> NDArray[Any]:
    """`value` as an ndarray of real numbers (no copy where numpy needs none)."""
    if type(value) is np.ndarray:
        a = value
    else:
        try:
            a = np.asarray(value)
        except (TypeError, ValueError) as e:
            raise TypeError(
                f"{name} must be an array of real numbers, got {type(value).__name__} ({e})"
            ) from None
    if a.dtype.kind not in "fiub":
        raise TypeError(
            f"{name} must be real numbers (float, integer or bool), got dtype {a.dtype}"
        )
    if a.dtype.itemsize > 8:
        raise TypeError(
            f"{name} must be at most float64 (glshade computes in float32 or float64), "
            f"got dtype {a.dtype}: convert it with .astype(np.float64)"
        )
    return a


def real(value: ArrayLike, name: str) -> Float64Array:
    """`value` as a C-contiguous float64 array of any shape (scene parameters, matrices)."""
    a: Float64Array = np.require(array(value, name), _FLOAT64, ("C", "A"))
    return a


def compute_dtype(*arrays: NDArray[Any]) -> np.dtype[Any]:
    """float32 when every array is float32 or float16, else float64."""
    for a in arrays:
        if a.dtype.kind != "f" or a.dtype.itemsize > 4:
            return _FLOAT64
    return _FLOAT32


def ready(a: NDArray[Any], dtype: np.dtype[Any]) -> FloatArray:
    """`a` as what the native module reads: C-contiguous, aligned, native order, `dtype`."""
    if a.dtype is dtype and a.flags.carray:
        return a
    result: FloatArray = np.require(a, dtype, ("C", "A"))
    return result


_WIDTHS = {"positions": (3,), "normals": (3,), "colors": (3, 4)}


def vertices(
    positions: ArrayLike, normals: ArrayLike, colors: ArrayLike | None, owner: str = "shade"
) -> tuple[FloatArray, FloatArray, FloatArray | None]:
    """The vertex arrays of `shade` as the native module reads them, broadcast against each
    other: (..., 3) positions and normals, (..., 3|4) colours of one leading shape. A
    ValueError names the arrays whose shapes do not fit; colours that look like bytes warn,
    naming `owner`, the function they were given to."""
    p, n = array(positions, "positions"), array(normals, "normals")
    dtype = compute_dtype(p, n)
    shape = p.shape
    if colors is None and shape == n.shape and shape and shape[-1] == 3:
        return ready(p, dtype), ready(n, dtype), None
    given = {"positions": p, "normals": n}
    if colors is not None:
        given["colors"] = color_values(vertex_colors(colors), "colors", owner)
    leading = []
    for name, a in given.items():
        if a.ndim == 0 or a.shape[-1] not in _WIDTHS[name]:
            expected = " or ".join(f"(..., {w})" for w in _WIDTHS[name])
            raise ValueError(f"{name} must have shape {expected}, got shape {a.shape}")
        leading.append(a.shape[:-1])
    try:
        common = np.broadcast_shapes(*leading)
    except ValueError:
        found = ", ".join(f"{name} {a.shape}" for name, a in given.items())
        raise ValueError(
            f"the leading shapes of {', '.join(given)} must broadcast together, got {found}"
        ) from None
    ready_arrays = [
        ready(np.broadcast_to(a, (*common, a.shape[-1])), dtype) for a in given.values()
    ]
    c = ready_arrays[2] if colors is not None else None
    return ready_arrays[0], ready_arrays[1], c


def color_values(a: NDArray[Any], name: str, owner: str) -> NDArray[Any]:
    """Per-vertex colours: uint8 (0-255) as float64 in [0, 1]; others as they are, with a
    `ColorRangeWarning` naming `name` and `owner` where they look like 0-255 bytes."""
    if a.dtype == np.uint8:
        scaled: NDArray[Any] = a / 255.0
        return scaled
    warn_if_bytes(a, name, owner)
    return a


def rows(
    value: ArrayLike, name: str, dtype: np.dtype[Any] | None = None, widths: tuple[int, ...] = (3,)
) -> FloatArray:
    """Mesh data as a ready (n, width) array of `dtype` (default: the one it computes in)."""
    a = array(value, name)
    if a.ndim != 2 or a.shape[1] not in widths:
        expected = " or ".join(f"(n, {w})" for w in widths)
        raise ValueError(f"{name} must have shape {expected}, got shape {a.shape}")
    return ready(a, compute_dtype(a) if dtype is None else dtype)


def indices(value: ArrayLike, name: str) -> NDArray[np.int64]:
    """Triangles as a C-contiguous (m, 3) int64 array, from any integer dtype."""
    a = array(value, name)
    if a.dtype.kind not in "iu" and not (a.size == 0 and a.dtype.kind == "f"):
        raise TypeError(f"{name} must be an integer array, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name} must have shape (m, 3), got shape {a.shape}")
    if a.dtype.kind == "u" and a.size and a.max() > np.iinfo(np.int64).max:
        raise IndexError(f"{name} holds index {a.max()}, beyond any vertex count")
    result: NDArray[np.int64] = np.require(a, np.int64, ("C", "A"))
    return result


def matrix(value: ArrayLike, name: str) -> Float64Array:
    """A (4, 4) matrix of real numbers as a C-contiguous float64 array."""
    m = real(value, name)
    if m.shape != (4, 4):
        raise ValueError(f"{name} must have shape (4, 4), got shape {m.shape}")
    return m


def transform(value: ArrayLike | None, name: str) -> Float64Array:
    """A (4, 4) float64 matrix (identity for None), finite, as a read-only copy."""
    m = np.eye(4) if value is None else matrix(value, name).copy()
    if not np.isfinite(m).all():
        raise ValueError(f"{name} must be finite, got {m.tolist()}")
    m.flags.writeable = False
    return m


def rgba(value: ArrayLike, name: str) -> tuple[float, float, float, float]:
    """A colour of 3 or 4 components as RGBA (a missing alpha is 1), checked by `color`."""
    a = color(value, name)
    if a.shape not in ((3,), (4,)):
        raise ValueError(f"{name} must have shape (3,) or (4,), got shape {a.shape}")
    r, g, b, alpha = (*a.tolist(), 1.0)[:4]
    return (r, g, b, alpha)


def flag(value: object, name: str) -> bool:
    """`value` checked to be True or False (numpy's bool too): a string such as 'no' is not."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise TypeError(f"{name} must be True or False, got {value!r}")


def integer(value: object, name: str, low: int, high: int) -> int:
    """`value` checked to be an integer in [low, high]."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, got {value!r}")
    if not low <= value <= high:
        raise ValueError(f"{name} must be in [{low}, {high}], got {value}")
    return int(value)


def number(value: object, name: str) -> float:
    """`value` checked to be a real number (not a bool, a string or None), as a float."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.number)):
        raise TypeError(f"{name} must be a number, got {value!r}")
    if isinstance(value, np.complexfloating):
        raise TypeError(f"{name} must be a real number, got {value!r}")
    return float(value)


def choice(value: object, name: str) -> str:
    """`value` checked to be a string, lower-cased before the native module parses it: names
    are case-insensitive (``"Phong"`` is ``"phong"``), as matplotlib's and Pillow's are."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, got {value!r}")
    return value.lower()


DISPLAY_REMOVED = (
    "accuracy='display' is deprecated: the display tier was removed because it was no faster "
    "than 'fast' (about 1.0x on 8 mixed lights, never the 2x it was for), so 'fast' is used "
    "instead. Its bound (within 2e-6 * max(1, sum|terms|) plus the power's conditioning term; "
    "see the documentation's Accuracy page) is inside the 2^-10 the display tier promised. The "
    "name 'display' will be removed in a future release: pass accuracy='fast'"
)


def accuracy_choice(value: object) -> str:
    """`value` as the native module's accuracy name: lower-cased, with ``"display"`` (the removed
    display tier's name, a deprecated alias) mapped to ``"fast"`` and a `DeprecationWarning`
    at the user's line; the native module no longer knows "display"."""
    name = choice(value, "accuracy")
    if name != "display":
        return name
    warnings.warn(DISPLAY_REMOVED, DeprecationWarning, stacklevel=_caller_level())
    return "fast"


def one_of(value: object, name: str, options: tuple[str, ...]) -> str:
    """`value` as one of the lower-case `options`, whatever its case."""
    name_given = choice(value, name)
    if name_given not in options:
        quoted = [repr(o) for o in options]
        alternatives = (
            ", ".join(quoted[:-1]) + " or " + quoted[-1] if len(quoted) > 1 else quoted[0]
        )
        raise ValueError(f"{name} must be {alternatives}, got {value!r}")
    return name_given


def optional_choice(value: object, name: str) -> str | None:
    """`value` checked to be a string or None."""
    return None if value is None else choice(value, name)


def _mapped_file(a: object) -> str | None:
    """The file `a`'s memory maps ("" when it is mapped from a file glshade cannot name)."""
    seen = 0
    while a is not None and seen < 64:
        if isinstance(a, np.memmap) and isinstance(a.filename, (str, os.PathLike)):
            return os.path.realpath(a.filename)
        if isinstance(a, mmap.mmap):
            return ""
        a = a.obj if isinstance(a, memoryview) else getattr(a, "base", None)
        seen += 1
    return None


def out_array(out: object, inputs: dict[str, NDArray[Any] | None]) -> FloatArray:
    """`out` checked to be a numpy array that maps no file an input maps too.

    Two maps of one file share memory at different addresses, which only the files tell; the
    native module checks the rest, where it is exact and costs nothing: `out` must have the
    result's dtype (native byte order) and shape, be C-contiguous, aligned and writeable, and
    span no byte of an input (the inputs it reads are C-contiguous)."""
    if not isinstance(out, np.ndarray):
        raise TypeError(f"out must be a numpy array, got {type(out).__name__}")
    mapped = _mapped_file(out)
    if mapped is None:
        return out
    for name, a in inputs.items():
        other = None if a is None else _mapped_file(a)
        if other is not None and (mapped == "" or other == "" or other == mapped):
            raise ValueError(
                f"out and {name} may share memory (both map {mapped or 'a file'}): the result "
                f"would overwrite {name} while it is read; pass a separate out"
            )
    return out


# CSS's names (matplotlib's too) of a few colours, for the error that meets a colour name.
_NAMED = {
    "black": (0.0, 0.0, 0.0),
    "white": (1.0, 1.0, 1.0),
    "red": (1.0, 0.0, 0.0),
    "lime": (0.0, 1.0, 0.0),
    "green": (0.0, 128 / 255, 0.0),
    "blue": (0.0, 0.0, 1.0),
    "yellow": (1.0, 1.0, 0.0),
    "cyan": (0.0, 1.0, 1.0),
    "magenta": (1.0, 0.0, 1.0),
    "gray": (128 / 255, 128 / 255, 128 / 255),
    "grey": (128 / 255, 128 / 255, 128 / 255),
    "orange": (1.0, 165 / 255, 0.0),
}


def _numbers(values: Any) -> str:
    return "(" + ", ".join(f"{float(x):.3g}" for x in values) + ")"


def _first_name(a: NDArray[Any]) -> str:
    """The first item of a string array that is not a number's text ("red" in ("1", "red"))."""
    for item in a.reshape(-1).tolist():
        try:
            float(item)
        except ValueError:
            return str(item)
    return str(a.reshape(-1)[0])


def _color_name_error(given: str, name: str) -> TypeError:
    """The error for a colour given by name: the numbers to write instead."""
    key = given.strip().lower()
    rgb: tuple[float, ...] | None = _NAMED.get(key)
    hex_digits = key[1:]
    if rgb is None and key.startswith("#") and len(hex_digits) in (6, 8):
        try:
            rgb = tuple(int(hex_digits[i : i + 2], 16) / 255 for i in range(0, 6, 2))
        except ValueError:
            rgb = None
    example = f"{_numbers(rgb)} for {given!r}" if rgb is not None else "(1, 0, 0) for red"
    return TypeError(
        f"{name} takes numbers, not a colour name: got {given!r}. Give RGB or RGBA components "
        f"in [0, 1], e.g. {name}={example}, or with alpha {example.split(' for')[0][:-1]}, 1)"
    )


def color(value: ArrayLike, name: str) -> Float64Array:
    """A scene colour (material, light, light model, background) as a float64 array of any
    shape: a name raises a TypeError giving the numbers instead; uint8 is divided by 255 (as
    vertex colours are); anything else is taken as the values themselves."""
    if isinstance(value, str):
        raise _color_name_error(value, name)
    a: NDArray[Any] | None = value if isinstance(value, np.ndarray) else None
    if a is None:
        try:
            a = np.asarray(value)
        except (TypeError, ValueError):
            a = None  # `real` names what numpy could not read
    if a is not None and a.dtype.kind in "US" and a.size:
        raise _color_name_error(_first_name(a), name)
    if a is not None and a.dtype == np.uint8:
        return real(a / 255.0, name)
    return real(value, name)


def vector(value: ArrayLike, name: str, size: int = 3) -> tuple[float, ...]:
    """`value` (a colour, position or direction, by `color`'s rules) as `size` floats, by
    name; ranges are the native scene's to check."""
    a = color(value, name)
    if a.shape != (size,):
        raise ValueError(f"{name} must have shape ({size},), got shape {a.shape}")
    return tuple(float(x) for x in a)


def vertex_colors(value: ArrayLike, name: str = "colors") -> NDArray[Any]:
    """Per-vertex colours as an array of real numbers; colour names raise a TypeError that says
    names are not accepted (the values of `color_values` follow)."""
    if isinstance(value, str):
        raise _color_name_error(value, name)
    a = value if isinstance(value, np.ndarray) else None
    if a is None:
        try:
            a = np.asarray(value)
        except (TypeError, ValueError):
            a = None
    if a is not None and a.dtype.kind in "US" and a.size:
        raise TypeError(
            f"{name} takes numbers, not colour names: got {_first_name(a)!r}. Give an "
            "(n, 3) or (n, 4) array of RGB(A) components in [0, 1] (uint8 0-255 is divided by "
            "255), e.g. np.tile((1, 0, 0), (n, 1)) for red"
        )
    return array(value, name)


# The smallest largest value of a colour taken for bytes: below it, values are more likely a
# bright light's (2, 2, 2) than a near-black byte colour (a sixteenth of full scale).
_BYTE_HINT = 16.0


# Set while glshade builds objects from colours it has already checked under the user's own
# names: a context variable, so another thread's (or task's) colours still warn.
_CHECKED: ContextVar[bool] = ContextVar("glshade_colors_checked", default=False)


@contextmanager
def colors_checked() -> Iterator[None]:
    """Builds `Light`, `Material` and `Scene` objects from colours that were checked and warned
    about already (under the user's names, or when the object was first made), without a
    second `ColorRangeWarning`."""
    token = _CHECKED.set(True)
    try:
        yield
    finally:
        _CHECKED.reset(token)


def looks_like_bytes(values: NDArray[Any]) -> bool:
    """The one rule every colour surface applies: every value (NaN aside) lies in [0, 255] and
    the largest is at least 16, as 0-255 bytes do and [0, 1] colours do not. The largest is
    read first, so a picture or a vertex array that is not bytes costs one pass."""
    if values.size == 0 or values.dtype.kind not in "fiu":
        return False
    high, low = values.max(), None
    if np.isnan(high):  # NaN rows aside, as the shading leaves them aside
        finite = values[~np.isnan(values)]
        if finite.size == 0:
            return False
        high, low = finite.max(), finite.min()
    if not _BYTE_HINT <= high <= 255.0:
        return False
    return bool((values.min() if low is None else low) >= 0.0)


def bytes_message(values: NDArray[Any], name: str, owner: str) -> str:
    """What every surface says of a colour `values` that `looks_like_bytes`: what was found,
    and the [0, 1] values to give instead (for one colour; an alpha of 1 kept)."""
    if values.ndim == 1 and values.size <= 4:
        divided = np.asarray(values, np.float64) / 255
        if len(values) == 4 and values[3] == 1.0:
            divided[3] = 1.0  # an alpha of 1 beside bytes is an opaque alpha, kept as it is
        shown = f"{name}={_numbers(values)}"
        scaled = f": {name}={_numbers(divided)}"
    else:
        shown = f"{name} (values up to {float(np.nanmax(values)):g})"
        scaled = f": {name} / 255 (or give it as uint8, which is divided by 255)"
    return (
        f"{owner} {shown} looks like 0-255 byte values, but glshade's colours are in [0, 1] "
        f"(above 1 they saturate: a near-white result). Divide by 255{scaled}"
    )


def warn_if_bytes(values: NDArray[Any], name: str, owner: str) -> None:
    """Warns (`ColorRangeWarning`) when the colour `values` `looks_like_bytes`: bytes written
    where glshade takes [0, 1], and values above 1 are allowed (high dynamic range). `owner`
    names the object or function the colour was given to ("Material", "shade")."""
    if _CHECKED.get() or not looks_like_bytes(values):
        return
    warnings.warn(
        ColorRangeWarning(
            bytes_message(values, name, owner) + "; or, if the values above 1 are meant (high "
            "dynamic range), silence this with "
            "warnings.filterwarnings('ignore', category=glshade.ColorRangeWarning)"
        ),
        stacklevel=_caller_level(),
    )


def refuse_bytes(values: NDArray[Any], name: str, owner: str) -> None:
    """Raises ValueError, with `bytes_message`, when the colour `values` `looks_like_bytes`
    where values above 1 are not allowed (glTF's factors)."""
    if looks_like_bytes(values):
        raise ValueError(bytes_message(values, name, owner))


_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _caller_level() -> int:
    """The stacklevel of the first frame outside glshade, so a warning points at the user's
    line whichever of glshade's functions built the colour."""
    level, frame = 1, sys._getframe(1)
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(_PACKAGE):
        frame = frame.f_back  # type: ignore[assignment]
        level += 1
    return level
