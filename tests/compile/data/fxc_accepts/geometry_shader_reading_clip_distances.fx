// Rule: a geometry shader may take the vertex struct with its SV_ClipDistance and
// SV_CullDistance members as its input array and pass them on (D3D10's FixedFuncEMU does);
// glslang crashes on that form (KhronosGroup/glslang#2392), fxkit rewrites it.
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 ClipPlane = { 0, 1, 0, 0 };

struct VSOut
{
    float4 pos : SV_Position;
    float3 world : TEXCOORD0;
    float clip : SV_ClipDistance0;
    float2 cull : SV_CullDistance0;
    float4 color : COLOR0;
};

VSOut VS(float4 p : POSITION)
{
    VSOut o = (VSOut)0;
    o.pos = mul(p, WorldViewProjection);
    o.world = p.xyz;
    o.clip = dot(p, ClipPlane);
    o.cull = float2(1, 1);
    o.color = float4(1, 0.5, 0.25, 1);
    return o;
}

[maxvertexcount(3)]
void GS(triangle VSOut input[3], inout TriangleStream<VSOut> stream)
{
    float3 n = normalize(cross(input[1].world - input[0].world, input[2].world - input[0].world));
    for (int i = 0; i < 3; i++)
    {
        VSOut o = input[i];
        o.color.rgb *= 0.5 + 0.5 * abs(n.y);
        stream.Append(o);
    }
    stream.RestartStrip();
}

float4 PS(VSOut i) : SV_Target { return i.color; }

technique10 ClipThroughTheGeometryShader
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(CompileShader(gs_4_0, GS()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
