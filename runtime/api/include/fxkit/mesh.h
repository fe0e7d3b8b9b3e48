// fxkit::Mesh: fxkit's built-in meshes (sphere, torus, teapot, quad) and OBJ files on
// the GPU, for tools, previews and samples. An engine draws its own geometry instead.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "fxkit/message.h"
#include "fxkit/target.h"

namespace fxkit {

class Device;

class Mesh {
 public:
  // `shape`: "sphere", "torus", "teapot", "quad", or an .obj file. nullptr with
  // `errors` when it cannot be made.
  static std::unique_ptr<Mesh> create(Device& device, const std::string& shape, std::vector<Message>& errors);
  ~Mesh();
  Mesh(const Mesh&) = delete;
  Mesh& operator=(const Mesh&) = delete;

  // The layout of every built-in mesh: one interleaved buffer of POSITION float3,
  // NORMAL float3, TANGENT float4, BINORMAL float3, TEXCOORD0 float2. Counter-clockwise
  // front faces (Winding::counter_clockwise).
  static const VertexLayout& vertex_layout();
  // Radius of the bounding sphere around the origin (for Scene::framing).
  float radius() const;
  // Binds the buffers and draws every triangle.
  void draw(VkCommandBuffer cmd) const;

 private:
  struct Impl;
  explicit Mesh(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace fxkit
