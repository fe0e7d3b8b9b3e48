// BRDF rendering by homomorphic factorization (McCool, Ang and Ahmad), the D3DX seed's
// DirectX 8 effect: f(wi, wo) cos(th_i) ~= p_i(wi) q(wh) p_o(wo), three factor textures
// looked up with the tangent-space light, half and view vectors and multiplied. Expect a
// sphere with the analytic BRDF's highlight shape (here an anisotropic Ward lobe,
// stretched along the tangent), modulated by the object texture.
// The factors come from the "brdf_factor" generator (parabolic maps, clamp addressing; cube
// maps for the seed's listing).
#include "common.fxh"
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

float4 lhtR : DIRECTION < string UIName = "Light direction (from the light)"; string Object = "DirectionalLight0"; string Space = "World"; > = {0.0, -0.707, -0.707, 0.0};
float4 MaterialColor : DIFFUSE < string UIName = "Material color"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0, 1.0};
float4 CameraPosition : CAMERAPOSITION < string UIWidget = "None"; >;

// One fit per factor, all with the same analytic BRDF (a Ward lobe, AlphaX along T).
texture BRDFTexture1 < string Generator = "brdf_factor"; string Factor = "out"; int Width = 32; string Lobe = "ward"; float AlphaX = 0.15; float AlphaY = 0.35; int Samples = 16384; int Iterations = 300; int Seed = 1; string Format = "float32"; >;
texture BRDFTexture2 < string Generator = "brdf_factor"; string Factor = "in"; int Width = 32; string Lobe = "ward"; float AlphaX = 0.15; float AlphaY = 0.35; int Samples = 16384; int Iterations = 300; int Seed = 1; string Format = "float32"; >;
texture BRDFTexture3 < string Generator = "brdf_factor"; string Factor = "half"; int Width = 32; string Lobe = "ward"; float AlphaX = 0.15; float AlphaY = 0.35; int Samples = 16384; int Iterations = 300; int Seed = 1; string Format = "float32"; >;
// The same fits resampled as cube maps (Shape = "cube"), for the seed's listing: its texture
// stages sample the factors with the raw tangent-space directions.
textureCUBE BRDFCube1 < string Generator = "brdf_factor"; string Factor = "out"; string Shape = "cube"; int Width = 32; string Lobe = "ward"; float AlphaX = 0.15; float AlphaY = 0.35; int Samples = 16384; int Iterations = 300; int Seed = 1; string Format = "float32"; >;
textureCUBE BRDFCube2 < string Generator = "brdf_factor"; string Factor = "in"; string Shape = "cube"; int Width = 32; string Lobe = "ward"; float AlphaX = 0.15; float AlphaY = 0.35; int Samples = 16384; int Iterations = 300; int Seed = 1; string Format = "float32"; >;
textureCUBE BRDFCube3 < string Generator = "brdf_factor"; string Factor = "half"; string Shape = "cube"; int Width = 32; string Lobe = "ward"; float AlphaX = 0.15; float AlphaY = 0.35; int Samples = 16384; int Iterations = 300; int Seed = 1; string Format = "float32"; >;
// An engine binds the object's own texture here; a faint checker shows the detail layer
// without hiding the lobe.
texture ObjectTexture : DIFFUSEMAP < string Generator = "color_map"; string Pattern = "checker"; string Color0 = "0.8 0.8 0.8"; string Color1 = "1 1 1"; int Checks = 8; int Width = 256; string UIName = "Object texture"; >;

// The seed's viewer strings.
string tec0 = "BRDF Shader";
float4 BCLR < string UIName = "Background (the seed: DWORD 0xff0000ff, ARGB)"; string UIWidget = "Color"; > = {0.0, 0.0, 1.0, 1.0};
string XFile = "sphere.x";

sampler2D OutFactorSampler = sampler_state { Texture = <BRDFTexture1>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };
sampler2D InFactorSampler = sampler_state { Texture = <BRDFTexture2>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };
sampler2D HalfFactorSampler = sampler_state { Texture = <BRDFTexture3>; MinFilter = Linear; MagFilter = Linear; MipFilter = None; AddressU = Clamp; AddressV = Clamp; };
sampler2D ObjectSampler = sampler_state { Texture = <ObjectTexture>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };

struct BrdfVertex
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
    float3 tangent  : TANGENT;
    float3 binormal : BINORMAL;
    float2 uv       : TEXCOORD0;
};

struct BrdfPixel
{
    float4 position : POSITION;
    float2 uv       : TEXCOORD0;
    float3 view     : TEXCOORD1;  // tangent space
    float3 light    : TEXCOORD2;
    float3 halfway  : TEXCOORD3;
};

BrdfPixel BrdfVS(BrdfVertex IN)
{
    BrdfPixel OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.uv = IN.uv;
    float3x3 frame = tangent_frame(IN.normal, IN.tangent, IN.binormal);
    float3 v = normalize_or(ViewInverse[3].xyz - mul(IN.position, World).xyz, float3(0.0, 0.0, 1.0));
    float3 l = normalize_or(-lhtR.xyz, float3(0.0, 0.0, 1.0));
    OUT.view = mul(frame, v);
    OUT.light = mul(frame, l);
    OUT.halfway = mul(frame, half_vector(l, v));
    return OUT;
}

