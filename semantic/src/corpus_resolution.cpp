// The semantic model over a corpus of effects (fx/corpus_resolution.h).
#include "fx/corpus_resolution.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

namespace fx::semantic {
namespace {

namespace fs = std::filesystem;

void resolve_file(const fs::path& file, CorpusResolution& tally) {
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::FrontEndOptions options;
  options.check.require_technique = false;
  fx::ParsedEffect parsed = fx::parse_effect_file(file.string(), sm, diags, options);
  if (diags.has_errors()) return;  // the front end refuses it: not a file that compiles
  SemanticModel model(parsed.ast, sm);
  ++tally.files;
  const ResolutionCounts& c = model.counts();
  tally.counts.identifiers += c.identifiers;
  tally.counts.resolved += c.resolved;
  tally.counts.intrinsics += c.intrinsics;
  tally.counts.methods += c.methods;
  tally.counts.unresolved += c.unresolved;
  tally.counts.diagnosed += c.diagnosed;
  for (const Symbol* s : model.globals())
    if (s->kind == SymbolKind::parameter || s->kind == SymbolKind::cbuffer_member) {
      ++tally.parameters;
      if (s->type.known()) ++tally.typed_parameters;
      else tally.untyped += std::string(s->name) + ": " + s->type.name + "\n";
    }
  if (!model.diagnostics().empty()) {
    ++tally.files_with_findings;
    tally.findings += fx::render_text(model.diagnostics(), sm);
  }
}

}  // namespace

std::string CorpusResolution::summary(const std::string& corpus) const {
  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %zu files, %zu identifiers in bodies: %zu resolved to declarations, %zu intrinsics, %zu object "
                "methods, %zu left alone, %zu findings in %zu files; %zu of %zu parameters typed\n",
                corpus.c_str(), files, counts.identifiers, counts.resolved, counts.intrinsics, counts.methods,
                counts.unresolved, counts.diagnosed, files_with_findings, typed_parameters, parameters);
  return line + untyped;
}

CorpusResolution resolve_corpus(const std::string& root) {
  CorpusResolution tally;
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() == ".fx") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) resolve_file(f, tally);
  return tally;
}

}  // namespace fx::semantic
