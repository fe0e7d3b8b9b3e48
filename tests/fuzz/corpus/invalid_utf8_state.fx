matrix mTot; vector lhtR; texture T0;
technique tec0 { pass p0 {
  VertexShaderConstant[4] = <mTot>; Texture[0] = <T0>; AddressU[0] = clamp; ColorOp[1] = Disable;
  VertexShader = decl { stream 0; float v0[3]; } asm { vs.1.1
    m4x4 oPos, v0, c4
    mov oT0.xy, v0.xy };
  Pi‘šlShader = asm { ps.1.1
    tex t0
    mul r0, t0, v0 };
} }
