// PreviewTestScene: the preview's mesh, lit and textured, behind a DXSAS ScriptExternal.
#include "preview_test_scene.h"

#include "fx/binding/effect_preview.h"

namespace fx::vk {
namespace {

// Lit from above the camera, a quarter of ambient light so that no side is black.
constexpr const char* kSceneEffect = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4x4 World : WORLD;
float3 Eye : CAMERAPOSITION;
texture Surface;
sampler SurfaceSampler = sampler_state { Texture = <Surface>; MinFilter = LINEAR; MagFilter = LINEAR; AddressU = WRAP; AddressV = WRAP; };
struct VSOut { float4 position : POSITION; float3 normal : TEXCOORD0; float3 world : TEXCOORD1; float2 uv : TEXCOORD2; };
VSOut VS(float4 position : POSITION, float3 normal : NORMAL, float2 uv : TEXCOORD0) {
  VSOut o;
  o.position = mul(position, WorldViewProjection);
  o.normal = mul(normal, (float3x3)World);
  o.world = mul(position, World).xyz;
  o.uv = uv;
  return o;
}
float4 PS(VSOut i) : COLOR0 {
  float3 to_light = normalize(normalize(Eye - i.world) + float3(0.3, 0.6, 0));
  float lit = 0.25 + 0.75 * saturate(dot(normalize(i.normal), to_light));
  return float4(tex2D(SurfaceSampler, i.uv * float2(2, 1)).rgb * lit, 1);
}
technique Scene { pass Lit { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

}  // namespace

std::unique_ptr<PreviewTestScene> PreviewTestScene::create(const Context& ctx, EffectPreview& preview,
                                                           DiagnosticSink& sink) {
  std::unique_ptr<PreviewTestScene> s(new PreviewTestScene);
  s->effect_ = EffectFile::load_text("fxkit-preview-test-scene.fx", kSceneEffect, {}, sink);
  if (!s->effect_) return nullptr;
  s->binding_ = EffectBinding::create(ctx, *s->effect_->model, *s->effect_->programs, *s->effect_->params,
                                      preview.textures(), preview.frames(), preview.binding_desc(), sink);
  if (!s->binding_ || !s->binding_->technique_ok(0)) {
    sink.error("vk-script-scene", {}, "the preview's test scene cannot be drawn on this device");
    return nullptr;
  }
  s->layout_ = s->binding_->add_vertex_layout(
      preview.vertex_layout(technique_vertex_inputs(*s->effect_->model, *s->effect_->programs, 0)));
  return s;
}

bool PreviewTestScene::draw(VkCommandBuffer cmd, const RenderingFormats& formats, const VkRect2D& area,
                            const SceneView& scene, const std::function<void(VkCommandBuffer)>& draw_mesh,
                            DiagnosticSink& sink) {
  set_standard_semantics(*effect_->params, *effect_->model, scene);
  const float x = float(area.offset.x), y = float(area.offset.y);
  const float w = float(area.extent.width), h = float(area.extent.height);
  const VkViewport viewport{x, y + h, w, -h, 0.0f, 1.0f};  // the preview's flip (binding_desc)
  bool ok = binding_->begin(cmd, 0, formats, viewport, area, sink);
  if (ok) {
    ok = binding_->apply(0, layout_, sink);
    if (ok) draw_mesh(cmd);
    binding_->end();
  }
  return ok;
}

}  // namespace fx::vk
