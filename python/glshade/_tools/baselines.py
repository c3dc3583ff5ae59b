"""``python -m glshade bench shade``: `gs.shade` beside numpy and numba implementations of the
same equation, timed in the same run.

The baselines are what a user writes today: the GL equation in float32 with a new RGBA array
per call, numpy vectorised over vertices with a Python loop over lights, and numba compiled
with ``parallel=True`` (a ``prange`` over vertices, all cores). Both precompute the per-light
colour products and normalise directional lights once, as glshade does; the tests check that
both agree with `gs.shade`.
"""

from __future__ import annotations

import functools
import os
import statistics
import time
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from ._bench import in_rounds

F32 = NDArray[np.float32]
SIZES = (10_000, 100_000, 1_000_000, 4_000_000)


def bench_scenes() -> dict[str, gs.Scene]:
    """The three scenes of the benchmark: one directional light (infinite viewer), one point
    light with a local viewer, and eight mixed lights (directional, attenuated point, spot),
    all with a Blinn-Phong specular term of shininess 32."""
    material = gs.Material(specular=(0.5, 0.5, 0.5, 1.0), shininess=32.0)
    grey = (0.3, 0.3, 0.3, 1.0)
    mixed = [
        gs.Light(position=(0.3, 0.5, 1.0, 0.0)),
        gs.Light(position=(-1.0, 0.5, 1.0, 0.0), diffuse=grey, specular=grey),
        gs.Light(position=(0.0, 3.0, 0.5, 0.0), diffuse=grey, specular=grey),
        gs.Light(position=(1.0, 2.0, 3.0, 1.0), linear_attenuation=0.1, diffuse=grey),
        gs.Light(position=(-2.0, 1.0, 3.0, 1.0), quadratic_attenuation=0.05, diffuse=grey),
        gs.Light(position=(2.0, -1.0, 3.0, 1.0), linear_attenuation=0.2, quadratic_attenuation=0.1),
        gs.Light(
            position=(0.0, 0.0, 4.0, 1.0),
            spot_direction=(0.0, 0.0, -1.0),
            spot_cutoff=30.0,
            spot_exponent=8.0,
        ),
        gs.Light(
            position=(1.0, 1.0, 4.0, 1.0),
            spot_direction=(-0.2, -0.2, -1.0),
            spot_cutoff=45.0,
            spot_exponent=2.0,
            linear_attenuation=0.1,
            ambient=(0.05, 0.05, 0.05, 1.0),
        ),
    ]
    return {
        "1 directional": gs.Scene([gs.Light(position=(0.3, 0.5, 1.0, 0.0))], material=material),
        "1 point, local viewer": gs.Scene(
            [gs.Light(position=(1.0, 2.0, 3.0, 1.0))], material=material, viewer=(0, 0, 0, 1)
        ),
        "8 mixed": gs.Scene(mixed, material=material, viewer=(0, 0, 0, 1)),
    }


def bench_vertices(n: int, seed: int = 0) -> tuple[F32, F32]:
    """`n` float32 positions in front of the eye and unit normals facing it, at random."""
    rng = np.random.default_rng(seed)
    positions = rng.uniform((-1.0, -1.0, -4.0), (1.0, 1.0, -2.0), (n, 3)).astype(np.float32)
    normals = rng.normal(size=(n, 3)) + np.array([0.0, 0.0, 1.5])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    return positions, normals.astype(np.float32)


def _light_table(scene: gs.Scene, dtype: Any = np.float32) -> NDArray[Any]:
    """One row per light, computed in float64 and rounded to `dtype`: position xyz w
    (directional ones normalised), the products a_cm·a_cl, d_cm·d_cl, s_cm·s_cl (RGB), the
    unit spot direction, spot exponent, cos cutoff (-2 for no cone), k0, k1, k2."""
    lights, m = scene.lights, scene.material
    position = lights.position.copy()
    directional = position[:, 3] == 0
    position[directional, :3] /= np.linalg.norm(position[directional, :3], axis=1, keepdims=True)
    position[~directional, :3] /= position[~directional, 3:]
    spot = lights.spot_direction / np.linalg.norm(lights.spot_direction, axis=1, keepdims=True)
    cutoff = lights.spot_cutoff
    cos_cutoff = np.where(cutoff == 180.0, -2.0, np.cos(np.radians(cutoff)))
    table = np.column_stack(
        [
            position,
            lights.ambient[:, :3] * m.ambient[:3],
            lights.diffuse[:, :3] * m.diffuse[:3],
            lights.specular[:, :3] * m.specular[:3],
            spot,
            lights.spot_exponent,
            cos_cutoff,
            lights.constant_attenuation,
            lights.linear_attenuation,
            lights.quadratic_attenuation,
        ]
    )
    return table.astype(dtype)


