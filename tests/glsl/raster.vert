// Rasterisation of an eye-space mesh into float targets (glpeers.rasterize). glpeers prepends
// "#version 330", the FF_MAX_LIGHTS define, FF_SHADING (0 phong, 1 gouraud, 2 flat) and
// ff_lighting.glsl.

uniform mat4 ff_projection;

in vec3 in_position;  // eye space
in vec3 in_normal;    // eye space
in vec4 in_color;     // COLOR_MATERIAL colour (alpha 1 when none was given)

out vec3 v_position;
out vec3 v_normal;
out vec4 v_color;
#if FF_SHADING == 1
out vec4 v_front_primary;
out vec4 v_front_secondary;
out vec4 v_back_primary;
out vec4 v_back_secondary;
#elif FF_SHADING == 2
flat out vec4 v_front_primary;
flat out vec4 v_front_secondary;
flat out vec4 v_back_primary;
flat out vec4 v_back_secondary;
#endif

void main() {
    v_position = in_position;
    v_normal = in_normal;
    v_color = in_color;
    gl_Position = ff_projection * vec4(in_position, 1.0);
#if FF_SHADING != 0
    // Per-vertex lighting (Gouraud, or flat from the provoking vertex, GL's last by default).
    vec3 n = ff_normalize != 0 ? ff_unit(in_normal) : in_normal;
    FFColor front = ff_lighting(in_position, n, 0, in_color);
    FFColor back = ff_two_side != 0 ? ff_lighting(in_position, -n, 1, in_color) : front;
    v_front_primary = front.primary;
    v_front_secondary = front.secondary;
    v_back_primary = back.primary;
    v_back_secondary = back.secondary;
#endif
}
