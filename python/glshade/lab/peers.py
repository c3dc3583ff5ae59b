"""Dr.Jit and JAX on the CPU, the peers of ``python -m glshade bench shade``: the equation
`baselines.numba_shade` computes (float32; Blinn, GL's specular gate, attenuation, a spot cone
with cutoff and exponent, emission + ambient base, one side, one final clamp to [0, 1], RGBA
with the material's diffuse alpha), written as a user of each writes it for speed.

Both read the scene through `baselines.light_table` and `baselines.constants`, the numbers numba
reads, take numpy arrays and return a (n, 4) float32 numpy array: what a user pays to get numpy
in and out is in the call.

- Dr.Jit (`drjit_shade`): ``drjit.llvm`` arrays, traced on every call; the scene's numbers are
  Python floats, so they are literals of the kernel (an integral exponent becomes multiplies),
  and the kernel comes from Dr.Jit's cache after the first call. One fused kernel gathers the
  vertices from the numpy memory it maps, lights them and scatters RGBA into a fresh buffer
  that numpy views.
- JAX (`jax_shade`): ``jax.jit`` with the lights unrolled by a Python loop, each light's kind
  static and its numbers traced, x, y and z as separate arrays; a second small jit interleaves
  the (n, 4) result, which numpy views.

Threads. glshade's pool has ``RAYON_NUM_THREADS`` threads, or one per usable CPU
(`glshade_threads`); Dr.Jit is given as many with ``drjit.set_thread_count``. JAX has no such
setting: XLA:CPU sizes its pool and splits its loops by the process's CPU affinity mask when
its backend starts (`jax_threads`; no XLA flag changes that in jaxlib 0.10.2). The bench does
not narrow the mask, which would bind glshade, numba and Dr.Jit too; it prints JAX's count
beside glshade's and says when they differ (run it under ``taskset -c 0-K`` for K + 1 of each).
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from dataclasses import dataclass
from importlib import metadata
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from .baselines import (
    ALPHA,
    AMBIENT,
    BASE,
    COS_CUTOFF,
    DIFFUSE,
    K0,
    K1,
    K2,
    SHININESS,
    SPECULAR,
    SPOT,
    SPOT_EXPONENT,
    VIEWER,
    W,
    constants,
    light_table,
)
from .machine import usable_cpus

__all__ = ["drjit_shade", "glshade_threads", "jax_shade", "jax_threads", "versions"]

F32 = NDArray[np.float32]
Shade = Callable[[F32, F32, gs.Scene], F32]


def glshade_threads() -> int:
    """glshade's thread pool in this process: ``RAYON_NUM_THREADS``, or one per usable CPU."""
    given = os.environ.get("RAYON_NUM_THREADS", "")
    if given.isdigit() and int(given) > 0:
        return int(given)
    return usable_cpus()


def jax_threads() -> int:
    """XLA:CPU's threads: the CPUs in this process's affinity mask when JAX's backend starts."""
    return usable_cpus()


