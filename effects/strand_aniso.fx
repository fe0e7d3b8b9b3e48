// Per-pixel strand-based anisotropic lighting (Isidoro & Brennan, ATI; seed:
// strand-anisotropic-lighting-ati.txt). A strand lit with Phong whose normal N' is L
// projected into the strand's normal plane: L.N' = sin(L,T), V.R' = sin(L,T)sin(V,T) -
// (L.T)(V.T). Brushed metal, hair, records: a highlight that stretches across the grooves.
//
// Feature variants (compile only what the scene enables; pass -D to the front end):
//   STRAND_LIGHTS 1..4  directional lights summed in one pass by the HLSL techniques
//   STRAND_BUMP   0|1   1 adds the bump-mapped (Gram-Schmidt) techniques
// Light directions point from the light into the scene, as the seed's -c16 expects.
#include "common.fxh"
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

#ifndef STRAND_LIGHTS
#define STRAND_LIGHTS 1
#endif
#ifndef STRAND_BUMP
#define STRAND_BUMP 1
#endif
#if STRAND_LIGHTS < 1 || STRAND_LIGHTS > 4
#error STRAND_LIGHTS must be 1 to 4
#endif
#define STRAND_LUT_SIZE 256
#define STRAND_EXPONENT 32

float4 CameraPosition : CAMERAPOSITION < string UIWidget = "None"; >;

// Lights 1-3 are dimmer fill lights in saturated hues: strand diffuse is sin(L, T), which
// does not fall off with the surface's facing, so four full-strength lights wash to white.
float3 Light0Direction : DIRECTION < string UIName = "Light 0 direction"; string Object = "DirectionalLight0"; string Space = "World"; > = {0.577, -0.577, 0.577};
float3 Light1Direction : DIRECTION < string UIName = "Light 1 direction"; string Object = "DirectionalLight1"; string Space = "World"; > = {-0.577, -0.577, 0.577};
float3 Light2Direction : DIRECTION < string UIName = "Light 2 direction"; string Object = "DirectionalLight2"; string Space = "World"; > = {0.0, -0.707, -0.707};
float3 Light3Direction : DIRECTION < string UIName = "Light 3 direction"; string Object = "DirectionalLight3"; string Space = "World"; > = {0.0, 1.0, 0.0};
float4 Light0Color : DIFFUSE < string UIName = "Light 0 color"; string UIWidget = "Color"; > = {1.0, 0.9, 0.8, 1.0};
float4 Light1Color : DIFFUSE < string UIName = "Light 1 color"; string UIWidget = "Color"; > = {0.05, 0.15, 0.6, 1.0};
float4 Light2Color : DIFFUSE < string UIName = "Light 2 color"; string UIWidget = "Color"; > = {0.6, 0.05, 0.05, 1.0};
float4 Light3Color : DIFFUSE < string UIName = "Light 3 color"; string UIWidget = "Color"; > = {0.05, 0.5, 0.1, 1.0};
float4 AmbientColor : AMBIENT < string UIName = "Ambient"; string UIWidget = "Color"; > = {0.05, 0.05, 0.05, 1.0};
float Kd < string UIName = "Diffuse"; float UIMin = 0.0; float UIMax = 1.0; float UIStep = 0.01; > = 0.6;
float Ks < string UIName = "Specular"; float UIMin = 0.0; float UIMax = 2.0; float UIStep = 0.01; > = 0.8;
float SpecularExponent : SPECULARPOWER < string UIName = "Exponent (analytic techniques; tables bake STRAND_EXPONENT)"; float UIMin = 1.0; float UIMax = 256.0; > = STRAND_EXPONENT;

