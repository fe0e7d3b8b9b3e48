// Anisotropic lighting without a strand tangent, from the "anisotropic lighting LUT and
// Ward" seed (ZwqXin, after the NVIDIA SDK sample and Gems):
//  - a 2D table indexed by (H.N, L.N): rgb = diffuse, a = specular, col.rgb * col.a; the
//    NVIDIA texture's formula is unpublished, the "ln_hn" generator bakes a documented
//    stand-in (saturate(L.N), and (H.N)^n or a Gaussian lobe). A soft sheen that slides
//    with the view, as on a lens surface.
//  - the Gems-style Gaussian c = exp(-e*e), e = k 0.3 (T.H) / (N.H): a highlight stretched
//    across the tangent direction (Ward's anisotropic exponent with one roughness).
// The seed evaluates both per vertex; per-pixel techniques are added ("just softer edges").
#include "common.fxh"
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

#define LN_HN_SIZE 128

float4 LightPosition : POSITION < string UIName = "Light position"; string Object = "PointLight0"; string Space = "World"; > = {10.0, 10.0, -10.0, 1.0};
float Intensity < string UIName = "Intensity"; float UIMin = 0.0; float UIMax = 4.0; > = 1.0;
float4 BaseColor : DIFFUSE < string UIName = "Base color"; string UIWidget = "Color"; > = {0.8, 0.8, 0.9, 1.0};
float ControlR < string UIName = "Gaussian sharpness k"; float UIMin = 0.0; float UIMax = 20.0; > = 4.0;

texture HalfAngleLut < string Generator = "ln_hn"; int Width = LN_HN_SIZE; string Lobe = "blinn_phong"; float Exponent = 32; string Mapping = "texel_centre"; string Format = "unorm8"; >;
sampler2D HalfAngleSampler = sampler_state { Texture = <HalfAngleLut>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };

struct AnisoVertex
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
    float3 tangent  : TANGENT;
};

struct AnisoPixel
{
    float4 position : POSITION;
    float3 normal   : TEXCOORD0;  // world
    float3 tangent  : TEXCOORD1;  // world
    float3 light    : TEXCOORD2;  // world, to the light
    float3 eye      : TEXCOORD3;  // world, to the eye
};

AnisoPixel AnisoVS(AnisoVertex IN)
{
    AnisoPixel OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    float3 world = mul(IN.position, World).xyz;
    OUT.normal = mul(IN.normal, (float3x3)World);
    OUT.tangent = mul(IN.tangent, (float3x3)World);
    OUT.light = LightPosition.xyz - world;
    OUT.eye = ViewInverse[3].xyz - world;
    return OUT;
}

// The table lookup, texel-centre mapped: u = H.N, v = L.N.
float4 ln_hn_color(float3 n, float3 l, float3 v)
{
    float3 h = half_vector(l, v);
    float2 uv = float2(texel_centre(dot(h, n), LN_HN_SIZE), texel_centre(dot(l, n), LN_HN_SIZE));
    float4 col = Intensity * tex2D(HalfAngleSampler, uv);
    return float4(col.rgb * col.a, 1.0);
}

// The seed's Gaussian, guarded: N.H <= 0 (where the seed divides by zero) gives 0.
// Mirrors fx::shading::ward_gaussian.
float4 gaussian_color(float3 n, float3 t, float3 l, float3 v)
{
    float3 h = half_vector(l, v);
    float u = dot(t, h) * 0.3;
    float w = dot(n, h);
    float e = w > 0.0 ? ControlR * u / w : 0.0;
    float c = w > 0.0 ? exp(-e * e) : 0.0;
    return BaseColor * c;
}

float4 LnHnPS(AnisoPixel IN) : COLOR0
{
    float3 n = normalize_or(IN.normal, float3(0.0, 0.0, 1.0));
    return ln_hn_color(n, normalize_or(IN.light, n), normalize_or(IN.eye, n));
}

float4 GaussianPS(AnisoPixel IN) : COLOR0
{
    float3 n = normalize_or(IN.normal, float3(0.0, 0.0, 1.0));
    float3 t = gram_schmidt_tangent(IN.tangent, n);
    return gaussian_color(n, t, normalize_or(IN.light, n), normalize_or(IN.eye, n));
}

// Per vertex, as the seed: the vertex computes the colour, the pixel passes it on.
struct AnisoVertexLit
{
    float4 position : POSITION;
    float4 color    : COLOR0;
};

AnisoVertexLit GaussianPerVertexVS(AnisoVertex IN)
{
    AnisoPixel p = AnisoVS(IN);
    AnisoVertexLit OUT;
    OUT.position = p.position;
    float3 n = normalize_or(p.normal, float3(0.0, 0.0, 1.0));
    float3 l = normalize_or(p.light, n);
    float3 v = normalize_or(p.eye, n);
    OUT.color = gaussian_color(n, gram_schmidt_tangent(p.tangent, n), l, v);
    return OUT;
}

// The table variant per vertex: the vertex only computes the (H.N, L.N) coordinates.
struct AnisoVertexCoords
{
    float4 position : POSITION;
    float2 coords   : TEXCOORD0;
};

AnisoVertexCoords LnHnPerVertexVS(AnisoVertex IN)
{
    AnisoPixel p = AnisoVS(IN);
    AnisoVertexCoords OUT;
    OUT.position = p.position;
    float3 n = normalize_or(p.normal, float3(0.0, 0.0, 1.0));
    float3 l = normalize_or(p.light, n);
    float3 h = half_vector(l, normalize_or(p.eye, n));
    OUT.coords = float2(texel_centre(dot(h, n), LN_HN_SIZE), texel_centre(dot(l, n), LN_HN_SIZE));
    return OUT;
}

float4 LnHnPerVertexPS(AnisoVertexCoords IN) : COLOR0
{
    float4 col = Intensity * tex2D(HalfAngleSampler, IN.coords);
    return float4(col.rgb * col.a, 1.0);
}

float4 VertexColorPS(AnisoVertexLit IN) : COLOR0
{
    return IN.color;
}

technique gaussian_per_pixel
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "gaussian"; float MaxDistance = 30.0; string Fallback = "gaussian_per_vertex"; string UIName = "Gaussian exp(-e*e), per pixel";  COST_gaussian_per_pixel >
{
    pass p0
    {
        VertexShader = compile vs_2_0 AnisoVS();
        PixelShader = compile ps_2_0 GaussianPS();
    }
}

technique gaussian_per_vertex
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "gaussian"; string UIName = "Gaussian exp(-e*e), per vertex (the seed)"; COST_gaussian_per_vertex >
{
    pass p0
    {
        VertexShader = compile vs_2_0 GaussianPerVertexVS();
        PixelShader = compile ps_2_0 VertexColorPS();
    }
}

technique ln_hn_per_pixel
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "table"; float MaxDistance = 30.0; string Fallback = "ln_hn_per_vertex"; string UIName = "(H.N, L.N) table, per pixel"; COST_ln_hn_per_pixel >
{
    pass p0
    {
        VertexShader = compile vs_2_0 AnisoVS();
        PixelShader = compile ps_2_0 LnHnPS();
    }
}

technique ln_hn_per_vertex
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "table"; string UIName = "(H.N, L.N) table, per-vertex coordinates (the seed)"; COST_ln_hn_per_vertex >
{
    pass p0
    {
        VertexShader = compile vs_2_0 LnHnPerVertexVS();
        PixelShader = compile ps_2_0 LnHnPerVertexPS();
    }
}
