// The semantic model on real effects: on every effect in effects/ (each compiles, which
// the effects' own suites prove) it must report nothing. `fxkit_semantic_corpus DIR`
// (bench/) measures the same on any other corpus.
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "fx/corpus_resolution.h"

namespace {

TEST(SemanticEffects, NoFindingsOnTheSeedEffects) {
  const std::string root = (std::filesystem::path(FXKIT_SOURCE_DIR) / "effects").string();
  const fx::semantic::CorpusResolution tally = fx::semantic::resolve_corpus(root);
  std::printf("%s", tally.summary(root).c_str());
  EXPECT_GE(tally.files, 5u);
  EXPECT_GT(tally.counts.resolved, 100u);
  EXPECT_EQ(tally.counts.diagnosed, 0u) << tally.findings;
}

}  // namespace
