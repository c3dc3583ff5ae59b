"""A C loop, the peer of ``python -m glshade bench shade`` that a C programmer writes for speed:
the equation `baselines.numba_shade` computes (float32; Blinn, GL's specular gate, attenuation,
a spot cone with cutoff and exponent, emission + ambient base, one side, one final clamp to
[0, 1], RGBA with the material's diffuse alpha), with the lights read from the same table
(`baselines.light_table`). An OpenMP ``parallel for`` over tiles of 256 vertices; in each tile
one ``omp simd`` loop over the vertices per light, specialised by the light's kind, summing
into the tile's colours. Compiled with ``gcc -O3 -march=native -ffast-math -fopenmp`` (``CC``
names another compiler) when the bench starts: ``-ffast-math`` lets gcc vectorise with
glibc's vector ``powf`` and its reciprocal square roots, which is what such a loop is written
for.

The table's columns reach the C source as macros from `baselines`, so the two cannot drift
apart; the loop reads numpy's memory through ctypes and writes a fresh (n, 4) array.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import shutil
import subprocess
import tempfile
from collections.abc import Callable
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from . import baselines
from .baselines import constants, light_table

__all__ = ["FLAGS", "OPTIONS", "SOURCE", "c_shade", "compiler_version"]

F32 = NDArray[np.float32]
Shade = Callable[[F32, F32, gs.Scene], F32]

#: The options that make the loop fast, as the bench reports them.
OPTIONS = ("-O3", "-march=native", "-ffast-math", "-fopenmp")
FLAGS = (*OPTIONS, "-shared", "-fPIC")
# After the source: glibc's vector powf is in libmvec, which -lm brings in.
LIBRARIES = ("-lm",)

#: The loop: `baselines.numba_shade`'s equation in C, in tiles of vertices with the light loop
#: outside the vertex loop, so gcc vectorises each light's loop (a loop over lights inside
#: the loop over vertices, as numba's, gcc 12 leaves scalar: "loop nest containing two or more
#: consecutive inner loops cannot be vectorized").
SOURCE = r"""
#include <math.h>
#include <omp.h>

#define TILE 256

void set_threads(int threads) { omp_set_num_threads(threads); }

static inline float clamp01(float x) { return fminf(fmaxf(x, 0.0f), 1.0f); }

/* One light over one tile of vertices: `positional` and `spot` are constants at each call, so
   the compiler makes one branch-free vector loop of each kind. */
static inline void light(const float *restrict row, int positional, int spot, float s, long m,
                         const float *restrict px, const float *restrict py,
                         const float *restrict pz, const float *restrict nx,
                         const float *restrict ny, const float *restrict nz,
                         const float *restrict vx, const float *restrict vy,
                         const float *restrict vz, float *restrict r, float *restrict g,
                         float *restrict b) {
#pragma omp simd
    for (long i = 0; i < m; i++) {
        float lx = row[0], ly = row[1], lz = row[2], weight = 1.0f;
        if (positional) {
            lx -= px[i]; ly -= py[i]; lz -= pz[i];
            const float d = sqrtf(lx * lx + ly * ly + lz * lz);
            lx /= d; ly /= d; lz /= d;
            weight = 1.0f / (row[K0] + row[K1] * d + row[K2] * d * d);
        }
        if (spot) {
            const float cos = lx * row[SPOT] + ly * row[SPOT + 1] + lz * row[SPOT + 2];
            const float c = fmaxf(-cos, 0.0f);
            weight *= c >= row[COS_CUTOFF] ? powf(c, row[SPOT_EXPONENT]) : 0.0f;
        }
        float red = weight * row[AMBIENT], green = weight * row[AMBIENT + 1];
        float blue = weight * row[AMBIENT + 2];
        const float n_dot_vp = nx[i] * lx + ny[i] * ly + nz[i] * lz;
        const float hx = lx + vx[i], hy = ly + vy[i], hz = lz + vz[i];
        const float h = sqrtf(hx * hx + hy * hy + hz * hz);
        const float n_dot_h = fmaxf((nx[i] * hx + ny[i] * hy + nz[i] * hz) / h, 0.0f);
        const float power = s != 0.0f ? powf(n_dot_h, s) : 1.0f;
        const float diffuse = n_dot_vp > 0.0f ? weight * n_dot_vp : 0.0f;
        const float specular = n_dot_vp > 0.0f ? weight * power : 0.0f;
        red += diffuse * row[DIFFUSE] + specular * row[SPECULAR];
        green += diffuse * row[DIFFUSE + 1] + specular * row[SPECULAR + 1];
        blue += diffuse * row[DIFFUSE + 2] + specular * row[SPECULAR + 2];
        r[i] += red; g[i] += green; b[i] += blue;
    }
}

