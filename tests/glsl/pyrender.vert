// The vertex shader glpeers loads into pyrender's program cache (test_vs_pyrender.py):
// pyrender's attribute layout (position at 0, NORMAL_LOC, INST_M_LOC, passed as defines) and
// its uniforms M, V, P; eye-space position and normal (GL's normal matrix) for the fragments.

layout(location = 0) in vec3 position;
layout(location = NORMAL_LOC) in vec3 normal;
layout(location = INST_M_LOC) in mat4 inst_m;

uniform mat4 M;
uniform mat4 V;
uniform mat4 P;

out vec3 v_position;
out vec3 v_normal;

void main() {
    mat4 MV = V * M * inst_m;
    vec4 eye = MV * vec4(position, 1.0);
    v_position = eye.xyz / eye.w;
    v_normal = transpose(inverse(mat3(MV))) * normal;
    gl_Position = P * eye;
}
