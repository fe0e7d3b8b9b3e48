// Rule: a static const declared inside a cbuffer is a constant of the shader, not a member
// of the buffer: it keeps its value and may size the arrays that follow it, as it does
// outside the buffer.
cbuffer Lights
{
    static const int kLights = 3;
    float4 g_lightColor[kLights];
    float4 g_ambient;
    static const float kScale = 0.5, kBias = 0.25;
};

float4 VS(float4 position : POSITION) : SV_Position { return position; }

float4 PS(float4 position : SV_Position) : SV_Target
{
    float4 sum = g_ambient;
    for (int i = 0; i < kLights; i++)
        sum += g_lightColor[i] * kScale + kBias;
    return sum;
}

technique10 StaticInBuffer
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
