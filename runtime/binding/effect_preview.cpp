// EffectPreview: mesh buffers, an offscreen target and a one-frame render loop.
#include "fx/binding/effect_preview.h"

#include <cstddef>

#include "fx/vulkan/one_shot.h"
#include "preview_test_scene.h"

namespace fx::vk {
namespace {

// The preview's constant attribute buffer (binding 1): what an attribute the mesh lacks reads.
struct PreviewAttributeData {
  DefaultAttributeData defaults;
  float blend_weight[4] = {1, 0, 0, 0};
  float color[4] = {1, 1, 1, 1};
};

}  // namespace

std::unique_ptr<EffectPreview> EffectPreview::create(const Context& ctx, const Mesh& mesh,
                                                     const EffectPreviewDesc& desc, DiagnosticSink& sink) {
  std::unique_ptr<EffectPreview> p(new EffectPreview(ctx));
  p->desc_ = desc;
  p->bounds_ = bounds(mesh);
  p->target_ =
      RenderTarget::create(ctx, {desc.width, desc.height, desc.color_format, desc.depth, 0, "fxkit preview"}, sink);
  p->frames_ = FrameResources::create(ctx, desc.frames, sink);
  if (!p->target_ || !p->frames_) return nullptr;
  const VkDeviceSize vbytes = mesh.vertices.size() * sizeof(Vertex), ibytes = mesh.indices.size() * sizeof(uint32_t);
  auto vb =
      Buffer::create(ctx, {vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUsage::upload, "preview vertices"}, sink);
  auto ib =
      Buffer::create(ctx, {ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUsage::upload, "preview indices"}, sink);
  // What an attribute the mesh lacks reads (vertex_layout): (0, 0, 0, 1), BLENDWEIGHT
  // (1, 0, 0, 0) so that one bone carries the vertex, and COLOR white, the colour of a mesh
  // whose vertex colours leave the material as it is.
  PreviewAttributeData constant;
  auto cb = Buffer::create(
      ctx, {sizeof constant, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUsage::upload, "preview constant attributes"},
      sink);
  if (!vb || !ib || !cb) return nullptr;
  if (!vb->write(mesh.vertices.data(), vbytes) || !ib->write(mesh.indices.data(), ibytes) ||
      !cb->write(&constant, sizeof constant)) {
    sink.error("vk-call-failed", {}, "could not write the preview mesh buffers");
    return nullptr;
  }
  p->vertices_ = std::move(*vb);
  p->indices_ = std::move(*ib);
  p->constants_ = std::move(*cb);
  p->index_count_ = uint32_t(mesh.indices.size());
  return p;
}

EffectPreview::EffectPreview(const Context& ctx) : ctx_(&ctx), textures_(ctx) {}

EffectPreview::~EffectPreview() {
  if (ctx_) ctx_->wait_idle();
}

RenderingFormats EffectPreview::formats() const { return target_->formats(); }

EffectBindingDesc EffectPreview::binding_desc() const {
  EffectBindingDesc d;
  // Every render target's blend state: a script may draw into several (RenderColorTarget1..3).
  d.target.color_attachment_count = kMaxColorAttachments;
  d.target.depth_bits = depth_bits(target_->formats().depth);
  // render() flips Y with a negative viewport height; the meshes are counter-clockwise
  // from outside (fx/mesh.h).
  d.target.negative_viewport_height = true;
  d.target.mesh_front_face = FrontFace::counter_clockwise;
  d.storage_image_extent = {desc_.width, desc_.height};
  return d;
}

SceneView EffectPreview::scene() const {
  SceneView s = frame_bounds(bounds_, float(desc_.width) / float(desc_.height));
  s.viewport_size = {float(desc_.width), float(desc_.height)};
  return s;
}

VertexLayout EffectPreview::vertex_layout(std::span<const InterfaceVariable> inputs) const {
  // GLSL inputs (no semantics) read the mesh attribute their name suggests (match_vertex_layout).
  VertexLayout layout = with_default_attributes(to_vertex_layout(mesh_vertex_layout(), 0), inputs, 1);
  for (VertexAttribute& a : layout.attributes) {
    if (a.binding != 1 || a.format != VK_FORMAT_R32G32B32A32_SFLOAT) continue;
    const std::string semantic = canonical_semantic(a.semantic);
    if (semantic.starts_with("BLENDWEIGHT")) a.offset = offsetof(PreviewAttributeData, blend_weight);
    if (semantic.starts_with("COLOR")) a.offset = offsetof(PreviewAttributeData, color);
  }
  return layout;
}

std::optional<fx::Image> EffectPreview::render(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout,
                                               DiagnosticSink& sink) {
  if (!draw_frame(binding, technique, vertex_layout, sink)) return std::nullopt;
  return target_->readback_pixels(sink);
}

std::optional<fx::ImageF> EffectPreview::render_floats(EffectBinding& binding, uint32_t technique,
                                                       uint32_t vertex_layout, DiagnosticSink& sink) {
  if (!draw_frame(binding, technique, vertex_layout, sink)) return std::nullopt;
  return target_->readback_floats(sink);
}

bool EffectPreview::draw_frame(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout,
                               DiagnosticSink& sink) {
  frames_->begin_frame();
  bool recorded = true;
  const bool submitted = submit_and_wait(
      *ctx_,
      [&](VkCommandBuffer cmd) {
        recorded = record_passes(cmd, binding, technique, vertex_layout, 1, target_->scissor(), sink);
        target_->record_readback(cmd);
      },
      sink);
  if (!submitted || !recorded) return false;
  return true;
}

bool EffectPreview::record_passes(VkCommandBuffer cmd, EffectBinding& binding, uint32_t technique,
                                  uint32_t vertex_layout, uint32_t draws, const VkRect2D& scissor,
                                  DiagnosticSink& sink) {
  const VkViewport viewport{0.0f, float(desc_.height), float(desc_.width), -float(desc_.height), 0.0f, 1.0f};
  // The technique's compute passes first, outside rendering ("simulate, then draw").
  bool recorded = binding.dispatch_compute_passes(cmd, technique, desc_.width, desc_.height, sink);
  const auto bind_mesh = [&](VkCommandBuffer c) {
    const VkBuffer buffers[2] = {vertices_.handle(), constants_.handle()};
    const VkDeviceSize offsets[2] = {0, 0};
    vkCmdBindVertexBuffers(c, 0, 2, buffers, offsets);
    vkCmdBindIndexBuffer(c, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  };
  // Then its stream-output passes capture the mesh, also outside rendering; the passes after
  // one draw what it captured (DrawAuto) instead of the mesh.
  recorded = recorded && binding.capture_stream_output_passes(
                             cmd, technique, vertex_layout,
                             [&](VkCommandBuffer c) {
                               bind_mesh(c);
                               vkCmdDrawIndexed(c, index_count_, 1, 0, 0, 0);
                             },
                             sink);
  ClearValues clear;
  clear.color = desc_.clear;
  target_->begin(cmd, clear);
  recorded = recorded && binding.begin(cmd, technique, formats(), viewport, scissor, sink);
  if (recorded) {
    bool mesh_bound = false;  // a draw of captured vertices binds vertex buffer 0 to them
    for (uint32_t d = 0; d < draws && recorded; ++d) {
      for (uint32_t p = 0; p < binding.pass_count(technique) && recorded; ++p) {
        if (!binding.draw_pass(technique, p) || binding.stream_output_pass(technique, p)) continue;
        if (const uint32_t source = binding.stream_output_source(technique, p); source != kNoIndex) {
          recorded = binding.draw_stream_output(cmd, p, source, sink);
          mesh_bound = false;
          continue;
        }
        if (!mesh_bound) bind_mesh(cmd);
        mesh_bound = true;
        recorded = binding.apply(p, vertex_layout, sink);
        if (recorded) vkCmdDrawIndexed(cmd, index_count_, 1, 0, 0, 0);
      }
    }
    binding.end();
  }
  target_->end(cmd);
  return recorded;
}

std::optional<double> EffectPreview::time_passes(EffectBinding& binding, uint32_t technique, uint32_t vertex_layout,
                                                 uint32_t draws, const VkRect2D& scissor, DiagnosticSink& sink) {
  uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx_->physical_device(), &families, nullptr);
  std::vector<VkQueueFamilyProperties> props(families);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx_->physical_device(), &families, props.data());
  const uint32_t valid_bits = props[ctx_->queue_family()].timestampValidBits;
  const double period_ns = ctx_->info().limits.timestampPeriod;
  if (valid_bits == 0 || period_ns <= 0) {
    sink.error("vk-no-timestamps", {}, "the device's graphics queue has no timestamps (" + ctx_->info().name + ")");
    return std::nullopt;
  }
  VkQueryPoolCreateInfo qp{};
  qp.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
  qp.queryType = VK_QUERY_TYPE_TIMESTAMP;
  qp.queryCount = 2;
  VkQueryPool queries = VK_NULL_HANDLE;
  if (vkCreateQueryPool(ctx_->device(), &qp, nullptr, &queries) != VK_SUCCESS) {
    sink.error("vk-call-failed", {}, "vkCreateQueryPool failed");
    return std::nullopt;
  }
  frames_->begin_frame();
  bool recorded = true;
  const bool submitted = submit_and_wait(
      *ctx_,
      [&](VkCommandBuffer cmd) {
        vkCmdResetQueryPool(cmd, queries, 0, 2);
        // Outside the rendering scope: a binning device rasterizes when the scope ends.
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
        recorded = record_passes(cmd, binding, technique, vertex_layout, draws, scissor, sink);
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
      },
      sink);
  uint64_t ts[2] = {};
  const bool read = submitted && recorded &&
                    vkGetQueryPoolResults(ctx_->device(), queries, 0, 2, sizeof ts, ts, sizeof(uint64_t),
                                          VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) == VK_SUCCESS;
  vkDestroyQueryPool(ctx_->device(), queries, nullptr);
  if (!read) return std::nullopt;
  const uint64_t mask = valid_bits >= 64 ? ~0ull : ((1ull << valid_bits) - 1);
  return double((ts[1] - ts[0]) & mask) * period_ns;
}

std::vector<InterfaceVariable> technique_vertex_inputs(const EffectModel& model, EffectPrograms& programs,
                                                       uint32_t technique) {
  std::vector<InterfaceVariable> out;
  if (technique >= model.techniques.size()) return out;
  for (const EffectPass& pass : programs.units().passes()) {
    if (pass.technique_index != technique) continue;
    const PassProgram& program = programs.program(pass);
    if (const StageProgram* vs = program.find(ShaderStage::vertex))
      for (const InterfaceVariable& v : vs->shader.reflection.inputs) out.push_back(v);
  }
  return out;
}

}  // namespace fx::vk