// An engine binds its own textures to DirectionMap, BaseMap and BumpMap; the generators
// bake brushed metal so the effect renders its seed's picture on its own: strands along
// u with a little jitter (Pattern = "circular" gives a record's grooves, "radial" a
// brushed disc), streaked grey metal, fibre bumps along the same strands.
texture DirectionMap < string Generator = "direction_field"; string Pattern = "linear"; float Angle = 0; float Amount = 0.12; int Frequency = 16; int Width = 256; int Seed = 1; string UIName = "Direction of anisotropy (tangent space, 0.5x+0.5)"; >;
texture BaseMap : DIFFUSEMAP < string Generator = "color_map"; string Pattern = "streaks"; string Color0 = "0.45 0.45 0.48"; string Color1 = "0.75 0.75 0.78"; float Threshold = 0.5; float Softness = 0.5; float Gloss0 = 0.6; float Gloss1 = 1.0; int Frequency = 4; int Stretch = 16; int Width = 256; int Seed = 2; string UIName = "Base color (alpha = gloss)"; >;
texture BumpMap : NORMALMAP < string Generator = "normal_map"; string Pattern = "streaks"; float Strength = 0.6; int Frequency = 4; int Stretch = 16; int Width = 256; int Seed = 2; string Alpha = "one"; string UIName = "Bump map (tangent-space normals)"; >;
// Both strand terms in one table: rgb = L.N', a = (V.R')^n with the exponent pre-baked.
texture StrandLut < string Generator = "strand"; int Width = STRAND_LUT_SIZE; float Exponent = STRAND_EXPONENT; string Mapping = "texel_centre"; string Index = "dot"; string Format = "unorm8"; >;
// The seed's layout: offset by half the table so wrap addressing adds the 0.5 bias.
texture StrandLutWrap < string Generator = "strand"; int Width = STRAND_LUT_SIZE; float Exponent = STRAND_EXPONENT; string Mapping = "seed_wrap"; string Index = "dot"; string Format = "unorm8"; >;

sampler2D DirectionSampler = sampler_state { Texture = <DirectionMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };
sampler2D BaseSampler = sampler_state { Texture = <BaseMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };
sampler2D BumpSampler = sampler_state { Texture = <BumpMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };
sampler2D StrandLutSampler = sampler_state { Texture = <StrandLut>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };
sampler2D StrandLutWrapSampler = sampler_state { Texture = <StrandLutWrap>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Wrap; AddressV = Wrap; };

struct StrandVertex
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
    float3 tangent  : TANGENT;
    float3 binormal : BINORMAL;
    float2 uv       : TEXCOORD0;
};

// Tangent-space vectors to the eye and to each light. `scale` is 1, or 0.5 for the
// seed's wrap trick (the dp3 in the pixel shader then yields 0.5 L.T).
struct StrandPixel
{
    float4 position : POSITION;
    float2 uv       : TEXCOORD0;
    float3 view     : TEXCOORD1;
    float3 light0   : TEXCOORD2;
    float3 light1   : TEXCOORD3;
    float3 light2   : TEXCOORD4;
    float3 light3   : TEXCOORD5;
};

float3 to_tangent(float3x3 frame, float3 v) { return mul(frame, v); }

// Fills the first `lights` light vectors (the rest are zero and unused).
StrandPixel StrandVS(StrandVertex IN, uniform float scale, uniform int lights)
{
    StrandPixel OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.uv = IN.uv;
    float3x3 frame = tangent_frame(IN.normal, IN.tangent, IN.binormal);
    float3 world = mul(IN.position, World).xyz;
    OUT.view = scale * to_tangent(frame, normalize_or(ViewInverse[3].xyz - world, float3(0.0, 0.0, 1.0)));
    OUT.light0 = scale * to_tangent(frame, -Light0Direction);
    OUT.light1 = lights > 1 ? scale * to_tangent(frame, -Light1Direction) : 0.0;
    OUT.light2 = lights > 2 ? scale * to_tangent(frame, -Light2Direction) : 0.0;
    OUT.light3 = lights > 3 ? scale * to_tangent(frame, -Light3Direction) : 0.0;
    return OUT;
}

float3 light_vector(StrandPixel IN, int i)
{
    return i == 0 ? IN.light0 : i == 1 ? IN.light1 : i == 2 ? IN.light2 : IN.light3;
}

float3 light_color(int i)
{
    return i == 0 ? Light0Color.rgb : i == 1 ? Light1Color.rgb : i == 2 ? Light2Color.rgb : Light3Color.rgb;
}

// The strand terms (L.N', (V.R')^n) from unit vectors, stable form: sines from |L x T|,
// not sqrt(1 - (L.T)^2), which cancels to 0 or goes NaN near the highlight ridge.
// Mirrors fx::shading::strand_from_vectors.
float2 strand_terms(float3 l, float3 v, float3 t, float exponent)
{
    float sl = min(length(cross(l, t)), 1.0);
    float sv = min(length(cross(v, t)), 1.0);
    float lt = clamp(dot(l, t), -1.0, 1.0);
    float vt = clamp(dot(v, t), -1.0, 1.0);
    return float2(sl, guarded_pow(sl * sv - lt * vt, exponent));
}

