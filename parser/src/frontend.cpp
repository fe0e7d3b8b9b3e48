#include "fx/frontend.h"

namespace fx {
namespace {

ParsedEffect finish(Preprocessor& pp, std::vector<Token> tokens, size_t errors_before, const SourceManager& sm,
                    DiagnosticSink& diags, const FrontEndOptions& options) {
  ParsedEffect result;
  result.files = pp.files();
  result.includes = pp.includes();
  result.ast = parse_effect(std::move(tokens), sm, diags, options.parse);
  // Checking a tree the parser gave up on would only repeat its errors as new ones.
  if (diags.error_count() == errors_before) check_effect(result.ast, sm, diags, options.check);
  result.ok = diags.error_count() == errors_before;
  result.ast.front_end_failed = !result.ok;
  return result;
}

}  // namespace

ParsedEffect parse_effect_file(const std::string& path, SourceManager& sm, DiagnosticSink& diags,
                               const FrontEndOptions& options) {
  size_t errors_before = diags.error_count();
  Preprocessor pp(sm, diags, options.preprocessor);
  std::vector<Token> tokens;
  pp.run_file(path, tokens);
  return finish(pp, std::move(tokens), errors_before, sm, diags, options);
}

ParsedEffect parse_effect_text(std::string name, std::string text, SourceManager& sm, DiagnosticSink& diags,
                               const FrontEndOptions& options) {
  size_t errors_before = diags.error_count();
  Preprocessor pp(sm, diags, options.preprocessor);
  std::vector<Token> tokens;
  pp.run_buffer(std::move(name), std::move(text), tokens);
  return finish(pp, std::move(tokens), errors_before, sm, diags, options);
}

}  // namespace fx
