// The semantic model on real effects: on every effect in effects/ (each compiles, which
// the effects' own suites prove) it must report nothing. FXKIT_SEMANTIC_CORPUS=DIR adds
// the `.fx` files below DIR that the front end accepts, and prints what the model resolved.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"
#include "fx/semantic_model.h"

namespace {

namespace fs = std::filesystem;

struct Tally {
  size_t files = 0, files_with_findings = 0;
  size_t parameters = 0, typed_parameters = 0;  // globals and cbuffer members; those with a known type
  fx::semantic::ResolutionCounts counts;
  std::string findings, untyped;
};

void model_file(const fs::path& file, Tally& tally) {
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::FrontEndOptions options;
  options.check.require_technique = false;
  fx::ParsedEffect parsed = fx::parse_effect_file(file.string(), sm, diags, options);
  if (diags.has_errors()) return;  // the front end refuses it: not a file that compiles
  fx::semantic::SemanticModel model(parsed.ast, sm);
  ++tally.files;
  const auto& c = model.counts();
  tally.counts.identifiers += c.identifiers;
  tally.counts.resolved += c.resolved;
  tally.counts.intrinsics += c.intrinsics;
  tally.counts.methods += c.methods;
  for (const fx::semantic::Symbol* s : model.globals())
    if (s->kind == fx::semantic::SymbolKind::parameter || s->kind == fx::semantic::SymbolKind::cbuffer_member) {
      ++tally.parameters;
      if (s->type.known()) ++tally.typed_parameters;
      else tally.untyped += std::string(s->name) + ": " + s->type.name + "\n";
    }
  tally.counts.unresolved += c.unresolved;
  tally.counts.diagnosed += c.diagnosed;
  if (!model.diagnostics().empty()) {
    ++tally.files_with_findings;
    tally.findings += fx::render_text(model.diagnostics(), sm);
  }
}

Tally model_tree(const fs::path& root) {
  Tally tally;
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() == ".fx") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) model_file(f, tally);
  std::printf(
      "%s: %zu files, %zu identifiers in bodies: %zu resolved to declarations, %zu intrinsics, %zu object "
      "methods, %zu left alone, %zu findings in %zu files; %zu of %zu parameters typed\n%s",
      root.string().c_str(), tally.files, tally.counts.identifiers, tally.counts.resolved, tally.counts.intrinsics,
      tally.counts.methods, tally.counts.unresolved, tally.counts.diagnosed, tally.files_with_findings,
      tally.typed_parameters, tally.parameters, tally.untyped.c_str());
  return tally;
}

TEST(SemanticEffects, NoFindingsOnTheSeedEffects) {
  Tally tally = model_tree(fs::path(FXKIT_SOURCE_DIR) / "effects");
  EXPECT_GE(tally.files, 5u);
  EXPECT_GT(tally.counts.resolved, 100u);
  EXPECT_EQ(tally.counts.diagnosed, 0u) << tally.findings;
}

TEST(SemanticEffects, CorpusFromTheEnvironment) {
  const char* dir = std::getenv("FXKIT_SEMANTIC_CORPUS");
  if (!dir) GTEST_SKIP() << "FXKIT_SEMANTIC_CORPUS not set";
  Tally tally = model_tree(dir);
  EXPECT_EQ(tally.counts.diagnosed, 0u) << tally.findings;
}

}  // namespace
