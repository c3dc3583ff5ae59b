"""GLSL of the lighting equation's powers, the specular (n̂⊙ĥ)^s_rm or (r̂⊙VP_e)^s_rm and the
spot factor (P_pli→V ⊙ ŝ_dli)^s_rli, formed as the CPU kernel forms them
(``src/lighting/fixed_function/power.rs``).

1 - cos is taken as x = |â - b̂|²/2, which has no cancellation near the highlight, and the power
as exp(s·ln(1 - x)): GLSL's pow(cos, s) rounds cos first and multiplies that rounding by s.
The length of a vector that stands for a direction (an unnormalised normal, Phong's R) enters
as |v| - 1 near 1, formed from exact squares and sums (Dekker, Knuth), and as ln |v| elsewhere.
GLSL has no log1p: ln(1 + y) is an atanh series near 0, and the series of the mantissa plus the
exponent elsewhere (llvmpipe's log is off by up to 1.2e-7 near 1, which s would multiply).

The operations are ``precise`` (GLSL 4.00 and later: neither reassociated nor fused). Without
it Mesa's NIR folds the exact sums away (measured: |v| - 1 then off by 4.5e-8, its own size);
GLSL 3.30 has no ``precise``, so there |v| - 1 is only as good as a plain float32 sum, which
matters only for a power on normals that are not normalised.
"""

from __future__ import annotations

_LOG = """\
// ln(1 + y) for y in [sqrt(1/2) - 1, sqrt(2) - 1]: 2 atanh(z), z = y / (2 + y) in
// [-0.1716, 0.1716], by its series to z^11 (the next term is below 1e-10 of the sum).
float gs_log1p_near(float y) {
    GS_PRECISE float z = y / (2.0 + y);
    GS_PRECISE float w = z * z;
    GS_PRECISE float tail = w * (0.333333333 + w * (0.2 + w * (0.142857143 + w * (0.111111111
        + w * 0.0909090909))));
    GS_PRECISE float twice = 2.0 * z;
    return twice + twice * tail;
}

// ln x for finite x > 0: k ln 2 + ln m with x = m 2^k, m in [sqrt(1/2), sqrt(2)) (m - 1 is
// exact), ln 2 split so that k times its leading part is exact.
float gs_log(float x) {
    GS_PRECISE float lifted = x < 1.17549435e-38 ? x * 16777216.0 : x;  // subnormal: 2^24 x
    int bits = floatBitsToInt(lifted);
    int k = ((bits >> 23) & 255) - (x < 1.17549435e-38 ? 151 : 127);
    GS_PRECISE float m = intBitsToFloat((bits & 8388607) | 1065353216);  // [1, 2)
    if (m >= 1.41421356) {
        m = 0.5 * m;
        k += 1;
    }
    GS_PRECISE float kf = float(k);
    GS_PRECISE float low = kf * 1.4286068e-06 + gs_log1p_near(m - 1.0);
    return kf * 0.693145751953125 + low;
}

// ln(1 + y) for y > -1: the series near 0, where log(1 + y) would lose the low bits of y;
// 1 + y is exact for y <= -1/2 and within 2^-25 of it in between.
float gs_log1p(float y) {
    if (y >= -0.29289322 && y <= 0.41421356) {
        return gs_log1p_near(y);
    }
    GS_PRECISE float u = 1.0 + y;
    return gs_log(u);
}

// How the length of a vector that stands for a unit direction enters a power: near 1
// (|v|^2 in [0.5, 2]) as |v| - 1, elsewhere as ln |v| (src/lighting/fixed_function/power.rs Scale).
struct GSScale {
    bool near;
    float magnitude;  // |v|, at most the largest float
    float minus_one;  // |v| - 1 where near
    float ln;         // ln |v| elsewhere (0 for v = 0)
};

// The scale of a unit vector.
GSScale gs_unit_scale() {
    return GSScale(true, 1.0, 0.0, 0.0);
}

// x x = p + e exactly (Dekker's product: x split into halves of 12 bits).
void gs_square_exact(float x, out float p, out float e) {
    GS_PRECISE float c = 4097.0 * x;
    GS_PRECISE float high = c - (c - x);
    GS_PRECISE float low = x - high;
    GS_PRECISE float square = x * x;
    p = square;
    GS_PRECISE float error = ((high * high - square) + 2.0 * high * low) + low * low;
    e = error;
}

// a + b = s + e exactly (Knuth's TwoSum).
void gs_sum_exact(float a, float b, out float s, out float e) {
    GS_PRECISE float sum = a + b;
    GS_PRECISE float bb = sum - a;
    GS_PRECISE float error = (a - (sum - bb)) + (b - bb);
    s = sum;
    e = error;
}

// The scale of v: |v|^2 - 1 from exact squares and sums keeps every bit when |v| is near 1
// (float32 unit normals are a few ulp off, and the power multiplies that by s).
GSScale gs_scale(vec3 v) {
    float a, ae, b, be, c, ce, ab, e1, abc, e2;
    gs_square_exact(v.x, a, ae);
    gs_square_exact(v.y, b, be);
    gs_square_exact(v.z, c, ce);
    gs_sum_exact(a, b, ab, e1);
    gs_sum_exact(ab, c, abc, e2);
    GS_PRECISE float len = min(sqrt(gs_dot(v, v)), 3.40282347e38);
    bool near = abc >= 0.5 && abc <= 2.0;
    // abc - 1 is exact (Sterbenz) where near.
    GS_PRECISE float squared_minus_one = (abc - 1.0) + ((e1 + e2) + ((ae + be) + ce));
    GS_PRECISE float minus_one = squared_minus_one / (len + 1.0);
    float ln = near || len == 0.0 ? 0.0 : gs_log(len);
    return GSScale(near, len, near ? minus_one : 0.0, ln);
}

// (scale.magnitude max(c, 0))^s for unit a, b with a.b = c, and section 2.1.1's 0^0 = 1:
// exp(s ln(1 - x)), x = |a - b|^2 / 2 (src/lighting/fixed_function/power.rs cos_pow).
float gs_cos_pow(float c, vec3 a, vec3 b, float s, GSScale scale) {
    if (s == 0.0) {
        return 1.0;
    }
    GS_PRECISE vec3 d = a - b;
    GS_PRECISE float x = 0.5 * gs_dot(d, d);
    GS_PRECISE float y = scale.near ? scale.minus_one - scale.magnitude * x : -x;
    // y > -1: the base is positive (not rounded to 0, whose ln is -inf).
    if (!(c > 0.0 && x < 1.0 && y > -1.0)) {
        return 0.0;
    }
    GS_PRECISE float ln = gs_log1p(y) + (scale.near ? 0.0 : scale.ln);
    return min(exp(s * ln), 3.40282347e38);
}"""


def functions(scaled: bool) -> list[str]:
    """The power's GLSL lines: ``gs_cos_pow``, ``GSScale`` and ``gs_unit_scale``, and with
    `scaled` ``gs_scale`` (the scale of a vector that is not unit)."""
    text = _LOG
    if not scaled:
        start = text.index("// x x = p + e exactly")
        end = text.index("// (scale.magnitude max(c, 0))^s")
        text = text[:start] + text[end:]
    return text.splitlines()
