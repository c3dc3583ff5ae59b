"""The world models as their users would write them, for ``bench shade``: pyrender's mesh.frag
(glTF metallic-roughness) and three.js r111's meshphong_frag (`MeshPhongMaterial`) in Dr.Jit
(traced per call, every scene number a literal, one kernel) and numba (one compiled loop over
vertices and a table of lights), float32 throughout, clamped to [0, 1] as `gs.shade` clamps.

They take the lights the bench's world scenes hold (directional, point and spot; an ambient
light) and raise `NotImplementedError` for any other, so a scene they do not cover is FAILED,
never mistimed.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

import glshade as gs

from .peers import glshade_threads

__all__ = ["drjit_world", "numba_world"]

F32 = NDArray[np.float32]
WorldScene = gs.gltf.Scene | gs.threejs.Scene
Shade = Callable[[F32, F32, WorldScene], F32]

# A light as the numba kernels read it: kind, then three triples and three numbers.
KIND, POSITION, AXIS, RADIANCE, A, B, C = 0, 1, 4, 7, 10, 11, 12
DIRECTIONAL, POINT, SPOT = 0.0, 1.0, 2.0
ROW = 13


def _unit(v: Any) -> NDArray[np.float64]:
    v = np.asarray(v, np.float64)
    return np.asarray(v / np.linalg.norm(v))


def _gltf_material(scene: gs.gltf.Scene) -> dict[str, Any]:
    """pyrender's material constants: f0, c_diff, k, a², the constant term and alpha."""
    m = scene.material
    r = min(max(m.roughness, 0.04), 1.0)
    metallic = min(max(m.metallic, 0.0), 1.0)
    base = np.array(m.base_color, np.float64)
    return {
        "f0": 0.04 * (1 - metallic) + base[:3] * metallic,
        "c_diff": base[:3] * 0.96 * (1 - metallic),
        "k": (r + 1) ** 2 / 8,
        "a2": r**4,
        "constant": base[:3] * np.array(scene.ambient_light) + np.array(m.emissive),
        "alpha": float(base[3]),
    }


def _gltf_lights(scene: gs.gltf.Scene) -> NDArray[np.float32]:
    """(lights, ROW) float32: each light's kind, to-light direction or position, spot axis,
    colour x intensity and the cone's scale and offset (pyrender's ``light_angle_scale``)."""
    rows = []
    for light in scene.lights:
        row = np.zeros(ROW)
        row[RADIANCE : RADIANCE + 3] = np.array(light.color) * light.intensity
        if isinstance(light, gs.gltf.DirectionalLight):
            row[KIND], row[POSITION : POSITION + 3] = DIRECTIONAL, -_unit(light.direction)
        elif isinstance(light, gs.gltf.PointLight):
            row[KIND], row[POSITION : POSITION + 3] = POINT, light.position
        elif isinstance(light, gs.gltf.SpotLight):
            row[KIND], row[POSITION : POSITION + 3] = SPOT, light.position
            row[AXIS : AXIS + 3] = _unit(light.direction)
            cos_inner, cos_outer = (
                math.cos(light.inner_cone_angle),
                math.cos(light.outer_cone_angle),
            )
            row[A] = 1 / max(0.001, cos_inner - cos_outer)
            row[B] = -cos_outer * row[A]
        else:
            raise NotImplementedError(f"no peer for {type(light).__name__}")
        rows.append(row)
    return np.array(rows, np.float32).reshape(-1, ROW)


