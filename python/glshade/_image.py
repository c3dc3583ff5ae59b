"""`Image`: a float image that is a numpy array, saves itself and shows itself in notebooks."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ._png import encode_png, write_png

__all__ = ["Image"]


def _image_shaped(a: np.ndarray[Any, Any]) -> bool:
    return a.ndim == 3 and a.shape[2] == 4 and a.dtype.kind == "f"


class Image(np.ndarray[Any, np.dtype[np.floating[Any]]]):
    """An (height, width, 4) RGBA float image, row 0 at the top: a numpy array that also saves
    itself as a PNG and shows itself in notebooks.

    Slices and arithmetic that keep the (height, width, 4) float shape stay images; everything
    else (a channel, a comparison, a reduction) is a plain array. ``np.asarray(image)`` gives
    the plain array.

    Examples
    --------
    >>> import numpy as np, glshade as gs
    >>> image = np.zeros((2, 3, 4)).view(gs.Image)
    >>> image.save("black.png")  # doctest: +SKIP
    """

    def save(self, path: str | Path) -> Path:
        """Writes the image as an 8-bit RGBA PNG (values clipped to [0, 1], NaN as 0).

        Parameters
        ----------
        path : str or Path
            Where to write.

        Returns
        -------
        Path
            The path written.
        """
        return write_png(path, np.asarray(self))

    def _repr_png_(self) -> bytes:
        """The PNG that IPython and Jupyter show."""
        return encode_png(np.asarray(self))

    def __getitem__(self, key: Any) -> Any:
        return _plain_unless_image(super().__getitem__(key))

    def __array_wrap__(self, array: Any, context: Any = None, return_scalar: bool = False) -> Any:
        result = _plain_unless_image(super().__array_wrap__(array, context, return_scalar))
        return result[()] if return_scalar and np.ndim(result) == 0 else result


def _plain_unless_image(value: Any) -> Any:
    if isinstance(value, Image) and not _image_shaped(value):
        return value.view(np.ndarray)
    return value
