// The semantic model measured on a corpus of effects: `fxkit_semantic_corpus DIR...` prints,
// per folder, how many identifiers in function bodies resolve (to declarations, intrinsics,
// object methods), how many are left alone, the findings (false positives on code that
// compiles) and how many parameters have a type for hover. Exits 1 when there are findings.
#include <cstdio>

#include "fx/corpus_resolution.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: fxkit_semantic_corpus DIR...\n");
    return 2;
  }
  size_t findings = 0;
  for (int i = 1; i < argc; ++i) {
    const fx::semantic::CorpusResolution tally = fx::semantic::resolve_corpus(argv[i]);
    std::printf("%s%s", tally.summary(argv[i]).c_str(), tally.findings.c_str());
    findings += tally.counts.diagnosed;
  }
  return findings == 0 ? 0 : 1;
}