def _threejs_lights(scene: gs.threejs.Scene) -> tuple[NDArray[np.float32], NDArray[np.float64]]:
    """(lights, ROW) float32 — kind, position or direction, spot axis, colour x intensity (xπ
    for legacy lights), the spot's cos(angle) and cos(angle·(1 - penumbra)), the decay — and
    the ambient irradiance. Unlimited distances only (``distance`` 0)."""
    t = gs.threejs
    scale = 1.0 if scene.physically_correct_lights else math.pi
    rows, ambient = [], np.zeros(3)
    for light in scene.lights:
        if isinstance(light, t.AmbientLight):
            ambient += np.array(light.color) * light.intensity * scale
            continue
        if not isinstance(light, (t.DirectionalLight, t.PointLight, t.SpotLight)):
            raise NotImplementedError(f"no peer for {light!r}")
        row = np.zeros(ROW)
        row[RADIANCE : RADIANCE + 3] = np.array(light.color) * light.intensity * scale
        if isinstance(light, t.DirectionalLight):
            row[KIND] = DIRECTIONAL
            row[POSITION : POSITION + 3] = _unit(np.subtract(light.position, light.target))
        elif isinstance(light, (t.PointLight, t.SpotLight)) and light.distance == 0:
            row[KIND], row[POSITION : POSITION + 3], row[C] = POINT, light.position, light.decay
            if isinstance(light, t.SpotLight):
                row[KIND] = SPOT
                row[AXIS : AXIS + 3] = _unit(np.subtract(light.position, light.target))
                row[A] = math.cos(light.angle)
                row[B] = math.cos(light.angle * (1 - light.penumbra))
        else:
            raise NotImplementedError(f"no peer for {light!r}")
        rows.append(row)
    return np.array(rows, np.float32).reshape(-1, ROW), ambient


def _view(scene: gs.threejs.Scene) -> tuple[bool, NDArray[np.float64]]:
    """(perspective, the camera's position or the unit view direction)."""
    if scene.view_direction is None:
        return True, np.asarray(scene.camera_position, np.float64)
    return False, _unit(scene.view_direction)


def _floats(row: Any) -> list[float]:
    """Python floats, which Dr.Jit takes as literals (it refuses numpy's scalars)."""
    return [float(x) for x in row]


def drjit_world() -> Shade | str:
    """Dr.Jit's LLVM backend: ``shade(positions, normals, scene)`` -> (n, 4) float32 for a
    glTF or three.js scene, or why it is not available."""
    try:
        import drjit as dr
        import drjit.llvm
    except ImportError as error:
        return f"Dr.Jit is not installed ({error}; pip install 'glshade[bench]'): no Dr.Jit peer"
    if not dr.has_backend(dr.JitBackend.LLVM):
        return "Dr.Jit found no libLLVM (>= 15; DRJIT_LIBLLVM_PATH): no Dr.Jit peer"
    dr.set_thread_count(glshade_threads())
    llvm: Any = drjit.llvm

    def shade(positions: F32, normals: F32, scene: WorldScene) -> F32:
        size = len(positions)
        index = dr.arange(llvm.UInt32, size)
        p_flat = llvm.Float(np.ascontiguousarray(positions, np.float32).reshape(-1))
        n_flat = llvm.Float(np.ascontiguousarray(normals, np.float32).reshape(-1))
        p = dr.gather(llvm.Array3f, p_flat, index)
        n = dr.normalize(dr.gather(llvm.Array3f, n_flat, index))
        if isinstance(scene, gs.gltf.Scene):
            rgb, alpha = _drjit_gltf(dr, llvm, p, n, scene)
        else:
            rgb, alpha = _drjit_threejs(dr, llvm, p, n, scene)
        out = dr.empty(llvm.Float, 4 * size)
        dr.scatter(out, llvm.Array4f(*(dr.clip(c, 0.0, 1.0) for c in rgb), alpha), index)
        dr.eval(out)
        result: F32 = out.numpy().reshape(size, 4)
        return result

    return shade


