// Hemisphere ("DIY") lighting from the per-pixel lighting seed: a sky colour and a ground
// colour blended by the fraction a of the sky a surface sees, optionally darkened by an
// occlusion term (per-vertex attribute or normal-map alpha), plus a directional "sun".
//   color = material * ((a sky + (1-a) ground)(1 - occlusion) + sun saturate(N.S))
// Sky fraction forms (q = angle between N and the sky axis):
//   cosine:  a = 0.5 + 0.5 cos q. The seed calls it a simplification; it is the EXACT
//            cosine-weighted integral of the sky hemisphere (verified by quadrature in
//            lib/shading/fx/shading/hemisphere.h, 4.3e-5 off at 600x1200 cells).
//   seed:    a = 1 - 0.5 sin q (q < 90), 0.5 sin q (q > 90), the seed's "actual integral".
//            A different model: up to (sqrt 2 - 1)/2 = 0.207 away at 45 and 135 degrees.
//            Kept as the "measurement" technique for comparison.
#include "common.fxh"
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

float3 SkyAxis < string UIName = "Sky axis (world)"; string Space = "World"; > = {0.0, 1.0, 0.0};
float4 SkyColor < string UIName = "Sky"; string UIWidget = "Color"; > = {0.55, 0.65, 0.9, 1.0};
float4 GroundColor < string UIName = "Ground"; string UIWidget = "Color"; > = {0.3, 0.25, 0.2, 1.0};
float3 SunDirection : DIRECTION < string UIName = "Sun direction (from the sun)"; string Object = "DirectionalLight0"; string Space = "World"; > = {-0.4, -0.8, -0.45};
float4 SunColor : DIFFUSE < string UIName = "Sun"; string UIWidget = "Color"; > = {0.6, 0.57, 0.5, 1.0};
float4 Half = {0.5, 0.5, 0.5, 0.5};
float4 One = {1.0, 1.0, 1.0, 1.0};

// An engine binds its own textures here; the generators bake a bumpy surface whose normal
// map alpha is the fraction of the sky its own relief blocks (the seed's "bump-mapped
// earth": a convex sphere has no self-occlusion, the bump map carries all of it).
texture NormalMap : NORMALMAP < string Generator = "normal_map"; string Pattern = "noise"; float Strength = 0.8; int Frequency = 8; int Octaves = 4; int Width = 256; int Seed = 5; string Alpha = "occlusion"; string UIName = "Normal map (alpha = occlusion)"; >;
texture BaseMap : DIFFUSEMAP < string Generator = "color_map"; string Pattern = "noise"; string Color0 = "0.62 0.58 0.54"; string Color1 = "0.85 0.82 0.78"; float Softness = 0.5; int Frequency = 8; int Octaves = 4; int Width = 256; int Seed = 5; string UIName = "Base texture"; >;
sampler2D NormalSampler = sampler_state { Texture = <NormalMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };
sampler2D BaseSampler = sampler_state { Texture = <BaseMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };

struct HemiVertex
{
    float4 position  : POSITION;
    float3 normal    : NORMAL;
    float3 tangent   : TANGENT;
    float3 binormal  : BINORMAL;
    float2 uv        : TEXCOORD0;
    float  occlusion : TEXCOORD1;  // baked per vertex (fraction of the sky hemisphere blocked)
};

struct HemiPixel
{
    float4 position  : POSITION;
    float2 uv        : TEXCOORD0;
    float3 sky       : TEXCOORD1;  // tangent space
    float3 sun       : TEXCOORD2;  // tangent space, to the sun
    float  occlusion : TEXCOORD3;
};

#define OCCLUSION_NONE 0
#define OCCLUSION_VERTEX 1
#define OCCLUSION_TEXTURE 2

#define FORM_COSINE 0
#define FORM_SEED 1

// Sky fraction from cos q: mirrors hemisphere_sky_fraction / _seed in lib/shading/fx/shading.
float sky_fraction(float cos_q, uniform int form)
{
    float c = clamp(cos_q, -1.0, 1.0);
    if (form == FORM_SEED)
    {
        float s = sqrt(saturate((1.0 - c) * (1.0 + c)));
        return c >= 0.0 ? 1.0 - 0.5 * s : 0.5 * s;
    }
    return 0.5 + 0.5 * c;
}

float3 hemisphere_light(float3 n, float3 sky, float3 sun, float occlusion, uniform int form, uniform bool with_sun)
{
    float a = sky_fraction(dot(n, sky), form);
    float3 ambient = (SkyColor.rgb - GroundColor.rgb) * a + GroundColor.rgb;  // the seed's lerp
    float3 lit = ambient * (1.0 - saturate(occlusion));
    return with_sun ? lit + SunColor.rgb * saturate(dot(n, sun)) : lit;
}

