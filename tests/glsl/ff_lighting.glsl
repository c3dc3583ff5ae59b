// The OpenGL 2.1 fixed-function lighting equation (spec section 2.14.1, eqs. 2.2-2.5) in GLSL,
// written from the specification for the cross-checks; it shares no code with glshade.
// No #version line: shaders prepend theirs (330 for vertex/fragment, 430 for compute) and may
// #define FF_MAX_LIGHTS. Every input is a uniform filled by glpeers.pack_scene from a gs.Scene.
//
// Float behaviour this relies on (GLSL 4.50 section 4.7.1, llvmpipe): +, -, * are binary32
// round-to-nearest; sqrt and division are correctly rounded or within 2.5 ulp; pow is
// exp2(y * log2(x)) with a relative error of about y * 1e-7. What GLSL leaves undefined is
// never evaluated: pow(0, 0), pow of a negative base, 1/0 and 0/0 are avoided with selects
// (not with multiplications by 0, which would spread NaN and inf; cf. Mesa commits b3f9c5cc0f
// and 16ef7ab5c1). normalize() and inversesqrt() are not
// used: llvmpipe's reciprocal square root is an approximation refined once.

#ifndef FF_MAX_LIGHTS
#define FF_MAX_LIGHTS 8
#endif

uniform int ff_light_count;
uniform vec4 ff_light_position[FF_MAX_LIGHTS];   // eye space, homogeneous (w = 0: directional)
uniform vec3 ff_light_ambient[FF_MAX_LIGHTS];    // a_cli
uniform vec3 ff_light_diffuse[FF_MAX_LIGHTS];    // d_cli
uniform vec3 ff_light_specular[FF_MAX_LIGHTS];   // s_cli
uniform vec3 ff_light_attenuation[FF_MAX_LIGHTS];  // (k0, k1, k2)
uniform vec3 ff_spot_direction[FF_MAX_LIGHTS];   // unit s_dli (normalised in float64 on the host)
uniform float ff_spot_exponent[FF_MAX_LIGHTS];   // s_rli
uniform float ff_spot_cutoff[FF_MAX_LIGHTS];     // c_rli in degrees (180: no spot)
uniform float ff_spot_cos_cutoff[FF_MAX_LIGHTS]; // cos(c_rli) in float64; exactly 0 for 90

// Materials: index 0 front, 1 back.
uniform vec4 ff_material_ambient[2];   // a_cm
uniform vec4 ff_material_diffuse[2];   // d_cm (its alpha is the output alpha)
uniform vec4 ff_material_specular[2];  // s_cm
uniform vec4 ff_material_emission[2];  // e_cm
uniform float ff_material_shininess[2];  // s_rm

uniform vec4 ff_global_ambient;  // a_cs
uniform vec4 ff_viewer;          // (0,0,1,0): infinite viewer; (0,0,0,1): local viewer; any point
uniform int ff_two_side;         // LIGHT_MODEL_TWO_SIDE
uniform int ff_separate_specular;  // LIGHT_MODEL_COLOR_CONTROL = SEPARATE_SPECULAR_COLOR
uniform int ff_phong;            // 1: (R.VP_e)^s with R = 2(n.VP)n - VP instead of (n.h)^s
uniform int ff_specular_gate;    // 1: GL's f_i; 0: specular wherever n and VP have a direction
// COLOR_MATERIAL: 0 off, 1 ambient, 2 diffuse, 3 specular, 4 emission, 5 ambient and diffuse;
// faces: bit 0 front, bit 1 back.
uniform int ff_color_material;
uniform int ff_color_material_faces;

// Section 2.11.3: the modelview, its normal matrix (inverse transpose of the upper 3x3, from
// float64), the RESCALE_NORMAL factor (1 when off) and NORMALIZE.
uniform mat4 ff_modelview;
uniform mat3 ff_normal_matrix;
uniform float ff_normal_scale;
uniform int ff_normalize;

// One side's lit colours, clamped: primary (alpha = d_cm alpha) and secondary (alpha 1).
struct FFColor {
    vec4 primary;
    vec4 secondary;
};

// v / |v|, and 0 for v = 0 (GL: undefined; glshade's convention).
vec3 ff_unit(vec3 v) {
    float len = sqrt(dot(v, v));
    return len > 0.0 ? v / len : vec3(0.0);
}

// x^e for x >= 0 with section 2.1.1's 0^0 = 1.
float ff_pow(float x, float e) {
    if (e == 0.0) {
        return 1.0;
    }
    return x > 0.0 ? pow(x, e) : 0.0;
}

