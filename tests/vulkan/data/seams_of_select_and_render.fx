// Techniques where selection and rendering once disagreed: a pixel-shader-only pass reading
// POSITION (fixed-function vertex processing feeds it), a technique with no pass, a pass with
// no state at all.
float4 PS(float4 p : POSITION) : COLOR { return p * 0.001; }
technique PsOnly { pass P0 { PixelShader = compile ps_3_0 PS(); } }
technique Empty { }
technique EmptyPass { pass P0 { } }
