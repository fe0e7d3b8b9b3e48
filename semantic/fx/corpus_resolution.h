// How much of a corpus of effects the semantic model resolves: the model built on every
// `.fx` file below a folder that the front end accepts, with its counts added up, the
// parameters it could type, and its findings (which on code that compiles are false
// positives). The seed effects' test holds it to zero findings; `fxkit_semantic_corpus DIR`
// (bench/) measures it on any other corpus.
#pragma once
#include <cstddef>
#include <string>

#include "fx/semantic_model.h"

namespace fx::semantic {

struct CorpusResolution {
  size_t files = 0, files_with_findings = 0;    // files the front end accepts; those with findings
  size_t parameters = 0, typed_parameters = 0;  // globals and cbuffer members; those with a known type
  ResolutionCounts counts;
  std::string findings;  // the findings as text
  std::string untyped;   // "name: type" of each parameter without a known type, one a line

  // One line of figures, then the untyped parameters.
  std::string summary(const std::string& corpus) const;
};

// The model on every `.fx` file below `root` (sorted, so runs compare).
CorpusResolution resolve_corpus(const std::string& root);

}  // namespace fx::semantic
