// Rule: asuint(d, out low, out high) splits a double into its two 32-bit halves (cs_5_0 and
// the other profiles with doubles); asdouble(low, high) puts them back together.
RWByteAddressBuffer Bits;
StructuredBuffer<double> Values;

[numthreads(4, 1, 1)]
void Split(uint3 id : SV_DispatchThreadID)
{
    uint low, high;
    asuint(Values[id.x] * 2.0, low, high);
    Bits.Store2(id.x * 8, uint2(low, high));
    uint one = asuint(1.0f);
    Bits.Store(64 + id.x * 4, one + (asdouble(low, high) == Values[id.x] * 2.0 ? 1u : 0u));
}

technique11 DoubleBits
{
    pass P0
    {
        SetComputeShader(CompileShader(cs_5_0, Split()));
    }
}
