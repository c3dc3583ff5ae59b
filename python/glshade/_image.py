"""`Image`: a float image that is a numpy array, saves itself and shows itself in notebooks."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, cast

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._intake import warn_if_bytes
from ._png import encode_png, quantize

__all__ = ["Image"]

# The formats `Image.save` writes, by lower-case extension: PNG by the built-in writer, the rest
# by Pillow under its format names.
_PILLOW_FORMATS = {
    ".jpg": "JPEG",
    ".jpeg": "JPEG",
    ".tif": "TIFF",
    ".tiff": "TIFF",
    ".webp": "WEBP",
}
_EXTENSIONS = ".png, .jpg, .jpeg, .tif, .tiff, .webp"
_SHAPES = "(height, width), (height, width, 3) or (height, width, 4)"


def _image_shape(shape: tuple[int, ...]) -> bool:
    return len(shape) == 2 or (len(shape) == 3 and shape[2] in (3, 4))


def _pixels(value: ArrayLike, name: str) -> NDArray[np.floating[Any]]:
    """`value` as an image's float array: float32 and float64 as they are (no copy), float16 as
    float32, longer floats as float64, uint8 / 255, uint16 / 65535 and bool as 0 or 1 in
    float32; anything else raises, naming `name`."""
    try:
        a = np.asarray(value)
    except (TypeError, ValueError) as e:
        raise TypeError(
            f"{name} must be an array of pixel values, got {type(value).__name__} ({e})"
        ) from None
    if not _image_shape(a.shape):
        raise ValueError(f"{name} must have shape {_SHAPES}, got {a.shape}{_shape_hint(a.shape)}")
    kind, size = a.dtype.kind, a.dtype.itemsize
    if kind == "f":
        warn_if_bytes(a, name, "Image")
        if size in (4, 8):
            return a
        return a.astype(np.float32 if size < 4 else np.float64)
    if kind == "u" and size in (1, 2):
        return a.astype(np.float32) / np.float32(255 if size == 1 else 65535)
    if kind == "b":
        return a.astype(np.float32)
    hint = ": scale it to floats in [0, 1] (or cast 0-255 values to uint8)" if kind in "iu" else ""
    raise TypeError(
        f"{name} must be float (values in [0, 1]), uint8 (0-255), uint16 (0-65535) or bool, "
        f"got dtype {a.dtype}{hint}"
    )


def _shape_hint(shape: tuple[int, ...]) -> str:
    """How to reach an accepted shape from a common near miss."""
    if len(shape) == 3 and shape[2] == 1:
        return ": drop the channel axis with array[..., 0]"
    if len(shape) == 4 and shape[0] == 2 and shape[3] in (3, 4):
        return (
            ": a two-sided result (front, back) from a scene with two_side or a double-sided "
            "material? take one side, array[0] (front) or array[1] (back)"
        )
    if len(shape) == 4 and shape[3] in (3, 4):
        return ": several images (views, or the colours of scene.outputs)? take one, array[0]"
    if len(shape) == 3 and shape[0] in (1, 3, 4) and shape[2] not in (3, 4):
        return ": channels first? move them last with np.moveaxis(array, 0, -1)"
    return ""


def _display_width(value: object) -> int | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise TypeError(
            f"display_width must be an int (pixels on screen) or None, got {type(value).__name__}"
        )
    if value < 1:
        raise ValueError(f"display_width must be at least 1 pixel, got {value}")
    return int(value)


class Image(np.ndarray[Any, np.dtype[np.floating[Any]]]):
    """A float image, row 0 at the top: a numpy array that also saves itself and shows itself
    in notebooks.

    An image is (height, width) grey, (height, width, 3) RGB or (height, width, 4) RGBA, of
    float values in [0, 1] (values outside are kept, and clipped only when saved or shown).
    ``gs.render`` returns (height, width, 4) images of the float dtype it computed in.

    Parameters
    ----------
    array : array_like, shape (height, width), (height, width, 3) or (height, width, 4)
        The pixels. float32 and float64 are kept as they are, without a copy (the image shares
        memory with `array`, as with ``np.asarray``); float16 becomes float32 and longer floats
        float64. uint8 is divided by 255, uint16 by 65535 and bool becomes 0 or 1, in float32
        (a copy). Other dtypes raise ``TypeError``, other shapes ``ValueError``.
    display_width : int, optional
        The width in screen pixels a notebook shows the image at, the height following the
        aspect ratio; None: its natural size (one screen pixel per image pixel). Also an
        attribute, which views, slices and arithmetic results keep.

    Attributes
    ----------
    display_width : int or None
        As the parameter; settable.

    Notes
    -----
    Slices and arithmetic that keep the image's layout (a float array with as many dimensions
    as the image, and for a colour image a last axis of 3 or 4) stay images, so ``image[::2]``,
    ``image[..., :3]`` and ``image * 0.5`` are images. Everything else is a plain array: a
    channel (``image[..., 0]``), a row, a pixel, a comparison, a reduction, a reshape or an
    integer ``astype``. ``np.asarray(image)`` is the plain array. ``array.view(gs.Image)``
    also makes an image, sharing memory, without checking `array`: its save and display
    check it then.

    In a notebook an image shows itself (IPython's ``_repr_png_``) as an 8-bit PNG.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> rgb = gs.Image(np.zeros((2, 3, 3), np.uint8))
    >>> rgb.shape, rgb.dtype
    ((2, 3, 3), dtype('float32'))
    >>> ramp = gs.Image(np.linspace(0, 1, 12).reshape(3, 4), display_width=400)
    >>> ramp[:, :2].display_width
    400
    >>> type(ramp[0]).__name__
    'ndarray'
    >>> ramp.save("ramp.png", bits=16)  # doctest: +SKIP
    PosixPath('ramp.png')
    >>> ramp.save("ramp.jpg")  # with Pillow: pip install 'glshade[image]'  # doctest: +SKIP
    PosixPath('ramp.jpg')
    """

    _display: int | None

    def __new__(cls, array: ArrayLike, *, display_width: int | None = None) -> Image:
        image = _pixels(array, "array").view(cls)
        image._display = _display_width(display_width)
        return image

    def __init__(self, array: ArrayLike, *, display_width: int | None = None) -> None:
        # numpy arrays are made in __new__; this signature is the one help() and the
        # reference show.
        pass

    def __array_finalize__(self, obj: NDArray[Any] | None) -> None:
        self._display = getattr(obj, "_display", None)

    @property
    def display_width(self) -> int | None:
        """The width in screen pixels a notebook shows the image at; None: natural size."""
        return self._display

    @display_width.setter
    def display_width(self, value: int | None) -> None:
        self._display = _display_width(value)

    def save(self, path: str | os.PathLike[str], *, bits: int = 8) -> Path:
        """Writes the image in the format its extension names (values clipped to [0, 1], NaN
        as 0).

        ``.png``: the built-in writer, grey, RGB or RGBA as the image is, 8 or 16 bits per
        channel. ``.jpg``/``.jpeg``, ``.tif``/``.tiff`` and ``.webp``: Pillow (``pip install
        'glshade[image]'``) at its default settings (JPEG quality 75, lossy WebP at quality
        80), 8 bits. JPEG has no alpha channel: an RGBA image is composited over white, as
        matplotlib saves a JPEG. Extensions are case-insensitive.

        Parameters
        ----------
        path : str or os.PathLike
            Where to write; its extension picks the format.
        bits : {8, 16}
            Bits per channel. 16 is written as PNG only.

        Returns
        -------
        Path
            The path written.

        Raises
        ------
        ValueError
            An extension other than the above (or none), JPEG, TIFF or WebP without Pillow (or
            a Pillow built without that format), `bits` other than 8 or 16, 16 bits for a
            format other than PNG, an empty image or an array that is not an image's shape.
        TypeError
            An array whose dtype is not an image's (see `Image`), as ``array.view(gs.Image)``
            can make.
        """
        path = Path(path)
        extension = path.suffix.lower()
        if isinstance(bits, bool) or not isinstance(bits, int | np.integer) or bits not in (8, 16):
            raise ValueError(f"bits must be 8 or 16, got {bits!r}")
        if extension != ".png" and extension not in _PILLOW_FORMATS:
            found = f"extension {path.suffix!r}" if path.suffix else "no extension"
            raise ValueError(
                f"path {str(path)!r} has {found}; Image.save writes {_EXTENSIONS} "
                "(JPEG, TIFF and WebP through Pillow)"
            )
        pixels = _pixels(self.view(np.ndarray), "the image")
        if extension == ".png":
            path.write_bytes(encode_png(pixels, bits))
            return path
        if bits != 8:
            raise ValueError(
                f"bits={bits} is written as PNG only; {path.suffix!r} takes 8 bits per channel "
                "(save as .png for 16)"
            )
        _save_with_pillow(pixels, path, _PILLOW_FORMATS[extension])
        return path

    def _repr_png_(self) -> bytes | tuple[bytes, dict[str, int]] | None:
        """The 8-bit PNG that IPython and Jupyter show, with the display size as metadata when
        `display_width` is set; None (IPython then shows the text) for an empty array or one
        that is not an image."""
        try:
            pixels = _pixels(self.view(np.ndarray), "the image")
        except (TypeError, ValueError):
            return None
        height, width = pixels.shape[:2]
        if height == 0 or width == 0:
            return None
        png = encode_png(pixels)
        if self._display is None:
            return png
        shown = self._display
        return png, {"width": shown, "height": max(1, round(shown * height / width))}

    def __reduce__(self) -> tuple[Any, ...]:
        # Pickles (multiprocessing, dask) carry display_width along with the array.
        reconstruct, arguments, state = cast(tuple[Any, Any, Any], super().__reduce__())
        return reconstruct, arguments, (state, self._display)

    def __setstate__(self, state: Any) -> None:
        array_state, self._display = state
        super().__setstate__(array_state)

    def __getitem__(self, key: Any) -> Any:
        return _plain_unless_image(super().__getitem__(key), self)

    def __array_wrap__(self, array: Any, context: Any = None, return_scalar: bool = False) -> Any:
        result = _plain_unless_image(super().__array_wrap__(array, context, return_scalar), self)
        return result[()] if return_scalar and np.ndim(result) == 0 else result

    def reshape(self, *args: Any, **kwargs: Any) -> Any:
        """As ``numpy.ndarray.reshape``: an image only where the result keeps its layout.

        Parameters
        ----------
        *args : Any
            As ``numpy.ndarray.reshape``'s.
        **kwargs : Any
            As ``numpy.ndarray.reshape``'s.

        Returns
        -------
        Image or numpy.ndarray
        """
        return _plain_unless_image(super().reshape(*args, **kwargs), self)

    def transpose(self, *axes: Any) -> Any:
        """As ``numpy.ndarray.transpose``: an image only where the result keeps its layout.

        Parameters
        ----------
        *axes : Any
            As ``numpy.ndarray.transpose``'s.

        Returns
        -------
        Image or numpy.ndarray
        """
        return _plain_unless_image(super().transpose(*axes), self)

    def swapaxes(self, *args: Any, **kwargs: Any) -> Any:
        """As ``numpy.ndarray.swapaxes``: an image only where the result keeps its layout.

        Parameters
        ----------
        *args : Any
            As ``numpy.ndarray.swapaxes``'s.
        **kwargs : Any
            As ``numpy.ndarray.swapaxes``'s.

        Returns
        -------
        Image or numpy.ndarray
        """
        return _plain_unless_image(super().swapaxes(*args, **kwargs), self)

    def squeeze(self, *args: Any, **kwargs: Any) -> Any:
        """As ``numpy.ndarray.squeeze``: an image only where the result keeps its layout.

        Parameters
        ----------
        *args : Any
            As ``numpy.ndarray.squeeze``'s.
        **kwargs : Any
            As ``numpy.ndarray.squeeze``'s.

        Returns
        -------
        Image or numpy.ndarray
        """
        return _plain_unless_image(super().squeeze(*args, **kwargs), self)

    def ravel(self, *args: Any, **kwargs: Any) -> Any:
        """As ``numpy.ndarray.ravel``: a plain one-dimensional array.

        Parameters
        ----------
        *args : Any
            As ``numpy.ndarray.ravel``'s.
        **kwargs : Any
            As ``numpy.ndarray.ravel``'s.

        Returns
        -------
        numpy.ndarray
        """
        return super().ravel(*args, **kwargs).view(np.ndarray)

    def flatten(self, *args: Any, **kwargs: Any) -> Any:
        """As ``numpy.ndarray.flatten``: a plain one-dimensional array.

        Parameters
        ----------
        *args : Any
            As ``numpy.ndarray.flatten``'s.
        **kwargs : Any
            As ``numpy.ndarray.flatten``'s.

        Returns
        -------
        numpy.ndarray
        """
        return super().flatten(*args, **kwargs).view(np.ndarray)

    def astype(self, *args: Any, **kwargs: Any) -> Any:
        """As ``numpy.ndarray.astype``: an image only for a float dtype.

        Parameters
        ----------
        *args : Any
            As ``numpy.ndarray.astype``'s.
        **kwargs : Any
            As ``numpy.ndarray.astype``'s.

        Returns
        -------
        Image or numpy.ndarray
        """
        return _plain_unless_image(super().astype(*args, **kwargs), self)

    @property
    def T(self) -> Any:
        """As ``numpy.ndarray.T``: an image only where the result keeps its layout."""
        return self.transpose()


def _plain_unless_image(value: Any, source: NDArray[Any]) -> Any:
    """`value` as a plain array unless it is a float array of `source`'s number of dimensions
    and an image's shape."""
    if isinstance(value, Image) and not (
        value.dtype.kind == "f" and value.ndim == source.ndim and _image_shape(value.shape)
    ):
        return value.view(np.ndarray)
    return value


def _save_with_pillow(pixels: NDArray[np.floating[Any]], path: Path, format: str) -> None:
    """Writes `pixels` through Pillow in `format` (JPEG, TIFF or WEBP), 8 bits per channel."""
    try:
        import PIL.features
        import PIL.Image
    except ImportError:
        raise ValueError(
            f"writing {path.suffix!r} needs Pillow, which is not installed: "
            "pip install 'glshade[image]' (or pip install pillow), or save as .png"
        ) from None
    if format == "WEBP" and not PIL.features.check("webp"):
        raise ValueError(
            f"writing {path.suffix!r} needs a Pillow built with WebP support, and this one "
            "(PIL.features.check('webp')) has none; save as .png"
        )
    if format == "JPEG" and pixels.ndim == 3 and pixels.shape[2] == 4:
        # JPEG has no alpha: composite over white, as matplotlib's imsave and savefig do.
        alpha = np.clip(np.nan_to_num(pixels[..., 3:], nan=0.0), 0.0, 1.0)
        colour = np.clip(np.nan_to_num(pixels[..., :3], nan=0.0), 0.0, 1.0)
        pixels = colour * alpha + (1.0 - alpha)
    PIL.Image.fromarray(quantize(pixels, 8)).save(path, format=format)
