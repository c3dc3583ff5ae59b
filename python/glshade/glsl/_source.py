"""GLSL text of a plan: the lighting functions (the "library"), a compute shader (GLSL 430) and a
vertex + fragment pair (GLSL 330 core) for flat, Gouraud and Phong shading.

The arithmetic is the spec's (section 2.14.1) in the CPU kernel's operations and order, with
what GLSL leaves undefined never evaluated: 0^0, the power of a negative base, 1/0 and 0/0 are
avoided with selects, not with multiplications by 0 (which would spread NaN and inf). The powers
are `_power`'s. normalize() and inversesqrt() are not used: llvmpipe's reciprocal square root is
an approximation refined once.
"""

from __future__ import annotations

from . import _power
from ._plan import LightGroup, Plan, Side
from ._values import SIDE_NAMES

# The library's arithmetic is `precise` (GLSL 4.00 on): as written, neither reassociated nor
# fused, so it rounds where the CPU kernel does; the library is also pasted into 3.30 shaders.
_PRECISE = [
    "#if __VERSION__ >= 400",
    "#define GS_PRECISE precise",
    "#else",
    "#define GS_PRECISE",
    "#endif",
]

# The GLSL type of every uniform a plan may declare, by name or by a light group's field.
_TYPES = {
    "gs_global_ambient": "vec3",
    "gs_viewer_direction": "vec3",
    "gs_viewer_point": "vec3",
    "gs_modelview": "mat4",
    "gs_normal_matrix": "mat3",
    "gs_projection": "mat4",
}
_GROUP_TYPES = {
    "vp": "vec3", "halfway": "vec3", "spot": "float", "point": "vec3", "attenuation": "vec3",
    "spot_direction": "vec3", "spot_cos_cutoff": "float", "spot_exponent": "float",
    "spot_edge_width": "float", "range": "float",
    "ambient": "vec3", "diffuse": "vec3", "specular": "vec3",
}  # fmt: skip
_COMMENTS = {
    "vp": "unit VP_pli", "halfway": "unit h_i, a constant (infinite viewer)",
    "spot": "spot_i, a constant", "point": "P_pli, eye space", "attenuation": "(k0, k1, k2)",
    "spot_direction": "unit s_dli", "spot_cos_cutoff": "cos(c_rli), exactly 0 at 90 degrees",
    "spot_exponent": "s_rli", "ambient": "a_cli", "diffuse": "d_cli", "specular": "s_cli",
    "spot_edge_width": "cos(inner) - cos(c_rli), the soft edge's width",
    "range": "no light beyond this distance",
}  # fmt: skip


def uniform_type(name: str, length: int) -> str:
    """The GLSL type of uniform `name` (``"vec3[4]"`` for an array of 4)."""
    if name in _TYPES:
        return _TYPES[name]
    if name.startswith("gs_light"):
        base = _GROUP_TYPES[name.split("_", 2)[2]]
        return f"{base}[{length}]"
    return "float" if name.endswith("_shininess") else "vec4"


def _declaration(name: str, length: int) -> str:
    t = uniform_type(name, length)
    if "[" in t:
        base, count = t[:-1].split("[")
        field = name.split("_", 2)[2]
        return f"uniform {base} {name}[{count}];  // {_COMMENTS[field]}"
    return f"uniform {t} {name};"


def _describe(plan: Plan) -> list[str]:
    """One comment line per light group: which lights, which terms."""
    lines = []
    for g, group in enumerate(plan.groups):
        kind = "directional" if group.directional else "positional"
        terms = [t for t in ("ambient", "diffuse", "specular") if getattr(group, t)]
        if group.attenuated:
            terms.append("attenuation")
        if group.spot:
            terms.append("spot cone")
        if group.soft:
            terms.append("soft edge")
        if group.ranged:
            terms.append("range")
        lights = ", ".join(str(i) for i in group.indices)
        lines.append(f"// gs_light{g}: lights {lights}, {kind}: {' + '.join(terms)}")
    return lines


def _powered(plan: Plan, side: Side) -> bool:
    """Whether `side` computes a specular power: its material has one and a light is lit."""
    return side.power and any(g.specular for g in plan.groups)


