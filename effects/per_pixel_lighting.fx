// Per-pixel lighting in tangent space (Taylor / Baker / Boyd; seed:
// d3dx-effects-and-per-pixel-lighting.txt, "Per-Pixel Lighting"). One look, one technique
// per hardware generation: HLSL ps_2_0, the seed's vs.1.1/ps.1.1 assembly, the
// DOTPRODUCT3 multitexture fallback (DirectX 7) and emboss bump mapping (DirectX 6).
// Schemes: "diffuse" (N.L only) and "specular" (N.L plus a (N.H)^n highlight).
// Fixed-function techniques parse and check now; they run once legacy emulation exists.
#include "common.fxh"
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

float4 CameraPosition : CAMERAPOSITION < string UIWidget = "None"; >;
float3 LightDirection : DIRECTION < string UIName = "Light direction"; string Object = "DirectionalLight0"; string Space = "World"; > = {0.45, -0.55, -0.7};
float4 LightColor : DIFFUSE < string UIName = "Light color"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0, 1.0};
float SpecularExponent : SPECULARPOWER < string UIName = "Exponent (native pow)"; float UIMin = 1.0; float UIMax = 256.0; > = 100.0;
float4 EmbossOffset < string UIName = "Emboss shift (texels along the light)"; float UIMin = 0.0; float UIMax = 0.01; > = {0.004, 0.004, 0.0, 0.0};

// An engine binds its own textures here; the generators bake the seed's bumpy earth from
// one height field (same Frequency, Octaves, Seed): land above sea level, bumps and the
// emboss height map agree texel for texel.
texture NormalMap : NORMALMAP < string Generator = "normal_map"; string Pattern = "noise"; float Strength = 0.7; int Frequency = 8; int Octaves = 4; int Width = 256; int Seed = 3; string Alpha = "height"; string UIName = "Normal map (0.5n+0.5)"; >;
texture ColorMap : DIFFUSEMAP < string Generator = "color_map"; string Pattern = "noise"; string Color0 = "0.08 0.2 0.55"; string Color1 = "0.4 0.55 0.25"; float Threshold = 0.5; float Softness = 0.04; int Frequency = 8; int Octaves = 4; int Width = 256; int Seed = 3; string UIName = "Color map"; >;
texture HeightMap : HEIGHTMAP < string Generator = "height_map"; string Pattern = "noise"; int Frequency = 8; int Octaves = 4; int Width = 256; int Seed = 3; string UIName = "Height map (emboss)"; >;
texture HighlightMap < string Generator = "color_map"; string Pattern = "spot"; string Color0 = "0 0 0"; string Color1 = "1 1 1"; float Radius = 0.2; int Width = 128; string UIName = "Highlight spot (specular emboss)"; >;
// The seed's LightEval table: rgb = pow(v, 100), a = u (D3DXFillTexture's texel centres).
texture LightEval < string Generator = "pow"; int Width = 256; int Height = 256; float Exponent = 100; string Format = "unorm8"; >;

sampler2D NormalSampler = sampler_state { Texture = <NormalMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };
sampler2D ColorSampler = sampler_state { Texture = <ColorMap>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };
sampler2D LightEvalSampler = sampler_state { Texture = <LightEval>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };

struct LitVertex
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
    float3 tangent  : TANGENT;
    float3 binormal : BINORMAL;
    float2 uv       : TEXCOORD0;
};

struct LitPixel
{
    float4 position : POSITION;
    float2 uv       : TEXCOORD0;
    float3 light    : TEXCOORD1;  // tangent space, to the light
    float3 halfway  : TEXCOORD2;  // tangent space half vector
};

