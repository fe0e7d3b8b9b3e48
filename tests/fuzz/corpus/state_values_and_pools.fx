float4 g_vLightPos[2];
stateblock Opaque = stateblock_state { CullMode = None; ZWriteEnable = false; };
shared cbuffer Pool { float4 Shared; unorm float4 Tint; snorm float Bias; };
technique T { pass { StateBlock = <Opaque>; LightPosition[0] = <g_vLightPos[1]>; } }
