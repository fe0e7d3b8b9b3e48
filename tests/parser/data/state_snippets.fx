// The render-state snippets that seeds/d3dx-effects-and-per-pixel-lighting.txt shows "in
// effects framework syntax", each wrapped in a pass. The article writes some values as
// prose ("World Matrix (transpose)", "normal map") and drops a few ';'; those values are
// written here as references to the parameters below, with the ';' restored. Everything
// else is as printed, including `(.5f, .5f, .5f, .5f)`.

matrix mWorldT;       // World Matrix (transpose)
matrix mTotalT;       // Total Matrix (transpose)
matrix mWorld;        // World Matrix
matrix mTotal;        // Total Matrix
vector vLightDir;     // Light Direction
vector vCameraPos;    // Camera Position (World)
vector vOffset;       // Offset Constant
texture NormalMap;
texture ColorMap;
texture BaseHeightMap;
texture NormalHeightMap;

// Per-pixel diffuse: renderstates for the dp3 pixel shader.
technique DiffusePixelShader
{
    pass P0
    {
        VertexShaderConstant[0] = <mWorldT>;
        VertexShaderConstant[8] = <mTotalT>;
        VertexShaderConstant[12] = <vLightDir>;
        VertexShaderConstant[20] = (.5f, .5f, .5f, .5f);

        Texture[0]          = <NormalMap>;
        Texture[1]          = <ColorMap>;
    }
}

// First fallback: the D3DTOP_DOTPRODUCT3 fixed-function operation.
technique DiffuseDotProduct3
{
    pass P0
    {
        ColorOp[0]      = DotProduct3;
        ColorArg1[0]    = Texture;
        ColorArg2[0] = Diffuse;

        ColorOp[1]   = Modulate;

        ColorArg1[1] = Texture;

        ColorArg2[1] = Current;

        VertexShaderConstant[0] = <mWorldT>;

        VertexShaderConstant[8] = <mTotalT>;

        VertexShaderConstant[12] = <vLightDir>;

        Texture[0]   = <NormalMap>;

        Texture[1]   = <ColorMap>;
    }
}

// Second fallback: emboss bump mapping with D3DTOP_ADDSIGNED and the complement modifier.
technique DiffuseEmboss
{
    pass P0
    {
        ColorOp[0]   = SelectArg1;

        ColorArg1[0] = Texture;

        ColorOp[1]   = AddSigned;

        ColorArg1[1] = Texture | Complement;

        ColorArg2[1] = Current;

        VertexShaderConstant[0] = <mWorldT>;
        VertexShaderConstant[8] = <mTotalT>;
        VertexShaderConstant[12] = <vLightDir>;
        VertexShaderConstant[24] = <vOffset>;

        Texture[0] = <BaseHeightMap>;
        Texture[1] = <NormalHeightMap>;
    }
}

// Per-pixel specular (multiply-based and table-based exponentiation share these).
technique SpecularPixelShader
{
    pass P0
    {
        VertexShaderConstant[0] = <mWorld>;
        VertexShaderConstant[8] = <mTotal>;

        VertexShaderConstant[12] = <vLightDir>;

        VertexShaderConstant[14] = <vCameraPos>;

        VertexShaderConstant[33] = (.5f, .5f, .5f, .5f);

        Texture[0]    = <NormalMap>;
        Texture[1]    = <ColorMap>;
    }
}
