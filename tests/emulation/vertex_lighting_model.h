// A double-precision CPU model of Direct3D 9 fixed-function vertex processing: the world and
// view transforms (normals by the inverse transpose), the lighting equations of the D3D
// documentation ("Mathematics of Lighting": ambient, diffuse, specular, emissive; point and
// spot attenuation and the spot cone), material colour sources and vertex fog.
#pragma once
#include <array>
#include <cmath>

#include "fx/emulation/fixed_function.h"
#include "texture_stage_model.h"

namespace fx::ff_model {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline Vec3 normalize(const Vec3& a) { return scale(a, 1 / length(a)); }
inline Vec3 xyz(const FixedVector& v) { return {v.value[0], v.value[1], v.value[2]}; }

// Row vector times a D3D matrix (m[row * 4 + col]): [x y z w] * M.
inline std::array<double, 4> times(const std::array<double, 4>& v, const std::array<float, 16>& m) {
  std::array<double, 4> r{};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) r[c] += v[k] * m[k * 4 + c];
  return r;
}
inline Vec3 point(const Vec3& p, const std::array<float, 16>& m) {
  auto r = times({p[0], p[1], p[2], 1}, m);
  return {r[0], r[1], r[2]};
}
inline Vec3 direction(const Vec3& d, const std::array<float, 16>& m) {
  auto r = times({d[0], d[1], d[2], 0}, m);
  return {r[0], r[1], r[2]};
}

struct VertexIn {
  Vec3 position, normal;
  Color diffuse, specular;
};
struct VertexOut {
  Color diffuse, specular;
  double fog = 1;
  Vec3 view_position, view_normal;
};

inline VertexOut process_vertex(const FixedFunctionState& s, const VertexIn& in) {
  VertexOut out;
  const Vec3 world = point(in.position, s.world.value);
  const Vec3 p = point(world, s.view.value);
  out.view_position = p;
  // Normal: by the inverse transpose of world * view's upper 3x3 (D3D transforms normals so).
  std::array<double, 9> m{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double v = 0;
      for (int k = 0; k < 3; ++k) v += double(s.world.value[r * 4 + k]) * s.view.value[k * 4 + c];
      m[r * 3 + c] = v;
    }
  const double det =
      m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  // (M^-1)^T = cofactor matrix / det; a row vector n times it.
  const std::array<double, 9> cof = {m[4] * m[8] - m[5] * m[7], m[5] * m[6] - m[3] * m[8], m[3] * m[7] - m[4] * m[6],
                                     m[2] * m[7] - m[1] * m[8], m[0] * m[8] - m[2] * m[6], m[1] * m[6] - m[0] * m[7],
                                     m[1] * m[5] - m[2] * m[4], m[2] * m[3] - m[0] * m[5], m[0] * m[4] - m[1] * m[3]};
  Vec3 n{};
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) n[c] += in.normal[k] * cof[k * 3 + c] / det;
  if (s.normalize_normals) n = normalize(n);
  out.view_normal = n;

  if (!s.lighting) {
    out.diffuse = in.diffuse;
    out.specular = in.specular;
  } else {
    auto material = [&](MaterialSource src, const FixedVector& mat) -> Color {
      if (s.color_vertex && src == MaterialSource::color1) return in.diffuse;
      if (s.color_vertex && src == MaterialSource::color2) return in.specular;
      return {mat.value[0], mat.value[1], mat.value[2], mat.value[3]};
    };
    const Color cd = material(s.diffuse_source, s.material_diffuse),
                ca = material(s.ambient_source, s.material_ambient),
                cs = material(s.specular_source, s.material_specular),
                ce = material(s.emissive_source, s.material_emissive);
    Vec3 ambient = xyz(s.ambient), diffuse{}, specular{};
    const Vec3 to_eye = s.local_viewer ? normalize(scale(p, -1)) : Vec3{0, 0, -1};
    for (const FixedLight& l : s.lights) {
      if (!l.enabled) continue;
      Vec3 to_light;
      double atten = 1;
      if (l.type == LightType::directional) {
        to_light = normalize(scale(direction(xyz(l.direction), s.view.value), -1));
      } else {
        const Vec3 offset = sub(point(xyz(l.position), s.view.value), p);
        const double d = length(offset);
        to_light = scale(offset, 1 / d);
        // Atten = 1 / (a0 + a1 d + a2 d^2), 0 beyond the range.
        atten = d <= l.range.value
                    ? 1 / (l.attenuation0.value + l.attenuation1.value * d + l.attenuation2.value * d * d)
                    : 0;
        if (l.type == LightType::spot) {
          // rho = cos of the angle between the spot axis and the light-to-vertex vector.
          const double rho = dot(scale(to_light, -1), normalize(direction(xyz(l.direction), s.view.value)));
          const double ct = std::cos(l.theta.value / 2), cp = std::cos(l.phi.value / 2);
          atten *= rho > ct ? 1 : rho <= cp ? 0 : std::pow((rho - cp) / (ct - cp), double(l.falloff.value));
        }
      }
      const double ndl = dot(n, to_light);
      for (int c = 0; c < 3; ++c) {
        ambient[c] += atten * l.ambient.value[c];
        diffuse[c] += atten * std::max(ndl, 0.0) * l.diffuse.value[c];
      }
      if (s.specular_enable && ndl > 0) {
        const Vec3 h = normalize(Vec3{to_eye[0] + to_light[0], to_eye[1] + to_light[1], to_eye[2] + to_light[2]});
        const double ndh = std::max(dot(n, h), 0.0);
        for (int c = 0; c < 3; ++c)
          specular[c] += atten * std::pow(ndh, double(s.material_power.value)) * l.specular.value[c];
      }
    }
    for (int c = 0; c < 3; ++c) {
      out.diffuse[c] = sat(ce[c] + ca[c] * ambient[c] + cd[c] * diffuse[c]);
      out.specular[c] = sat(cs[c] * specular[c]);
    }
    out.diffuse[3] = sat(cd[3]);
    out.specular[3] = sat(in.specular[3]);
  }
  if (s.fog && s.fog_table_mode == FogMode::none) {
    if (s.fog_vertex_mode == FogMode::none) {
      out.fog = out.specular[3];
    } else {
      const double d = s.range_fog ? length(p) : std::fabs(p[2]);
      out.fog = fog_factor(s.fog_vertex_mode, d, s.fog_start.value, s.fog_end.value, s.fog_density.value);
    }
  }
  return out;
}

