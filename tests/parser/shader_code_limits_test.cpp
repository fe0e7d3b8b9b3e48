// The front end's checks of the shader code glslang gets (fxkit issue #32): nesting depth,
// operators per statement, over-long names and numbers, preprocessor tokens left in the
// code. Each is one located error per declaration; what real effects write passes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "front_end_helpers.h"

namespace fx {
namespace {

using fxtest::run_front_end;

using Ids = std::vector<std::string>;
constexpr const char* kTechnique = "technique T { pass P { } }\n";

std::string function_returning(const std::string& expression) {
  return "float4 PS(float4 x : COLOR0) : COLOR {\n  return " + expression + ";\n}\n" + kTechnique;
}

TEST(ShaderCodeLimits, OpenParenthesesAreOneLocatedError) {
  auto f = run_front_end(function_returning(std::string(20000, '(') + "x"));
  ASSERT_EQ(f->ids(), Ids{"shader-nesting-too-deep"}) << f->text();
  EXPECT_TRUE(f->text().starts_with("t.fx:2:")) << f->text();
  EXPECT_TRUE(f->parsed.ast.front_end_failed);
  // 256 levels are fine, as in the effect parser's own expressions.
  auto g = run_front_end(function_returning(std::string(255, '(') + "x" + std::string(255, ')')));
  EXPECT_EQ(g->text(), "");
  EXPECT_FALSE(g->parsed.ast.front_end_failed);
}

TEST(ShaderCodeLimits, BracesStatementsAndPrefixOperatorsCountAsNesting) {
  auto braces = run_front_end("void F() " + std::string(300, '{') + std::string(300, '}') + "\n" + kTechnique);
  EXPECT_EQ(braces->ids(), Ids{"shader-nesting-too-deep"}) << braces->text();
  std::string ifs;
  for (int i = 0; i < 300; ++i) ifs += "if (x > 0) ";
  auto statements = run_front_end("float F(float x) { " + ifs + "x = 1; return x; }\n" + kTechnique);
  EXPECT_EQ(statements->ids(), Ids{"shader-nesting-too-deep"}) << statements->text();
  std::string negations;
  for (int i = 0; i < 300; ++i) negations += "- ";
  auto prefixes = run_front_end(function_returning(negations + "x"));
  EXPECT_EQ(prefixes->ids(), Ids{"shader-nesting-too-deep"}) << prefixes->text();
  prefixes = run_front_end(function_returning(std::string(600, '-') + "x"));  // `--` 300 times
  EXPECT_EQ(prefixes->ids(), Ids{"shader-nesting-too-deep"}) << prefixes->text();
  // An else-if chain does not nest deeper, nor do statements one after another.
  std::string chain = "float F(float x) { ";
  for (int i = 0; i < 600; ++i) chain += "if (x > " + std::to_string(i) + ") x = 1; else ";
  chain += "x = 0;\n";
  for (int i = 0; i < 600; ++i) chain += "if (x > 0) x -= 1;\n";
  auto fine = run_front_end(chain + "return x; }\n" + kTechnique);
  EXPECT_EQ(fine->text(), "");
}

TEST(ShaderCodeLimits, LongOperatorChainsInOneStatement) {
  std::string product = "x";
  for (int i = 0; i < 5000; ++i) product += " * x";
  auto f = run_front_end(function_returning(product));
  EXPECT_EQ(f->ids(), Ids{"shader-statement-too-long"}) << f->text();
  // Large tables are commas and unary minus signs, not operators.
  std::string table = "static const float T[5000] = { ";
  for (int i = 0; i < 5000; ++i) table += "-0.5, ";
  auto g = run_front_end(table + "1 };\n" + kTechnique);
  EXPECT_EQ(g->text(), "");
}

TEST(ShaderCodeLimits, NamesAndNumbersLongerThanGlslangTakes) {
  auto f = run_front_end(function_returning("x * 1" + std::string(2000, '0')));
  ASSERT_EQ(f->ids(), Ids{"shader-token-too-long"}) << f->text();
  EXPECT_EQ(f->diags.diagnostics()[0].message, "number of 2001 characters in shader code (at most 1024)");
  auto g = run_front_end("float " + std::string(1100, 'a') + ";\n" + kTechnique);
  EXPECT_EQ(g->ids(), Ids{"shader-token-too-long"}) << g->text();
}

TEST(ShaderCodeLimits, PreprocessorTokensLeftInTheCode) {
  // A macro's replacement cannot make a directive: glslang must not see `#define` again.
  auto f = run_front_end("#define H #\nfloat F() {\nH define Q(x) x##x\n  return Q(1);\n}\n" + std::string(kTechnique));
  ASSERT_FALSE(f->ids().empty());
  EXPECT_EQ(f->ids()[0], "shader-preprocessor-token") << f->text();
  EXPECT_TRUE(f->text().starts_with("t.fx:3:1: error: '#' in shader code")) << f->text();
  auto g = run_front_end(function_returning("x ## x"));
  EXPECT_EQ(g->ids(), Ids{"shader-preprocessor-token"}) << g->text();
  auto h = run_front_end("float F() {\n#version 450\n  return 1;\n}\n" + std::string(kTechnique));
  EXPECT_EQ(h->ids(), Ids{"shader-preprocessor-token"}) << h->text();
  // Pasting in a macro is the preprocessor's, and #pragma and a GLSL block's version stay.
  auto fine = run_front_end(
      "#define CAT(a, b) a##b\nfloat F() {\n#pragma warning(disable : 3571)\n  float CAT(c, 0) = 1; "
      "return c0;\n}\nGLSLShader G { #version 450\n void main() {} }\n" +
      std::string(kTechnique));
  EXPECT_EQ(fine->text(), "");
}

}  // namespace
}  // namespace fx