LitPixel TangentSpaceVS(LitVertex IN)
{
    LitPixel OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.uv = IN.uv;
    float3x3 frame = tangent_frame(IN.normal, IN.tangent, IN.binormal);
    float3 world = mul(IN.position, World).xyz;
    float3 l = normalize_or(-LightDirection, float3(0.0, 0.0, 1.0));
    float3 v = normalize_or(ViewInverse[3].xyz - world, float3(0.0, 0.0, 1.0));
    OUT.light = mul(frame, l);
    OUT.halfway = mul(frame, half_vector(l, v));
    return OUT;
}

float3 surface_normal(float2 uv)
{
    return normalize_or(tex2D(NormalSampler, uv).xyz * 2.0 - 1.0, float3(0.0, 0.0, 1.0));
}

// How the highlight's exponent is evaluated.
#define SPECULAR_NONE 0
#define SPECULAR_SQUARING 1   // x^16 by four multiplies (the seed's ps.1.1 "pow2 by multiplies")
#define SPECULAR_TABLE 2      // the LightEval table, indexed (N.L, N.H) like texm3x2tex
#define SPECULAR_POW 3        // native pow (ps_2_0 has it)

float4 TangentSpacePS(LitPixel IN, uniform int specular_mode) : COLOR0
{
    float3 n = surface_normal(IN.uv);
    float3 l = normalize_or(IN.light, float3(0.0, 0.0, 1.0));
    float4 color = tex2D(ColorSampler, IN.uv);
    float nl = saturate(dot(n, l));
    float nh = saturate(dot(n, normalize_or(IN.halfway, float3(0.0, 0.0, 0.0))));
    float specular = 0.0;
    if (specular_mode == SPECULAR_SQUARING)
    {
        float x2 = nh * nh, x4 = x2 * x2, x8 = x4 * x4;
        specular = x8 * x8;
    }
    else if (specular_mode == SPECULAR_TABLE)
    {
        // Naive mapping as D3DXFillTexture filled it: texel i holds u = (i + 0.5) / 256.
        specular = tex2D(LightEvalSampler, float2(nl, nh)).r;
    }
    else if (specular_mode == SPECULAR_POW)
    {
        specular = guarded_pow(nh, SpecularExponent);
    }
    return float4(LightColor.rgb * (color.rgb * nl + specular), color.a);
}

technique diffuse_ps20
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "diffuse"; string Fallback = "diffuse_ps11"; string UIName = "Diffuse, HLSL ps_2_0"; COST_diffuse_ps20 >
{
    pass p0
    {
        VertexShader = compile vs_2_0 TangentSpaceVS();
        PixelShader = compile ps_2_0 TangentSpacePS(SPECULAR_NONE);
    }
}

// The seed's diffuse vertex and pixel shaders (light in oD0, biased by 0.5).
technique diffuse_ps11
< string Requires = "vs_1_1 ps_1_1"; string Scheme = "diffuse"; string Fallback = "dot3_multitexture"; string UIName = "Diffuse, ps.1.1 (DirectX 8)"; COST_diffuse_ps11 >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[4] = <WorldViewProjection>;
        VertexShaderConstant[16] = <LightDirection>;
        VertexShaderConstant[20] = float4(0.5, 0.5, 0.5, 0.5);
        Texture[0] = <ColorMap>;
        Texture[1] = <NormalMap>;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[2]; float v8[3]; }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c4          // transform position
            m3x3 r3, v8, c0            // gen tangent
            m3x3 r5, v3, c0            // gen normal
            mul r0, -r3.zxyw, r5.yzxw  // gen binormal via cross product
            mad r4, -r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, -c16         // diffuse, transform the light vector
            dp3 r6.y, r4, -c16
            dp3 r6.z, r5, -c16
            mad oD0.xyz, r6.xyz, c20, c20  // light in oD0: multiply by a half then add half
            mov oT0.xy, v7.xy
            mov oT1.xy, v7.xy
        };
        PixelShader =
        asm
        {
            ps.1.1
            tex t0                     // sample texture
            tex t1                     // sample normal
            dp3_sat r1, t1_bx2, v0_bx2 // dot(normal, light)
            mul r0, t0, r1             // modulate against base color
        };
    }
}