void shade(const float *restrict p, const float *restrict n, long count,
           const float *restrict table, long lights, const float *restrict k,
           float *restrict out) {
    const float alpha = clamp01(k[ALPHA]), s = k[SHININESS];
#pragma omp parallel for schedule(static)
    for (long start = 0; start < count; start += TILE) {
        const long m = count - start < TILE ? count - start : TILE;
        float px[TILE], py[TILE], pz[TILE], nx[TILE], ny[TILE], nz[TILE];
        float vx[TILE], vy[TILE], vz[TILE], r[TILE], g[TILE], b[TILE];
#pragma omp simd
        for (long i = 0; i < m; i++) {
            const long v = start + i;
            px[i] = p[3 * v]; py[i] = p[3 * v + 1]; pz[i] = p[3 * v + 2];
            nx[i] = n[3 * v]; ny[i] = n[3 * v + 1]; nz[i] = n[3 * v + 2];
            float x = k[VIEWER], y = k[VIEWER + 1], z = k[VIEWER + 2];
            if (k[VIEWER + 3] != 0.0f) {
                x = x / k[VIEWER + 3] - px[i];
                y = y / k[VIEWER + 3] - py[i];
                z = z / k[VIEWER + 3] - pz[i];
            }
            const float length = sqrtf(x * x + y * y + z * z);
            vx[i] = x / length; vy[i] = y / length; vz[i] = z / length;
            r[i] = k[BASE]; g[i] = k[BASE + 1]; b[i] = k[BASE + 2];
        }
        for (long j = 0; j < lights; j++) {
            const float *row = table + j * COLUMNS;
            const int positional = row[W] != 0.0f, spot = row[COS_CUTOFF] > -2.0f;
            if (positional && spot)
                light(row, 1, 1, s, m, px, py, pz, nx, ny, nz, vx, vy, vz, r, g, b);
            else if (positional)
                light(row, 1, 0, s, m, px, py, pz, nx, ny, nz, vx, vy, vz, r, g, b);
            else if (spot)
                light(row, 0, 1, s, m, px, py, pz, nx, ny, nz, vx, vy, vz, r, g, b);
            else
                light(row, 0, 0, s, m, px, py, pz, nx, ny, nz, vx, vy, vz, r, g, b);
        }
#pragma omp simd
        for (long i = 0; i < m; i++) {
            const long v = start + i;
            out[4 * v] = clamp01(r[i]); out[4 * v + 1] = clamp01(g[i]);
            out[4 * v + 2] = clamp01(b[i]); out[4 * v + 3] = alpha;
        }
    }
}
"""

#: The columns of `baselines.light_table` and `baselines.constants` the loop reads.
_COLUMNS = (
    "W AMBIENT DIFFUSE SPECULAR SPOT SPOT_EXPONENT COS_CUTOFF K0 K1 K2 BASE ALPHA SHININESS VIEWER"
)


def _compiler() -> str | None:
    """The C compiler: ``$CC``, else gcc, else cc."""
    return os.environ.get("CC") or shutil.which("gcc") or shutil.which("cc")


def compiler_version() -> str:
    """The first line of the compiler's ``--version`` ("gcc (Debian 14.2.0-19) 14.2.0")."""
    compiler = _compiler()
    if compiler is None:
        return "none"
    found = subprocess.run([compiler, "--version"], capture_output=True, text=True, check=False)
    return found.stdout.splitlines()[0] if found.stdout else compiler


def _compile(compiler: str) -> Path:
    """The loop built as a shared library (cached by its source, flags and compiler)."""
    defines = [f"-D{name}={getattr(baselines, name)}" for name in _COLUMNS.split()]
    defines.append(f"-DCOLUMNS={baselines.K2 + 1}")
    parts = [SOURCE, compiler, *FLAGS, *defines, *LIBRARIES]
    key = hashlib.sha256("\n".join(parts).encode()).hexdigest()
    library = Path(tempfile.gettempdir()) / f"glshade-c-loop-{key[:16]}.so"
    if not library.exists():
        with tempfile.TemporaryDirectory() as work:
            source = Path(work) / "shade.c"
            source.write_text(SOURCE)
            built = Path(work) / "shade.so"
            command = [compiler, *FLAGS, *defines, str(source), "-o", str(built), *LIBRARIES]
            subprocess.run(command, check=True, capture_output=True, text=True)
            shutil.move(built, library)
    return library


def c_shade(threads: int) -> Shade | str:
    """The C loop: ``shade(positions, normals, scene)`` -> (n, 4) float32, or why there is none.

    Parameters
    ----------
    threads : int
        OpenMP's thread count for the loop (glshade's, so both run as many).

    Returns
    -------
    callable or str
        The peer, or the reason there is none (no C compiler, or it failed).
    """
    compiler = _compiler()
    if compiler is None:
        return "no C compiler (gcc, cc or $CC): no C loop"
    try:
        library = ctypes.CDLL(str(_compile(compiler)))
    except subprocess.CalledProcessError as error:
        return f"{compiler} failed on the C loop ({error.stderr.strip()[-300:]}): no C loop"
    library.set_threads(ctypes.c_int(threads))
    pointer = ctypes.POINTER(ctypes.c_float)
    library.shade.argtypes = [
        pointer,
        pointer,
        ctypes.c_long,
        pointer,
        ctypes.c_long,
        pointer,
        pointer,
    ]
    library.shade.restype = None

    def address(a: F32) -> ctypes._Pointer[ctypes.c_float]:
        return a.ctypes.data_as(pointer)

    def shade(positions: F32, normals: F32, scene: gs.Scene) -> F32:
        p = np.ascontiguousarray(positions, np.float32)
        n = np.ascontiguousarray(normals, np.float32)
        table = np.ascontiguousarray(light_table(scene), np.float32)
        k = np.ascontiguousarray(constants(scene), np.float32)
        out = np.zeros((len(p), 4), np.float32)
        arrays = address(p), address(n), len(p), address(table), len(table), address(k)
        library.shade(*arrays, address(out))
        return out

    return shade