def _drjit_gltf(
    dr: Any, llvm: Any, p: Any, n: Any, scene: gs.gltf.Scene
) -> tuple[list[Any], float]:
    """mesh.frag's ``main`` for a material without textures: the RGB sums and alpha."""
    m = _gltf_material(scene)
    k, a2 = m["k"], m["a2"]
    v = dr.normalize(llvm.Array3f(*_floats(scene.camera_position)) - p)
    nv = dr.clip(dr.abs(dr.dot(n, v)), 0.001, 1.0)
    rgb = [llvm.Float(c) for c in _floats(m["constant"])]
    f0, c_diff = _floats(m["f0"]), _floats(m["c_diff"])
    for row in map(_floats, _gltf_lights(scene)):
        if row[KIND] == DIRECTIONAL:
            ray, attenuation = llvm.Array3f(*row[POSITION : POSITION + 3]), 1.0
        else:
            to_light = llvm.Array3f(*row[POSITION : POSITION + 3]) - p
            d2 = dr.dot(to_light, to_light)
            ray, attenuation = dr.normalize(to_light), 1.0 / d2
            if row[KIND] == SPOT:
                cd = dr.clip(dr.dot(llvm.Array3f(*row[AXIS : AXIS + 3]), -ray), 0.0, 1.0)
                s = dr.clip(cd * row[A] + row[B], 0.0, 1.0)
                attenuation = attenuation * s * s
        h = dr.normalize(ray + v)
        nl = dr.clip(dr.dot(n, ray), 0.001, 1.0)
        nh = dr.clip(dr.dot(n, h), 0.0, 1.0)
        vh = dr.clip(dr.dot(v, h), 0.0, 1.0)
        q = dr.power(1.0 - vh, 5.0)
        g = nv / (nv * (1.0 - k) + k) * (nl / (nl * (1.0 - k) + k))
        den = nh * nh * (a2 - 1.0) + 1.0
        specular = g * (a2 / (math.pi * den * den)) / (4.0 * nl * nv + 0.001)
        w = nl * attenuation
        for c in range(3):
            f = f0[c] + (1.0 - f0[c]) * q
            brdf = (1.0 - f) * (c_diff[c] / math.pi) + f * specular
            rgb[c] = rgb[c] + w * row[RADIANCE + c] * brdf
    return rgb, m["alpha"]


def _drjit_threejs(
    dr: Any, llvm: Any, p: Any, n: Any, scene: gs.threejs.Scene
) -> tuple[list[Any], float]:
    """meshphong_frag's ``outgoingLight`` for a front-sided material without maps."""
    m = scene.material
    lights, ambient = _threejs_lights(scene)
    perspective, eye = _view(scene)
    eye3 = llvm.Array3f(*_floats(eye))
    v = dr.normalize(eye3 - p) if perspective else eye3
    s = max(m.shininess, 1e-4)
    diffuse = [llvm.Float(a) for a in _floats(ambient)]
    specular = [llvm.Float(0.0) for _ in range(3)]
    for row in map(_floats, lights):
        if row[KIND] == DIRECTIONAL:
            ray, factor = llvm.Array3f(*row[POSITION : POSITION + 3]), None
        else:
            to_light = llvm.Array3f(*row[POSITION : POSITION + 3]) - p
            d = dr.norm(to_light)
            ray = to_light / d
            factor = 1.0 / dr.maximum(dr.power(d, row[C]), 0.01)
            if row[KIND] == SPOT:
                cos = dr.dot(ray, llvm.Array3f(*row[AXIS : AXIS + 3]))
                t = dr.clip((cos - row[A]) / (row[B] - row[A]), 0.0, 1.0)
                cone = dr.select(cos > row[A], t * t * (3.0 - 2.0 * t), 0.0)
                factor = factor * cone
        nl = dr.clip(dr.dot(n, ray), 0.0, 1.0)
        e = nl if factor is None else nl * factor
        h = dr.normalize(ray + v)
        nh = dr.clip(dr.dot(n, h), 0.0, 1.0)
        lh = dr.clip(dr.dot(ray, h), 0.0, 1.0)
        fresnel = dr.exp2((-5.55473 * lh - 6.98316) * lh)
        d_term = (s * 0.5 + 1.0) / math.pi * dr.power(nh, s) * 0.25
        for c in range(3):
            f = (1.0 - m.specular[c]) * fresnel + m.specular[c]
            diffuse[c] = diffuse[c] + e * row[RADIANCE + c]
            specular[c] = specular[c] + e * row[RADIANCE + c] * f * d_term
    emissive = _floats(np.array(m.emissive) * m.emissive_intensity)
    rgb = [diffuse[c] * (m.color[c] / math.pi) + specular[c] + emissive[c] for c in range(3)]
    return rgb, float(m.opacity)


