// ScriptQuad: Draw=Buffer's quad in the application's vertex layout.
#include "script_quad.h"

#include <array>
#include <cstring>

#include "fx/ascii_case.h"

namespace fxkit::detail {
namespace {

// The floats a format holds (2 to 4 32-bit floats), else 0: such an attribute stays zero.
uint32_t float_count(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R32G32_SFLOAT: return 2;
    case VK_FORMAT_R32G32B32_SFLOAT: return 3;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 4;
    default: return 0;
  }
}

bool is_semantic(const std::string& semantic, std::string_view name) {
  return fx::iequals(semantic, name) || fx::iequals(semantic, std::string(name) + "0");
}

}  // namespace

std::optional<ScriptQuad> ScriptQuad::create(const fx::vk::Context& ctx, const Target& target,
                                             fx::DiagnosticSink& sink) {
  // Corners as seen on screen (x right, y up) and their texture coordinates, v = 0 at the
  // top; counter-clockwise as seen.
  constexpr std::array<std::array<float, 4>, 4> corners = {
      {{-1, -1, 0, 1}, {1, -1, 1, 1}, {1, 1, 1, 0}, {-1, 1, 0, 0}}};
  // Clip space +Y is up on screen with a negative viewport; a projection that flips Y draws
  // clip space +Y down.
  const float y_sign = target.y_flip == YFlip::projection ? -1.f : 1.f;
  ScriptQuad quad;
  for (const VertexBinding& b : target.vertex_layout.bindings) {
    std::vector<std::byte> bytes(size_t(b.stride) * corners.size());
    for (const VertexAttribute& a : target.vertex_layout.attributes) {
      const uint32_t n = float_count(a.format);
      if (a.binding != b.binding || n == 0) continue;
      for (size_t v = 0; v < corners.size(); ++v) {
        std::array<float, 4> value{0, 0, 0, 1};
        if (is_semantic(a.semantic, "POSITION")) value = {corners[v][0], y_sign * corners[v][1], 0, 1};
        else if (is_semantic(a.semantic, "TEXCOORD")) value = {corners[v][2], corners[v][3], 0, 0};
        else continue;
        if (a.offset + n * sizeof(float) <= b.stride)
          std::memcpy(bytes.data() + v * b.stride + a.offset, value.data(), n * sizeof(float));
      }
    }
    auto buffer = fx::vk::Buffer::create(
        ctx, {bytes.size(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "fxkit script quad"}, sink);
    if (!buffer || !buffer->write(bytes.data(), bytes.size())) return std::nullopt;
    quad.vertices_.push_back(std::move(*buffer));
    quad.bindings_.push_back(b.binding);
  }
  // Front faces as the application's meshes: the corners are counter-clockwise as seen.
  const std::array<uint32_t, 6> indices = target.front_faces == Winding::clockwise
                                              ? std::array<uint32_t, 6>{0, 2, 1, 0, 3, 2}
                                              : std::array<uint32_t, 6>{0, 1, 2, 0, 2, 3};
  auto ib = fx::vk::Buffer::create(
      ctx,
      {sizeof(indices), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "fxkit script quad indices"},
      sink);
  if (!ib || !ib->write(indices.data(), sizeof(indices))) return std::nullopt;
  quad.indices_ = std::move(*ib);
  return quad;
}

void ScriptQuad::draw(VkCommandBuffer cmd) const {
  const VkDeviceSize offset = 0;
  for (size_t i = 0; i < vertices_.size(); ++i) {
    const VkBuffer buffer = vertices_[i].handle();
    vkCmdBindVertexBuffers(cmd, bindings_[i], 1, &buffer, &offset);
  }
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, 6, 1, 0, 0, 0);
}

}  // namespace fxkit::detail