// DirectX 7: D3DTOP_DOTPRODUCT3 (implicit _bx2 and _sat), then modulate by the color map.
// The light vector arrives biased in the diffuse color from the same vertex shader.
technique dot3_multitexture
< string Requires = "vs_1_1 fixed_function_stages dot3 textures>=2"; string Scheme = "diffuse"; string Fallback = "emboss"; string UIName = "Diffuse, DOTPRODUCT3 multitexture (DirectX 7)"; COST_dot3_multitexture >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[4] = <WorldViewProjection>;
        VertexShaderConstant[16] = <LightDirection>;
        VertexShaderConstant[20] = float4(0.5, 0.5, 0.5, 0.5);
        Texture[0] = <NormalMap>;
        Texture[1] = <ColorMap>;
        TexCoordIndex[0] = 0;
        TexCoordIndex[1] = 0;
        ColorOp[0] = DotProduct3;
        ColorArg1[0] = Texture;
        ColorArg2[0] = Diffuse;
        ColorOp[1] = Modulate;
        ColorArg1[1] = Texture;
        ColorArg2[1] = Current;
        ColorOp[2] = Disable;
        AlphaOp[2] = Disable;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[2]; float v8[3]; }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c4
            m3x3 r3, v8, c0
            m3x3 r5, v3, c0
            mul r0, -r3.zxyw, r5.yzxw
            mad r4, -r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, -c16
            dp3 r6.y, r4, -c16
            dp3 r6.z, r5, -c16
            mad oD0.xyz, r6.xyz, c20, c20
            mov oT0.xy, v7.xy
        };
    }
}

// DirectX 6: emboss. The height map shifted toward the light is subtracted (AddSigned of
// the complement) from the unshifted one; Modulate2X would brighten it as the seed says.
technique emboss
< string Requires = "vs_1_1 fixed_function_stages subtract textures>=2"; string Scheme = "diffuse"; string UIName = "Diffuse, emboss bump mapping (DirectX 6)"; COST_emboss >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[8] = <WorldViewProjection>;
        VertexShaderConstant[12] = <LightDirection>;
        VertexShaderConstant[24] = <EmbossOffset>;
        Texture[0] = <HeightMap>;
        Texture[1] = <HeightMap>;
        TexCoordIndex[0] = 0;
        TexCoordIndex[1] = 1;
        ColorOp[0] = SelectArg1;
        ColorArg1[0] = Texture;
        ColorOp[1] = AddSigned;
        ColorArg1[1] = Texture | Complement;
        ColorArg2[1] = Current;
        ColorOp[2] = Disable;
        AlphaOp[2] = Disable;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[2]; float v8[3]; }
        asm
        {
            vs.1.1                     // for emboss
            m4x4 oPos, v0, c8          // generate output position
            m3x3 r3, v8, c0            // transform tan to world space
            m3x3 r5, v3, c0            // transform norm to world space
            mul r0, r3.zxyw, r5.yzxw   // cross prod to generate binormal
            mad r4, r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, c12          // tangent space light in r6
            dp3 r6.y, r4, c12          // only x and y shifts matter
            mul r1.xy, r6.xy, -c24.xy  // set up the texture, based on light direction
            mov oT0.xy, v7.xy          // copy the base height map
            add oT1.xy, v7.xy, r1.xy   // offset the normal height map
            dp3 oD0.xyz, v3.xyz, c12.xyz  // simple dot product for global darkening
        };
    }
}

technique specular_pow_ps20
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "specular"; string Fallback = "specular_table_ps11"; string UIName = "Specular, native pow, HLSL ps_2_0"; COST_specular_pow_ps20 >
{
    pass p0
    {
        VertexShader = compile vs_2_0 TangentSpaceVS();
        PixelShader = compile ps_2_0 TangentSpacePS(SPECULAR_POW);
    }
}

