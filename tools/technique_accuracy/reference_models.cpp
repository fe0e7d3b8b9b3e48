// The seed effects' documented shading models in double (lib/fx/shading), per pixel, with
// the parameter sets (defaults and hard cases) each effect is measured over.
#include "reference_models.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "fx/shading/brdf_factorization.h"
#include "fx/shading/hemisphere.h"
#include "fx/shading/highlight.h"
#include "fx/shading/specular_power.h"
#include "fx/shading/strand.h"
#include "fx/shading/ward.h"
#include "fx/shading/wood.h"

namespace fx::bench {
namespace {

using glm::dvec3;

dvec3 normalized_or(const dvec3& v, const dvec3& fallback) {
  const double len = glm::length(v);
  return std::isfinite(len) && len > 1e-300 ? v / len : fallback;
}

// A tangent-space vector taken to world space through the pixel's own (interpolated,
// renormalized) tangent frame: what per-pixel tangent-space lighting approximates.
dvec3 to_world(const PixelInputs& in, const dvec3& v) {
  return normalized_or(in.tangent, {1, 0, 0}) * v.x + normalized_or(in.binormal, {0, 1, 0}) * v.y +
         normalized_or(in.normal, {0, 0, 1}) * v.z;
}

// A world-space vector in the pixel's own (interpolated, renormalized) tangent frame.
dvec3 to_tangent(const PixelInputs& in, const dvec3& w) {
  return dvec3(glm::dot(w, normalized_or(in.tangent, {1, 0, 0})), glm::dot(w, normalized_or(in.binormal, {0, 1, 0})),
               glm::dot(w, normalized_or(in.normal, {0, 0, 1})));
}

// The normal map's normal in world space.
dvec3 mapped_normal(const PixelInputs& in, const glm::dvec4& normal_texel) {
  const dvec3 n = normalized_or(dvec3(normal_texel) * 2.0 - 1.0, {0, 0, 1});
  return normalized_or(to_world(in, n), normalized_or(in.normal, {0, 0, 1}));
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
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const TechniqueRef&) {
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
  m.covers = [](const TechniqueRef& t) { return t.scheme == "diffuse" || t.scheme == "specular"; };
  m.group = [](const TechniqueRef& t) { return t.scheme; };
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const TechniqueRef& t) {
    const dvec3 n = mapped_normal(in, in.textures[0]);
    const dvec3 l = normalized_or(-dvec3(read_parameter(p, "LightDirection")), {0, 0, 1});
    const dvec3 v = normalized_or(in.eye - in.position, {0, 0, 1});
    const dvec3 h = normalized_or(l + v, dvec3(0.0));
    const double nl = shading::lambert(n, l);
    double specular = 0.0;
    if (t.scheme == "specular")
      specular = shading::specular_power_reference(glm::dot(n, h), read_parameter(p, "SpecularExponent").x);
    return rgb(p, "LightColor") * (dvec3(in.textures[1]) * nl + specular);
  };
  return m;
}

// strand_aniso.fx: base (ambient + Kd sum color_i sin(L_i, T)) + Ks gloss sum color_i
// max(-cos(a_i + b), 0)^n (Phong on the strand, lib/fx/shading/strand.h), T the direction
// map's strand through the per-pixel frame. Each technique against its own variant of the
// model: the bump techniques' T is Gram-Schmidt orthonormalized against the bump normal
// (STRAND_BUMP), strand_four_lights sums four lights (the others STRAND_LIGHTS = 1); the
// variants are separate substitute groups.
ReferenceModel strand_aniso() {
  ReferenceModel m;
  m.effect = "strand_aniso.fx";
  m.description =
      "base (ambient + Kd sum color sin(L,T)) + Ks gloss sum color max(-cos(a+b),0)^SpecularExponent, T from the "
      "direction map (bump techniques: orthonormalized against the bump normal) through the per-pixel frame, V "
      "per pixel";
  m.textures = {"tex2D(DirectionSampler, uv)", "tex2D(BaseSampler, uv)", "tex2D(BumpSampler, uv)"};
  m.parameter_sets = {{"defaults", {}},
                      {"light along the strands", {{"Light0Direction", {-1.0f, 0.0f, 0.0f}}}},
                      {"light head-on", {{"Light0Direction", {0.0f, -0.1f, -1.0f}}}},
                      {"light against the camera", {{"Light0Direction", {0.0f, 0.05f, 1.0f}}}}};
  // strand_four_lights and the seed's ps.1.4 listing strand_four_lights_ps14 sum four lights.
  auto lights = [](const TechniqueRef& t) { return t.name.rfind("strand_four_lights", 0) == 0 ? 4 : 1; };
  auto bump = [](const TechniqueRef& t) { return t.name.rfind("strand_bump_", 0) == 0; };
  m.group = [=](const TechniqueRef& t) {
    return std::string(bump(t) ? "bump mapped" : "") + (lights(t) > 1 ? "four lights" : "");
  };
  m.shade = [=](const PixelInputs& in, const ParameterStore& p, const TechniqueRef& t) {
    dvec3 strand = normalized_or(dvec3(in.textures[0]) * 2.0 - 1.0, {1, 0, 0});
    if (bump(t))
      strand = shading::gram_schmidt_tangent(strand, normalized_or(dvec3(in.textures[2]) * 2.0 - 1.0, {0, 0, 1}));
    const dvec3 tangent = normalized_or(to_world(in, strand), {1, 0, 0});
    const dvec3 v = normalized_or(in.eye - in.position, {0, 0, 1});
    const double exponent = read_parameter(p, "SpecularExponent").x;
    dvec3 diffuse(0.0), specular(0.0);
    for (int i = 0; i < lights(t); ++i) {
      const std::string light = "Light" + std::to_string(i);
      const dvec3 l = normalized_or(-dvec3(read_parameter(p, light + "Direction")), {0, 0, 1});
      const auto terms = shading::strand_reference(l, v, tangent, exponent);
      const dvec3 color(read_parameter(p, light + "Color"));
      diffuse += color * terms.diffuse;
      specular += color * terms.specular;
    }
    const glm::dvec4 base = in.textures[1];
    return dvec3(base) * (rgb(p, "AmbientColor") + read_parameter(p, "Kd").x * diffuse) +
           read_parameter(p, "Ks").x * base.w * specular;
  };
  return m;
}

// aniso_lut_ward.fx, point light, no textures but the table: scheme "gaussian" is
// BaseColor exp(-(k 0.3 T.H / N.H)^2) (0 for N.H <= 0, ward_gaussian); scheme "table" is the
// documented (L.N, H.N) stand-in, Intensity^2 saturate(L.N) (H.N)^32 (ln_hn_terms, the
// table's baked exponent). N, T per pixel from the interpolated frame, L and V per pixel.
ReferenceModel aniso_lut_ward() {
  ReferenceModel m;
  m.effect = "aniso_lut_ward.fx";
  m.description =
      "gaussian: BaseColor exp(-(k 0.3 T.H / N.H)^2); table: Intensity^2 saturate(L.N) (H.N)^32; N, T, L, V per "
      "pixel (point light)";
  m.parameter_sets = {{"defaults", {}},
                      {"light head-on", {{"LightPosition", {0.0f, 0.5f, 10.0f, 1.0f}}}},
                      {"light behind", {{"LightPosition", {0.0f, 0.0f, -10.0f, 1.0f}}}},
                      {"sharp lobe", {{"ControlR", {12.0f}}}}};
  m.covers = [](const TechniqueRef& t) { return t.scheme == "gaussian" || t.scheme == "table"; };
  m.group = [](const TechniqueRef& t) { return t.scheme; };
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const TechniqueRef& t) {
    const dvec3 n = normalized_or(in.normal, {0, 0, 1});
    const dvec3 l = normalized_or(dvec3(read_parameter(p, "LightPosition")) - in.position, n);
    const dvec3 v = normalized_or(in.eye - in.position, n);
    const dvec3 h = normalized_or(l + v, dvec3(0.0));
    if (t.scheme == "gaussian") {
      const dvec3 tangent = shading::gram_schmidt_tangent(normalized_or(in.tangent, {1, 0, 0}), n);
      return dvec3(read_parameter(p, "BaseColor")) *
             shading::ward_gaussian(n, tangent, h, read_parameter(p, "ControlR").x);
    }
    const auto terms = shading::ln_hn_terms(glm::dot(l, n), glm::dot(h, n), shading::HalfAngleLobe::blinn_phong, 32.0);
    const double intensity = read_parameter(p, "Intensity").x;
    return dvec3(intensity * intensity * terms.diffuse * terms.specular);
  };
  return m;
}

