// EffectPreview::render_script: a technique's DXSAS Script run on the preview's mesh and target.
#include "fx/binding/effect_preview.h"
#include "fx/binding/script_runner.h"
#include "fx/vulkan/one_shot.h"
#include "preview_test_scene.h"

namespace fx::vk {

bool EffectPreview::make_quad(DiagnosticSink& sink) {
  if (quad_vertices_) return true;
  // The library's quad (counter-clockwise, v = 0 at the top) doubled to cover clip space.
  Mesh quad = make_mesh("quad", sink).value_or(Mesh{});
  for (Vertex& v : quad.vertices) v.position *= 2.0f;
  const VkDeviceSize vbytes = quad.vertices.size() * sizeof(Vertex), ibytes = quad.indices.size() * sizeof(uint32_t);
  auto vb = Buffer::create(
      *ctx_, {vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUsage::upload, "preview quad vertices"}, sink);
  auto ib = Buffer::create(
      *ctx_, {ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryUsage::upload, "preview quad indices"}, sink);
  if (quad.indices.empty() || !vb || !ib || !vb->write(quad.vertices.data(), vbytes) ||
      !ib->write(quad.indices.data(), ibytes))
    return false;
  quad_vertices_ = std::move(*vb);
  quad_indices_ = std::move(*ib);
  quad_index_count_ = uint32_t(quad.indices.size());
  return true;
}

std::optional<fx::Image> EffectPreview::render_script(ScriptRunner& runner, uint32_t vertex_layout,
                                                      DiagnosticSink& sink) {
  if (!make_quad(sink)) return std::nullopt;
  if (runner.draws_scene() && !test_scene_) {
    test_scene_ = PreviewTestScene::create(*ctx_, *this, sink);
    if (!test_scene_) return std::nullopt;
  }
  auto draw = [this](VkCommandBuffer cmd, VkBuffer vertices, VkBuffer indices, uint32_t count) {
    const VkBuffer buffers[2] = {vertices, constants_.handle()};
    const VkDeviceSize offsets[2] = {0, 0};
    vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
    vkCmdBindIndexBuffer(cmd, indices, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, count, 1, 0, 0, 0);
  };
  ScriptFrame frame;
  frame.target = &*target_;
  frame.vertex_layout = vertex_layout;
  frame.viewport = {0.0f, float(desc_.height), float(desc_.width), -float(desc_.height), 0.0f, 1.0f};
  frame.draw_geometry = [&](VkCommandBuffer cmd) { draw(cmd, vertices_.handle(), indices_.handle(), index_count_); };
  frame.draw_quad = [&](VkCommandBuffer cmd) {
    draw(cmd, quad_vertices_.handle(), quad_indices_.handle(), quad_index_count_);
  };
  bool scene_drawn = true;
  if (test_scene_)
    frame.draw_scene = [&](VkCommandBuffer cmd, const RenderingFormats& formats, const VkRect2D& area) {
      scene_drawn = test_scene_->draw(cmd, formats, area, scene(), frame.draw_geometry, sink) && scene_drawn;
    };
  frames_->begin_frame();
  bool recorded = true;
  const bool submitted = submit_and_wait(
      *ctx_,
      [&](VkCommandBuffer cmd) {
        ClearValues clear;  // the frame starts cleared, as render() clears it
        clear.color = desc_.clear;
        target_->begin(cmd, clear);
        target_->end(cmd);
        recorded = runner.record(cmd, frame, sink);
        target_->record_readback(cmd);
      },
      sink);
  if (!submitted || !recorded || !scene_drawn) return std::nullopt;
  return target_->readback_pixels(sink);
}

}  // namespace fx::vk