HemiPixel HemisphereVS(HemiVertex IN)
{
    HemiPixel OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.uv = IN.uv;
    float3x3 frame = tangent_frame(IN.normal, IN.tangent, IN.binormal);
    OUT.sky = mul(frame, normalize_or(SkyAxis, float3(0.0, 1.0, 0.0)));
    OUT.sun = mul(frame, normalize_or(-SunDirection, float3(0.0, 1.0, 0.0)));
    OUT.occlusion = IN.occlusion;
    return OUT;
}

float4 HemispherePS(HemiPixel IN, uniform int occlusion_source, uniform int form, uniform bool with_sun) : COLOR0
{
    float4 normal = tex2D(NormalSampler, IN.uv);
    float3 n = normalize_or(normal.xyz * 2.0 - 1.0, float3(0.0, 0.0, 1.0));
    float occlusion = occlusion_source == OCCLUSION_VERTEX ? IN.occlusion
                    : occlusion_source == OCCLUSION_TEXTURE ? normal.a : 0.0;
    float3 sky = normalize_or(IN.sky, float3(0.0, 0.0, 1.0));
    float3 sun = normalize_or(IN.sun, float3(0.0, 0.0, 1.0));
    float4 base = tex2D(BaseSampler, IN.uv);
    return float4(base.rgb * hemisphere_light(n, sky, sun, occlusion, form, with_sun), base.a);
}

// Per vertex (the seed's vs.1.1 shader as HLSL): world normal against the sky axis.
struct HemiVertexLit
{
    float4 position : POSITION;
    float2 uv       : TEXCOORD0;
    float4 light    : COLOR0;
};

HemiVertexLit HemisphereVertexVS(HemiVertex IN)
{
    HemiVertexLit OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.uv = IN.uv;
    float3 n = normalize_or(mul(IN.normal, (float3x3)World), float3(0.0, 1.0, 0.0));
    float3 sky = normalize_or(SkyAxis, float3(0.0, 1.0, 0.0));
    float3 sun = normalize_or(-SunDirection, float3(0.0, 1.0, 0.0));
    OUT.light = float4(hemisphere_light(n, sky, sun, IN.occlusion, FORM_COSINE, true), 1.0);
    return OUT;
}

float4 HemisphereVertexPS(HemiVertexLit IN) : COLOR0
{
    float4 base = tex2D(BaseSampler, IN.uv);
    return float4(base.rgb * IN.light.rgb, base.a);
}

technique hemisphere_sun
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "quality"; float MaxDistance = 50.0; string Fallback = "hemisphere_ps11"; string UIName = "Three-term hemisphere (texture occlusion) + sun, per pixel"; COST_hemisphere_sun >
{
    pass p0
    {
        VertexShader = compile vs_2_0 HemisphereVS();
        PixelShader = compile ps_2_0 HemispherePS(OCCLUSION_TEXTURE, FORM_COSINE, true);
    }
}

technique hemisphere_vertex_occlusion_sun
< string Requires = "vs_2_0 ps_2_0"; float MaxDistance = 50.0; string UIName = "Three-term hemisphere (vertex occlusion) + sun, per pixel"; COST_hemisphere_vertex_occlusion_sun >
{
    pass p0
    {
        VertexShader = compile vs_2_0 HemisphereVS();
        PixelShader = compile ps_2_0 HemispherePS(OCCLUSION_VERTEX, FORM_COSINE, true);
    }
}

technique hemisphere_three_term
< string Requires = "vs_2_0 ps_2_0"; float MaxDistance = 50.0; string UIName = "Three-term hemisphere (texture occlusion), per pixel"; COST_hemisphere_three_term >
{
    pass p0
    {
        VertexShader = compile vs_2_0 HemisphereVS();
        PixelShader = compile ps_2_0 HemispherePS(OCCLUSION_TEXTURE, FORM_COSINE, false);
    }
}

technique hemisphere_two_term
< string Requires = "vs_2_0 ps_2_0"; float MaxDistance = 50.0; string UIName = "Two-term hemisphere (sky/ground), per pixel";  COST_hemisphere_two_term >
{
    pass p0
    {
        VertexShader = compile vs_2_0 HemisphereVS();
        PixelShader = compile ps_2_0 HemispherePS(OCCLUSION_NONE, FORM_COSINE, false);
    }
}