technique specular_table_ps20
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "specular"; string UIName = "Specular, LightEval table, HLSL ps_2_0"; COST_specular_table_ps20 >
{
    pass p0
    {
        VertexShader = compile vs_2_0 TangentSpaceVS();
        PixelShader = compile ps_2_0 TangentSpacePS(SPECULAR_TABLE);
    }
}

technique specular_squaring_ps20
< string Requires = "vs_2_0 ps_2_0"; string Scheme = "specular"; string UIName = "Specular, x^16 by squaring, HLSL ps_2_0";  COST_specular_squaring_ps20 >
{
    pass p0
    {
        VertexShader = compile vs_2_0 TangentSpaceVS();
        PixelShader = compile ps_2_0 TangentSpacePS(SPECULAR_SQUARING);
    }
}

// The seed's table-lookup shaders: texm3x2pad/texm3x2tex form (N.L, N.H) and read the
// LightEval table at stage 2. The listing reads t3 without sampling it; `tex t3` added.
technique specular_table_ps11
< string Requires = "vs_1_1 ps_1_1 textures>=4"; string Scheme = "specular"; string Fallback = "specular_squaring_ps11"; string UIName = "Specular, table lookup, ps.1.1 (DirectX 8)"; COST_specular_table_ps11 >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[4] = <WorldViewProjection>;
        VertexShaderConstant[16] = <LightDirection>;
        VertexShaderConstant[24] = <CameraPosition>;
        Texture[0] = <NormalMap>;
        Texture[2] = <LightEval>;
        Texture[3] = <ColorMap>;
        AddressU[2] = Clamp;
        AddressV[2] = Clamp;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[2]; float v8[3]; }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c4          // transform position
            m3x3 r3, v8, c0            // transform tangent
            m3x3 r5, v3, c0            // and normal
            mul r0, -r3.zxyw, r5.yzxw  // cross product
            mad r4, -r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, -c16         // light into tangent space (first row)
            dp3 r6.y, r4, -c16
            dp3 r6.z, r5, -c16
            m4x4 r2, v0, c0            // transform position
            add r2, -r2, c24           // get a vector toward the camera
            dp3 r11.x, r2.xyz, r2.xyz
            rsq r11.xyz, r11.x
            mul r2.xyz, r2.xyz, r11.xyz
            add r2.xyz, r2.xyz, -c16   // get half angle
            dp3 r11.x, r2.xyz, r2.xyz  // normalize
            rsq r11.xyz, r11.x
            mul r2.xyz, r2.xyz, r11.xyz
            dp3 r8.x, r3, r2           // transform the half angle vector
            dp3 r8.y, r4, r2
            dp3 r8.z, r5, r2
            mov oT0.xy, v7.xy          // coord to sample normal from
            mov oT1.xyz, r6            // the diffuse light direction
            mov oT2.xyz, r8            // not a tex coord, but half angle
            mov oT3.xy, v7.xy
        };
        PixelShader =
        asm
        {
            ps.1.1                     // exponentiation by table lookup
            tex t0                     // sample the normal map
            texm3x2pad t1, t0_bx2      // 1st row of mult, 1st dotproduct = u
            texm3x2tex t2, t0_bx2      // 2nd row of mult, 2nd dotproduct = v
            tex t3                     // color map (missing from the listing)
            mov r0, t2                 // use (u,v) above to get intensity
            mul r0, r0, t3             // blend terms
        };
    }
}