def _light_loop(plan: Plan, g: int, group: LightGroup, side: Side) -> list[str]:
    """The statements adding light group `g`'s terms to c_pri (and c_sec) on one side."""
    u = f"gs_light{g}_"
    k = len(group.indices)
    body = []
    weighted = group.attenuated or group.spot or group.ranged
    if group.directional:
        body.append(f"vec3 VP = {u}vp[i];")
        if group.spot:
            body.append(f"float w = {u}spot[i];")
    else:
        body.append(f"vec3 D = {u}point[i] - V;")
        body.append("GS_PRECISE float d = sqrt(gs_dot(D, D));")
        body.append("GS_PRECISE vec3 VP = d > 0.0 ? D * (1.0 / d) : vec3(0.0);")
        if group.attenuated:
            body.append(f"vec3 k = {u}attenuation[i];")
            body.append("float w = 1.0 / (k.x + k.y * d + k.z * d * d);  // eq. 2.4")
        if group.spot:  # eq. 2.5
            body.append(f"float c = max(gs_dot(-VP, {u}spot_direction[i]), 0.0);")
            power = (
                f"gs_cos_pow(c, -VP, {u}spot_direction[i], {u}spot_exponent[i], gs_unit_scale())"
            )
            spot = f"c >= {u}spot_cos_cutoff[i] ? {power} : 0.0"
            body.append(f"w = w * ({spot});" if group.attenuated else f"float w = {spot};")
            if group.soft:  # learnopengl's clamp((theta - outerCutOff) / epsilon, 0.0, 1.0)
                ramp = f"(c - {u}spot_cos_cutoff[i]) / {u}spot_edge_width[i]"
                body.append(f"w = w * clamp({ramp}, 0.0, 1.0);")
        if group.ranged:  # Luna's `if (d > L.Range) return;`
            r = f"{u}range[i]"
            weighed = group.attenuated or group.spot  # w is declared already
            body.append(
                f"w = d <= {r} ? w : 0.0;" if weighed else f"float w = d <= {r} ? 1.0 : 0.0;"
            )
    w = "w * " if weighted else ""
    specular = group.specular and side.specular
    if group.diffuse or specular:
        body.append("GS_PRECISE float n_dot_vp = gs_dot(n, VP);")
    if group.ambient:
        body.append(f"c_pri += {w}a_cm.rgb * {u}ambient[i];")
    if group.diffuse:
        body.append(f"c_pri += {w}max(n_dot_vp, 0.0) * d_cm.rgb * {u}diffuse[i];")
    if specular:
        power = ""
        if side.power and group.halfway:
            body.append(f"vec3 h = {u}halfway[i];")
            body.append("float power = gs_cos_pow(gs_dot(n_unit, h), n_unit, h, s_rm, n_scale);")
            power = "power * "
        elif side.power and not plan.phong:
            body.append("vec3 h = gs_direction(VP + VPe);  // eq. 2.3; 0 gives no power")
            body.append("float power = gs_cos_pow(gs_dot(n_unit, h), n_unit, h, s_rm, n_scale);")
            power = "power * "
        elif side.power:
            body.append("GS_PRECISE vec3 R = n * (n_dot_vp + n_dot_vp) - VP;")
            body.append("vec3 r_unit = gs_direction(R);  // 0 for R = 0: no power, as for VPe = 0")
            scale = "gs_unit_scale()" if plan.normalize else "gs_scale(R)"
            body.append(
                f"float power = gs_cos_pow(gs_dot(r_unit, VPe), r_unit, VPe, s_rm, {scale});"
            )
            power = "power * "
        if plan.gate:  # eq. 2.2's f_i, a select: power may be huge where f_i = 0
            body.append("bool f_i = n_dot_vp > 0.0;")
        else:  # learnopengl: only a zero n or VP, which have no direction, gives no specular
            body.append("bool f_i = dot(n, n) > 0.0 && dot(VP, VP) > 0.0;")
        target = "c_sec" if plan.separate_specular else "c_pri"
        body.append(f"{target} += f_i ? {w}{power}s_cm.rgb * {u}specular[i] : vec3(0.0);")
    return [f"    for (int i = 0; i < {k}; ++i) {{", *[f"        {s}" for s in body], "    }"]


