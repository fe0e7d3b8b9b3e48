// Wavefront OBJ loading through tinyobjloader (a packaged, maintained parser: the format's
// corner cases - negative indices, line continuations, mtllib - are its business).
#include <cmath>
#include <string>
#include <system_error>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "detail.h"

namespace fx {
namespace {

struct CornerKey {
  int v, vt, vn;
  friend bool operator==(const CornerKey&, const CornerKey&) = default;
};
struct CornerKeyHash {
  size_t operator()(const CornerKey& k) const {
    uint64_t h = uint64_t(uint32_t(k.v)) * 0x9E3779B97F4A7C15ull;
    h ^= (uint64_t(uint32_t(k.vt)) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
    h ^= (uint64_t(uint32_t(k.vn)) + 0x8CB92BA72F3D8DD7ull + (h << 6) + (h >> 2));
    return size_t(h);
  }
};

// tinyobjloader messages end in newlines and may hold several lines; one diagnostic each.
void report_lines(DiagnosticSink& sink, Severity severity, const char* id, const std::string& prefix,
                  const std::string& text) {
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) sink.report(severity, id, {}, prefix + line);
    start = end + 1;
  }
}

}  // namespace

std::optional<Mesh> load_obj(const std::filesystem::path& path, DiagnosticSink& sink) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    sink.error("mesh-open-failed", {},
               "cannot open mesh file '" + name + "'" +
                   (std::filesystem::exists(path, ec) ? ": not a regular file" : ": no such file"));
    return std::nullopt;
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  config.mtl_search_path = path.parent_path().string();
  tinyobj::ObjReader reader;
  bool ok = reader.ParseFromFile(name, config);
  report_lines(sink, Severity::warning, "obj-warning", name + ": ", reader.Warning());
  if (!ok) {
    std::string message = reader.Error();
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
    sink.error("obj-parse-failed", {}, name + ": " + (message.empty() ? "not a valid OBJ file" : message));
    return std::nullopt;
  }

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const int positions = int(attrib.vertices.size() / 3), normals = int(attrib.normals.size() / 3),
            texcoords = int(attrib.texcoords.size() / 2);

  Mesh mesh;
  std::unordered_map<CornerKey, uint32_t, CornerKeyHash> corners;
  size_t skipped_faces = 0;

  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const size_t count = shape.mesh.num_face_vertices[f];
      if (offset + count > shape.mesh.indices.size()) break;
      if (count < 3) {  // points or lines smuggled into an `f` line
        ++skipped_faces;
        offset += count;
        continue;
      }
      std::vector<uint32_t> face;
      face.reserve(count);
      for (size_t k = 0; k < count; ++k) {
        const tinyobj::index_t& ix = shape.mesh.indices[offset + k];
        // tinyobjloader only warns about out-of-range indices; reading them would overrun.
        if (ix.vertex_index < 0 || ix.vertex_index >= positions || ix.texcoord_index >= texcoords ||
            ix.normal_index >= normals) {
          sink.error("obj-index-out-of-range", {},
                     name + ": face " + std::to_string(f + 1) + " of '" + shape.name +
                         "' refers to a vertex, texture coordinate or normal that the file does "
                         "not define (" +
                         std::to_string(positions) + " v, " + std::to_string(texcoords) + " vt, " +
                         std::to_string(normals) + " vn)");
          return std::nullopt;
        }
        CornerKey key{ix.vertex_index, ix.texcoord_index, ix.normal_index};
        auto [it, inserted] = corners.try_emplace(key, uint32_t(mesh.vertices.size()));
        if (inserted) {
          Vertex v;
          const float* p = &attrib.vertices[size_t(3 * ix.vertex_index)];
          v.position = {p[0], p[1], p[2]};
          if (ix.texcoord_index >= 0) {
            const float* t = &attrib.texcoords[size_t(2 * ix.texcoord_index)];
            v.uv = {t[0], 1.0f - t[1]};  // OBJ's v grows upwards; fxkit's rows grow down
          }
          if (ix.normal_index >= 0) {
            const float* n = &attrib.normals[size_t(3 * ix.normal_index)];
            v.normal = {n[0], n[1], n[2]};
          }
          // No normal, or a zero one: left zero, which smooth_normals below fills in.
          if (ix.normal_index < 0 || !mesh_detail::usable_normal(v.normal)) v.normal = glm::vec3(0.0f);
          mesh.vertices.push_back(v);
        }
        face.push_back(it->second);
      }
      // Triangulated by the loader already; a fan covers what it leaves (it keeps
      // polygons whose triangulation it declines).
      for (size_t k = 1; k + 1 < face.size(); ++k)
        mesh.indices.insert(mesh.indices.end(), {face[0], face[k], face[k + 1]});
      offset += count;
    }
  }
  if (skipped_faces)
    sink.warning("obj-warning", {},
                 name + ": " + std::to_string(skipped_faces) + " face(s) with fewer than 3 vertices ignored");
  if (mesh.indices.empty()) {
    sink.error("obj-no-faces", {}, name + ": the file defines no triangles or polygons");
    return std::nullopt;
  }

  // Fills only the missing ones (smooth across corners sharing a position, so uv seams do
  // not crease shading) and normalises the file's own.
  mesh_detail::smooth_normals(mesh, /*only_unusable=*/true);
  compute_tangents(mesh);
  return mesh;
}

}  // namespace fx
