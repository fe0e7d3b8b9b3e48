// Rule: fxc reads the type names dword, float, matrix and vector in any case (`Matrix
// transform;`, `FLOAT scale;` in D3D9 effects; vkd3d, which follows fxc, looks them up
// case-insensitively): as parameters, locals, function parameters and casts. A struct the
// effect declares under such a name is that struct.
Matrix transform : WORLDVIEWPROJECTION;
FLOAT scale = 2;
Vector tint = { 1, 0.5, 0.25, 1 };
DWORD flags = 3;

struct Dword { float value; };

float4 Scaled(float4 position, Float factor) { return position * factor; }

void VS(float4 position : POSITION, float2 uv : TEXCOORD0, out float4 oPosition : POSITION, out float2 oUv : TEXCOORD0)
{
    MATRIX local = transform;
    oPosition = Scaled(mul(position, local), (Float)flags);
    oUv = uv;
}

float4 PS(float2 uv : TEXCOORD0) : COLOR
{
    Dword half_tint;
    half_tint.value = 0.5 * scale;
    return tint * half_tint.value * uv.x;
}

technique AnyCase
{
    pass P0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 PS();
    }
}