// Direction of anisotropy from its map, in tangent space.
float3 strand_direction(float2 uv)
{
    return normalize_or(tex2D(DirectionSampler, uv).xyz * 2.0 - 1.0, float3(1.0, 0.0, 0.0));
}

// Phong on the strand per light: base * (ambient + sum color (kd diffuse + ks gloss spec)).
float4 strand_shade(float4 base, float3 lit_diffuse, float3 lit_specular)
{
    return float4(base.rgb * (AmbientColor.rgb + Kd * lit_diffuse) + Ks * base.a * lit_specular, 1.0);
}

// Analytic per pixel (the reference technique).
float4 StrandAnalyticPS(StrandPixel IN) : COLOR0
{
    float3 t = strand_direction(IN.uv);
    float3 v = normalize_or(IN.view, float3(0.0, 0.0, 1.0));
    float3 diffuse = 0.0, specular = 0.0;
    [unroll] for (int i = 0; i < STRAND_LIGHTS; ++i)
    {
        float2 terms = strand_terms(normalize_or(light_vector(IN, i), float3(0.0, 0.0, 1.0)), v, t, SpecularExponent);
        diffuse += light_color(i) * terms.x;
        specular += light_color(i) * terms.y;
    }
    return strand_shade(tex2D(BaseSampler, IN.uv), diffuse, specular);
}

// One fetch per light from the (L.T, V.T) table, texel-centre mapping, clamp addressing.
float4 strand_lut(float3 l, float3 v, float3 t)
{
    float2 uv = float2(texel_centre(dot(l, t), STRAND_LUT_SIZE), texel_centre(dot(v, t), STRAND_LUT_SIZE));
    return tex2D(StrandLutSampler, uv);
}

// Table lookup per pixel; `bump` perturbs T by the bump normal with Gram-Schmidt,
// `renormalize` chooses between normalize(T - (N.T)N) and the seed's shorter T - (N.T)N.
float4 StrandLutPS(StrandPixel IN, uniform int lights, uniform bool bump, uniform bool renormalize) : COLOR0
{
    float3 t = strand_direction(IN.uv);
    if (bump)
    {
        float3 n = normalize_or(tex2D(BumpSampler, IN.uv).xyz * 2.0 - 1.0, float3(0.0, 0.0, 1.0));
        t = renormalize ? gram_schmidt_tangent(t, n) : gram_schmidt_unnormalized(t, n);
    }
    float3 v = normalize_or(IN.view, float3(0.0, 0.0, 1.0));
    float3 diffuse = 0.0, specular = 0.0;
    [unroll] for (int i = 0; i < lights; ++i)
    {
        float4 terms = strand_lut(normalize_or(light_vector(IN, i), float3(0.0, 0.0, 1.0)), v, t);
        diffuse += light_color(i) * terms.rgb;
        specular += light_color(i) * terms.a;
    }
    return strand_shade(tex2D(BaseSampler, IN.uv), diffuse, specular);
}

// The seed's "bias for free": the vertex shader scales L and V by 0.5, the table is offset
// by half its size and wrapped, so the dot products index it directly. Kept as its own
// technique to measure what the trick costs in accuracy (the corner texels blend the
// opposite edge).
float4 StrandLutSeedWrapPS(StrandPixel IN) : COLOR0
{
    float3 t = strand_direction(IN.uv);
    float3 diffuse = 0.0, specular = 0.0;
    [unroll] for (int i = 0; i < STRAND_LIGHTS; ++i)
    {
        float4 terms = tex2D(StrandLutWrapSampler, float2(dot(light_vector(IN, i), t), dot(IN.view, t)));
        diffuse += light_color(i) * terms.rgb;
        specular += light_color(i) * terms.a;
    }
    return strand_shade(tex2D(BaseSampler, IN.uv), diffuse, specular);
}

// Per vertex: the strand terms from the mesh tangent at each vertex, interpolated.
struct StrandVertexLit
{
    float4 position : POSITION;
    float2 uv       : TEXCOORD0;
    float4 diffuse  : COLOR0;
    float4 specular : COLOR1;
};

