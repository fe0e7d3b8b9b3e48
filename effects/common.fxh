// Shared HLSL for the seed effects: standard transforms (SAS semantics) and the guarded
// operations of lib/shading/fx/shading/guarded.h, written in the same operation order so the CPU
// mirrors there predict these shaders' results. Include once per effect.
#ifndef FXKIT_EFFECTS_COMMON_FXH
#define FXKIT_EFFECTS_COMMON_FXH

float4x4 WorldViewProjection : WORLDVIEWPROJECTION < string UIWidget = "None"; >;
float4x4 World : WORLD < string UIWidget = "None"; >;
float4x4 ViewInverse : VIEWINVERSE < string UIWidget = "None"; >;

// Below this length a vector is rounding noise (4 float epsilons, degenerate_length<float>):
// its direction carries no information, so the guarded forms fall back instead.
static const float kDegenerateLength = 4.76837158e-7;

// normalize(v), or `fallback` when v is too short to have a direction (normalize(0) is
// undefined in SPIR-V).
float3 normalize_or(float3 v, float3 fallback)
{
    float len = length(v);
    // An infinite component makes len infinite and v / len NaN: fall back, as for zero.
    return len > kDegenerateLength && !isinf(len) ? v / len : fallback;
}

// pow(x, y) with x clamped to [0, 1] and pow(0, 0) = 1: pow(x<0, y) and pow(0, 0) are
// undefined in SPIR-V (they compile to exp2(y * log2(x))).
float guarded_pow(float x, float y)
{
    float s = saturate(x);
    return s > 0.0 ? pow(s, y) : (y == 0.0 ? 1.0 : 0.0);
}

// A unit vector perpendicular to unit n (Duff et al. 2017): the fallback tangent when a
// Gram-Schmidt projection collapses because T is parallel to N.
float3 any_perpendicular(float3 n)
{
    float sgn = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (sgn + n.z);
    float b = n.x * n.y * a;
    return float3(1.0 + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
}

// normalize(T - (N.T)N), projected twice (one pass leaves ~eps/sin(angle) along N), with
// any_perpendicular(N) when T is parallel to N.
float3 gram_schmidt_tangent(float3 t, float3 n)
{
    float3 p = t - dot(n, t) * n;
    p = p - dot(n, p) * n;
    return normalize_or(p, any_perpendicular(n));
}

// The seed's ps.1.4 form: T - (N.T)N without renormalization (brighter near steep bumps).
float3 gram_schmidt_unnormalized(float3 t, float3 n)
{
    return t - dot(n, t) * n;
}

// normalize(L + V), zero when L = -V (no highlight rather than 0/0).
float3 half_vector(float3 l, float3 v)
{
    return normalize_or(l + v, float3(0.0, 0.0, 0.0));
}

// World-space tangent frame of a vertex: (tangent, binormal, normal) rows, so that
// mul(frame, v) takes a world vector into tangent space (the seed's three dp3s).
float3x3 tangent_frame(float3 normal, float3 tangent, float3 binormal)
{
    float3 n = normalize_or(mul(normal, (float3x3)World), float3(0.0, 0.0, 1.0));
    float3 t = gram_schmidt_tangent(mul(tangent, (float3x3)World), n);
    float3 b = mul(binormal, (float3x3)World);
    // Keep the handedness the mesh authored, but rebuild the length from the cross product.
    float3 c = cross(n, t);
    b = dot(c, b) < 0.0 ? -c : c;
    return float3x3(t, b, n);
}

// Texel-centre mapping of a cosine into a table of `size` texels with clamp addressing:
// u = 0.5x + 0.5 at texel centres (u(N-1)+0.5)/N (docs/shading-math.md, "Tables").
float texel_centre(float cosine, float size)
{
    return ((0.5 * cosine + 0.5) * (size - 1.0) + 0.5) / size;
}

#endif