technique hemisphere_seed_form
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "measurement"; float MaxDistance = 50.0; string UIName = "Three-term hemisphere + sun, the seed's 1 - 0.5 sin q form";  COST_hemisphere_seed_form >
{
    pass p0
    {
        VertexShader = compile vs_2_0 HemisphereVS();
        PixelShader = compile ps_2_0 HemispherePS(OCCLUSION_TEXTURE, FORM_SEED, true);
    }
}

technique hemisphere_per_vertex
< string Requires = "vs_2_0 ps_2_0"; float MinDistance = 50.0; string Fallback = "hemisphere_vs11"; string UIName = "Three-term hemisphere + sun, per vertex (far away)"; COST_hemisphere_per_vertex >
{
    pass p0
    {
        VertexShader = compile vs_2_0 HemisphereVertexVS();
        PixelShader = compile ps_2_0 HemisphereVertexPS();
    }
}

// The seed's per-pixel fragment (ps.1.1) with a vertex shader that puts the tangent-space
// sky axis, biased, in oD0 (and the vertex occlusion in its alpha). c1 sky, c2 ground,
// c5 = 0.5: dp3_d2 gives 0.5 N.A, + 0.5 is the cosine form.
technique hemisphere_ps11
< string Requires = "vs_1_1 ps_1_1"; string Fallback = "hemisphere_vs11"; string UIName = "Two-term hemisphere, ps.1.1 (DirectX 8)"; COST_hemisphere_ps11 >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[8] = <WorldViewProjection>;
        VertexShaderConstant[33] = <Half>;
        VertexShaderConstant[40] = <SkyAxis>;
        PixelShaderConstant[1] = <SkyColor>;
        PixelShaderConstant[2] = <GroundColor>;
        PixelShaderConstant[5] = <Half>;
        Texture[0] = <NormalMap>;
        Texture[1] = <BaseMap>;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[3]; float v8[3]; }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c8
            m3x3 r3, v8, c0            // tangent to world
            m3x3 r5, v3, c0            // normal to world
            mul r0, r3.zxyw, r5.yzxw   // binormal
            mad r4, r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, c40          // sky axis into tangent space
            dp3 r6.y, r4, c40
            dp3 r6.z, r5, c40
            mad oD0.xyz, r6.xyz, c33, c33  // biased for _bx2
            mov oD0.w, v7.z            // occlusion ratio
            mov oT0.xy, v7.xy
            mov oT1.xy, v7.xy
        };
        PixelShader =
        asm
        {
            ps.1.1
            tex t0                         // normal map
            tex t1                         // base texture
            dp3_d2_sat r0, v0_bx2, t0_bx2  // dot normal with hemi axis
            add r0, r0, c5                 // map into range, not _sat
            lrp r0, r0, c1, c2
            mul r0, r0, t1                 // modulate base texture
        };
    }
}

// The seed's vs.1.1 per-vertex hemisphere (three-term with v7.z occlusion). Works on
// DirectX 7-class hardware with software vertex processing, as the seed notes.
technique hemisphere_vs11
< string Requires = "vs_1_1 fixed_function_stages"; string UIName = "Three-term hemisphere, vs.1.1 per vertex (DirectX 7)"; COST_hemisphere_vs11 >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[8] = <WorldViewProjection>;
        VertexShaderConstant[33] = <Half>;
        VertexShaderConstant[40] = <SkyAxis>;
        VertexShaderConstant[41] = <SkyColor>;
        VertexShaderConstant[42] = <GroundColor>;
        VertexShaderConstant[43] = <One>;
        VertexShaderConstant[44] = <One>;
        Texture[0] = <BaseMap>;
        ColorOp[0] = Modulate;
        ColorArg1[0] = Texture;
        ColorArg2[0] = Diffuse;
        ColorOp[1] = Disable;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[3]; }
        asm
        {
            vs.1.1                 // vertex hemisphere shader
            m4x4 oPos, v0, c8      // transform position
            m3x3 r0, v3, c0        // transform normal
            dp3 r0, r0, c40        // c40 is sky vector
            mov r1, c33            // c33 is .5f in all channels
            mad r0, r0, c33, r1    // bias operation
            mov r1, c42            // c42 is ground color
            sub r1, c41, r1        // c41 is sky color
            mad r0, r1, r0, c42    // lerp operation
            sub r1, c44, v7.zzz    // v7.zzz = occlusion term
            mul r0, r0, r1
            mul oD0, r0, c43
            mov oT0.xy, v7.xy
        };
    }
}
