"""matplotlib's relief shading, computed by glshade: `LightSource` takes the arguments of
``matplotlib.colors.LightSource`` and returns what it returns (hillshades, shaded normals, and
the hsv, soft light and overlay blends), from a parallel Rust core; `shade_colors` is mplot3d's
shading of polygons by their normals. matplotlib is not imported (a colormap passed to
`LightSource.shade` is any callable).

>>> import numpy as np, glshade as gs
>>> z = np.add.outer(np.linspace(0, 1, 4), np.linspace(0, 2, 5))
>>> gs.relief.LightSource(azdeg=315, altdeg=45).hillshade(z).shape
(4, 5)
"""

from __future__ import annotations

from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _glshade
from ._intake import number, one_of

__all__ = ["LightSource", "shade_colors"]

BlendMode = Literal["hsv", "soft", "overlay"]


def _float64(value: ArrayLike, name: str) -> NDArray[np.float64]:
    """`value` as a C-contiguous float64 array; a masked array is refused by name."""
    if isinstance(value, np.ma.MaskedArray):
        raise TypeError(
            f"{name} is a masked array: glshade.relief takes plain arrays (fill the mask, or use "
            "matplotlib's LightSource, which keeps masked pixels unshaded)"
        )
    a = np.asarray(value)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{name} must be a real array, got dtype {a.dtype}")
    return np.ascontiguousarray(a, dtype=np.float64)


def _finite(value: object, name: str) -> float:
    """A finite real number (matplotlib takes NaN, and returns NaN everywhere)."""
    x = number(value, name)
    if not np.isfinite(x):
        raise ValueError(f"{name} must be a finite number, got {x}")
    return x


