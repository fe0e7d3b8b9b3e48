#include "fx/shading/generator.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>

#include "fx/shading/bakers.h"
#include "fx/shading/brdf_factorization.h"
#include "param_reader.h"

namespace fx::shading {

namespace {

using detail::failure;
using detail::finish;
using detail::ParamReader;
using fx::ascii_lower;

BakeResult bake_strand(ParamReader& in) {
  StrandTableOptions o;
  o.size = in.integer("Width", o.size);
  int height = in.integer("Height", o.size);
  if (height != o.size) in.fail("the strand table is square: Height must equal Width");
  o.exponent = in.number("Exponent", o.exponent);
  o.mapping = in.mapping(o.mapping);
  o.index = in.choice("Index", {"dot", "angle"}, 0) == 0 ? LutIndex::cosine : LutIndex::angle;
  o.format = in.format(o.format);
  return finish(in, o, bake_strand_table);
}

BakeResult bake_pow(ParamReader& in) {
  PowTableOptions o;
  o.width = in.integer("Width", o.width);
  o.height = in.integer("Height", o.height);
  o.exponent = in.number("Exponent", o.exponent);
  o.mapping = in.mapping(o.mapping);
  o.format = in.format(o.format);
  return finish(in, o, bake_pow_table);
}

BakeResult bake_ln_hn(ParamReader& in) {
  HalfAngleTableOptions o;
  o.size = in.integer("Width", o.size);
  o.lobe =
      in.choice("Lobe", {"blinn_phong", "gaussian"}, 0) == 0 ? HalfAngleLobe::blinn_phong : HalfAngleLobe::gaussian;
  double exponent = in.number("Exponent", 32.0), roughness = in.number("Roughness", 0.3);
  o.shape = o.lobe == HalfAngleLobe::blinn_phong ? exponent : roughness;
  o.mapping = in.mapping(o.mapping);
  o.format = in.format(o.format);
  return finish(in, o, bake_ln_hn_table);
}

BakeResult bake_noise(ParamReader& in) {
  NoiseTableOptions o;
  o.width = in.integer("Width", o.width);
  o.height = in.integer("Height", o.width);
  o.depth = in.integer("Depth", o.width);
  o.channels = in.integer("Channels", o.channels);
  o.noise.period = in.integer("Period", o.noise.period);
  double seed = in.number("Seed", 1.0);
  if (seed < 0 || seed > 4294967295.0 || seed != std::floor(seed)) in.fail("Seed must be an integer in [0, 2^32)");
  o.noise.seed = uint32_t(seed);
  o.noise.kind = in.choice("Kind", {"gradient", "value"}, 0) == 0 ? NoiseKind::gradient : NoiseKind::value;
  o.noise.octaves = in.integer("Octaves", o.noise.octaves);
  o.format = in.format(o.format);
  return finish(in, o, bake_noise_table);
}

BakeResult bake_hemisphere(ParamReader& in) {
  HemisphereTableOptions o;
  o.width = in.integer("Width", o.width);
  o.format = in.format(o.format);
  return finish(in, o, bake_hemisphere_table);
}

// brdf_factor bakes one of the three factors; its options validate inline.
struct BrdfFactorRequest {
  AnalyticBrdf brdf;
  BrdfFactorizationOptions fit;
  int factor = 0;     // 0 in, 1 half, 2 out
  bool cube = false;  // resampled as a cube map (parabolic_to_cube)
};

std::string validate(const BrdfFactorRequest& r) {
  if (r.fit.size < 2 || r.fit.size > 256) return "Width must be in [2, 256]";
  if (r.fit.samples < 16 || r.fit.samples > (1 << 22)) return "Samples must be in [16, 4194304]";
  if (r.fit.iterations < 1 || r.fit.iterations > 10000) return "Iterations must be in [1, 10000]";
  if (!(r.brdf.exponent >= 0 && r.brdf.exponent <= 1e4)) return "Exponent must be in [0, 10000]";
  if (!(r.brdf.alpha_x >= 1e-3 && r.brdf.alpha_y >= 1e-3)) return "AlphaX and AlphaY must be >= 0.001";
  if (!(r.brdf.diffuse >= 0)) return "Diffuse must be >= 0";
  return {};
}

BakeResult bake_brdf_factor(ParamReader& in) {
  BrdfFactorRequest r;
  r.factor = in.choice("Factor", {"in", "half", "out"}, 0);
  r.fit.size = in.integer("Width", r.fit.size);
  r.cube = in.choice("Shape", {"parabolic", "cube"}, 0) == 1;
  r.brdf.lobe = BrdfLobe(in.choice("Lobe", {"phong", "blinn_phong", "ward"}, 0));
  r.brdf.exponent = in.number("Exponent", r.brdf.exponent);
  r.brdf.alpha_x = in.number("AlphaX", r.brdf.alpha_x);
  r.brdf.alpha_y = in.number("AlphaY", r.brdf.alpha_y);
  r.brdf.diffuse = in.number("Diffuse", r.brdf.diffuse);
  r.fit.samples = in.integer("Samples", r.fit.samples);
  r.fit.iterations = in.integer("Iterations", r.fit.iterations);
  double seed = in.number("Seed", 1.0);
  if (seed < 0 || seed > 4294967295.0 || seed != std::floor(seed)) in.fail("Seed must be an integer in [0, 2^32)");
  r.fit.seed = uint32_t(seed);
  if (in.format(TableFormat::float32) != TableFormat::float32)
    in.fail("brdf_factor tables are float32: the factors' range is not [0, 1]");
  return finish(in, r, [](const BrdfFactorRequest& q) {
    BrdfFactors f = factorize_brdf(q.brdf, q.fit);
    const Table& factor = q.factor == 0 ? f.in : q.factor == 1 ? f.half : f.out;
    if (!q.cube) return factor;
    // DirectX 8 listings multiply the factors' texels whole: a luminance cube (rgb = the
    // factor, alpha 1), as an L8/L16 factor map reads in D3D.
    const Table one = parabolic_to_cube(factor, q.fit.size);
    Table rgb = Table::make(one.width, one.height, one.depth, 3, one.format);
    rgb.cube = true;
    for (int z = 0; z < one.depth; ++z)
      for (int y = 0; y < one.height; ++y)
        for (int x = 0; x < one.width; ++x)
          for (int c = 0; c < 3; ++c) rgb.store(x, y, z, c, one.fetch(x, y, z, 0));
    return rgb;
  });
}

struct GeneratorEntry {
  std::string_view name;
  BakeResult (*bake)(ParamReader&);
};

constexpr GeneratorEntry kGenerators[] = {
    {"strand", bake_strand},
    {"pow", bake_pow},
    {"ln_hn", bake_ln_hn},
    {"noise3d", bake_noise},
    {"hemisphere", bake_hemisphere},
    {"brdf_factor", bake_brdf_factor},
    // Texture assets (asset_generators.h): stand-ins for an engine's own textures.
    {"direction_field", detail::bake_direction_field_asset},
    {"normal_map", detail::bake_normal_map_asset},
    {"height_map", detail::bake_height_map_asset},
    {"color_map", detail::bake_color_map_asset},
    {"gloss_map", detail::bake_gloss_map_asset},
};

}  // namespace

GeneratorParams& GeneratorParams::set(std::string_view name, double value) {
  values_[ascii_lower(name)] = value;
  return *this;
}

GeneratorParams& GeneratorParams::set(std::string_view name, std::string_view value) {
  values_[ascii_lower(name)] = std::string(value);
  return *this;
}

const GeneratorParams::Value* GeneratorParams::find(std::string_view name) const {
  auto it = values_.find(ascii_lower(name));
  return it == values_.end() ? nullptr : &it->second;
}

std::vector<std::string_view> generator_names() {
  std::vector<std::string_view> names;
  for (const GeneratorEntry& g : kGenerators) names.push_back(g.name);
  return names;
}

BakeResult bake(std::string_view generator, const GeneratorParams& params) {
  std::string name = ascii_lower(generator);
  for (const GeneratorEntry& g : kGenerators) {
    if (g.name != name) continue;
    ParamReader in(g.name, params);
    return g.bake(in);
  }
  std::string message = "unknown table generator '" + std::string(generator) + "'";
  std::string near = closest_match(name, generator_names());
  if (!near.empty()) message += "; did you mean '" + near + "'?";
  return failure("unknown-generator", message);
}

std::optional<Table> bake(std::string_view generator, const GeneratorParams& params, DiagnosticSink& sink,
                          SourceRange where) {
  BakeResult r = bake(generator, params);
  if (!r.ok()) {
    sink.error(r.error_id, where, r.message);
    return std::nullopt;
  }
  return std::move(r.table);
}

}  // namespace fx::shading
