Technique T < int Pass_Count = 1; >
{
    Pass
    {
        VertexShader = COMPILE vs_2_0 VS();
        Sampler[0] = Sampler_State { MinFilter = Linear; };
    }
    PASS P1 { }
}
TECHNIQUE10 T10 { pass { } }
float Pass;
