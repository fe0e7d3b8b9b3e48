// Built-in meshes (sphere, torus, quad, Utah teapot) and Wavefront OBJ loading, as CPU
// data with normals, per-vertex averaged tangents (handedness in w), binormals and
// texture coordinates. No GPU code: the app (or `fxkit render`) uploads the arrays and
// matches `mesh_vertex_layout()` to its shaders' input semantics.
//
// Conventions (docs/meshes.md): right-handed, +Y up, triangles counter-clockwise seen
// from outside, texture v = 0 at the top row of an image (as D3D and Vulkan sample it).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "fx/diagnostic.h"

namespace fx {

// One interleaved vertex; `mesh_vertex_layout()` describes it by D3D semantic.
struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  // Unit tangent along +u (dP/du made orthogonal to the normal); w = +-1 is the
  // handedness: binormal == cross(normal, tangent.xyz) * w.
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
  glm::vec3 binormal{0.0f, 1.0f, 0.0f};  // unit, along +v (D3D's BINORMAL)
  glm::vec2 uv{0.0f};
};

// An indexed triangle list.
struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // three per triangle

  size_t triangle_count() const { return indices.size() / 3; }
};

// Vertex attribute formats, API-neutral (the Vulkan backend maps them to VkFormat).
enum class VertexFormat : uint8_t { float2, float3, float4 };
// Bytes one attribute of this format occupies.
uint32_t format_size(VertexFormat format);
const char* to_string(VertexFormat format);

// One attribute of an interleaved vertex, named by its D3D semantic ("TEXCOORD", 0).
struct MeshVertexAttribute {
  std::string_view semantic;  // upper case, without the index: POSITION, NORMAL, ...
  uint32_t semantic_index = 0;
  VertexFormat format = VertexFormat::float3;
  uint32_t offset = 0;  // bytes from the start of the vertex
};

// The attributes of an interleaved vertex buffer and its stride.
struct MeshVertexLayout {
  uint32_t stride = 0;
  std::vector<MeshVertexAttribute> attributes;

  // The attribute for a shader input semantic such as "TEXCOORD0", "texcoord" (index 0),
  // "NORMAL" or "POSITION0"; case-insensitive. nullptr when the layout has none.
  const MeshVertexAttribute* find(std::string_view semantic) const;
};

// Layout of `Vertex`: POSITION0 float3, NORMAL0 float3, TANGENT0 float4, BINORMAL0 float3,
// TEXCOORD0 float2.
const MeshVertexLayout& mesh_vertex_layout();

// Axis-aligned bounds and the bounding sphere around their centre (for framing a camera).
struct MeshBounds {
  glm::vec3 min{0.0f}, max{0.0f};
  glm::vec3 center() const { return (min + max) * 0.5f; }
  float radius = 0.0f;  // farthest vertex from center()
};
MeshBounds bounds(const Mesh& mesh);

// Unit sphere around the origin, poles on +-Y; u runs around (u = 0 and 1 on the +Z
// meridian), v from the north pole (0) to the south pole (1). rings >= 2, segments >= 3
// (smaller values are raised to these).
Mesh sphere(uint32_t rings = 32, uint32_t segments = 64);

// Torus around the Y axis: tube centre circle of radius `major_radius` in the XZ plane,
// tube radius `minor_radius`. u runs around the axis (`rings` steps), v around the tube
// (`segments` steps) starting at the outer equator. rings, segments >= 3.
Mesh torus(float major_radius = 1.0f, float minor_radius = 0.35f, uint32_t rings = 48, uint32_t segments = 24);

// Unit square [-0.5, 0.5]^2 in the XY plane facing +Z; uv (0,0) at the top-left corner.
Mesh quad();

// The Utah (Newell) teapot: its 32 bicubic Bezier patches, each tessellated into
// `tessellation` x `tessellation` quads (3..256). Newell's units (about 6.4 wide, 3.15 tall), turned
// from its original Z up to +Y up, bottom at y = 0, spout towards +X. Per-patch uv 0..1.
Mesh teapot(uint32_t tessellation = 8);

// Newell's original data, exposed for tests and tools: 306 control points (Z up, as
// published) and 32 patches of 16 zero-based indices, row-major (4 rows of 4).
std::span<const glm::vec3> teapot_control_points();
std::span<const std::array<uint16_t, 16>> teapot_patches();

// Loads a Wavefront OBJ through tinyobjloader: polygons are triangulated, missing or
// zero normals are computed (as compute_normals does), OBJ's
// bottom-up v is flipped to top-down, tangents computed. Materials are ignored. Errors:
// "mesh-open-failed", "obj-parse-failed", "obj-index-out-of-range", "obj-no-faces";
// loader warnings come through as "obj-warning".
std::optional<Mesh> load_obj(const std::filesystem::path& path, DiagnosticSink& sink);

// Maps a `--mesh` argument to a mesh: "sphere", "torus", "quad", "teapot" (default
// tessellations), otherwise a path to an .obj file. "unknown-mesh" (with a did-you-mean)
// for a name that is neither a built-in nor an .obj path.
std::optional<Mesh> make_mesh(std::string_view name, DiagnosticSink& sink);

// Sets every vertex normal to the corner-angle-weighted average of the faces around its
// position (vertices at the same position share the result: smooth, no seam creases).
void compute_normals(Mesh& mesh);

// Fills tangent (xyz + handedness w) and binormal from positions, uvs and normals:
// per-triangle dP/du and dP/dv, averaged per vertex (and across uv seams where vertices
// share position and normal), Gram-Schmidt against the normal. Never produces NaN:
// degenerate uvs or normals fall back to an arbitrary perpendicular frame.
void compute_tangents(Mesh& mesh);

}  // namespace fx
