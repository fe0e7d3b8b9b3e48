// Test helper: runs the whole front end (preprocess, parse, check) on a source string.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

namespace fxtest {

struct FrontEnd {
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::ParsedEffect parsed;
  // All diagnostics rendered as clang-style text.
  std::string text() const { return fx::render_text(diags.diagnostics(), sm); }
  std::vector<std::string> ids() const {
    std::vector<std::string> out;
    for (const fx::Diagnostic& d : diags.diagnostics()) out.push_back(d.id);
    return out;
  }
  const fx::ast::Decl& decl(size_t i) const { return parsed.ast.decls.at(i); }
};

// `source` as the file "t.fx", checked under `profile`.
inline std::unique_ptr<FrontEnd> run_front_end(std::string source,
                                               fx::EffectProfile profile = fx::EffectProfile::automatic) {
  auto f = std::make_unique<FrontEnd>();
  fx::FrontEndOptions options;
  options.check.profile = profile;
  f->parsed = fx::parse_effect_text("t.fx", std::move(source), f->sm, f->diags, options);
  return f;
}

}  // namespace fxtest
