// Parses effect text and builds its model, keeping everything the model points into alive.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"

namespace fx::test {

struct Built {
  std::unique_ptr<SourceManager> sm = std::make_unique<SourceManager>();
  DiagnosticSink diags;
  ParsedEffect parsed;
  EffectModel model;
  bool has(std::string_view id) const {
    for (const Diagnostic& d : diags.diagnostics())
      if (d.id == id) return true;
    return false;
  }
  std::string text() const { return render_text(diags.diagnostics(), *sm); }
};

inline std::unique_ptr<Built> build(std::string text, bool require_technique = false) {
  auto b = std::make_unique<Built>();
  FrontEndOptions options;
  options.check.require_technique = require_technique;
  b->parsed = parse_effect_text("test.fx", std::move(text), *b->sm, b->diags, options);
  b->model = build_effect_model(b->parsed, *b->sm, b->diags);
  return b;
}

inline const Parameter& param(const Built& b, std::string_view name) {
  static const Parameter none;
  uint32_t i = b.model.find_parameter(name);
  return i == kNoIndex ? none : b.model.parameters[i];
}

// A block member holding the words `path` names (a failed expectation when it names none).
inline BlockMemberLayout placed(const EffectModel& model, std::string_view path, uint32_t offset, uint32_t size,
                                uint32_t array_stride, uint32_t matrix_stride, MatrixPacking order) {
  std::optional<ParameterSlice> slice = find_slice(model, path);
  EXPECT_TRUE(slice) << path;
  return {slice.value_or(ParameterSlice{}), offset, size, array_stride, matrix_stride, order};
}

}  // namespace fx::test