StrandVertexLit StrandPerVertexVS(StrandVertex IN)
{
    StrandVertexLit OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.uv = IN.uv;
    float3 world = mul(IN.position, World).xyz;
    float3 n = normalize_or(mul(IN.normal, (float3x3)World), float3(0.0, 0.0, 1.0));
    float3 t = gram_schmidt_tangent(mul(IN.tangent, (float3x3)World), n);
    float3 v = normalize_or(ViewInverse[3].xyz - world, float3(0.0, 0.0, 1.0));
    float3 diffuse = 0.0, specular = 0.0;
    [unroll] for (int i = 0; i < STRAND_LIGHTS; ++i)
    {
        float3 l = -(i == 0 ? Light0Direction : i == 1 ? Light1Direction : i == 2 ? Light2Direction : Light3Direction);
        float2 terms = strand_terms(normalize_or(l, float3(0.0, 0.0, 1.0)), v, t, SpecularExponent);
        diffuse += light_color(i) * terms.x;
        specular += light_color(i) * terms.y;
    }
    OUT.diffuse = float4(diffuse, 1.0);
    // COLOR1 saturates on D3D9 hardware; the highlight is a single light's peak anyway.
    OUT.specular = float4(specular, 1.0);
    return OUT;
}

float4 StrandPerVertexPS(StrandVertexLit IN) : COLOR0
{
    return strand_shade(tex2D(BaseSampler, IN.uv), IN.diffuse.rgb, IN.specular.rgb);
}

#if STRAND_BUMP
// Bump-mapped strands, T orthonormalized against the bump normal per pixel.
technique strand_bump_renormalized
<
    string Requires = "vs_2_0 ps_2_0";
    string Scheme = "quality";
    float MaxDistance = 40.0;
    string Fallback = "strand_bump_unnormalized";
    string UIName = "Strands, bump mapped (Gram-Schmidt, renormalized)";
 COST_strand_bump_renormalized
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandVS(1.0, STRAND_LIGHTS);
        PixelShader = compile ps_2_0 StrandLutPS(STRAND_LIGHTS, true, true);
    }
}

// The seed's ps.1.4 bump shader skips the renormalization ("almost no visual impact";
// lighting near severe bumps gets slightly brighter). Written for ps_2_0.
technique strand_bump_unnormalized
<
    string Requires = "vs_2_0 ps_2_0";
    string Generation = "dx8_1: the seed's ps.1.4 Gram-Schmidt shader";
    string Scheme = "performance";
    float MaxDistance = 40.0;
    string Fallback = "strand_lut";
    string UIName = "Strands, bump mapped (Gram-Schmidt, not renormalized)";
 COST_strand_bump_unnormalized
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandVS(1.0, STRAND_LIGHTS);
        PixelShader = compile ps_2_0 StrandLutPS(STRAND_LIGHTS, true, false);
    }
}
#endif

technique strand_analytic
<
    string Requires = "vs_2_0 ps_2_0";
    string Scheme = "quality";
    float MaxDistance = 40.0;
    string Fallback = "strand_lut";
    string UIName = "Strands, analytic per pixel";
 COST_strand_analytic
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandVS(1.0, STRAND_LIGHTS);
        PixelShader = compile ps_2_0 StrandAnalyticPS();
    }
}

technique strand_lut
<
    string Requires = "vs_2_0 ps_2_0";
    float MaxDistance = 40.0;
    string Fallback = "strand_four_lights_ps14";
    string UIName = "Strands, table per pixel (texel-centre mapping)";
 COST_strand_lut
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandVS(1.0, STRAND_LIGHTS);
        PixelShader = compile ps_2_0 StrandLutPS(STRAND_LIGHTS, false, false);
    }
}

// Measurement variant: only chosen when the "measurement" scheme is asked for by name.
technique strand_lut_seed_wrap
<
    string Requires = "vs_2_0 ps_2_0";
    string Scheme = "measurement";
    float MaxDistance = 40.0;
    string UIName = "Strands, table per pixel (seed's wrap bias)";
 COST_strand_lut_seed_wrap
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandVS(0.5, STRAND_LIGHTS);
        PixelShader = compile ps_2_0 StrandLutSeedWrapPS();
    }
}

// Four coloured lights in one pass: the seed's DirectX 8.1 ps.1.4 technique (one table
// fetch per light, diffuse * base + specular, weighted by each light's colour), as HLSL.
technique strand_four_lights
<
    string Requires = "vs_2_0 ps_2_0";
    string Generation = "dx8_1: the seed's ps.1.4 four-light shader";
    float MaxDistance = 40.0;
    string Fallback = "strand_four_lights_ps14";
    string UIName = "Strands, four coloured lights, table per pixel";
 COST_strand_four_lights
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandVS(1.0, 4);
        PixelShader = compile ps_2_0 StrandLutPS(4, false, false);
    }
}

