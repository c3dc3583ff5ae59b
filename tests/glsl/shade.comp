// Per-vertex fixed-function lighting: eye space from model space (ff_eye_space), then
// ff_lighting for each colour the scene asks for, in gs.shade's output layout.
// glpeers prepends "#version 430" and the FF_MAX_LIGHTS define, and appends ff_lighting.glsl
// before this file.

layout(local_size_x = 64) in;

// Tightly packed float arrays: std430 would pad a vec3 array to 16 bytes per element.
layout(std430, binding = 0) readonly buffer Positions { float ff_p[]; };
layout(std430, binding = 1) readonly buffer Normals { float ff_n[]; };
layout(std430, binding = 2) readonly buffer Colors { vec4 ff_c[]; };
// (outputs, count) planes of RGBA rows: front primary[, front secondary][, back primary[, back
// secondary]], as scene.outputs names them.
layout(std430, binding = 3) writeonly buffer Result { vec4 ff_out[]; };

uniform uint ff_count;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= ff_count) {
        return;
    }
    vec3 p = vec3(ff_p[3u * i], ff_p[3u * i + 1u], ff_p[3u * i + 2u]);
    vec3 normal = vec3(ff_n[3u * i], ff_n[3u * i + 1u], ff_n[3u * i + 2u]);
    vec3 V;
    vec3 n;
    ff_eye_space(p, normal, V, n);
    uint plane = 0u;
    for (int side = 0; side <= ff_two_side; ++side) {
        FFColor c = ff_lighting(V, side == 0 ? n : -n, side, ff_c[i]);
        ff_out[plane * ff_count + i] = c.primary;
        plane += 1u;
        if (ff_separate_specular != 0) {
            ff_out[plane * ff_count + i] = c.secondary;
            plane += 1u;
        }
    }
}