// wood.fx: the RenderMan wood (fx::shading::wood_shade's terms) on the object-space
// position, each technique with its own ring profile (the seed's Hermite curve, or
// RenderMan's smoothstep for scheme "renderman"). The two noise samples come from the
// G-buffer: noise3 at the scaled position, and noise1 at the ring radius as the shader
// computes it in float (the reference recomputes the radius in double from the sample).
ReferenceModel wood() {
  ReferenceModel m;
  m.effect = "wood.fx";
  m.description =
      "(ambient Ka + diffuse Kd N.L) lerp(light, dark, ring) + specular (N.H)^(1/roughness) Ks (0.3 ring + 0.7), "
      "ring = profile(frac(|pp.yz| ringscale + |noise1 turbulence|)), pp = P point_scale + noise3 turbulence";
  const std::string pp = "(object * point_scale + noise3(object * point_scale) * turbulence)";
  m.textures = {"float4(object, 1.0)", "float4(noise3(object * point_scale), 1.0)",
                "float4(noise1(length(" + pp + ".yz) * ringscale), 0.0, 0.0, 1.0)"};
  m.parameter_sets = {{"defaults", {}},
                      {"light head-on", {{"LightDirection", {0.0f, -0.1f, -1.0f}}}},
                      {"light against the camera", {{"LightDirection", {0.0f, 0.05f, 1.0f}}}},
                      {"turbulence 1 (the seed's)", {{"turbulence", {1.0f}}}}};
  m.group = [](const TechniqueRef& t) { return t.scheme; };
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const TechniqueRef& t) {
    auto x = [&](const char* name) { return read_parameter(p, name).x; };
    const dvec3 pp = dvec3(in.textures[0]) * x("point_scale") + dvec3(in.textures[1]) * x("turbulence");
    double r = std::sqrt(pp.y * pp.y + pp.z * pp.z) * x("ringscale");
    r = shading::frc(r + std::abs(in.textures[2].x * x("turbulence")));
    r = t.scheme == "renderman" ? shading::wood_ring_renderman(r) : shading::wood_ring_seed(r);
    const dvec3 n = normalized_or(in.normal, {0, 0, 1});
    const dvec3 l = normalized_or(-dvec3(read_parameter(p, "LightDirection")), {0, 0, 1});
    const dvec3 e = normalized_or(in.eye - in.position, {0, 0, 1});
    const dvec3 diffuse = rgb(p, "diffuse_color") * glm::dot(n, l);
    const dvec3 h = normalized_or(l + e, dvec3(0.0));
    const dvec3 specular = rgb(p, "specular_color") * shading::guarded_pow(glm::dot(h, n), 1.0 / x("roughness"));
    return (rgb(p, "ambient_color") * x("Ka") + diffuse * x("Kd")) *
               shading::lerp(rgb(p, "lightwood"), rgb(p, "darkwood"), r) +
           specular * (x("Ks") * (0.3 * r + 0.7));
  };
  return m;
}