def _side_function(plan: Plan, index: int) -> list[str]:
    side = plan.sides[index]
    name = SIDE_NAMES[index]
    lines = [
        f"// Eqs. 2.2-2.5 for the {name} side: n is that side's normal (the back side gets -n),",
        "// `color` the vertex colour (GL_COLOR_MATERIAL); the sums clamped once at the end.",
        f"GSColor gs_lighting_{name}(vec3 V, vec3 n, vec4 color) {{",
    ]
    parameters = (("a_cm", "ambient"), ("d_cm", "diffuse"), ("e_cm", "emission"))
    for var, parameter in parameters + ((("s_cm", "specular"),) if side.specular else ()):
        value = "color" if parameter in side.tracked else f"gs_{name}_{parameter}"
        lines.append(f"    vec4 {var} = {value};")
    if side.power:
        lines.append(f"    float s_rm = gs_{name}_shininess;")
        if not plan.phong and _powered(plan, side):
            # (n.h)^s = (|n| n_unit.h)^s: the length enters the power apart (see _power).
            unit = ("n", "gs_unit_scale()") if plan.normalize else ("gs_unit(n)", "gs_scale(n)")
            lines.append(f"    vec3 n_unit = {unit[0]};")
            lines.append(f"    GSScale n_scale = {unit[1]};")
        if plan.view:
            lines.append("    vec3 VPe = gs_direction(gs_viewer_point - V);")
        elif plan.viewer_direction:
            lines.append("    vec3 VPe = gs_viewer_direction;")
    lines.append("    vec3 c_pri = e_cm.rgb + a_cm.rgb * gs_global_ambient;")
    if plan.separate_specular:
        lines.append("    vec3 c_sec = vec3(0.0);")
    for g, group in enumerate(plan.groups):
        if group.ambient or group.diffuse or (group.specular and side.specular):
            lines += _light_loop(plan, g, group, side)
    secondary = (
        "clamp(vec4(c_sec, 1.0), 0.0, 1.0)" if plan.separate_specular else "vec4(0, 0, 0, 1)"
    )
    lines += [
        "    GSColor result;",
        "    result.primary = clamp(vec4(c_pri, d_cm.a), 0.0, 1.0);",
        f"    result.secondary = {secondary};",
        "    return result;",
        "}",
    ]
    return lines


def library(plan: Plan, lengths: dict[str, int]) -> str:
    """The uniforms (`lengths`: array length by name, 0 for a non-array), `GSColor`, the helpers
    (`gs_dot`, `gs_transform`, `gs_unit`, `gs_direction`, the power's where one is needed),
    `gs_eye_space` and one ``gs_lighting_<side>`` function per lit side."""
    powered = [side for side in plan.sides if _powered(plan, side)]
    uses_pow = bool(powered) or any(g.spot and not g.directional for g in plan.groups)
    lines = [
        "// The OpenGL 2.1 lighting equation (section 2.14.1) for one scene, generated by",
        "// glshade.glsl: terms the scene does not need are left out (as in Scene.plan()).",
        *_describe(plan),
        "struct GSColor {",
        "    vec4 primary;    // clamped, alpha = d_cm alpha",
        "    vec4 secondary;  // clamped, alpha 1 (GL_SEPARATE_SPECULAR_COLOR; else 0)",
        "};",
        *[_declaration(name, n) for name, n in lengths.items()],
        "",
        *_PRECISE,
        "// a.b summed in the kernel's order, (x + y) + z, unfused (src/simd/lanes.rs V3::dot).",
        "float gs_dot(vec3 a, vec3 b) {",
        "    GS_PRECISE float d = (a.x * b.x + a.y * b.y) + a.z * b.z;",
        "    return d;",
        "}",
        "// m v in the kernel's order, column by column (src/lighting/transform.rs mul3).",
        "vec3 gs_transform(mat3 m, vec3 v) {",
        "    GS_PRECISE vec3 t = (m[0] * v.x + m[1] * v.y) + m[2] * v.z;",
        "    return t;",
        "}",
        "// v / |v|, and 0 for v = 0 (GL: undefined; glshade's convention).",
        "vec3 gs_unit(vec3 v) {",
        "    GS_PRECISE float len = sqrt(gs_dot(v, v));",
        "    return len > 0.0 ? v / len : vec3(0.0);",
        "}",
        "// v * (1 / |v|), and 0 for v = 0: the kernel's one division for VP, VP_e, h and R.",
        "vec3 gs_direction(vec3 v) {",
        "    GS_PRECISE float len = sqrt(gs_dot(v, v));",
        "    GS_PRECISE vec3 unit = len > 0.0 ? v * (1.0 / len) : vec3(0.0);",
        "    return unit;",
        "}",
    ]
    if uses_pow:
        lines += _power.functions(scaled=bool(powered) and not plan.normalize)
    m = plan.modelview is not None
    lines += [
        "// Section 2.11.3: eye-space position and normal (normalised with GL_NORMALIZE).",
        "void gs_eye_space(vec3 p, vec3 normal, out vec3 V, out vec3 n) {",
        "    V = gs_transform(mat3(gs_modelview), p) + gs_modelview[3].xyz;" if m else "    V = p;",
        "    n = gs_transform(gs_normal_matrix, normal);" if m else "    n = normal;",
        *(["    n = gs_unit(n);"] if plan.normalize else []),
        "}",
    ]
    for index in range(len(plan.sides)):
        lines += _side_function(plan, index)
    return "\n".join(lines) + "\n"


