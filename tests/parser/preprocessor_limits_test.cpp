// Limits (expansions, tokens, nesting, input bytes) and preprocessing throughput.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "preprocessor_fixture.h"

namespace fx {
namespace {

using test::kHangSeconds;
using test::Pp;
using test::seconds_since;

TEST(PreprocessorLimits, ExponentialMacroHitsTheExpansionLimit) {
  std::string src = "#define A0 x x\n";
  for (int i = 1; i <= 40; ++i)
    src += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + " A" + std::to_string(i - 1) + "\n";
  src += "A40\n";
  Pp p;
  auto start = std::chrono::steady_clock::now();
  p.run(src);
  EXPECT_LT(seconds_since(start), kHangSeconds);
  EXPECT_EQ(p.only().id, "limit-exceeded");
  EXPECT_LT(p.tokens.size(), 2u << 20);
}

TEST(PreprocessorLimits, ExponentialArgumentsHitTheTokenLimit) {
  // Each level doubles an argument: the token budget stops it, not memory.
  std::string src = "#define D0(x) x x\n";
  for (int i = 1; i <= 40; ++i) src += "#define D" + std::to_string(i) + "(x) D" + std::to_string(i - 1) + "(x x)\n";
  src += "D40(y)\n";
  Pp p;
  p.options.limits.max_tokens = 1u << 20;
  auto start = std::chrono::steady_clock::now();
  p.run(src);
  EXPECT_LT(seconds_since(start), kHangSeconds);
  EXPECT_EQ(p.only().id, "limit-exceeded");
  EXPECT_LE(p.tokens.size(), p.options.limits.max_tokens + 1);  // the budget and the eof
}

TEST(PreprocessorLimits, DeepParenthesesInIf) {
  std::string expr(10000, '(');
  expr += "1" + std::string(10000, ')');
  Pp p;
  auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(p.run("#if " + expr + "\nyes\n#endif\n-"), "");
  EXPECT_LT(seconds_since(start), kHangSeconds);
  EXPECT_EQ(p.only().id, "limit-exceeded");
  // Within the limit it evaluates.
  Pp q;
  EXPECT_EQ(q.run("#if " + std::string(100, '(') + "1" + std::string(100, ')') + "\nyes\n#endif\n"), "yes");
  Pp r;
  EXPECT_EQ(r.run("#if " + std::string(10000, '!') + "1\n#endif\n"), "");
  EXPECT_EQ(r.only().id, "limit-exceeded");
}

TEST(PreprocessorLimits, DeeplyNestedMacroArguments) {
  std::string src = "#define f(x) x\n";
  for (int i = 0; i < 10000; ++i) src += "f(";
  src += "1";
  src += std::string(10000, ')');
  Pp p;
  auto start = std::chrono::steady_clock::now();
  p.run(src);
  EXPECT_LT(seconds_since(start), kHangSeconds);
  EXPECT_EQ(p.only().id, "limit-exceeded");
  Pp q;
  EXPECT_EQ(q.run("#define f(x) x\nf(f(f(f(f(1)))))"), "1");
}

TEST(PreprocessorLimits, InputAndOutputBudgets) {
  Pp p;
  p.options.limits.max_input_bytes = 100;
  p.files["big.fxh"] = std::string(200, 'x');
  p.run("#include \"big.fxh\"\n");
  EXPECT_EQ(p.only().id, "limit-exceeded");
  Pp q;
  q.options.limits.max_tokens = 10;
  q.run("a b c d e f g h i j k l m n o p\n");
  EXPECT_EQ(q.only().id, "limit-exceeded");
  EXPECT_EQ(q.tokens.size(), 11u);
}

// ---- throughput (a correctness check on the generated input; prints MB/s) ---------------

TEST(PreprocessorThroughput, GeneratedEffect) {
  std::string src = "#define SCALE(x) ((x) * 0.5f)\n#define BIAS 0.25f\n";
  for (int i = 0; src.size() < (1u << 20); ++i)
    src += "float4 v" + std::to_string(i) + " = SCALE(float4(1.0, 2.0, 3.0, 4.0)) + BIAS; // c\n";
  Pp p;
  auto start = std::chrono::steady_clock::now();
  std::string text = src;
  std::vector<Token> out;
  Preprocessor pp(p.sm, p.diags, p.options);
  ASSERT_TRUE(pp.run_buffer("gen.fx", std::move(text), out));
  double s = seconds_since(start);
  std::printf("preprocessed %.1f MB in %.3f s: %.1f MB/s (%zu tokens)\n", src.size() / 1e6, s, src.size() / 1e6 / s,
              out.size());
  size_t lines = 0;
  for (char c : src) lines += c == '\n';
  EXPECT_EQ(out.size(), (lines - 2) * 22 + 1);
}

}  // namespace
}  // namespace fx
