#include "fx/shading/generator.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>

#include "fx/shading/bakers.h"
#include "fx/shading/brdf_factorization.h"

namespace fx::shading {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// One swap of adjacent letters ("Widht"): closest_match's distance budget misses these.
bool is_transposition(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  size_t i = 0;
  while (i < a.size() && a[i] == b[i]) ++i;
  return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] && a.substr(i + 2) == b.substr(i + 2);
}

// Reads typed parameters for one generator, remembering which names it asked for (the
// vocabulary) and the first error.
class ParamReader {
 public:
  ParamReader(std::string_view generator, const GeneratorParams& p) : generator_(generator), params_(p) {}

  double number(std::string_view name, double fallback) {
    vocabulary_.push_back(name);
    const GeneratorParams::Value* v = params_.find(name);
    if (!v) return fallback;
    if (const double* d = std::get_if<double>(v)) {
      if (std::isfinite(*d)) return *d;
      fail(std::string(name) + " must be a finite number");
    } else {
      fail(std::string(name) + " must be a number, got the string \"" + std::get<std::string>(*v) + "\"");
    }
    return fallback;
  }

  int integer(std::string_view name, int fallback) {
    double d = number(name, fallback);
    if (d != std::floor(d) || d < -2147483648.0 || d > 2147483647.0) {
      fail(std::string(name) + " must be an integer");
      return fallback;
    }
    return int(d);
  }

  // One of `choices` (case-insensitive); returns its index.
  int choice(std::string_view name, std::initializer_list<std::string_view> choices, int fallback) {
    vocabulary_.push_back(name);
    const GeneratorParams::Value* v = params_.find(name);
    if (!v) return fallback;
    const std::string* s = std::get_if<std::string>(v);
    std::string want = s ? lower(*s) : std::string();
    int i = 0;
    for (std::string_view c : choices) {
      if (s && want == c) return i;
      ++i;
    }
    std::string list;
    for (std::string_view c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
    std::string hint;
    if (s) {
      std::string near = closest_match(want, std::vector<std::string_view>(choices));
      if (!near.empty()) hint = "; did you mean '" + near + "'?";
    }
    fail(std::string(name) + " must be one of " + list + (s ? ", got '" + *s + "'" : ", got a number") + hint);
    return fallback;
  }

  TableFormat format(TableFormat fallback) {
    int i = choice("Format", {"unorm8", "float32"}, fallback == TableFormat::unorm8 ? 0 : 1);
    return i == 0 ? TableFormat::unorm8 : TableFormat::float32;
  }

  LutMapping mapping(LutMapping fallback) {
    int i = choice("Mapping", {"naive", "seed_wrap", "texel_centre", "texel_centre_wrap"}, int(fallback));
    return LutMapping(i);
  }

  void fail(std::string message) {
    if (error_.empty()) error_ = std::move(message);
  }

  // Rejects near-misses of the vocabulary ("Widht"); other names are the annotation's own.
  void check_unknown() {
    std::vector<std::string> known;
    for (std::string_view v : vocabulary_) known.push_back(lower(v));
    known.push_back("generator");
    for (const auto& [name, value] : params_.entries()) {
      if (std::find(known.begin(), known.end(), name) != known.end()) continue;
      std::string near = closest_match(name, std::vector<std::string_view>(vocabulary_.begin(), vocabulary_.end()));
      for (std::string_view v : vocabulary_)
        if (near.empty() && is_transposition(name, lower(v))) near = std::string(v);
      if (!near.empty())
        fail("unknown parameter '" + name + "' for generator '" + generator_ + "'; did you mean '" + near + "'?");
    }
  }

  const std::string& error() const { return error_; }

 private:
  std::string generator_;
  const GeneratorParams& params_;
  std::vector<std::string_view> vocabulary_;
  std::string error_;
};

BakeResult failure(std::string id, std::string message) {
  BakeResult r;
  r.error_id = std::move(id);
  r.message = std::move(message);
  return r;
}

// Finishes a bake: parameter errors first, then the typed validator, then the table.
template <class Options, class Bake>
BakeResult finish(ParamReader& in, const Options& o, Bake&& bake_fn) {
  in.check_unknown();
  if (!in.error().empty()) return failure("bad-generator-parameter", in.error());
  if (std::string e = validate(o); !e.empty()) return failure("bad-generator-parameter", e);
  BakeResult r;
  r.table = bake_fn(o);
  return r;
}

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
  o.lobe = in.choice("Lobe", {"blinn_phong", "gaussian"}, 0) == 0 ? HalfAngleLobe::blinn_phong
                                                                   : HalfAngleLobe::gaussian;
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
  int factor = 0;  // 0 in, 1 half, 2 out
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
    return q.factor == 0 ? f.in : q.factor == 1 ? f.half : f.out;
  });
}

struct GeneratorEntry {
  std::string_view name;
  BakeResult (*bake)(ParamReader&);
};

constexpr GeneratorEntry kGenerators[] = {
    {"strand", bake_strand},   {"pow", bake_pow},           {"ln_hn", bake_ln_hn},
    {"noise3d", bake_noise},   {"hemisphere", bake_hemisphere}, {"brdf_factor", bake_brdf_factor},
};

}  // namespace

GeneratorParams& GeneratorParams::set(std::string_view name, double value) {
  values_[lower(name)] = value;
  return *this;
}

GeneratorParams& GeneratorParams::set(std::string_view name, std::string_view value) {
  values_[lower(name)] = std::string(value);
  return *this;
}

const GeneratorParams::Value* GeneratorParams::find(std::string_view name) const {
  auto it = values_.find(lower(name));
  return it == values_.end() ? nullptr : &it->second;
}

std::vector<std::string_view> generator_names() {
  std::vector<std::string_view> names;
  for (const GeneratorEntry& g : kGenerators) names.push_back(g.name);
  return names;
}

BakeResult bake(std::string_view generator, const GeneratorParams& params) {
  std::string name = lower(generator);
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