def numba_world() -> Shade | str:
    """numba (``parallel=True``, float32): ``shade(positions, normals, scene)`` -> (n, 4)
    float32 for a glTF or three.js scene, or why it is not available."""
    try:
        import numba  # noqa: F401  (the kernels import it again, typed)
    except ImportError as error:
        return f"numba is not installed ({error}; pip install 'glshade[bench]'): no numba peer"
    gltf, threejs = _numba_kernels()

    def shade(positions: F32, normals: F32, scene: WorldScene) -> F32:
        p = np.ascontiguousarray(positions, np.float32)
        n = np.ascontiguousarray(normals, np.float32)
        out = np.zeros((len(p), 4), np.float32)
        if isinstance(scene, gs.gltf.Scene):
            m = _gltf_material(scene)
            material = np.array(
                [*m["f0"], *m["c_diff"], m["k"], m["a2"], *m["constant"], m["alpha"]], np.float32
            )
            camera = np.array(scene.camera_position, np.float32)
            gltf(p, n, _gltf_lights(scene), material, camera, out)
        else:
            mat = scene.material
            lights, ambient = _threejs_lights(scene)
            perspective, eye = _view(scene)
            emissive = np.array(mat.emissive) * mat.emissive_intensity
            material = np.array(
                [*np.divide(mat.color, math.pi), *mat.specular, max(mat.shininess, 1e-4),
                 *emissive, *ambient, mat.opacity],
                np.float32,
            )  # fmt: skip
            threejs(p, n, lights, material, np.float32(eye), perspective, out)
        return out

    return shade


