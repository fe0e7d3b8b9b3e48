// Rule: a D3D9 `sampler` declared without a dimension takes it from the calls that read it:
// `tex1D(s, x)` reads a 1D texture, `tex3D` a volume, `texCUBE` a cube (fxc types the sampler
// from the intrinsic); a sampler only tex2D reads, or none, stays two-dimensional.
texture g_ramp;
texture g_volume;
texture g_sky;
texture g_albedo;

sampler RampSampler = sampler_state { Texture = (g_ramp); AddressU = Clamp; MinFilter = Linear; };
sampler VolumeSampler = sampler_state { Texture = <g_volume>; };
sampler SkySampler = sampler_state { Texture = <g_sky>; };
sampler AlbedoSampler = sampler_state { Texture = <g_albedo>; };

float4 shade_ramp(sampler ramp, float x) { return tex1Dlod(ramp, float4(x, 0, 0, 0)); }

void VS(float4 position : POSITION, float3 uvw : TEXCOORD0, out float4 oPosition : POSITION, out float3 oUvw : TEXCOORD0)
{
    oPosition = position;
    oUvw = uvw;
}

float4 PS(float3 uvw : TEXCOORD0) : COLOR0
{
    float4 ramp = tex1D(RampSampler, uvw.x) + shade_ramp(RampSampler, uvw.y);
    float4 fog = tex3D(VolumeSampler, uvw);
    float4 sky = texCUBEbias(SkySampler, float4(uvw, 1));
    return ramp * fog + sky * tex2D(AlbedoSampler, uvw.xy);
}

technique UntypedSamplers
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
