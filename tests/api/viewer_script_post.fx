// A DXSAS post effect for the viewer tests: the mesh, lit orange, into a render target, then a
// full-screen pass that swaps its colour channels into the frame, so a window that draws the
// passes on the mesh instead of running the script shows an orange or black sphere, not a blue one.
float Script : STANDARDSGLOBAL < string ScriptClass = "scene"; string ScriptOrder = "postprocess";
                                 string ScriptOutput = "color"; > = 0.8;
float4 ClearColor = {0, 0, 0, 0};
texture ScnMap : RENDERCOLORTARGET < float2 ViewportRatio = {1, 1}; string Format = "A8R8G8B8"; >;
sampler ScnSamp = sampler_state { Texture = <ScnMap>; MinFilter = POINT; MagFilter = POINT; AddressU = CLAMP; AddressV = CLAMP; };
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x4 World : WORLD;

struct S {
  float4 pos : POSITION;
  float3 normal : TEXCOORD0;
};
S SceneVS(float4 p : POSITION, float3 n : NORMAL) {
  S o;
  o.pos = mul(p, WorldViewProjection);
  o.normal = mul(n, (float3x3)World);
  return o;
}
float4 ScenePS(S i) : COLOR0 { return float4(float3(0.9, 0.6, 0.2) * (0.4 + 0.6 * saturate(normalize(i.normal).z)), 1); }

struct Q {
  float4 pos : POSITION;
  float2 uv : TEXCOORD0;
};
Q QuadVS(float4 p : POSITION, float2 uv : TEXCOORD0) {
  Q o;
  o.pos = p;
  o.uv = uv;
  return o;
}
float4 SwapPS(float2 uv : TEXCOORD0) : COLOR0 { return float4(tex2D(ScnSamp, uv).bgr, 1); }

technique Post < string Script = "RenderColorTarget0=ScnMap; ClearSetColor=ClearColor; Clear=Color; Clear=Depth;"
                                 "Pass=Scene; RenderColorTarget0=; Pass=Swap;"; > {
  pass Scene < string Script = "Draw=Geometry;"; > {
    VertexShader = compile vs_3_0 SceneVS();
    PixelShader = compile ps_3_0 ScenePS();
  }
  pass Swap < string Script = "Draw=Buffer;"; > {
    CullMode = None;
    ZEnable = false;
    VertexShader = compile vs_3_0 QuadVS();
    PixelShader = compile ps_3_0 SwapPS();
  }
}
