// Rule: a read-only buffer may hold three-component elements, `Buffer<float3>` (the DirectX
// SDK's PipesGS reads its adjacency so); Load returns the element's three components.
Buffer<float3> g_adjacency;
float4x4 g_worldViewProjection : WORLDVIEWPROJECTION;

float4 VS(float4 position : POSITION) : SV_Position { return mul(position, g_worldViewProjection); }

float4 PS(float4 position : SV_Position) : SV_Target
{
    float3 neighbour = g_adjacency.Load(uint(position.x) % 16);
    return float4(abs(neighbour), 1);
}

technique10 Render
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