// brdf.fx: the analytic BRDF its factor textures are fitted to (the anisotropic Ward lobe of
// the brdf_factor annotations: AlphaX 0.15 along T, AlphaY 0.35; AnalyticBrdf::evaluate is
// f cos(theta_i)) in the per-pixel tangent frame, times the object texture and the material
// colour; zero with the light below the surface.
ReferenceModel brdf() {
  ReferenceModel m;
  m.effect = "brdf.fx";
  m.description =
      "Ward(alpha_x 0.15, alpha_y 0.35) f(L, V) cos(theta_L) in the per-pixel tangent frame x object texture x "
      "MaterialColor (the BRDF the factor textures approximate)";
  m.textures = {"tex2D(ObjectSampler, uv)"};
  m.parameter_sets = {{"defaults", {}},
                      {"light head-on", {{"lhtR", {0.0f, -0.1f, -1.0f, 0.0f}}}},
                      {"light grazing", {{"lhtR", {1.0f, 0.0f, 0.05f, 0.0f}}}}};
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const TechniqueRef&) {
    const dvec3 l = to_tangent(in, normalized_or(-dvec3(read_parameter(p, "lhtR")), {0, 0, 1}));
    const dvec3 v = to_tangent(in, normalized_or(in.eye - in.position, {0, 0, 1}));
    shading::AnalyticBrdf ward;
    ward.lobe = shading::BrdfLobe::ward;
    ward.alpha_x = 0.15;
    ward.alpha_y = 0.35;
    const double f = l.z > 0.0 ? ward.evaluate(normalized_or(l, {0, 0, 1}), normalized_or(v, {0, 0, 1})) : 0.0;
    return f * dvec3(in.textures[0]) * rgb(p, "MaterialColor");
  };
  return m;
}

