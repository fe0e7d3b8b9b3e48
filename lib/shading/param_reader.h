// Reading generator parameters from annotations: typed getters that remember the
// generator's vocabulary (for did-you-mean on near-miss names) and the first error.
// Private to lib/shading: shared by the registry (generator.cpp) and the texture-asset
// generators (asset_generators.cpp) so both report errors in the same words.
#pragma once
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fx/ascii_case.h"
#include "fx/shading/bakers.h"
#include "fx/shading/generator.h"

namespace fx::shading::detail {

// One swap of adjacent letters ("Widht"): closest_match's distance budget misses these.
inline bool is_transposition(std::string_view a, std::string_view b) {
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

  // A string parameter (colours as "r g b"); a number is an error.
  std::string text(std::string_view name, std::string_view fallback) {
    vocabulary_.push_back(name);
    const GeneratorParams::Value* v = params_.find(name);
    if (!v) return std::string(fallback);
    if (const std::string* s = std::get_if<std::string>(v)) return *s;
    fail(std::string(name) + " must be a string");
    return std::string(fallback);
  }

  // One of `choices` (case-insensitive); returns its index.
  int choice(std::string_view name, std::initializer_list<std::string_view> choices, int fallback) {
    vocabulary_.push_back(name);
    const GeneratorParams::Value* v = params_.find(name);
    if (!v) return fallback;
    const std::string* s = std::get_if<std::string>(v);
    std::string want = s ? ascii_lower(*s) : std::string();
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
    for (std::string_view v : vocabulary_) known.push_back(ascii_lower(v));
    known.push_back("generator");
    for (const auto& [name, value] : params_.entries()) {
      if (std::find(known.begin(), known.end(), name) != known.end()) continue;
      std::string near = closest_match(name, std::vector<std::string_view>(vocabulary_.begin(), vocabulary_.end()));
      for (std::string_view v : vocabulary_)
        if (near.empty() && is_transposition(name, ascii_lower(v))) near = std::string(v);
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

inline BakeResult failure(std::string id, std::string message) {
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

// Annotation readers of the texture-asset generators (asset_generators.cpp), for the
// registry table.
BakeResult bake_direction_field_asset(ParamReader& in);
BakeResult bake_normal_map_asset(ParamReader& in);
BakeResult bake_height_map_asset(ParamReader& in);
BakeResult bake_color_map_asset(ParamReader& in);
BakeResult bake_gloss_map_asset(ParamReader& in);

}  // namespace fx::shading::detail
