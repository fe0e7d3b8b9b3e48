// fxkit::Mesh: a built-in or OBJ mesh (lib/mesh) in host-visible vertex and index buffers.
#include "fxkit/mesh.h"

#include "api_state.h"
#include "fx/binding/vertex_layout.h"
#include "fx/mesh.h"
#include "fx/vulkan/buffer.h"

namespace fxkit {

struct Mesh::Impl {
  fx::vk::Buffer vertices, indices;
  uint32_t index_count = 0;
  float radius = 0.f;
};

Mesh::Mesh(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Mesh::~Mesh() = default;

std::unique_ptr<Mesh> Mesh::create(Device& device, const std::string& shape, std::vector<Message>& errors) {
  fx::DiagnosticSink sink;
  const fx::vk::Context& ctx = *device.state().ctx;
  auto fail = [&]() -> std::unique_ptr<Mesh> {
    auto more = detail::to_messages(sink.diagnostics(), nullptr);
    errors.insert(errors.end(), more.begin(), more.end());
    return nullptr;
  };
  std::optional<fx::Mesh> mesh = fx::make_mesh(shape, sink);
  if (!mesh) return fail();
  const VkDeviceSize vbytes = mesh->vertices.size() * sizeof(fx::Vertex);
  const VkDeviceSize ibytes = mesh->indices.size() * sizeof(uint32_t);
  auto vb = fx::vk::Buffer::create(
      ctx, {vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "mesh vertices"}, sink);
  auto ib = fx::vk::Buffer::create(
      ctx, {ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "mesh indices"}, sink);
  if (!vb || !ib) return fail();
  if (!vb->write(mesh->vertices.data(), vbytes) || !ib->write(mesh->indices.data(), ibytes)) {
    sink.error("vk-call-failed", {}, "could not write the mesh buffers");
    return fail();
  }
  auto impl = std::make_unique<Impl>();
  impl->vertices = std::move(*vb);
  impl->indices = std::move(*ib);
  impl->index_count = uint32_t(mesh->indices.size());
  const fx::MeshBounds b = fx::bounds(*mesh);
  impl->radius = glm::length(b.center()) + b.radius;  // around the origin, not the centre
  return std::unique_ptr<Mesh>(new Mesh(std::move(impl)));
}

const VertexLayout& Mesh::vertex_layout() {
  static const VertexLayout layout = fx::vk::to_vertex_layout(fx::mesh_vertex_layout());
  return layout;
}

float Mesh::radius() const { return impl_->radius; }

void Mesh::draw(VkCommandBuffer cmd) const {
  const VkBuffer vb = impl_->vertices.handle();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd, impl_->indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, impl_->index_count, 1, 0, 0, 0);
}

}  // namespace fxkit
