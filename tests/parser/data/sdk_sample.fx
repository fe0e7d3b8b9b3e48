// A DirectX-SDK-sample-style effect: SAS annotations, shared parameters, sampler_state,
// D3D9 techniques with compile, and a technique10 with state objects.

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "object";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=Main;";
> = 0.8;

shared float4x4 g_mWorldViewProjection : WORLDVIEWPROJECTION < string UIWidget = "None"; >;
shared float4x4 g_mWorld : WORLD;
shared float g_fTime : TIME;

float3 g_LightDir : DIRECTION <
    string Object = "DirectionalLight0";
    string Space = "World";
    string UIName = "Light Direction";
> = {0.577f, -0.577f, 0.577f};

float4 g_MaterialDiffuse : DIFFUSE < string UIName = "Diffuse"; string UIWidget = "Color"; >
    = float4(1.0f, 1.0f, 1.0f, 1.0f);

float g_Gloss < string UIName = "Gloss"; float UIMin = 1; float UIMax = 128; float UIStep = 1; >
    = 32;

int g_nNumLights < string UIName = "Lights"; int UIMin = 1; int UIMax = 4; > = 1;
bool g_bTexture = true;
float2 g_Range[2] < float2 Default = {0, 1}; int Dims[2] = {2, 2}; > = { {0, 1}, {0, 2} };

texture g_MeshTexture : DIFFUSEMAP < string ResourceName = "Tiny_skin.dds"; string ResourceType = "2D"; >;

sampler MeshTextureSampler = sampler_state
{
    Texture = <g_MeshTexture>;
    MipFilter = LINEAR;
    MinFilter = LINEAR;
    MagFilter = LINEAR;
    AddressU = Wrap;
    AddressV = Wrap;
};

struct VS_OUTPUT
{
    float4 Position   : POSITION;
    float4 Diffuse    : COLOR0;
    float2 TextureUV  : TEXCOORD0;
};

VS_OUTPUT RenderSceneVS(float4 vPos : POSITION, float3 vNormal : NORMAL,
                        float2 vTexCoord0 : TEXCOORD0, uniform int nNumLights,
                        uniform bool bTexture, uniform bool bAnimate)
{
    VS_OUTPUT Output;
    float3 vNormalWorldSpace;
    Output.Position = mul(vPos, g_mWorldViewProjection);
    vNormalWorldSpace = normalize(mul(vNormal, (float3x3)g_mWorld));
    Output.Diffuse.rgb = g_MaterialDiffuse.rgb * max(0, dot(vNormalWorldSpace, g_LightDir));
    Output.Diffuse.a = 1.0f;
    Output.TextureUV = bTexture ? vTexCoord0 : 0;
    return Output;
}

struct PS_OUTPUT
{
    float4 RGBColor : COLOR0;
};

PS_OUTPUT RenderScenePS(VS_OUTPUT In, uniform bool bTexture)
{
    PS_OUTPUT Output;
    if (bTexture)
        Output.RGBColor = tex2D(MeshTextureSampler, In.TextureUV) * In.Diffuse;
    else
        Output.RGBColor = In.Diffuse;
    return Output;
}

technique RenderSceneWithTexture1Light < string Script = "Pass=P0;"; >
{
    pass P0 < string Script = "Draw=geometry;"; >
    {
        VertexShader = compile vs_2_0 RenderSceneVS(1, true, true);
        PixelShader  = compile ps_2_0 RenderScenePS(true);
        ZEnable = true;
        ZWriteEnable = true;
        CullMode = CCW;
        AlphaBlendEnable = false;
    }
}

technique RenderSceneNoTexture
{
    pass P0
    {
        VertexShader = compile vs_1_1 RenderSceneVS(1, false, true);
        PixelShader  = NULL;
        Sampler[0] = (MeshTextureSampler);
        ColorOp[0] = SelectArg1;
        ColorArg1[0] = Diffuse;
    }
}

// Direct3D 10 form of the same effect.
cbuffer cbPerObject : register(b0)
{
    float4x4 g_mWorldViewProj10 : WORLDVIEWPROJECTION;
    float4   g_vDiffuse10 = float4(1, 1, 1, 1);
};

Texture2D<float4> g_txDiffuse : register(t0);

SamplerState g_samLinear : register(s0)
{
    Filter = MIN_MAG_MIP_LINEAR;
    AddressU = Wrap;
    AddressV = Wrap;
};

BlendState NoBlending
{
    AlphaToCoverageEnable = FALSE;
    BlendEnable[0] = FALSE;
    RenderTargetWriteMask[0] = 0x0F;
};

DepthStencilState EnableDepth
{
    DepthEnable = TRUE;
    DepthWriteMask = ALL;
    DepthFunc = LESS_EQUAL;
};

RasterizerState CullBack { CullMode = Back; FillMode = Solid; MultisampleEnable = FALSE; };

struct VS_OUTPUT10
{
    float4 Pos : SV_POSITION;
    float2 Tex : TEXCOORD0;
};

VS_OUTPUT10 VS10(float4 Pos : POSITION, float2 Tex : TEXCOORD0)
{
    VS_OUTPUT10 o;
    o.Pos = mul(Pos, g_mWorldViewProj10);
    o.Tex = Tex;
    return o;
}

float4 PS10(VS_OUTPUT10 i) : SV_Target
{
    return g_txDiffuse.Sample(g_samLinear, i.Tex) * g_vDiffuse10;
}

technique10 Render10 < string Script = "Pass=P0;"; >
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS10()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS10()));
        SetBlendState(NoBlending, float4(0.0f, 0.0f, 0.0f, 0.0f), 0xFFFFFFFF);
        SetDepthStencilState(EnableDepth, 0);
        SetRasterizerState(CullBack);
    }
}