def _constants(scene: gs.Scene, dtype: Any = np.float32) -> NDArray[Any]:
    """emission + a_cm·a_cs (RGB), the diffuse alpha, the shininess, the viewer (xyzw)."""
    m = scene.material
    base = m.emission[:3] + m.ambient[:3] * scene.global_ambient[:3]
    return np.concatenate([base, [m.diffuse[3], m.shininess], scene.viewer]).astype(dtype)


def naive_power(normals: NDArray[Any], h: NDArray[Any], s: Any) -> NDArray[Any]:
    """max(n . h, 0)^s, as a shader writes it."""
    power: NDArray[Any] = np.maximum(np.einsum("ij,ij->i", normals, h), 0)[:, None] ** s
    return power


def numpy_shade(
    positions: NDArray[Any],
    normals: NDArray[Any],
    scene: gs.Scene,
    power: Callable[[NDArray[Any], NDArray[Any], Any], Any] = naive_power,
) -> NDArray[Any]:
    """The GL equation (Blinn, GL's specular gate, no two-sided lighting) in numpy, in the
    dtype of `positions` (float32 for the benchmark), with `power(n, h, s)` the specular
    power for s > 0."""
    dtype = positions.dtype
    table, k = _light_table(scene, dtype), _constants(scene, dtype)
    local = k[8] != 0
    if local:
        view = k[5:8] - positions
        view /= np.linalg.norm(view, axis=1, keepdims=True)
    else:
        view = np.broadcast_to(k[5:8] / np.linalg.norm(k[5:8]), positions.shape)
    rgb = np.broadcast_to(k[:3], positions.shape).copy()
    for row in table:
        if row[3] == 0:
            vp = np.broadcast_to(row[:3], positions.shape)
            weight = dtype.type(1.0)
        else:
            vp = row[:3] - positions
            d = np.linalg.norm(vp, axis=1, keepdims=True)
            vp = vp / d
            weight = 1 / (row[18] + row[19] * d + row[20] * d * d)
            if row[17] > -2:
                c = -(vp @ row[13:16])[:, None]
                weight = weight * np.where(c >= row[17], np.maximum(c, 0) ** row[16], 0)
        rgb += weight * row[4:7]
        n_dot_vp = np.einsum("ij,ij->i", normals, vp)[:, None]
        lit = n_dot_vp > 0
        rgb += np.where(lit, weight * n_dot_vp, 0) * row[7:10]
        h = vp + view
        h /= np.linalg.norm(h, axis=1, keepdims=True)
        specular = power(normals, h, k[4]) if k[4] != 0 else dtype.type(1.0)
        rgb += np.where(lit, weight * specular, 0) * row[10:13]
    out = np.zeros((len(positions), 4), dtype)
    out[:, :3] = np.clip(rgb, 0, 1)
    out[:, 3] = np.clip(k[3], 0, 1)
    return out


def numba_shade() -> Callable[[F32, F32, gs.Scene], F32] | str:
    """The same equation as `numpy_shade`, compiled by numba with ``parallel=True``, float32
    throughout; or why numba is not available."""
    # numba's OpenMP threads spin after each parallel loop unless told to sleep, and on a
    # machine with few cores they would take them from whichever method runs next.
    os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    try:
        import numba
    except ImportError:
        return "numba is not installed (pip install numba): no numba baseline"

    @numba.njit(parallel=True, fastmath=False, cache=False)
    def kernel(p: F32, n: F32, table: F32, k: F32, out: F32) -> None:  # pragma: no cover
        zero, one = np.float32(0.0), np.float32(1.0)
        for i in numba.prange(len(p)):
            px, py, pz = p[i, 0], p[i, 1], p[i, 2]
            nx, ny, nz = n[i, 0], n[i, 1], n[i, 2]
            vx, vy, vz = k[5], k[6], k[7]
            if k[8] != zero:
                vx, vy, vz = vx - px, vy - py, vz - pz
            length = np.sqrt(vx * vx + vy * vy + vz * vz)
            vx, vy, vz = vx / length, vy / length, vz / length
            r, g, b = k[0], k[1], k[2]
            for j in range(len(table)):
                row = table[j]
                lx, ly, lz = row[0], row[1], row[2]
                weight = one
                if row[3] != zero:
                    lx, ly, lz = lx - px, ly - py, lz - pz
                    d = np.sqrt(lx * lx + ly * ly + lz * lz)
                    lx, ly, lz = lx / d, ly / d, lz / d
                    weight = one / (row[18] + row[19] * d + row[20] * d * d)
                    if row[17] > np.float32(-2.0):
                        c = -(lx * row[13] + ly * row[14] + lz * row[15])
                        weight = weight * (max(c, zero) ** row[16] if c >= row[17] else zero)
                r += weight * row[4]
                g += weight * row[5]
                b += weight * row[6]
                n_dot_vp = nx * lx + ny * ly + nz * lz
                if n_dot_vp > zero:
                    diffuse = weight * n_dot_vp
                    r += diffuse * row[7]
                    g += diffuse * row[8]
                    b += diffuse * row[9]
                    hx, hy, hz = lx + vx, ly + vy, lz + vz
                    length = np.sqrt(hx * hx + hy * hy + hz * hz)
                    n_dot_h = max((nx * hx + ny * hy + nz * hz) / length, zero)
                    power = n_dot_h ** k[4] if k[4] != zero else one
                    specular = weight * power
                    r += specular * row[10]
                    g += specular * row[11]
                    b += specular * row[12]
            out[i, 0] = min(max(r, zero), one)
            out[i, 1] = min(max(g, zero), one)
            out[i, 2] = min(max(b, zero), one)
            out[i, 3] = min(max(k[3], zero), one)

    def shade(positions: F32, normals: F32, scene: gs.Scene) -> F32:
        out = np.zeros((len(positions), 4), np.float32)
        kernel(positions, normals, _light_table(scene), _constants(scene), out)
        return out

    return shade