def versions() -> dict[str, str]:
    """The installed versions of the compiled baselines and peers.

    Returns
    -------
    dict of str to str
        ``numba``, ``drjit``, ``jax``, ``jaxlib`` ("not installed" where missing), and
        ``drjit_llvm``, the libLLVM Dr.Jit loads, where its LLVM backend is available.
    """
    found = {}
    for name in ("numba", "drjit", "jax", "jaxlib"):
        try:
            found[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            found[name] = "not installed"
    try:
        import drjit as dr

        if dr.has_backend(dr.JitBackend.LLVM):
            found["drjit_llvm"] = ".".join(map(str, dr.detail.llvm_version()))
    except ImportError:
        pass
    return found


@dataclass(frozen=True)
class _Light:
    """One row of `light_table` as Python floats, and what decides its code path.

    Attributes
    ----------
    row : tuple of float
        The row (float32 values, exact as Python floats), columns as in `baselines`.
    halfway : tuple of float, optional
        The unit halfway vector where VP and the view direction are both constant (a directional
        light and an infinite viewer), in float32; None where it varies per vertex.
    """

    row: tuple[float, ...]
    halfway: tuple[float, float, float] | None

    @property
    def positional(self) -> bool:
        return self.row[W] != 0

    @property
    def spot(self) -> bool:
        return self.row[COS_CUTOFF] > -2

    @property
    def attenuated(self) -> bool:
        """Not 1 / (1 + 0 d + 0 d²): a weight to compute."""
        return self.positional and (self.row[K0], self.row[K1], self.row[K2]) != (1, 0, 0)

    @property
    def kind(self) -> tuple[bool, bool, bool, bool]:
        """positional, spot, attenuated, constant halfway: JAX's static structure."""
        return self.positional, self.spot, self.attenuated, self.halfway is not None


def _lights(scene: gs.Scene) -> tuple[list[_Light], NDArray[np.float32]]:
    """The scene's lights (`_Light`) and `constants` (float32, the columns of `baselines`)."""
    table, k = light_table(scene), constants(scene)
    eye = k[VIEWER : VIEWER + 4]
    lights = []
    for row in table:
        halfway = None
        if row[W] == 0 and eye[3] == 0:
            h = row[:3] + eye[:3] / np.sqrt((eye[:3] ** 2).sum())
            u = h / np.sqrt((h**2).sum())
            halfway = (float(u[0]), float(u[1]), float(u[2]))
        lights.append(_Light(tuple(float(x) for x in row), halfway))
    return lights, k


def drjit_shade(threads: int | None = None) -> Shade | str:
    """Dr.Jit's LLVM backend: ``shade(positions, normals, scene)`` -> (n, 4) float32, or why
    it is not available.

    Parameters
    ----------
    threads : int, optional
        Dr.Jit's thread count (``drjit.set_thread_count``, for the whole process); default:
        glshade's (`glshade_threads`).

    Returns
    -------
    callable or str
        The peer, or the reason there is none (Dr.Jit not installed, no libLLVM).
    """
    try:
        import drjit as dr
        import drjit.llvm
    except ImportError as error:
        return f"Dr.Jit is not installed ({error}; pip install 'glshade[bench]'): no Dr.Jit peer"
    if not dr.has_backend(dr.JitBackend.LLVM):
        return "Dr.Jit found no libLLVM (>= 15; DRJIT_LIBLLVM_PATH): no Dr.Jit peer"
    dr.set_thread_count(threads or glshade_threads())
    # Below LLVM 19, dr.maximum, minimum and clip abort the process in x86 instruction selection.
    select_only = tuple(dr.detail.llvm_version()) < (19,)
    llvm: Any = drjit.llvm

    def max0(x: Any) -> Any:
        return dr.select(x > 0.0, x, 0.0) if select_only else dr.maximum(x, 0.0)

    def clamp(x: Any) -> Any:
        return (
            dr.select(x > 0.0, dr.select(x < 1.0, x, 1.0), 0.0)
            if select_only
            else dr.clip(x, 0.0, 1.0)
        )

    def shade(positions: F32, normals: F32, scene: gs.Scene) -> F32:
        n = len(positions)
        # Float(ndarray) maps the numpy memory on the LLVM backend: no copy in.
        p_flat = llvm.Float(np.ascontiguousarray(positions, np.float32).reshape(-1))
        n_flat = llvm.Float(np.ascontiguousarray(normals, np.float32).reshape(-1))
        index = dr.arange(llvm.UInt32, n)
        p = dr.gather(llvm.Array3f, p_flat, index)
        normal = dr.gather(llvm.Array3f, n_flat, index)
        lights, k = _lights(scene)
        rgb = _drjit_lights(dr, llvm, p, normal, lights, k, max0)
        out = dr.empty(llvm.Float, 4 * n)
        alpha = float(np.clip(k[ALPHA], 0, 1))
        dr.scatter(out, llvm.Array4f(*(clamp(c) for c in rgb), alpha), index)
        dr.eval(out)  # one kernel: gather, lighting, scatter
        result: F32 = out.numpy().reshape(n, 4)  # a view of Dr.Jit's buffer
        return result

    return shade


def _drjit_lights(
    dr: Any, llvm: Any, p: Any, normal: Any, lights: list[_Light], k: F32, max0: Any
) -> list[Any]:
    """The traced sums (r, g, b) before the clamp, every scene number a kernel literal.

    Parameters
    ----------
    dr, llvm : module
        ``drjit`` and ``drjit.llvm``.
    p, normal : Array3f
        The gathered positions and normals, n each.
    lights : list of _Light
        The scene's lights.
    k : (9,) float32 ndarray
        `constants`.
    max0 : callable
        max(x, 0) as this LLVM compiles it.
    """
    eye = [float(x) for x in k[VIEWER : VIEWER + 4]]
    if eye[3] != 0:
        view = llvm.Array3f(eye[0] / eye[3], eye[1] / eye[3], eye[2] / eye[3]) - p
        view = view / dr.norm(view)
    else:
        view = llvm.Array3f(*eye[:3]) / float(np.sqrt(sum(e * e for e in eye[:3])))
    rgb = [llvm.Float(float(k[BASE + c])) for c in range(3)]
    shininess = float(k[SHININESS])
    for light in lights:
        row = light.row
        weight = None  # 1: no multiply
        if light.positional:
            to_light = llvm.Array3f(*row[:3]) - p
            d = dr.norm(to_light)
            vp = to_light / d
            if light.attenuated:
                weight = 1.0 / (row[K0] + row[K1] * d + row[K2] * d * d)
        else:
            vp = llvm.Array3f(*row[:3])
        if light.spot:
            c = max0(-dr.dot(vp, llvm.Array3f(*row[SPOT : SPOT + 3])))
            cone = dr.power(c, row[SPOT_EXPONENT])
            weight = dr.select(c >= row[COS_CUTOFF], cone if weight is None else weight * cone, 0.0)
        n_dot_vp = dr.dot(normal, vp)
        lit = n_dot_vp > 0.0
        if light.halfway is not None:
            n_dot_h = dr.dot(normal, llvm.Array3f(*light.halfway))
        else:
            h = vp + view
            n_dot_h = dr.dot(normal, h) / dr.norm(h)
        power = dr.power(max0(n_dot_h), shininess) if shininess != 0 else 1.0
        diffuse = dr.select(lit, n_dot_vp, 0.0)
        specular = dr.select(lit, power, 0.0)
        for c in range(3):
            term = diffuse * row[DIFFUSE + c] + specular * row[SPECULAR + c]
            if row[AMBIENT + c] != 0:
                term = term + row[AMBIENT + c]
            rgb[c] = rgb[c] + (term if weight is None else weight * term)
    return rgb


def jax_shade() -> Shade | str:
    """JAX on its CPU backend: ``shade(positions, normals, scene)`` -> (n, 4) float32 (a
    read-only view of XLA's buffer), or why it is not available.

    JAX compiles once per light structure (each light's kind, the viewer's) and input shape:
    new numbers reuse the compiled code. Every call hands the numpy inputs to XLA as a user's
    call does (a copy where XLA wants other alignment). Its threads follow the affinity mask
    (`jax_threads`; see the module's notes).

    Returns
    -------
    callable or str
        The peer, or the reason there is none (JAX not installed, not on the CPU).
    """
    # JAX picks its platform when it first starts: the bench compares CPUs.
    os.environ.setdefault("JAX_PLATFORMS", "cpu")
    try:
        import jax
        import jax.numpy as jnp
    except ImportError as error:
        return f"JAX is not installed ({error}; pip install 'glshade[bench]'): no JAX peer"
    if jax.default_backend() != "cpu":
        return f"JAX runs on {jax.default_backend()} (JAX_PLATFORMS=cpu for the CPU): no JAX peer"

    @functools.partial(jax.jit, static_argnames=("kinds", "local"))
    def colour(
        positions: Any, normals: Any, table: Any, halfway: Any, k: Any, *, kinds: Any, local: bool
    ) -> Any:
        return _jax_lights(jnp, positions, normals, table, halfway, k, kinds, local)

    # Stacking inside `colour` makes XLA fuse the lighting into the concatenation, which
    # evaluates it once per channel: a second loop that only interleaves is faster.
    @jax.jit
    def interleave(r: Any, g: Any, b: Any, alpha: Any) -> Any:
        return jnp.stack([r, g, b, jnp.broadcast_to(alpha, r.shape)], axis=1)

    def shade(positions: F32, normals: F32, scene: gs.Scene) -> F32:
        lights, k = _lights(scene)
        table = np.asarray([light.row for light in lights], np.float32)
        halfway = np.asarray([light.halfway or (0, 0, 0) for light in lights], np.float32)
        kinds = tuple(light.kind for light in lights)
        r, g, b = colour(
            positions, normals, table, halfway, k, kinds=kinds, local=bool(k[VIEWER + 3] != 0)
        )
        alpha = np.float32(np.clip(k[ALPHA], 0, 1))
        result: F32 = np.asarray(interleave(r, g, b, alpha))
        return result

    return shade


def _jax_lights(
    jnp: Any,
    positions: Any,
    normals: Any,
    table: Any,
    halfway: Any,
    k: Any,
    kinds: tuple[tuple[bool, bool, bool, bool], ...],
    local: bool,
) -> tuple[Any, Any, Any]:
    """The clamped (r, g, b) columns, traced: the lights unrolled, their kinds static.

    Parameters
    ----------
    jnp : module
        ``jax.numpy``.
    positions, normals : (n, 3) float32 arrays
        The vertices.
    table : (lights, 21) float32 array
        `light_table`.
    halfway : (lights, 3) float32 array
        Each light's constant unit halfway vector (zeros where it varies).
    k : (9,) float32 array
        `constants`.
    kinds : tuple of (bool, bool, bool, bool)
        Per light: positional, spot, attenuated, constant halfway (`_Light.kind`).
    local : bool
        Whether the viewer is local (w != 0).
    """
    px, py, pz = positions[:, 0], positions[:, 1], positions[:, 2]
    nx, ny, nz = normals[:, 0], normals[:, 1], normals[:, 2]
    eye = k[VIEWER : VIEWER + 4]
    if local:
        vx, vy, vz = eye[0] / eye[3] - px, eye[1] / eye[3] - py, eye[2] / eye[3] - pz
    else:
        vx, vy, vz = eye[0], eye[1], eye[2]
    length = jnp.sqrt(vx * vx + vy * vy + vz * vz)
    vx, vy, vz = vx / length, vy / length, vz / length
    rgb = [jnp.full(px.shape, k[BASE + c], jnp.float32) for c in range(3)]
    for row, hat, (positional, spot, attenuated, constant_halfway) in zip(
        table, halfway, kinds, strict=True
    ):
        weight: Any = None  # 1: no multiply
        if positional:
            lx, ly, lz = row[0] - px, row[1] - py, row[2] - pz
            d = jnp.sqrt(lx * lx + ly * ly + lz * lz)
            lx, ly, lz = lx / d, ly / d, lz / d
            if attenuated:
                weight = 1 / (row[K0] + row[K1] * d + row[K2] * d * d)
        else:
            lx, ly, lz = row[0], row[1], row[2]
        if spot:
            c = jnp.maximum(-(lx * row[SPOT] + ly * row[SPOT + 1] + lz * row[SPOT + 2]), 0)
            cone = c ** row[SPOT_EXPONENT]
            weight = jnp.where(c >= row[COS_CUTOFF], cone if weight is None else weight * cone, 0)
        n_dot_vp = nx * lx + ny * ly + nz * lz
        lit = n_dot_vp > 0
        if constant_halfway:
            n_dot_h = nx * hat[0] + ny * hat[1] + nz * hat[2]
        else:
            hx, hy, hz = lx + vx, ly + vy, lz + vz
            n_dot_h = (nx * hx + ny * hy + nz * hz) / jnp.sqrt(hx * hx + hy * hy + hz * hz)
        diffuse = jnp.where(lit, n_dot_vp, 0)
        specular = jnp.where(lit, jnp.maximum(n_dot_h, 0) ** k[SHININESS], 0)
        for c in range(3):
            term = row[AMBIENT + c] + diffuse * row[DIFFUSE + c] + specular * row[SPECULAR + c]
            rgb[c] = rgb[c] + (term if weight is None else weight * term)
    r, g, b = (jnp.clip(c, 0, 1) for c in rgb)
    return r, g, b
