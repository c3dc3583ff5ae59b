// The fragment shader glpeers loads into pyrender's program cache, after glshade.glsl's
// lighting library (gs_lighting_front/back, gs_unit) and the defines GS_TWO_SIDE and
// GS_NORMALIZE. ff_output picks what the 8-bit colour buffer receives: 0 the lit colour
// (primary + secondary, clamped: GL's colour sum), 1 the unit eye normal as n / 2 + 1/2,
// 2 gl_PrimitiveID + 1 in 24 bits of RGB.

in vec3 v_position;
in vec3 v_normal;

uniform int ff_output;

out vec4 frag_color;

void main() {
    if (ff_output == 2) {
        int id = gl_PrimitiveID + 1;
        frag_color = vec4(float(id & 255), float((id >> 8) & 255), float((id >> 16) & 255), 255.0)
            / 255.0;
    } else if (ff_output == 1) {
        frag_color = vec4(0.5 * gs_unit(v_normal) + 0.5, 1.0);
    } else {
        vec3 n = GS_NORMALIZE != 0 ? gs_unit(v_normal) : v_normal;
#if GS_TWO_SIDE
        GSColor c = gl_FrontFacing ? gs_lighting_front(v_position, n, vec4(1.0))
                                   : gs_lighting_back(v_position, -n, vec4(1.0));
#else
        GSColor c = gs_lighting_front(v_position, n, vec4(1.0));
#endif
        frag_color = clamp(c.primary + vec4(c.secondary.rgb, 0.0), 0.0, 1.0);
    }
}