class LightSource:
    """A light at infinity, from azimuth `azdeg` (degrees clockwise from north) and altitude
    `altdeg` (degrees above the horizon): ``matplotlib.colors.LightSource``, computed by
    glshade.

    Parameters
    ----------
    azdeg : float
        Azimuth, 0 to 360 degrees clockwise from north (row 0 of a grid is north); 315 by
        default, from the northwest.
    altdeg : float
        Altitude, 0 to 90 degrees; 45 by default.
    hsv_min_val : float
        The least value ("v" of hsv) the hsv blend shifts colours to.
    hsv_max_val : float
        The greatest value the hsv blend shifts colours to.
    hsv_min_sat : float
        The saturation the hsv blend moves to in shadow.
    hsv_max_sat : float
        The saturation the hsv blend moves to in light.

    Notes
    -----
    Everything is computed in float64, as matplotlib does for float64 input; a grid needs at
    least 2 rows and 2 columns (numpy's gradient). Masked arrays are refused.
    """

    def __init__(
        self,
        azdeg: float = 315,
        altdeg: float = 45,
        hsv_min_val: float = 0,
        hsv_max_val: float = 1,
        hsv_min_sat: float = 1,
        hsv_max_sat: float = 0,
    ) -> None:
        self.azdeg = _finite(azdeg, "azdeg")
        self.altdeg = _finite(altdeg, "altdeg")
        self.hsv_min_val = _finite(hsv_min_val, "hsv_min_val")
        self.hsv_max_val = _finite(hsv_max_val, "hsv_max_val")
        self.hsv_min_sat = _finite(hsv_min_sat, "hsv_min_sat")
        self.hsv_max_sat = _finite(hsv_max_sat, "hsv_max_sat")

    @property
    def direction(self) -> NDArray[np.float64]:
        """(3,) The unit vector towards the light: x east, y north, z up."""
        az = np.radians(90 - self.azdeg)
        alt = np.radians(self.altdeg)
        return np.array([np.cos(az) * np.cos(alt), np.sin(az) * np.cos(alt), np.sin(alt)])

    def hillshade(
        self, elevation: ArrayLike, vert_exag: float = 1, dx: float = 1, dy: float = 1,
        fraction: float = 1.0,
    ) -> NDArray[np.float64]:  # fmt: skip
        """The illumination of a surface, in [0, 1].

        Parameters
        ----------
        elevation : (rows, cols) array-like
            Heights, row 0 at the top (north), as images have it.
        vert_exag : float
            Exaggerates the heights.
        dx : float
            The spacing of the columns.
        dy : float
            The spacing of the rows.
        fraction : float
            Contrast: the dot products are multiplied by it before the stretch of the whole
            image to [0, 1] (matplotlib's order), then clipped.

        Returns
        -------
        (rows, cols) float64 ndarray
            The intensity of each grid point.
        """
        return _glshade.hillshade(
            _float64(elevation, "elevation"), vert_exag=number(vert_exag, "vert_exag"),
            dx=number(dx, "dx"), dy=number(dy, "dy"), direction=tuple(self.direction),
            fraction=number(fraction, "fraction"),
        )  # fmt: skip

    def shade_normals(self, normals: ArrayLike, fraction: float = 1.0) -> NDArray[np.float64]:
        """The illumination of unit normals, stretched over all of them to [0, 1].

        Parameters
        ----------
        normals : (..., 3) array-like
            Unit normals.
        fraction : float
            Contrast, as for `hillshade`.

        Returns
        -------
        (...) float64 ndarray
            The intensity of each normal.
        """
        return _glshade.shade_normals(
            _float64(normals, "normals"), direction=tuple(self.direction),
            fraction=number(fraction, "fraction"),
        )  # fmt: skip

    def _blend(
        self, rgb: ArrayLike, intensity: ArrayLike, mode: str, hsv: tuple[float, ...]
    ) -> NDArray[np.float64]:
        colors = _float64(rgb, "rgb")
        levels = _float64(intensity, "intensity")
        if levels.shape == (*colors.shape[:-1], 1):
            levels = levels[..., 0]
        if mode != "hsv" and colors.shape[-1:] == (4,) and levels.shape == colors.shape[:-1]:
            # matplotlib blends an RGBA image's alpha by the same formula as its colours.
            rgb_part = self._blend(colors[..., :3], levels, mode, hsv)
            alpha = self._blend(np.repeat(colors[..., 3:], 3, axis=-1), levels, mode, hsv)
            return np.concatenate([rgb_part, alpha[..., :1]], axis=-1)
        if colors.shape[-1:] != (3,) or levels.shape != colors.shape[:-1]:
            raise ValueError(
                f"rgb must have shape (..., 3) and intensity (...) or (..., 1) of the same "
                f"leading shape, got {colors.shape} and {np.shape(intensity)}"
            )
        return _glshade.blend(np.ascontiguousarray(colors), np.ascontiguousarray(levels),
                              mode=mode, hsv=hsv)  # fmt: skip

    def blend_hsv(
        self, rgb: ArrayLike, intensity: ArrayLike, hsv_max_sat: float | None = None,
        hsv_max_val: float | None = None, hsv_min_val: float | None = None,
        hsv_min_sat: float | None = None,
    ) -> NDArray[np.float64]:  # fmt: skip
        """The colours with their saturation and value moved by the intensity (in hsv).

        Parameters
        ----------
        rgb : (..., 3) or (..., 4) array-like
            Colours in [0, 1]; of RGBA, the RGB.
        intensity : (..., 1) or (...) array-like
            Intensities in [0, 1]; 0.5 changes nothing.
        hsv_max_sat : float, optional
            Default: the light source's.
        hsv_max_val : float, optional
            Default: the light source's.
        hsv_min_val : float, optional
            Default: the light source's.
        hsv_min_sat : float, optional
            Default: the light source's.

        Returns
        -------
        (..., 3) float64 ndarray
            The blended colours.
        """
        hsv = tuple(
            number(own if given is None else given, name)
            for name, given, own in (
                ("hsv_min_val", hsv_min_val, self.hsv_min_val),
                ("hsv_max_val", hsv_max_val, self.hsv_max_val),
                ("hsv_min_sat", hsv_min_sat, self.hsv_min_sat),
                ("hsv_max_sat", hsv_max_sat, self.hsv_max_sat),
            )
        )
        # matplotlib reads the first three channels (an RGBA image's colour) and returns RGB.
        return self._blend(np.asarray(rgb)[..., :3], intensity, "hsv", hsv)

    def blend_soft_light(self, rgb: ArrayLike, intensity: ArrayLike) -> NDArray[np.float64]:
        """Soft light ("pegtop"): ``2 i c + (1 - 2 i) c**2``.

        Parameters
        ----------
        rgb : (..., 3) array-like
            Colours in [0, 1].
        intensity : (..., 1) or (...) array-like
            Intensities in [0, 1].

        Returns
        -------
        (..., 3) float64 ndarray
            The blended colours.
        """
        return self._blend(rgb, intensity, "soft", (0.0, 0.0, 0.0, 0.0))

    def blend_overlay(self, rgb: ArrayLike, intensity: ArrayLike) -> NDArray[np.float64]:
        """Overlay: ``2 i c`` where ``c <= 0.5``, else ``1 - 2 (1 - i)(1 - c)``.

        Parameters
        ----------
        rgb : (..., 3) array-like
            Colours in [0, 1].
        intensity : (..., 1) or (...) array-like
            Intensities in [0, 1].

        Returns
        -------
        (..., 3) float64 ndarray
            The blended colours.
        """
        return self._blend(rgb, intensity, "overlay", (0.0, 0.0, 0.0, 0.0))

    def shade_rgb(
        self, rgb: ArrayLike, elevation: ArrayLike, fraction: float = 1.0,
        blend_mode: BlendMode = "hsv", vert_exag: float = 1, dx: float = 1, dy: float = 1,
        **kwargs: Any,
    ) -> NDArray[np.float64]:  # fmt: skip
        """An RGB image shaded by the hillshade of `elevation`.

        Parameters
        ----------
        rgb : (rows, cols, 3) array-like
            Colours in [0, 1].
        elevation : (rows, cols) array-like
            Heights, as for `hillshade`.
        fraction : float
            Contrast, as for `hillshade`.
        blend_mode : {"hsv", "soft", "overlay"}
            The blend.
        vert_exag : float
            As for `hillshade`.
        dx : float
            As for `hillshade`.
        dy : float
            As for `hillshade`.
        **kwargs
            The hsv blend's ``hsv_*`` overrides.

        Returns
        -------
        (rows, cols, 3) float64 ndarray
            The shaded image.
        """
        mode = one_of(blend_mode, "blend_mode", ("hsv", "soft", "overlay"))
        intensity = self.hillshade(elevation, vert_exag, dx, dy, fraction)
        if mode == "hsv":
            return self.blend_hsv(rgb, intensity, **kwargs)
        if kwargs:
            raise TypeError(f"the {mode} blend takes no further arguments, got {sorted(kwargs)}")
        if mode == "soft":
            return self.blend_soft_light(rgb, intensity)
        return self.blend_overlay(rgb, intensity)

    def shade(
        self, data: ArrayLike, cmap: Any, norm: Any = None, blend_mode: BlendMode = "overlay",
        vmin: float | None = None, vmax: float | None = None, vert_exag: float = 1,
        dx: float = 1, dy: float = 1, fraction: float = 1, **kwargs: Any,
    ) -> NDArray[np.float64]:  # fmt: skip
        """`data` coloured by `cmap` and shaded by its own hillshade: RGBA.

        Parameters
        ----------
        data : (rows, cols) array-like
            Heights, coloured and shaded.
        cmap : callable
            A colormap (a matplotlib ``Colormap``): values in [0, 1] to RGBA.
        norm : callable, optional
            Values to [0, 1]; default: linear from `vmin` to `vmax`.
        blend_mode : {"hsv", "soft", "overlay"}
            The blend (matplotlib's default here is overlay).
        vmin : float, optional
            Default: the data's least value.
        vmax : float, optional
            Default: the data's greatest value.
        vert_exag : float
            As for `hillshade`.
        dx : float
            As for `hillshade`.
        dy : float
            As for `hillshade`.
        fraction : float
            As for `hillshade`.
        **kwargs
            The hsv blend's ``hsv_*`` overrides.

        Returns
        -------
        (rows, cols, 4) float64 ndarray
            The colours, shaded, with the colormap's alpha.
        """
        values = _float64(data, "data")
        if vmin is None:
            vmin = float(values.min())
        if vmax is None:
            vmax = float(values.max())
        if norm is None:
            span = vmax - vmin
            scaled = (values - vmin) / span if span != 0 else np.zeros_like(values)
        else:
            scaled = norm(values)
        rgba = np.array(cmap(scaled), dtype=np.float64)
        shaded = self.shade_rgb(
            rgba, values, fraction=fraction, blend_mode=blend_mode, vert_exag=vert_exag,
            dx=dx, dy=dy, **kwargs,
        )  # fmt: skip
        rgba[..., :3] = shaded[..., :3]
        return rgba


