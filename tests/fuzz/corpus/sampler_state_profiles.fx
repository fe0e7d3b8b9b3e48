Texture2D Tex;
sampler2D S = sampler_state { Texture = <Tex>; Filter = MIN_MAG_MIP_LINEAR; AddressU = WRAP; MinFilter = Linear; };
technique T9 { pass P { Sampler[0] = sampler_state { Filter = ANISOTROPIC; }; } }
technique10 T10 { pass P { } }