technique strand_per_vertex
<
    string Requires = "vs_2_0 ps_2_0";
    float MinDistance = 40.0;
    string Fallback = "strand_lut_ps11";
    string UIName = "Strands, per vertex (far away)";
 COST_strand_per_vertex
>
{
    pass p0
    {
        VertexShader = compile vs_2_0 StrandPerVertexVS();
        PixelShader = compile ps_2_0 StrandPerVertexPS();
    }
}

// The seed's ps.1.4 shader verbatim except its texcrd destinations (the listing writes
// all five into r1; r1..r5 is what the dp3s read). Stage 0: direction map (alpha = 1),
// stages 1-4: the wrapped table, stage 5: base map; c1-c4 light colours. Its dp3_d2 makes
// the table's 0.5 L.T itself, so the vertex shader passes L and V unscaled (c20 = 1; the
// ps.1.1 listing's texm3x2 does not halve, and its vertex shader scales by 0.5). The sum
// has no Kd/Ks weights and no ambient: with these light colours it saturates wherever
// sin(L,T) is large (docs/effects.md).
technique strand_four_lights_ps14
<
    string Requires = "vs_1_1 ps_1_4 textures>=6";
    string Fallback = "strand_lut_ps11";
    string UIName = "Strands, four lights, ps.1.4 (DirectX 8.1)";
 COST_strand_four_lights_ps14
>
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[4] = <WorldViewProjection>;
        VertexShaderConstant[16] = <Light0Direction>;
        VertexShaderConstant[17] = <Light1Direction>;
        VertexShaderConstant[18] = <Light2Direction>;
        VertexShaderConstant[19] = <Light3Direction>;
        VertexShaderConstant[20] = float4(1.0, 1.0, 1.0, 1.0);  // unscaled: dp3_d2 halves
        VertexShaderConstant[24] = <CameraPosition>;
        PixelShaderConstant[1] = <Light0Color>;
        PixelShaderConstant[2] = <Light1Color>;
        PixelShaderConstant[3] = <Light2Color>;
        PixelShaderConstant[4] = <Light3Color>;
        Texture[0] = <DirectionMap>;
        Texture[1] = <StrandLutWrap>;
        Texture[2] = <StrandLutWrap>;
        Texture[3] = <StrandLutWrap>;
        Texture[4] = <StrandLutWrap>;
        Texture[5] = <BaseMap>;
        AddressU[1] = Wrap; AddressV[1] = Wrap;
        AddressU[2] = Wrap; AddressV[2] = Wrap;
        AddressU[3] = Wrap; AddressV[3] = Wrap;
        AddressU[4] = Wrap; AddressV[4] = Wrap;
        VertexShader =
        decl
        {
            stream 0;
            float v0[3];    // position
            float v3[3];    // normal
            float v7[2];    // texcoord
            float v8[3];    // tangent
        }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c4          // clip-space position
            m3x3 r3, v8, c0            // tangent to world
            m3x3 r5, v3, c0            // normal to world
            mul r0, r3.zxyw, r5.yzxw   // binormal by cross product
            mad r4, r3.yzxw, r5.zxyw, -r0
            m4x4 r2, v0, c0            // world position
            add r2, -r2, c24           // to the camera
            dp3 r11.x, r2.xyz, r2.xyz
            rsq r11.xyz, r11.x
            mul r2.xyz, r2.xyz, r11.xyz
            dp3 r8.x, r3, r2           // view into tangent space
            dp3 r8.y, r4, r2
            dp3 r8.z, r5, r2
            mul oT5.xyz, r8.xyz, c20   // V (c20 = 1)
            dp3 r6.x, r3, -c16         // light 0
            dp3 r6.y, r4, -c16
            dp3 r6.z, r5, -c16
            mul oT1.xyz, r6.xyz, c20
            dp3 r6.x, r3, -c17         // light 1
            dp3 r6.y, r4, -c17
            dp3 r6.z, r5, -c17
            mul oT2.xyz, r6.xyz, c20
            dp3 r6.x, r3, -c18         // light 2
            dp3 r6.y, r4, -c18
            dp3 r6.z, r5, -c18
            mul oT3.xyz, r6.xyz, c20
            dp3 r6.x, r3, -c19         // light 3
            dp3 r6.y, r4, -c19
            dp3 r6.z, r5, -c19
            mul oT4.xyz, r6.xyz, c20
            mov oT0.xy, v7.xy
        };
        PixelShader =
        asm
        {
            ps.1.4
            texld r0, t0             // sample bump map (note alpha channel = 1)
            texcrd r1, t1
            texcrd r2, t2
            texcrd r3, t3
            texcrd r4, t4
            texcrd r5, t5

            dp3_d2 r1.rba, r1, r0_bx2  // .5 L0.T
            dp3_d2 r2.rba, r2, r0_bx2  // .5 L1.T
            dp3_d2 r3.rba, r3, r0_bx2  // .5 L2.T
            dp3_d2 r4.rba, r4, r0_bx2  // .5 L3.T
            dp3_d2 r1.g, r5, r0_bx2    // .5 V.T
            mov r2.g, r1.g
            mov r3.g, r1.g
            mov r4.g, r1.g

            phase
            texld r1, r1             // aniso lookup 0
            texld r2, r2             // aniso lookup 1
            texld r3, r3             // aniso lookup 2
            texld r4, r4             // aniso lookup 3
            texld r5, t0             // sample base map

            mad r1, r1, r5, r1.a     // diffuse0 * base + specular
            mad r2, r2, r5, r2.a     // diffuse1 * base + specular
            mad r3, r3, r5, r3.a     // diffuse2 * base + specular
            mad r4, r4, r5, r4.a     // diffuse3 * base + specular
            mul r0, r1, c1           // lightcolor0 * light0 effect
            mad r0, r2, c2, r0       // lightcolor1 * light1 effect + previous
            mad r0, r3, c3, r0       // lightcolor2 * light2 effect + previous
            mad r0, r4, c4, r0       // lightcolor3 * light3 effect + previous
        };
    }
}