// The seed's multiply-based exponent: four squarings give x^16 in 8-bit registers (the
// banding in its Figure 5). Half vector in oD1, biased.
technique specular_squaring_ps11
< string Requires = "vs_1_1 ps_1_1"; string Scheme = "specular"; string Fallback = "specular_emboss"; string UIName = "Specular, x^16 by squaring, ps.1.1 (DirectX 8)";  COST_specular_squaring_ps11 >
{
    pass p0
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[4] = <WorldViewProjection>;
        VertexShaderConstant[16] = <LightDirection>;
        VertexShaderConstant[20] = float4(0.5, 0.5, 0.5, 0.5);
        VertexShaderConstant[24] = <CameraPosition>;
        Texture[0] = <ColorMap>;
        Texture[1] = <NormalMap>;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[2]; float v8[3]; }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c4
            m3x3 r3, v8, c0
            m3x3 r5, v3, c0
            mul r0, -r3.zxyw, r5.yzxw
            mad r4, -r3.yzxw, r5.zxyw, -r0
            m4x4 r2, v0, c0
            add r2, -r2, c24
            dp3 r11.x, r2.xyz, r2.xyz
            rsq r11.xyz, r11.x
            mul r2.xyz, r2.xyz, r11.xyz
            add r2.xyz, r2.xyz, -c16
            dp3 r11.x, r2.xyz, r2.xyz
            rsq r11.xyz, r11.x
            mul r2.xyz, r2.xyz, r11.xyz
            dp3 r8.x, r3, r2
            dp3 r8.y, r4, r2
            dp3 r8.z, r5, r2
            mad oD1.xyz, r8.xyz, c20, c20  // half-angle in oD1
            mov oT0.xy, v7.xy
            mov oT1.xy, v7.xy
        };
        PixelShader =
        asm
        {
            ps.1.1                     // pow2 by multiplies
            tex t0                     // color map
            tex t1                     // normal map
            dp3_sat r0, t1_bx2, v1_bx2 // specular lighting dot product
            mul r1, r0, r0             // 2nd power
            mul r0, r1, r1             // 4th power
            mul r1, r0, r0             // 8th power
            mul r0, r1, r1             // 16th power!
            mul r0, r0, t0             // modulate by color map
        };
    }
}

// Specular emboss (the seed describes it and skips the listing): the emboss pass, then a
// highlight spot placed by the vertex shader minus the height map, added to the frame.
technique specular_emboss
< string Requires = "vs_1_1 fixed_function_stages subtract textures>=2"; string Scheme = "specular"; string UIName = "Specular emboss (DirectX 6/7)"; COST_specular_emboss >
{
    pass diffuse
    {
        VertexShaderConstant[0] = <World>;
        VertexShaderConstant[8] = <WorldViewProjection>;
        VertexShaderConstant[12] = <LightDirection>;
        VertexShaderConstant[24] = <EmbossOffset>;
        Texture[0] = <HeightMap>;
        Texture[1] = <HeightMap>;
        ColorOp[0] = SelectArg1;
        ColorArg1[0] = Texture;
        ColorOp[1] = AddSigned;
        ColorArg1[1] = Texture | Complement;
        ColorArg2[1] = Current;
        ColorOp[2] = Disable;
        VertexShader =
        decl { stream 0; float v0[3]; float v3[3]; float v7[2]; float v8[3]; }
        asm
        {
            vs.1.1
            m4x4 oPos, v0, c8
            m3x3 r3, v8, c0
            m3x3 r5, v3, c0
            mul r0, r3.zxyw, r5.yzxw
            mad r4, r3.yzxw, r5.zxyw, -r0
            dp3 r6.x, r3, c12
            dp3 r6.y, r4, c12
            mul r1.xy, r6.xy, -c24.xy
            mov oT0.xy, v7.xy
            add oT1.xy, v7.xy, r1.xy
            dp3 oD0.xyz, v3.xyz, c12.xyz
        };
    }
    pass highlight
    {
        AlphaBlendEnable = True;
        SrcBlend = One;
        DestBlend = One;
        Texture[0] = <HighlightMap>;
        Texture[1] = <HeightMap>;
        ColorOp[0] = SelectArg1;
        ColorArg1[0] = Texture;
        ColorOp[1] = Subtract;
        ColorArg1[1] = Current;
        ColorArg2[1] = Texture;
        ColorOp[2] = Disable;
    }
}
