// Float targets of glpeers.rasterize: lit colour, secondary colour, eye position (w = 1 where
// covered) and interpolated eye normal (w = +1 front-facing, -1 back-facing). Cleared to 0.

in vec3 v_position;
in vec3 v_normal;
in vec4 v_color;
#if FF_SHADING == 1
in vec4 v_front_primary;
in vec4 v_front_secondary;
in vec4 v_back_primary;
in vec4 v_back_secondary;
#elif FF_SHADING == 2
flat in vec4 v_front_primary;
flat in vec4 v_front_secondary;
flat in vec4 v_back_primary;
flat in vec4 v_back_secondary;
#endif

layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_secondary;
layout(location = 2) out vec4 out_position;
layout(location = 3) out vec4 out_normal;

void main() {
    bool back = ff_two_side != 0 && !gl_FrontFacing;
#if FF_SHADING == 0
    // Per-fragment lighting of the interpolated position and normal (normalised with NORMALIZE).
    vec3 n = ff_normalize != 0 ? ff_unit(v_normal) : v_normal;
    FFColor c = ff_lighting(v_position, back ? -n : n, back ? 1 : 0, v_color);
    out_color = c.primary;
    out_secondary = c.secondary;
#else
    out_color = back ? v_back_primary : v_front_primary;
    out_secondary = back ? v_back_secondary : v_front_secondary;
#endif
    out_position = vec4(v_position, 1.0);
    out_normal = vec4(v_normal, gl_FrontFacing ? 1.0 : -1.0);
}
