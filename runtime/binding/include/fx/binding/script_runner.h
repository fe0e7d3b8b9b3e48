// fx::vk::ScriptRunner: runs a technique's DXSAS Script (fx/model/dxsas_script.h) into a
// command buffer: the render targets its texture parameters declare (RENDERCOLORTARGET with
// ViewportRatio / Dimensions / Format annotations), bound to the passes that sample them;
// RenderColorTarget0..3, Clear / ClearSetColor / ClearSetDepth, Pass=, Draw=Geometry (the host's
// mesh), Draw=Buffer (a full-screen quad), ScriptExternal (the host's scene), LoopByCount and
// LoopGetIndex. Used by EffectPreview::render_script (`fxkit render`) and by the public API's
// Technique::run_script (an application's frame). docs/dxsas.md says what runs and what does not.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fx/binding/effect_binding.h"
#include "fx/vulkan/render_target.h"

namespace fx::vk {

// A frame that is no RenderTarget: an application's colour and depth-stencil images, which
// the runner begins rendering on in the attachment layouts they are in, and leaves so.
struct FrameAttachments {
  VkImageView color = VK_NULL_HANDLE;
  VkImageView depth = VK_NULL_HANDLE;  // null when `formats` has no depth
  VkImageLayout color_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkImageLayout depth_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  RenderingFormats formats;  // one colour attachment, depth and stencil as the images
  VkRect2D area{};           // the part of the images the script draws into
};

// What the host gives a script for one frame.
struct ScriptFrame {
  RenderTarget* target = nullptr;  // the frame's own colour and depth (RenderColorTarget0=), or
  FrameAttachments attachments;    // when `target` is null, the frame's attachments
  uint32_t vertex_layout = 0;      // the binding's layout id for draw_geometry's and draw_quad's vertices
  VkViewport viewport{};           // of the frame's target; scaled to each render target
  // Binds its buffers and draws the application's geometry (Draw=Geometry).
  std::function<void(VkCommandBuffer)> draw_geometry;
  // Binds its buffers and draws a quad covering the target, positions in clip space (-1..1)
  // and TEXCOORD0 0..1 with v = 0 at the top (Draw=Buffer).
  std::function<void(VkCommandBuffer)> draw_quad;
  // Draws the host's scene into the current target, which is rendering with `formats` over
  // `area` (ScriptExternal); empty leaves the target as the script cleared it.
  std::function<void(VkCommandBuffer, const RenderingFormats& formats, const VkRect2D& area)> draw_scene;
};

class ScriptRunner {
 public:
  // For `technique` of `model`, bound by `binding` with `params`: creates a render target
  // for every RENDERCOLORTARGET texture parameter the script names, sized from the frame
  // (`frame_width` x `frame_height`) and their annotations, and binds each to the passes
  // that sample it. Null ("vk-script-none") when the technique has no Script.
  static std::unique_ptr<ScriptRunner> create(const Context& ctx, const EffectModel& model, EffectBinding& binding,
                                              ParameterStore& params, uint32_t technique, uint32_t frame_width,
                                              uint32_t frame_height, DiagnosticSink& sink);
  ~ScriptRunner();

  // Records the script into `cmd`, outside any rendering. Leaves the frame's target ended
  // (its colour in COLOR_ATTACHMENT_OPTIMAL, as RenderTarget::end does; the frame's
  // attachments written and visible to later attachment access). False on a failed apply
  // (diagnostics in `sink`).
  bool record(VkCommandBuffer cmd, const ScriptFrame& frame, DiagnosticSink& sink);

  // True when the technique's script or a pass's has ScriptExternal: it draws the host's scene.
  bool draws_scene() const;

  // The render target made for texture parameter `name`, or null.
  const RenderTarget* target(const std::string& name) const;
  // Every render target made, with its texture parameter's name.
  std::vector<std::pair<std::string, const RenderTarget*>> targets() const;

 private:
  struct State;
  ScriptRunner(const Context& ctx, const EffectModel& model, EffectBinding& binding, ParameterStore& params,
               uint32_t technique)
      : ctx_(&ctx), model_(&model), binding_(&binding), params_(&params), technique_(technique) {}
  // Runs steps [begin, end) of `steps`; false on a failed apply.
  bool run(const std::vector<ScriptStep>& steps, size_t begin, size_t end, State& state, DiagnosticSink& sink);
  // Draws the pass `step` names (its own script, or Draw=Geometry) into the current targets.
  bool draw_pass(const ScriptStep& step, State& state, DiagnosticSink& sink);
  // Draws `what` with pass `pass` into the current targets; `step` locates warnings.
  bool draw(const ScriptStep& step, ScriptDraw what, uint32_t pass, State& state, DiagnosticSink& sink);

  const Context* ctx_;
  const EffectModel* model_;
  EffectBinding* binding_;
  ParameterStore* params_;
  uint32_t technique_;
  std::map<uint32_t, RenderTarget> targets_;  // by texture parameter
};

}  // namespace fx::vk
