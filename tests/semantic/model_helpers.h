// Test helper: the front end and the semantic model over one effect source string.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "fx/frontend.h"
#include "fx/semantic_model.h"

namespace fxtest {

struct Modelled {
  fx::SourceManager sm;
  fx::DiagnosticSink front_end;
  fx::ParsedEffect parsed;
  std::unique_ptr<fx::semantic::SemanticModel> model;

  // The index of the n-th token spelled `text` (0-based), or -1.
  int64_t token(std::string_view text, int n = 0) const {
    for (size_t i = 0; i < parsed.ast.tokens.size(); ++i)
      if (parsed.ast.tokens[i].text() == text && n-- == 0) return static_cast<int64_t>(i);
    return -1;
  }
  const fx::semantic::Reference* reference(std::string_view text, int n = 0) const {
    const int64_t t = token(text, n);
    return t < 0 ? nullptr : model->reference_at(static_cast<uint32_t>(t));
  }
  std::vector<std::string> ids() const {
    std::vector<std::string> out;
    for (const fx::Diagnostic& d : model->diagnostics()) out.push_back(d.id);
    return out;
  }
};

inline std::unique_ptr<Modelled> model_of(std::string source) {
  auto m = std::make_unique<Modelled>();
  fx::FrontEndOptions options;
  options.check.require_technique = false;
  m->parsed = fx::parse_effect_text("t.fx", std::move(source), m->sm, m->front_end, options);
  m->model = std::make_unique<fx::semantic::SemanticModel>(m->parsed.ast, m->sm);
  return m;
}

}  // namespace fxtest
