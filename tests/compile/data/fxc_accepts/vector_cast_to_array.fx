// Rule: fxc casts a vector to an array of its components, `(int[4])indices`, and truncates
// a longer vector, `(float[3])weights`; the DirectX SDK's skinning shaders split blend
// indices and weights so. glslang has no array casts.
float4x3 g_palette[16];

struct Skinned { float4 position : POSITION; float4 color : COLOR0; };

Skinned VS(float4 position : POSITION, float4 weights : BLENDWEIGHT, float4 indices : BLENDINDICES)
{
    int bone[4] = (int[4])D3DCOLORtoUBYTE4(indices);
    float weight[3] = (float[ 3 ])weights, last = 1;
    Skinned o;
    o.position = float4(0, 0, 0, 1);
    for (int i = 0; i < 3; i++)
    {
        o.position.xyz += mul(position, g_palette[bone[i]]) * weight[i];
        last -= weight[i];
    }
    o.position.xyz += mul(position, g_palette[bone[3]]) * last;
    o.color = float4(weight[0], weight[1], weight[2], 1);
    return o;
}

float4 PS(float4 color : COLOR0) : COLOR0 { return color; }

technique Skinning
{
    pass P0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 PS();
    }
}