// Parabolic-map coordinates of an upper-hemisphere direction (parabolic_coords in
// lib/shading/fx/shading/brdf_factorization.h); below the horizon the map's rim is reused.
float2 parabolic(float3 w)
{
    float3 d = normalize_or(w, float3(0.0, 0.0, 1.0));
    return 0.5 + 0.5 * d.xy / (1.0 + max(d.z, 0.0));
}

float4 BrdfPS(BrdfPixel IN) : COLOR0
{
    float product = tex2D(OutFactorSampler, parabolic(IN.view)).r *
                    tex2D(InFactorSampler, parabolic(IN.light)).r *
                    tex2D(HalfFactorSampler, parabolic(IN.halfway)).r;
    // The light below the surface: the factors extrapolate there, the BRDF is zero.
    float lit = IN.light.z > 0.0 ? 1.0 : 0.0;
    float4 object = tex2D(ObjectSampler, IN.uv);
    return float4(product * lit * object.rgb * MaterialColor.rgb, object.a);
}

technique brdf_ps20
< string Requires = "vs_2_0 ps_2_0 float_textures"; string Fallback = "tec0"; string UIName = "BRDF factorization, HLSL ps_2_0"; COST_brdf_ps20 >
{
    pass p0
    {
        VertexShader = compile vs_2_0 BrdfVS();
        PixelShader = compile ps_2_0 BrdfPS();
    }
}

// The seed's technique. Its factors are cube maps read with 3D texture coordinates (the
// BRDFCube textures). The listing's `dp3 oT2.z,-c16,r0` (light z into the half-vector
// register) is corrected to oT1.z, and c10 (the camera, never set in the listing) is bound
// to CameraPosition.
technique tec0
< string Requires = "vs_1_1 ps_1_1 cube_maps textures>=4"; string UIName = "BRDF Shader (seed, vs.1.1/ps.1.1)"; COST_tec0 >
{
    pass p0
    {
        //load matrices
        VertexShaderConstant[0] = <World>;                // World Matrix
        VertexShaderConstant[4] = <WorldViewProjection>;  // World*View*Proj Matrix

        //Material properties of object
        VertexShaderConstant[9] = <MaterialColor>;
        VertexShaderConstant[10] = <CameraPosition>;

        // Light Properties.
        // lhtR, the light direction, is input from the shader app
        // for BRDFs, these color constants are built into the texture maps
        VertexShaderConstant[16] = <lhtR>;           // light direction

        Texture[0] = <BRDFCube1>;
        Texture[1] = <BRDFCube2>;
        Texture[2] = <BRDFCube3>;
        Texture[3] = <ObjectTexture>;

        // Only one colour being used
        ColorOp[1]   = Disable;
        AlphaOp[1]   = Disable;

        AddressU[0] = clamp;      // set up clamping for cube maps
        AddressV[0] = clamp;
        AddressW[0] = clamp;

        AddressU[1] = clamp;
        AddressV[1] = clamp;
        AddressW[1] = clamp;

        AddressU[2] = clamp;
        AddressV[2] = clamp;
        AddressW[2] = clamp;

        // object's detail texture
        AddressU[3] = wrap;
        AddressV[3] = wrap;

        // Definition of the vertex shader, declarations then assembly.
        VertexShader =
        decl
        {
            stream 0;
            float v0[3];      // Position
            float v3[3];      // Normal
            float v7[3];      // Texture Coord1
            float v8[3];      // Tangent
        }
        asm
        {
            vs.1.1           // version number

            m4x4 oPos, v0, c4 // transform point to projection space
            m4x4 r4,v0,c0     // transform point to world space
            m3x3 r0,v3,c0     // transform Normal to World Space, result in r0
            m3x3 r1,v8,c0     // transform Tangent to World Space

            mul r2,-r1.zxyw,r0.yzxw; // compute binorm with cross product
            mad r2,-r1.yzxw,r0.zxyw,-r2;

            // get negative view vector
            add r4.xyz,-r4.xyz,c10
            dp3 r5.x,r4.xyz,r4.xyz
            rsq r5.x,r5.x
            mul r4.xyz,r5.xxx,r4.xyz

            //compute the half angle and normalize
            add r5.xyz,r4.xyz,-c16
            dp3 r6.x,r5.xyz,r5.xyz
            rsq r6.x,r6.x
            mul r5.xyz,r6.xxx,r5.xyz

            //now inverse transform everything
            //r1 = tangent
            //r2 = binormal
            //r0 = normal

            //t0 = view
            dp3 oT0.x,r4,r1
            dp3 oT0.y,r4,r2
            dp3 oT0.z,r4,r0

            //t1 = -light
            dp3 oT1.x,-c16,r1
            dp3 oT1.y,-c16,r2
            dp3 oT1.z,-c16,r0

            //t2 = half angle
            dp3 oT2.x,r5,r1
            dp3 oT2.y,r5,r2
            dp3 oT2.z,r5,r0

            //object might have its own texture
            mov oT3.xy,v7.xy

            //move diffuse color in
            mov oD0,c9
        };

        pixelshader =
        asm
        {
            ps.1.1
            tex t0
            tex t1
            tex t2
            tex t3

            mul r0,t0,t1    // combine 1st 2 brdf factors
            mul r0,r0,t2    // multiply in 3rd factor
            mul r0,r0,t3    // apply detail texture
            mul r0,r0,v0    // light using diffuse primary color
        };
    }
}
