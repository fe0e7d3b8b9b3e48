// Rule: fx_5_0 dynamic linkage: an interface variable holds the class instance the application
// binds (FX11's SetClassInstance); a call through it runs the bound class's method, whose
// member data is the instance's. BindInterfaces binds a shader's interface parameters to
// interface variables or class instances, in parameter order.
interface iLight
{
    float3 Illuminate(float3 normal);
};

interface iTint
{
    float4 Apply(float4 colour);
};

class cAmbientLight : iLight
{
    float3 colour;
    float3 Illuminate(float3 normal) { return colour; }
};

class cDirectionalLight : iLight
{
    float3 colour;
    float3 direction;
    float3 Illuminate(float3 normal) { return colour * saturate(dot(normal, -direction)); }
};

class cNoTint : iTint
{
    float4 Apply(float4 colour) { return colour; }
};

class cGreyTint : iTint
{
    float strength;
    float4 Shade(float4 colour) { return lerp(colour, dot(colour.rgb, 0.333).xxxx, strength); }
    float4 Apply(float4 colour) { return Shade(colour); }
};

iLight g_abstractLight;
iLight g_abstractLights[2];
iTint g_abstractTint;

cAmbientLight g_ambient;
cDirectionalLight g_sun;
cDirectionalLight g_lamps[2];
cNoTint g_noTint;
cGreyTint g_grey;

float4x4 g_mWorldViewProjection;

struct VS_OUTPUT
{
    float4 position : SV_POSITION;
    float3 normal : NORMAL;
};

VS_OUTPUT VS(float4 position : POSITION, float3 normal : NORMAL)
{
    VS_OUTPUT o;
    o.position = mul(position, g_mWorldViewProjection);
    o.normal = normal;
    return o;
}

float4 LitPS(VS_OUTPUT input, iLight light, iTint tint) : SV_TARGET
{
    float3 n = normalize(input.normal);
    return tint.Apply(float4(light.Illuminate(n) + g_abstractLights[1].Illuminate(n), 1));
}

float4 GlobalPS(VS_OUTPUT input) : SV_TARGET
{
    return float4(g_abstractLight.Illuminate(normalize(input.normal)) + g_sun.Illuminate(input.normal), 1);
}

PixelShader g_litPS = CompileShader(ps_5_0, LitPS());

technique11 BoundToVariables
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(BindInterfaces(g_litPS, g_abstractLight, g_abstractTint));
    }
}

technique11 BoundToInstances
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(BindInterfaces(CompileShader(ps_5_0, LitPS()), g_lamps[1], g_grey));
    }
}

technique11 GlobalInterface
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(CompileShader(ps_5_0, GlobalPS()));
    }
}
