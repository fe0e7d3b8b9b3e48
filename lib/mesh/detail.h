// Private to lib/mesh: the parameter-grid triangulation and normal smoothing shared by the
// generators and the OBJ loader.
#pragma once
#include <cstdint>
#include <functional>

#include "fx/mesh.h"

namespace fx::mesh_detail {

// Appends (columns+1) x (rows+1) vertices, u = column / columns rightwards and v = row / rows
// downwards, filled by `surface(u, v, vertex)` (position, normal, uv), and two
// triangles per cell, counter-clockwise when cross(dP/dv, dP/du) points at the viewer.
// Triangles with two coincident corners (poles, collapsed patch edges) are left out.
void append_grid(Mesh& mesh, uint32_t columns, uint32_t rows,
                 const std::function<void(float u, float v, Vertex& vertex)>& surface);

// Smooth normals: the corner-angle-weighted average of the faces around each position
// (vertices with bit-identical positions pool their faces, so uv seams do not crease).
// With `only_unusable`, vertices whose normal is already a usable direction keep it.
void smooth_normals(Mesh& mesh, bool only_unusable);

// True when `n` has a direction (finite, not ~zero length).
bool usable_normal(const glm::vec3& n);

}  // namespace fx::mesh_detail