// aniso_highlights_glsl.fx: LightColor (color saturate(N.L) + gloss.r highlight), the
// highlight lib/fx/shading/highlight.h's (Phong R.E or Blinn-Phong N.H, E and L or H
// projected onto the plane of the strand and the normal when anisotropic). In tangent
// space: N from the normal map, E and L per pixel through the interpolated frame, the
// strand and exponent decoded from the gloss map as the seed does. Each scheme is its own
// group; runtime_switch follows the toggleaniso/togglemodel parameters.
ReferenceModel aniso_highlights_glsl() {
  ReferenceModel m;
  m.effect = "aniso_highlights_glsl.fx";
  m.description =
      "LightColor (color saturate(N.L) + gloss.r highlight), highlight = Phong R.E or Blinn-Phong N.H with E, L (or "
      "H) projected onto the strand plane when anisotropic, exponent gloss.g^2 128, strand angle from gloss.b; E, L "
      "per pixel in the interpolated tangent frame";
  m.textures = {"texture(ColorMap, uv)", "texture(NormalMap, uv)", "texture(GlossMap, uv)"};
  m.glsl_blocks = {"Header", "Interface"};
  m.parameter_sets = {{"defaults", {}},
                      {"light head-on", {{"LightPosition", {0.0f, 0.5f, 10.0f, 1.0f}}}},
                      {"light grazing", {{"LightPosition", {10.0f, 0.0f, 0.5f, 1.0f}}}},
                      {"light behind", {{"LightPosition", {0.0f, 0.0f, -10.0f, 1.0f}}}}};
  m.group = [](const TechniqueRef& t) { return t.scheme; };
  m.shade = [](const PixelInputs& in, const ParameterStore& p, const TechniqueRef& t) {
    bool anisotropic = t.scheme.find("isotropic") == std::string::npos;
    bool blinn_phong = t.scheme.find("blinn_phong") != std::string::npos;
    if (t.scheme == "interactive") {
      int32_t aniso = 0, model = 0;
      p.get(p.find("toggleaniso"), aniso);
      p.get(p.find("togglemodel"), model);
      anisotropic = aniso != 0, blinn_phong = model != 0;
    }
    const glm::dvec4 gloss = in.textures[2];
    shading::HighlightInputs<double> h;
    h.n = normalized_or(dvec3(in.textures[1]) - 0.5, {0, 0, 1});
    h.e = normalized_or(to_tangent(in, in.eye - in.position), h.n);
    h.l = normalized_or(to_tangent(in, dvec3(read_parameter(p, "LightPosition")) - in.position), h.n);
    h.exponent = gloss.y * gloss.y * 128.0;
    // Strand angle: blue 0 isotropic, else (blue 255 - 2) degrees from the tangent.
    const double angle = (gloss.z * 255.0 - 2.0) * (3.14159265358979 / 180.0);
    h.t = dvec3(std::cos(angle), std::sin(angle), 0.0);
    const double highlight = shading::anisotropic_highlight(
        h, blinn_phong ? shading::HighlightModel::blinn_phong : shading::HighlightModel::phong,
        anisotropic && gloss.z * 255.0 >= 2.5);
    const double diffuse = std::clamp(glm::dot(h.n, h.l), 0.0, 1.0);
    return rgb(p, "LightColor") * (dvec3(in.textures[0]) * diffuse + gloss.x * highlight);
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
  static const std::vector<ReferenceModel> models = {
      hemisphere(), per_pixel_lighting(), strand_aniso(), aniso_lut_ward(), wood(), brdf(), aniso_highlights_glsl()};
  return models;
}

}  // namespace fx::bench
