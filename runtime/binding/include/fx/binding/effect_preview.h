// fx::vk::EffectPreview: renders an effect on a mesh into an offscreen image: the headless
// path of `fxkit render`, `fxkit watch` and the rendering tests. Owns the render target,
// the mesh's vertex and index buffers, the per-frame resources and the texture cache the
// bindings it draws were created with.
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <span>

#include "fx/binding/effect_binding.h"
#include "fx/binding/effect_scene.h"
#include "fx/mesh.h"
#include "fx/vulkan/render_target.h"

namespace fx::vk {

class ScriptRunner;
class PreviewTestScene;

struct EffectPreviewDesc {
  uint32_t width = 256, height = 256;
  // RGBA8 for pictures (render); R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT to read the
  // shader's values unclamped (render_floats).
  VkFormat color_format = VK_FORMAT_R8G8B8A8_UNORM;
  DepthAttachment depth = DepthAttachment::d24s8;
  std::array<float, 4> clear{0.08f, 0.08f, 0.1f, 1.0f};
  FrameResourcesDesc frames;
};

class EffectPreview {
 public:
  // Uploads `mesh`; null with diagnostics on failure.
  static std::unique_ptr<EffectPreview> create(const Context& ctx, const Mesh& mesh, const EffectPreviewDesc& desc,
                                               DiagnosticSink& sink);
  ~EffectPreview();

  FrameResources& frames() { return *frames_; }
  EffectTextureCache& textures() { return textures_; }
  RenderingFormats formats() const;
  // What bindings drawn here should be created with: one colour attachment, the depth
  // format's bits, a negative viewport height and counter-clockwise meshes (fx/mesh.h).
  EffectBindingDesc binding_desc() const;
  // The camera framing the mesh, for set_standard_semantics.
  SceneView scene() const;

  // The mesh's vertex layout for these shader inputs: POSITION, NORMAL, TANGENT, BINORMAL,
  // TEXCOORD0 from the mesh; GLSL inputs (no semantics) by their names (…position, …normal,
  // …tangent, …binormal/bitangent, …texcoord/uv); any other input reads a constant
  // (0, 0, 0, 1) from a second, zero-stride stream, as Direct3D reads undeclared elements,
  // except BLENDWEIGHT, (1, 0, 0, 0) so that one bone carries the vertex, and COLOR, white
  // (vertex colours that leave the material as it is); integer inputs such as BLENDINDICES
  // read (0, 0, 0, 1) as integers.
  VertexLayout vertex_layout(std::span<const InterfaceVariable> inputs) const;

  // One frame: begin_frame, clear, begin/apply every pass of `technique` with a mesh draw
  // per pass, end, read back. nullopt with diagnostics on failure.
  std::optional<fx::Image> render(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout,
                                  DiagnosticSink& sink);
  // One frame of a technique's DXSAS Script (the runner made for this binding and technique
  // with the preview's size): the frame cleared, then the script's steps, Draw=Geometry
  // drawing the mesh, Draw=Buffer a full-screen quad in the same vertex layout and
  // ScriptExternal the test scene (the mesh lit and textured, preview_test_scene.h); read back.
  // Defined in effect_preview_script.cpp.
  std::optional<fx::Image> render_script(ScriptRunner& runner, uint32_t vertex_layout, DiagnosticSink& sink);
  // The same frame read back as floats, from a float color_format.
  std::optional<fx::ImageF> render_floats(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout,
                                          DiagnosticSink& sink);
  // GPU time in ns of `draws` repetitions of every pass of `technique` (a mesh draw per
  // pass), between two vkCmdWriteTimestamp around the rendering scope, drawn with `scissor`
  // (a 1x1 scissor off the mesh leaves the vertex work alone). No readback. nullopt with
  // "vk-no-timestamps" when the queue has none, or on a failed submission.
  std::optional<double> time_passes(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout, uint32_t draws,
                                    const VkRect2D& scissor, DiagnosticSink& sink);
  // Frames rendered by render().

 private:
  explicit EffectPreview(const Context& ctx);
  // Records and submits one frame of `technique` and its readback; false on failure.
  bool draw_frame(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout, DiagnosticSink& sink);
  // Records the clear, `draws` repetitions of every pass of `technique` (a mesh draw per
  // pass) within `scissor`, and the end of the target's rendering; false on a failed apply.
  bool record_passes(VkCommandBuffer cmd, EffectBinding& binding, uint32_t technique, uint32_t vertex_layout,
                     uint32_t draws, const VkRect2D& scissor, DiagnosticSink& sink);
  // Uploads the full-screen quad of Draw=Buffer on first use.
  bool make_quad(DiagnosticSink& sink);
  const Context* ctx_;
  EffectPreviewDesc desc_;
  MeshBounds bounds_;
  std::optional<RenderTarget> target_;
  std::optional<FrameResources> frames_;
  EffectTextureCache textures_;
  Buffer vertices_, indices_, constants_;
  uint32_t index_count_ = 0;
  Buffer quad_vertices_, quad_indices_;
  uint32_t quad_index_count_ = 0;
  std::unique_ptr<PreviewTestScene> test_scene_;  // made by the first script with ScriptExternal
};

// The union of the vertex shader inputs of a technique's passes (for vertex_layout()).
std::vector<InterfaceVariable> technique_vertex_inputs(const EffectModel& model, EffectPrograms& programs,
                                                       uint32_t technique);

}  // namespace fx::vk