def shade_colors(
    color: ArrayLike, normals: ArrayLike, lightsource: LightSource | None = None
) -> NDArray[np.float64]:
    """mplot3d's shading of polygons (``Axes3D._shade_colors``): each colour times
    ``0.3 + 0.7 (s + 1)/2`` for ``s = n . direction`` of its unit normal, its alpha kept.

    Parameters
    ----------
    color : (m, 4) or (4,) array-like
        RGBA colours in [0, 1], one per polygon or one for all.
    normals : (m, 3) array-like
        Polygon normals, any length (normalised first).
    lightsource : LightSource, optional
        Default: mplot3d's, azimuth 225 and altitude 19.4712 degrees.

    Returns
    -------
    (m, 4) float64 ndarray
        The shaded colours. A zero normal is shaded as facing sideways (s = 0, factor 0.65);
        when every normal is zero the colours come back as given, as in mplot3d.
    """
    light = LightSource(azdeg=225, altdeg=19.4712) if lightsource is None else lightsource
    n = _float64(normals, "normals")
    given = _float64(color, "color")
    with np.errstate(invalid="ignore", divide="ignore"):
        shade: NDArray[np.float64] = (n / np.linalg.norm(n, axis=1, keepdims=True)) @ (
            light.direction
        )
    lit = ~np.isnan(shade)
    if not lit.any():
        return given.copy()
    shade[~lit] = 0
    # mplot3d's Normalize(-1, 1) then Normalize(0.3, 1).inverse, in their operations.
    factor = 0.3 + (shade + 1) / 2 * (1 - 0.3)
    colors: NDArray[np.float64] = factor[:, None] * np.atleast_2d(given)
    colors[:, 3] = np.broadcast_to(np.atleast_2d(given)[:, 3], len(n))
    return colors
