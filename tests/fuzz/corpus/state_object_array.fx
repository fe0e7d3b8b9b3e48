int i;
BlendState Blends[3] { { BlendOp = Add; }, { BlendOp = Subtract; }, { BlendOp = Rev_Subtract; } };
DepthStencilState Depths[2] { { DepthFunc = 1; }, { DepthFunc = i + 2; }, };
technique10 T { pass P { SetBlendState(Blends[i], float4(0, 0, 0, 0), 0xFFFFFFFF); SetDepthStencilState(Depths[i * 3 + 1], 5); } }
