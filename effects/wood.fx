// The DirectX 9 HLSL wood shader of the D3DX seed (from the RenderMan Companion),
// modernized: a volume of procedural gradient noise perturbs the object-space position,
// the distance from the tree's axis (x) picks a ring, and the ring blends light and dark
// wood, lit by one directional light with a Blinn specular that is stronger on the dark
// rings. Expect concentric rings around the x axis, wobbly from the noise.
// The seed's listing, kept close to the original, is effects/seeds/wood_seed.fx.
#include "common.fxh"
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

float ringscale < string UIName = "Ring scale"; float UIMin = 1.0; float UIMax = 40.0; > = 10.0;
float point_scale < string UIName = "Point scale"; float UIMin = 0.1; float UIMax = 4.0; > = 1.0;
// The seed uses 1.0 in RenderMan scene units; on unit-sized meshes that much noise scrambles
// the rings, so the default here is 0.1.
float turbulence < string UIName = "Turbulence"; float UIMin = 0.0; float UIMax = 2.0; > = 0.1;
float3 lightwood < string UIName = "Light wood"; string UIWidget = "Color"; > = {0.3, 0.12, 0.03};
float3 darkwood < string UIName = "Dark wood"; string UIWidget = "Color"; > = {0.05, 0.01, 0.005};
float Ka < string UIName = "Ambient"; float UIMin = 0.0; float UIMax = 1.0; > = 0.2;
float Kd < string UIName = "Diffuse"; float UIMin = 0.0; float UIMax = 1.0; > = 0.4;
float Ks < string UIName = "Specular"; float UIMin = 0.0; float UIMax = 1.0; > = 0.6;
float roughness < string UIName = "Roughness (1/exponent)"; float UIMin = 0.01; float UIMax = 1.0; > = 0.1;
float3 ambient_color : AMBIENT < string UIName = "Ambient color"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0};
float3 diffuse_color : DIFFUSE < string UIName = "Diffuse color"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0};
float3 specular_color : SPECULAR < string UIName = "Specular color"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0};
float3 LightDirection : DIRECTION < string UIName = "Light direction (from the light)"; string Object = "DirectionalLight0"; string Space = "World"; > = {-0.577, -0.577, -0.577};

// Periodic gradient noise, 3 channels, stored 0.5n + 0.5 (expand with *2-1).
texture NoiseVolume < string Generator = "noise3d"; int Width = 32; int Channels = 3; int Period = 8; int Seed = 1; string Kind = "gradient"; int Octaves = 2; string Format = "unorm8"; >;
sampler3D NoiseSampler = sampler_state { Texture = <NoiseVolume>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Wrap; AddressV = Wrap; AddressW = Wrap; };

struct WoodVertex
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
    float4 color    : COLOR0;  // alpha scales the diffuse wood, as v.Color.a in the seed
};

struct WoodPixel
{
    float4 position : POSITION;
    float4 color    : COLOR0;
    float3 object   : TEXCOORD0;  // object-space position: the wood is solid
    float3 normal   : TEXCOORD1;  // world
    float3 eye      : TEXCOORD2;  // world, to the eye
};

WoodPixel WoodVS(WoodVertex IN)
{
    WoodPixel OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.color = IN.color;
    OUT.object = IN.position.xyz;
    OUT.normal = mul(IN.normal, (float3x3)World);
    OUT.eye = ViewInverse[3].xyz - mul(IN.position, World).xyz;
    return OUT;
}

float3 noise3(float3 p) { return tex3D(NoiseSampler, p).xyz * 2.0 - 1.0; }
// sample1d on a volume in the seed: the first channel along x.
float noise1(float x) { return tex3D(NoiseSampler, float3(x, 0.0, 0.0)).x * 2.0 - 1.0; }

// The seed's smoothstep(a, b, s): a Hermite curve from VALUE a to VALUE b with unit
// tangents, not RenderMan's smoothstep(edge0, edge1, x) (wood.h: up to 1.29 apart).
float seed_smoothstep(float a, float b, float s)
{
    float s2 = s * s;
    float s3 = s * s2;
    float sV1 = 2.0 * s3 - 3.0 * s2 + 1.0;
    float sT1 = s3 - 2.0 * s2 + s;
    float sV2 = -2.0 * s3 + 3.0 * s2;
    float sT2 = s3 - s2;
    return s < 0.0 ? a : s > 1.0 ? b : sV1 * a + sT1 + sV2 * b + sT2;
}

#define RING_SEED 0
#define RING_RENDERMAN 1

float4 WoodPS(WoodPixel IN, uniform int ring_profile) : COLOR0
{
    // Perturb P to add irregularity.
    float3 pp = IN.object * point_scale;
    pp += noise3(pp) * turbulence;
    // Radial distance from the tree's axis, into a ring position in [0, 1).
    float r = sqrt(pp.y * pp.y + pp.z * pp.z);
    r *= ringscale;
    r += abs(noise1(r) * turbulence);
    r = frac(r);
    r = ring_profile == RING_SEED ? seed_smoothstep(0.0, 0.8, r) - seed_smoothstep(0.83, 1.0, r)
                                  : smoothstep(0.0, 0.8, r) - smoothstep(0.83, 1.0, r);
    float3 n = normalize_or(IN.normal, float3(0.0, 0.0, 1.0));
    float3 l = normalize_or(-LightDirection, float3(0.0, 0.0, 1.0));
    float3 e = normalize_or(IN.eye, float3(0.0, 0.0, 1.0));
    float3 diffuse = diffuse_color * dot(n, l);
    float3 specular = specular_color * guarded_pow(dot(half_vector(l, e), n), 1.0 / roughness);
    float3 color = (ambient_color * Ka + diffuse * Kd) * lerp(lightwood, darkwood, r) * IN.color.a +
                   specular * (Ks * (0.3 * r + 0.7));
    return float4(color, IN.color.a);
}

technique wood
< string Requires = "vs_2_0 ps_2_0 volume_textures"; string UIName = "Wood (seed ring profile)"; COST_wood >
{
    pass p0
    {
        VertexShader = compile vs_2_0 WoodVS();
        PixelShader = compile ps_2_0 WoodPS(RING_SEED);
    }
}

// The Companion's intent: RenderMan smoothstep edges, softer ring borders.
technique wood_renderman_rings
< string Requires = "vs_2_0 ps_2_0 volume_textures"; string Scheme = "renderman"; string UIName = "Wood (RenderMan ring profile)"; COST_wood_renderman_rings >
{
    pass p0
    {
        VertexShader = compile vs_2_0 WoodVS();
        PixelShader = compile ps_2_0 WoodPS(RING_RENDERMAN);
    }
}