// Texture coordinates of a stage (D3D "Texture Coordinate Processing"): the vertex's set
// extended to (u, v, 1, 0), or generated in camera space (the normal; the position; the
// reflection R = I - 2 (N.I) N of the eye ray I = normalize(position), (0, 0, 1) with a
// non-local viewer; the sphere map (Rx / m + 1/2, Ry / m + 1/2), m = 2 sqrt(Rx^2 + Ry^2 +
// (Rz + 1)^2)), then times the texture transform when its count is not zero.
inline std::array<double, 4> texture_coordinates(const FixedFunctionState& s, const TextureStageState& st,
                                                 const VertexOut& v, double u, double w) {
  const Vec3 n = v.view_normal, p = v.view_position;
  std::array<double, 4> tc{u, w, 1, 0};
  const Vec3 i = s.local_viewer ? normalize(p) : Vec3{0, 0, 1};
  const double ni = dot(n, i);
  const Vec3 r{i[0] - 2 * ni * n[0], i[1] - 2 * ni * n[1], i[2] - 2 * ni * n[2]};
  switch (st.tex_coord_index & 0xFFFF0000u) {
    case texcoord_gen::camera_space_normal: tc = {n[0], n[1], n[2], 1}; break;
    case texcoord_gen::camera_space_position: tc = {p[0], p[1], p[2], 1}; break;
    case texcoord_gen::camera_space_reflection_vector: tc = {r[0], r[1], r[2], 1}; break;
    case texcoord_gen::sphere_map: {
      const double m = 2 * std::sqrt(r[0] * r[0] + r[1] * r[1] + (r[2] + 1) * (r[2] + 1));
      tc = {r[0] / m + 0.5, r[1] / m + 0.5, 1, 1};
      break;
    }
    default: break;
  }
  if ((st.texture_transform_flags & texture_transform::count_mask) != 0) tc = times(tc, st.texture_transform.value);
  return tc;
}

}  // namespace fx::ff_model