def compute(plan: Plan, lib: str) -> str:
    """The compute shader: gs.shade's output planes for `gs_count` vertices."""
    cm = plan.color_material is not None
    outputs = []
    for index, name in enumerate(SIDE_NAMES[: len(plan.sides)]):
        outputs.append(
            f"    GSColor {name} = gs_lighting_{name}(V, {'-n' if index else 'n'}, color);"
        )
        outputs.append(f"    gs_result[plane * gs_count + i] = {name}.primary;")
        outputs.append("    plane += 1u;")
        if plan.separate_specular:
            outputs.append(f"    gs_result[plane * gs_count + i] = {name}.secondary;")
            outputs.append("    plane += 1u;")
    read = "vec3(gs_{0}[3u * i], gs_{0}[3u * i + 1u], gs_{0}[3u * i + 2u])"
    return "\n".join(
        [
            "#version 430",
            lib,
            "layout(local_size_x = 64) in;",
            "// Tightly packed floats (std430 pads a vec3 array to 16 bytes per element).",
            *(["layout(std430, binding = 0) readonly buffer GSPositions { float gs_positions[]; };"]
              if plan.positions else []),
            "layout(std430, binding = 1) readonly buffer GSNormals { float gs_normals[]; };",
            *(["layout(std430, binding = 2) readonly buffer GSColors { vec4 gs_colors[]; };"]
              if cm else []),
            "// (outputs, count) planes of RGBA rows, in gs.shade's order (Scene.outputs).",
            "layout(std430, binding = 3) writeonly buffer GSResult { vec4 gs_result[]; };",
            "uniform uint gs_count;",
            "",
            "void main() {",
            "    uint i = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u + gl_GlobalInvocationID.x;",  # noqa: E501
            "    if (i >= gs_count) {",
            "        return;",
            "    }",
            f"    vec3 p = {read.format('positions') if plan.positions else 'vec3(0.0)'};",
            f"    vec3 normal = {read.format('normals')};",
            f"    vec4 color = {'gs_colors[i]' if cm else 'vec4(1.0)'};",
            "    vec3 V;",
            "    vec3 n;",
            "    gs_eye_space(p, normal, V, n);",
            "    uint plane = 0u;",
            *outputs,
            "}",
            "",
        ]
    )  # fmt: skip


