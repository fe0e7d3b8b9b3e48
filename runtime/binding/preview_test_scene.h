// fx::vk::PreviewTestScene: what a preview draws behind a DXSAS `ScriptExternal`: its mesh lit
// by a light above the camera, its surface the texture stand-in of the preview's cache (the
// colour test pattern with preview stand-ins), so that a post effect has a scene to process.
#pragma once
#include <functional>
#include <memory>

#include "fx/binding/effect_binding.h"
#include "fx/binding/effect_scene.h"
#include "fx/compile/effect_file.h"
#include "fx/vulkan/render_target.h"

namespace fx::vk {

class EffectPreview;

class PreviewTestScene {
 public:
  // The scene's effect compiled and bound with `preview`'s textures, frames and vertex streams.
  static std::unique_ptr<PreviewTestScene> create(const Context& ctx, EffectPreview& preview, DiagnosticSink& sink);

  // Draws into attachments of `formats` that are rendering over `area`, with the camera of
  // `scene`; `draw_mesh` binds the preview's vertex streams and draws its mesh.
  bool draw(VkCommandBuffer cmd, const RenderingFormats& formats, const VkRect2D& area, const SceneView& scene,
            const std::function<void(VkCommandBuffer)>& draw_mesh, DiagnosticSink& sink);

 private:
  std::unique_ptr<EffectFile> effect_;
  std::unique_ptr<EffectBinding> binding_;
  uint32_t layout_ = 0;
};

}  // namespace fx::vk
