// The interleaved layout of fx::Vertex by D3D semantic, and mesh bounds.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "fx/mesh.h"

namespace fx {

static_assert(std::is_standard_layout_v<Vertex>, "offsetof needs a standard-layout Vertex");
static_assert(sizeof(Vertex) == 60, "Vertex must stay tightly packed (no glm alignment)");

uint32_t format_size(VertexFormat format) {
  switch (format) {
    case VertexFormat::float2: return 8;
    case VertexFormat::float3: return 12;
    case VertexFormat::float4: return 16;
  }
  return 0;
}

const char* to_string(VertexFormat format) {
  switch (format) {
    case VertexFormat::float2: return "float2";
    case VertexFormat::float3: return "float3";
    case VertexFormat::float4: return "float4";
  }
  return "?";
}

const MeshVertexLayout& mesh_vertex_layout() {
  static const MeshVertexLayout layout{uint32_t(sizeof(Vertex)),
                                       {
                                           {"POSITION", 0, VertexFormat::float3, uint32_t(offsetof(Vertex, position))},
                                           {"NORMAL", 0, VertexFormat::float3, uint32_t(offsetof(Vertex, normal))},
                                           {"TANGENT", 0, VertexFormat::float4, uint32_t(offsetof(Vertex, tangent))},
                                           {"BINORMAL", 0, VertexFormat::float3, uint32_t(offsetof(Vertex, binormal))},
                                           {"TEXCOORD", 0, VertexFormat::float2, uint32_t(offsetof(Vertex, uv))},
                                       }};
  return layout;
}

const MeshVertexAttribute* MeshVertexLayout::find(std::string_view semantic) const {
  // Split "TEXCOORD12" into name and index; HLSL semantics without digits mean index 0.
  size_t digits = semantic.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(semantic[digits - 1]))) --digits;
  std::string_view name = semantic.substr(0, digits);
  uint32_t index = 0;
  for (char c : semantic.substr(digits)) {
    if (index > 1000) return nullptr;  // no real layout has that many; avoids overflow
    index = index * 10 + uint32_t(c - '0');
  }
  auto same = [](std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
             return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
  };
  for (const MeshVertexAttribute& a : attributes)
    if (a.semantic_index == index && same(a.semantic, name)) return &a;
  return nullptr;
}

MeshBounds bounds(const Mesh& mesh) {
  MeshBounds b;
  if (mesh.vertices.empty()) return b;
  b.min = b.max = mesh.vertices.front().position;
  for (const Vertex& v : mesh.vertices) {
    b.min = glm::min(b.min, v.position);
    b.max = glm::max(b.max, v.position);
  }
  glm::vec3 c = b.center();
  float r2 = 0.0f;
  for (const Vertex& v : mesh.vertices) {
    glm::vec3 d = v.position - c;
    r2 = std::max(r2, glm::dot(d, d));
  }
  b.radius = std::sqrt(r2);
  return b;
}

}  // namespace fx