// The seed's ps.1.1 shader verbatim: one light, stage 0 direction map, stage 1 base map,
// stage 3 the wrapped table addressed by texm3x2pad/texm3x2tex (0.5 L.T, 0.5 V.T).
technique strand_lut_ps11
<
    string Requires = "vs_1_1 ps_1_1 textures>=4";
    string UIName = "Strands, one light, ps.1.1 (DirectX 8)";
 COST_strand_lut_ps11
>
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[4] = <WorldViewProjection>;
        VertexShaderConstant[16] = <Light0Direction>;
        VertexShaderConstant[20] = float4(0.5, 0.5, 0.5, 0.5);
        VertexShaderConstant[24] = <CameraPosition>;
        PixelShaderConstant[0] = <Light0Color>;
        Texture[0] = <DirectionMap>;
        Texture[1] = <BaseMap>;
        Texture[3] = <StrandLutWrap>;
        AddressU[3] = Wrap;
        AddressV[3] = Wrap;
        VertexShader =
        decl
        {
            stream 0;
            float v0[3];    // position
            float v3[3];    // normal
            float v7[2];    // texcoord
            float v8[3];    // tangent
        }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c4
            m3x3 r3, v8, c0
            m3x3 r5, v3, c0
            mul r0, r3.zxyw, r5.yzxw
            mad r4, r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, -c16         // light into tangent space
            dp3 r6.y, r4, -c16
            dp3 r6.z, r5, -c16
            mul oT2.xyz, r6.xyz, c20   // 0.5 L: first row of the 3x2 multiply
            m4x4 r2, v0, c0
            add r2, -r2, c24
            dp3 r11.x, r2.xyz, r2.xyz
            rsq r11.xyz, r11.x
            mul r2.xyz, r2.xyz, r11.xyz
            dp3 r8.x, r3, r2           // view into tangent space
            dp3 r8.y, r4, r2
            dp3 r8.z, r5, r2
            mul oT3.xyz, r8.xyz, c20   // 0.5 V: second row
            mov oT0.xy, v7.xy
            mov oT1.xy, v7.xy
        };
        PixelShader =
        asm
        {
            ps.1.1
            tex t0                 // Contains direction of anisotropy in tangent space
            tex t1                 // base map
            texm3x2pad t2, t0_bx2  // Perform first row of matrix multiply.
            texm3x2tex t3, t0_bx2  // Second row, then sample the aniso lookup table
            mad r0, t3, t1, t1.a   // basemap * diffuse + specular
            mul r0, r0, c0         // color * basemap * diffuse
        };
    }
}
