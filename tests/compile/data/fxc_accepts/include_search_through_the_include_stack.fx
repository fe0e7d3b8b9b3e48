// Rule: fxc (like MSVC) looks for `#include "x"` beside the file holding the directive, then
// beside each file that included that one, innermost first, then in the -I folders: a header
// in a subfolder names a sibling of its includer (include_stack/parts/lighting.fxh includes
// "palette.fxh" and "tint.fxh", which sit beside include_stack/material.fxh and beside this
// file). Innermost first: include_stack/palette.fxh wins over the palette.fxh beside this file.
#include "include_stack/material.fxh"

float4x4 g_worldViewProjection;

void VS(float4 position : POSITION, float2 uv : TEXCOORD0, out float4 oPosition : POSITION, out float2 oUv : TEXCOORD0)
{
    oPosition = mul(position, g_worldViewProjection);
    oUv = uv;
}

float4 PS(float2 uv : TEXCOORD0) : COLOR { return Shade(uv); }

technique IncludeStack
{
    pass P0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 PS();
    }
}