def call_overhead(repeat: int = 2000) -> float:
    """Median seconds of `gs.shade` on 16 float32 vertices and one directional light."""
    scene = gs.Scene([gs.Light()])
    p, n = bench_vertices(16)
    for _ in range(100):
        gs.shade(p, n, scene)
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        gs.shade(p, n, scene)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


BURST = 3


def wake_cost(n: int = 1_000_000, repeat: int = 7) -> tuple[float, float]:
    """Median seconds of `gs.shade` (one directional light, `n` vertices) right after 50 ms of
    idle, and back to back."""
    scene = bench_scenes()["1 directional"]
    p, normals = bench_vertices(n)
    cold: list[float] = []
    warm: list[float] = []
    for _ in range(repeat):
        time.sleep(0.05)
        for times in (cold, warm):
            start = time.perf_counter()
            gs.shade(p, normals, scene)
            times.append(time.perf_counter() - start)
    return statistics.median(cold), statistics.median(warm)


def bench_shade(sizes: tuple[int, ...], repeat: int) -> int:
    """Prints, for every scene and size, the median million vertices per second of glshade,
    numpy and numba, and glshade's speed-up over each (the median of per-round ratios)."""
    numba = numba_shade()
    threads = os.environ.get("RAYON_NUM_THREADS") or f"{os.cpu_count()} (all cores)"
    print(
        f"float32, a new (n, 4) array per call; {repeat} rounds; in each round every method "
        f"runs {BURST} times in a row and its fastest call counts"
    )
    print(f"glshade threads: {threads}; numpy {np.__version__}", end="")
    if isinstance(numba, str):
        print(f"\n{numba}")
    else:
        import numba as nb

        # Compiles the kernel and starts the threading layer, which is named only after that.
        numba(*bench_vertices(64), bench_scenes()["1 directional"])
        layer = nb.threading_layer()  # type: ignore[attr-defined]
        print(
            f"; numba {nb.__version__} (parallel=True, {nb.get_num_threads()} threads, "
            f"{layer} layer, OMP_WAIT_POLICY={os.environ['OMP_WAIT_POLICY']})"
        )
    print(f"per-call overhead: {call_overhead() * 1e6:.1f} us (16 vertices, one light, median)")
    cold, warm = wake_cost()
    print(
        f"waking idle cores: {cold * 1e3:.2f} ms for the first call after 50 ms of idle, "
        f"{warm * 1e3:.2f} ms for the next (10^6 vertices, one light, medians)"
    )
    for name, scene in bench_scenes().items():
        print(f"\n{name}: {scene.plan()}")
        print(
            f"  {'vertices':>10} {'glshade':>9} {'numpy':>9} {'numba':>9}"
            f"   {'x numpy':>8} {'x numba':>8}   (million vertices/s, medians)"
        )
        for n in sizes:
            p, normals = bench_vertices(n)
            methods: dict[str, Callable[[], Any]] = {
                "glshade": functools.partial(gs.shade, p, normals, scene),
                "numpy": functools.partial(numpy_shade, p, normals, scene),
            }
            if not isinstance(numba, str):
                methods["numba"] = functools.partial(numba, p, normals, scene)
            times = in_rounds(methods, repeat, settle=0.0, burst=BURST)
            rate = {k: n / statistics.median(t) / 1e6 for k, t in times.items()}

            def ratio(baseline: str, times: dict[str, list[float]] = times) -> str:
                if baseline not in times:
                    return f"{'-':>8}"
                pairs = zip(times[baseline], times["glshade"], strict=True)
                return f"{statistics.median(b / o for b, o in pairs):7.1f}x"

            print(
                f"  {n:>10,} {rate['glshade']:9.1f} {rate['numpy']:9.1f} "
                f"{rate.get('numba', float('nan')):9.1f}   {ratio('numpy')} {ratio('numba')}"
            )
    return 0