def _numba_kernels() -> tuple[Any, Any]:
    """The two compiled loops, glTF's and three.js'."""
    import numba as nb

    one, zero = np.float32(1), np.float32(0)

    @nb.njit(inline="always")
    def clip(x: Any, lo: Any, hi: Any) -> Any:
        return min(max(x, lo), hi)

    @nb.njit(inline="always")
    def unit(x: Any, y: Any, z: Any) -> tuple[Any, Any, Any]:
        inv = one / np.sqrt(x * x + y * y + z * z)
        return x * inv, y * inv, z * inv

    @nb.njit(parallel=True, fastmath=False, cache=False)
    def gltf(p: Any, n: Any, lights: Any, material: Any, camera: Any, out: Any) -> None:
        f0, c_diff = material[0:3], material[3:6]
        k, a2, alpha = material[6], material[7], material[11]
        pi = np.float32(math.pi)
        for i in nb.prange(p.shape[0]):
            nx, ny, nz = unit(n[i, 0], n[i, 1], n[i, 2])
            vx, vy, vz = unit(camera[0] - p[i, 0], camera[1] - p[i, 1], camera[2] - p[i, 2])
            nv = clip(abs(nx * vx + ny * vy + nz * vz), np.float32(0.001), one)
            r, g, b = material[8], material[9], material[10]
            for j in range(lights.shape[0]):
                row = lights[j]
                attenuation = one
                lx, ly, lz = row[1], row[2], row[3]
                if row[0] != 0:
                    lx, ly, lz = lx - p[i, 0], ly - p[i, 1], lz - p[i, 2]
                    d2 = lx * lx + ly * ly + lz * lz
                    inv = one / np.sqrt(d2)
                    lx, ly, lz = lx * inv, ly * inv, lz * inv
                    attenuation = one / d2
                    if row[0] == 2:
                        cd = clip(-(row[4] * lx + row[5] * ly + row[6] * lz), zero, one)
                        s = clip(cd * row[10] + row[11], zero, one)
                        attenuation *= s * s
                hx, hy, hz = unit(lx + vx, ly + vy, lz + vz)
                nl = clip(nx * lx + ny * ly + nz * lz, np.float32(0.001), one)
                nh = clip(nx * hx + ny * hy + nz * hz, zero, one)
                vh = clip(vx * hx + vy * hy + vz * hz, zero, one)
                t = one - vh
                q = t * t * t * t * t
                occlusion = nv / (nv * (one - k) + k) * (nl / (nl * (one - k) + k))
                den = nh * nh * (a2 - one) + one
                specular = (
                    occlusion
                    * (a2 / (pi * den * den))
                    / (np.float32(4) * nl * nv + np.float32(0.001))
                )
                w = nl * attenuation
                f = f0[0] + (one - f0[0]) * q
                r += w * row[7] * ((one - f) * (c_diff[0] / pi) + f * specular)
                f = f0[1] + (one - f0[1]) * q
                g += w * row[8] * ((one - f) * (c_diff[1] / pi) + f * specular)
                f = f0[2] + (one - f0[2]) * q
                b += w * row[9] * ((one - f) * (c_diff[2] / pi) + f * specular)
            out[i, 0], out[i, 1], out[i, 2] = (
                clip(r, zero, one),
                clip(g, zero, one),
                clip(b, zero, one),
            )
            out[i, 3] = alpha

    @nb.njit(parallel=True, fastmath=False, cache=False)
    def threejs(
        p: Any, n: Any, lights: Any, material: Any, eye: Any, perspective: bool, out: Any
    ) -> None:
        color, f0, s = material[0:3], material[3:6], material[6]
        emissive, ambient, opacity = material[7:10], material[10:13], material[13]
        norm = (s * np.float32(0.5) + one) / np.float32(math.pi) * np.float32(0.25)
        for i in nb.prange(p.shape[0]):
            nx, ny, nz = unit(n[i, 0], n[i, 1], n[i, 2])
            vx, vy, vz = eye[0], eye[1], eye[2]
            if perspective:
                vx, vy, vz = unit(vx - p[i, 0], vy - p[i, 1], vz - p[i, 2])
            er, eg, eb = ambient[0], ambient[1], ambient[2]
            sr, sg, sb = zero, zero, zero
            for j in range(lights.shape[0]):
                row = lights[j]
                factor = one
                lx, ly, lz = row[1], row[2], row[3]
                if row[0] != 0:
                    lx, ly, lz = lx - p[i, 0], ly - p[i, 1], lz - p[i, 2]
                    d = np.sqrt(lx * lx + ly * ly + lz * lz)
                    lx, ly, lz = lx / d, ly / d, lz / d
                    factor = one / max(d ** row[12], np.float32(0.01))
                    if row[0] == 2:
                        cos = lx * row[4] + ly * row[5] + lz * row[6]
                        t = clip((cos - row[10]) / (row[11] - row[10]), zero, one)
                        factor *= (
                            t * t * (np.float32(3) - np.float32(2) * t) if cos > row[10] else zero
                        )
                e = clip(nx * lx + ny * ly + nz * lz, zero, one) * factor
                hx, hy, hz = unit(lx + vx, ly + vy, lz + vz)
                nh = clip(nx * hx + ny * hy + nz * hz, zero, one)
                lh = clip(lx * hx + ly * hy + lz * hz, zero, one)
                fresnel = np.float32(2) ** ((np.float32(-5.55473) * lh - np.float32(6.98316)) * lh)
                dd = norm * nh**s
                er += e * row[7]
                eg += e * row[8]
                eb += e * row[9]
                sr += e * row[7] * ((one - f0[0]) * fresnel + f0[0]) * dd
                sg += e * row[8] * ((one - f0[1]) * fresnel + f0[1]) * dd
                sb += e * row[9] * ((one - f0[2]) * fresnel + f0[2]) * dd
            out[i, 0] = clip(er * color[0] + sr + emissive[0], zero, one)
            out[i, 1] = clip(eg * color[1] + sg + emissive[1], zero, one)
            out[i, 2] = clip(eb * color[2] + sb + emissive[2], zero, one)
            out[i, 3] = opacity

    return gltf, threejs