def vertex(plan: Plan, shading: str, lib: str) -> str:
    """The vertex shader: eye space, clip space, and per-vertex lighting unless Phong."""
    cm = plan.color_material is not None
    m = plan.modelview is not None
    two = len(plan.sides) == 2
    qualifier = "flat " if shading == "flat" else ""
    lines = ["#version 330 core", *([lib] if shading != "phong" else []),
             "uniform mat4 gs_projection;  // eye to clip coordinates",
             *(["uniform mat4 gs_modelview;", "uniform mat3 gs_normal_matrix;"]
               if m and shading == "phong" else []),
             "layout(location = 0) in vec3 gs_position;",
             "layout(location = 1) in vec3 gs_normal;",
             *(["layout(location = 2) in vec4 gs_color;  // GL_COLOR_MATERIAL's colour"]
               if cm else []),
             "out vec3 gs_v_position;  // eye space",
             "out vec3 gs_v_normal;    // eye space, as transformed (not normalised)",
             *(["out vec4 gs_v_color;"] if cm and shading == "phong" else [])]  # fmt: skip
    lit = [f"{qualifier}out vec4 gs_v_{s}_{c};" for s in SIDE_NAMES[: len(plan.sides)]
           for c in ("primary", "secondary")]  # fmt: skip
    if shading != "phong":
        lines += lit
    lines += [
        "",
        "void main() {",
        "    vec4 eye = gs_modelview * vec4(gs_position, 1.0);"
        if m
        else "    vec4 eye = vec4(gs_position, 1.0);",
        "    gs_v_position = eye.xyz;",
        f"    gs_v_normal = {'gs_normal_matrix * gs_normal' if m else 'gs_normal'};",
        "    gl_Position = gs_projection * eye;",
    ]
    color = "gs_color" if cm else "vec4(1.0)"
    if shading == "phong":
        lines += ["    gs_v_color = gs_color;"] if cm else []
    else:
        n = "gs_unit(gs_v_normal)" if plan.normalize else "gs_v_normal"
        lines.append(f"    vec3 n = {n};")
        lines.append(f"    GSColor front = gs_lighting_front(gs_v_position, n, {color});")
        if two:
            lines.append(f"    GSColor back = gs_lighting_back(gs_v_position, -n, {color});")
        for s in SIDE_NAMES[: len(plan.sides)]:
            lines.append(f"    gs_v_{s}_primary = {s}.primary;")
            lines.append(f"    gs_v_{s}_secondary = {s}.secondary;")
    lines += ["}", ""]
    return "\n".join(lines)


def fragment(plan: Plan, shading: str, lib: str) -> str:
    """The fragment shader: the colour sum at location 0; primary, secondary, eye position
    (w = 1) and eye normal (w = +1 front-facing, -1 back-facing) at locations 1 to 4."""
    cm = plan.color_material is not None
    two = len(plan.sides) == 2
    qualifier = "flat " if shading == "flat" else ""
    lines = ["#version 330 core", *([lib] if shading == "phong" else []),
             "in vec3 gs_v_position;", "in vec3 gs_v_normal;",
             *(["in vec4 gs_v_color;"] if cm and shading == "phong" else [])]  # fmt: skip
    if shading != "phong":
        lines += [
            f"{qualifier}in vec4 gs_v_{s}_{c};"
            for s in SIDE_NAMES[: len(plan.sides)]
            for c in ("primary", "secondary")
        ]
    lines += [
        "layout(location = 0) out vec4 gs_frag_color;      // the colour sum, clamped",
        "layout(location = 1) out vec4 gs_frag_primary;",
        "layout(location = 2) out vec4 gs_frag_secondary;",
        "layout(location = 3) out vec4 gs_frag_position;   // eye space, w = 1",
        "layout(location = 4) out vec4 gs_frag_normal;     // w = +1 front-facing, -1 back",
        "",
        "void main() {",
    ]
    if shading == "phong":
        n = "gs_unit(gs_v_normal)" if plan.normalize else "gs_v_normal"
        color = "gs_v_color" if cm else "vec4(1.0)"
        lines.append(f"    vec3 n = {n};")
        if two:
            lines += [
                "    GSColor c = gl_FrontFacing",
                f"        ? gs_lighting_front(gs_v_position, n, {color})",
                f"        : gs_lighting_back(gs_v_position, -n, {color});",
            ]
        else:
            lines.append(f"    GSColor c = gs_lighting_front(gs_v_position, n, {color});")
        lines += ["    vec4 primary = c.primary;", "    vec4 secondary = c.secondary;"]
    elif two:
        lines += [
            "    vec4 primary = gl_FrontFacing ? gs_v_front_primary : gs_v_back_primary;",
            "    vec4 secondary = gl_FrontFacing ? gs_v_front_secondary : gs_v_back_secondary;",
        ]
    else:
        lines += [
            "    vec4 primary = gs_v_front_primary;",
            "    vec4 secondary = gs_v_front_secondary;",
        ]
    total = (
        "clamp(primary + vec4(secondary.rgb, 0.0), 0.0, 1.0)"
        if plan.separate_specular
        else "primary"
    )
    lines += [
        f"    gs_frag_color = {total};  // section 3.9: the colour sum",
        "    gs_frag_primary = primary;",
        "    gs_frag_secondary = secondary;",
        "    gs_frag_position = vec4(gs_v_position, 1.0);",
        "    gs_frag_normal = vec4(gs_v_normal, gl_FrontFacing ? 1.0 : -1.0);",
        "}",
        "",
    ]
    return "\n".join(lines)
