// Rule: an entry point may be overloaded by its uniform parameters: `PS()` and
// `PS(uniform int mode)` in one effect, `compile ps_3_0 PS(2)` naming the second and
// `compile ps_3_0 PS()` the first; the compile-time arguments choose the overload.
float4x4 g_worldViewProjection;
float4 g_color;

float4 VS(float4 position : POSITION) : POSITION { return mul(position, g_worldViewProjection); }

float4 VS(float4 position : POSITION, uniform float scale) : POSITION
{
    return mul(position * scale, g_worldViewProjection);
}

float4 PS() : COLOR { return g_color; }

float4 PS(uniform int mode) : COLOR { return mode == 2 ? g_color * 0.5 : g_color; }

technique Overloads
{
    pass Plain
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
    pass Chosen
    {
        VertexShader = compile vs_3_0 VS(2.0);
        PixelShader = compile ps_3_0 PS(2);
    }
}