// Section 2.11.3: V = M (p, 1), n = f (M^-1)^T n, then n / |n| with NORMALIZE.
void ff_eye_space(vec3 p, vec3 normal, out vec3 V, out vec3 n) {
    vec4 Vh = ff_modelview * vec4(p, 1.0);
    V = Vh.xyz / Vh.w;
    n = ff_normal_scale * (ff_normal_matrix * normal);
    if (ff_normalize != 0) {
        n = ff_unit(n);
    }
}

// Eqs. 2.2-2.5 for one side: n is the normal of that side (the back side passes -n) and `color`
// the vertex colour, used for the parameters COLOR_MATERIAL tracks on that side.
FFColor ff_lighting(vec3 V, vec3 n, int side, vec4 color) {
    vec4 a_cm = ff_material_ambient[side];
    vec4 d_cm = ff_material_diffuse[side];
    vec4 s_cm = ff_material_specular[side];
    vec4 e_cm = ff_material_emission[side];
    float s_rm = ff_material_shininess[side];
    if ((ff_color_material_faces & (1 << side)) != 0) {  // section 2.14.3
        if (ff_color_material == 1 || ff_color_material == 5) a_cm = color;
        if (ff_color_material == 2 || ff_color_material == 5) d_cm = color;
        if (ff_color_material == 3) s_cm = color;
        if (ff_color_material == 4) e_cm = color;
    }
    // VP_e: the unit vector from V to the viewer; (0, 0, 1) for GL's infinite viewer.
    vec3 VPe = ff_viewer.w == 0.0 ? ff_unit(ff_viewer.xyz) : ff_unit(ff_viewer.xyz / ff_viewer.w - V);

    vec3 c_pri = e_cm.rgb + a_cm.rgb * ff_global_ambient.rgb;
    vec3 c_sec = vec3(0.0);
    for (int i = 0; i < ff_light_count; ++i) {
        vec4 P = ff_light_position[i];
        vec3 VP;
        float att;
        if (P.w == 0.0) {
            VP = ff_unit(P.xyz);
            att = 1.0;  // eq. 2.4: no attenuation for directional lights
        } else {
            vec3 D = P.xyz / P.w - V;
            float d = sqrt(dot(D, D));
            VP = ff_unit(D);
            vec3 k = ff_light_attenuation[i];
            att = 1.0 / (k.x + k.y * d + k.z * d * d);
        }
        float spot = 1.0;  // eq. 2.5, cutoff 180
        if (ff_spot_cutoff[i] != 180.0) {
            float c = max(dot(-VP, ff_spot_direction[i]), 0.0);  // P_pli V (.) s_dli
            spot = c >= ff_spot_cos_cutoff[i] ? ff_pow(c, ff_spot_exponent[i]) : 0.0;
        }
        float n_dot_vp = dot(n, VP);
        float power = 1.0;  // (n (.) h)^s_rm, or (R (.) VP_e)^s_rm; 0^0 = 1 whatever h or R
        if (s_rm != 0.0 && ff_phong == 0) {
            vec3 h = VP + VPe;  // eq. 2.3
            float h_len = sqrt(dot(h, h));
            power = h_len > 0.0 ? ff_pow(max(dot(n, h / h_len), 0.0), s_rm) : 0.0;
        } else if (s_rm != 0.0) {
            vec3 R = 2.0 * n_dot_vp * n - VP;
            power = dot(VPe, VPe) > 0.0 ? ff_pow(max(dot(R, VPe), 0.0), s_rm) : 0.0;
        }
        float w = att * spot;
        c_pri += w * a_cm.rgb * ff_light_ambient[i];
        c_pri += w * max(n_dot_vp, 0.0) * d_cm.rgb * ff_light_diffuse[i];
        // eq. 2.2: f_i = 0 unless n.VP > 0 (a select: power may be huge where f_i = 0); without
        // the gate (learnopengl) only a zero n or VP, which have no direction, gives no specular.
        bool f_i = ff_specular_gate != 0 ? n_dot_vp > 0.0 : dot(n, n) > 0.0 && dot(VP, VP) > 0.0;
        vec3 spec = f_i ? w * power * s_cm.rgb * ff_light_specular[i] : vec3(0.0);
        if (ff_separate_specular != 0) {
            c_sec += spec;
        } else {
            c_pri += spec;
        }
    }
    FFColor result;
    result.primary = clamp(vec4(c_pri, d_cm.a), 0.0, 1.0);  // section 2.14.6: one clamp, at the end
    result.secondary = clamp(vec4(c_sec, 1.0), 0.0, 1.0);
    return result;
}
