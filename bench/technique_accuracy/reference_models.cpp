// The seed effects' documented shading models in double (lib/fx/shading), per pixel, with
// the parameter sets (defaults and hard cases) each effect is measured over.
#include "reference_models.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "fx/shading/hemisphere.h"
#include "fx/shading/specular_power.h"

namespace fx::bench {
namespace {

using glm::dvec3;

dvec3 normalized_or(const dvec3& v, const dvec3& fallback) {
  const double len = glm::length(v);
  return std::isfinite(len) && len > 1e-300 ? v / len : fallback;
}

// The normal map's normal taken to world space through the pixel's own (interpolated,
// renormalized) tangent frame: what per-pixel tangent-space lighting approximates.
dvec3 mapped_normal(const PixelInputs& in, const glm::dvec4& normal_texel) {
  const dvec3 n = normalized_or(dvec3(normal_texel) * 2.0 - 1.0, {0, 0, 1});
  const dvec3 frame_n = normalized_or(in.normal, {0, 0, 1});
  const dvec3 frame_t = normalized_or(in.tangent, {1, 0, 0});
  const dvec3 frame_b = normalized_or(in.binormal, {0, 1, 0});
  return normalized_or(frame_t * n.x + frame_b * n.y + frame_n * n.z, frame_n);
}

dvec3 rgb(const ParameterStore& p, const char* name) { return dvec3(read_parameter(p, name)); }

// hemisphere.fx: color = base * ((a sky + (1-a) ground)(1 - occlusion) + sun saturate(N.S)),
// a = 0.5 + 0.5 cos q (the exact cosine-weighted sky fraction), occlusion = normal map alpha.
ReferenceModel hemisphere() {
  ReferenceModel m;
  m.effect = "hemisphere.fx";
  m.description =
      "base x ((a sky + (1-a) ground)(1 - occlusion) + sun saturate(N.S)), a = 0.5 + 0.5 N.A exact, N from the "
      "normal map through the per-pixel frame, occlusion from its alpha";
  m.textures = {"tex2D(NormalSampler, uv)", "tex2D(BaseSampler, uv)"};
  m.parameter_sets = {{"defaults", {}},
                      {"sun head-on", {{"SunDirection", {0.0f, -0.2f, -1.0f}}}},
                      {"sun behind", {{"SunDirection", {0.1f, 0.1f, 1.0f}}}},
                      {"sky axis tilted", {{"SkyAxis", {1.0f, 0.3f, 0.0f}}}}};
  m.covers = [](const std::string&) { return true; };
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const std::string&) {
    shading::HemisphereLight<double> h;
    h.sky_axis = normalized_or(dvec3(read_parameter(p, "SkyAxis")), {0, 1, 0});
    h.sky_color = rgb(p, "SkyColor");
    h.ground_color = rgb(p, "GroundColor");
    h.sun_direction = normalized_or(-dvec3(read_parameter(p, "SunDirection")), {0, 1, 0});
    h.sun_color = rgb(p, "SunColor");
    h.material = dvec3(in.textures[1]);
    return shading::hemisphere_lighting(h, mapped_normal(in, in.textures[0]), in.textures[0].w);
  };
  return m;
}

// per_pixel_lighting.fx: light x (color N.L) for "diffuse", light x (color N.L + (N.H)^n) for
// "specular", with n = SpecularExponent, V from the pixel to the camera, H = normalize(L + V).
ReferenceModel per_pixel_lighting() {
  ReferenceModel m;
  m.effect = "per_pixel_lighting.fx";
  m.description =
      "light x (color saturate(N.L)) [diffuse] + light x saturate(N.H)^SpecularExponent [specular], N from the "
      "normal map through the per-pixel frame, V and H per pixel";
  m.textures = {"tex2D(NormalSampler, uv)", "tex2D(ColorSampler, uv)"};
  m.parameter_sets = {{"defaults", {}},
                      {"light head-on", {{"LightDirection", {0.0f, -0.1f, -1.0f}}}},
                      {"light grazing", {{"LightDirection", {1.0f, 0.0f, 0.05f}}}},
                      {"light against the camera", {{"LightDirection", {0.0f, 0.05f, 1.0f}}}},
                      {"exponent 16", {{"SpecularExponent", {16.0f}}}}};
  m.covers = [](const std::string& scheme) { return scheme == "diffuse" || scheme == "specular"; };
  m.group = [](const std::string& scheme) { return scheme; };
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const std::string& scheme) {
    const dvec3 n = mapped_normal(in, in.textures[0]);
    const dvec3 l = normalized_or(-dvec3(read_parameter(p, "LightDirection")), {0, 0, 1});
    const dvec3 v = normalized_or(in.eye - in.position, {0, 0, 1});
    const dvec3 h = normalized_or(l + v, dvec3(0.0));
    const double nl = shading::lambert(n, l);
    double specular = 0.0;
    if (scheme == "specular")
      specular = shading::specular_power_reference(glm::dot(n, h), read_parameter(p, "SpecularExponent").x);
    return rgb(p, "LightColor") * (dvec3(in.textures[1]) * nl + specular);
  };
  return m;
}

}  // namespace

glm::dvec4 read_parameter(const ParameterStore& params, const std::string& name) {
  glm::dvec4 out(0.0);
  const Param h = params.find(name);
  const Type* t = params.type(h);
  if (!t) return out;
  float v[16] = {};
  const size_t n = std::min<size_t>(size_t(t->rows) * t->cols, 16);
  if (!params.get(h, std::span<float>(v, n))) return out;
  for (size_t i = 0; i < std::min<size_t>(n, 4); ++i) out[int(i)] = v[i];
  return out;
}

const std::vector<ReferenceModel>& reference_models() {
  static const std::vector<ReferenceModel> models = {hemisphere(), per_pixel_lighting()};
  return models;
}

}  // namespace fx::bench
