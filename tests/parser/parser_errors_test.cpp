// The parser on invalid input: the exact rendered diagnostic (one mistake gives one
// diagnostic), recovery that keeps the following declarations, and nesting limits.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "parse_helpers.h"

using namespace fx;
using fxtest::parse;
using fxtest::var;

namespace {

void expect_one(const std::string& source, const std::string& golden) {
  auto p = parse(source);
  EXPECT_EQ(p->diags.diagnostics().size(), 1u) << p->text();
  EXPECT_EQ(p->text(), golden);
}

TEST(ParserErrors, MissingSemicolonOnNewLine) {
  auto p = parse("float a = 1\nfloat b;\n");
  EXPECT_EQ(p->text(),
            "test.fx:1:12: error: expected ';' after declaration [expected-token]\n"
            "float a = 1\n"
            "           ^\n"
            "test.fx:1:12: note: fix-it: insert ';'\n");
  EXPECT_EQ(p->effect.decls.size(), 2u);  // b is still parsed
}

TEST(ParserErrors, StrayBrace) {
  expect_one("float a;\n}\nfloat b;\n",
             "test.fx:2:1: error: expected a declaration, found '}' [expected-declaration]\n"
             "}\n"
             "^\n");
}

// A character that starts no token is the lexer's one diagnostic: the parser does not see
// it again, at file scope or in shader code, and what follows still parses (through the
// preprocessor too: PreprocessorMacros.StrayCharacterInAMacroIsReportedOnce).
TEST(ParserErrors, StrayCharacterIsOneDiagnostic) {
  auto p = parse("float a;\n@ float b;\n");
  EXPECT_EQ(p->text(),
            "test.fx:2:1: error: unexpected character in source [unknown-character]\n"
            "@ float b;\n"
            "^\n");
  EXPECT_EQ(p->effect.decls.size(), 2u);  // b is still parsed
  auto q = parse("float4 PS() : COLOR { return 1 ` 2; }\n");
  ASSERT_EQ(q->diags.diagnostics().size(), 1u) << q->text();
  EXPECT_EQ(q->diags.diagnostics()[0].id, "unknown-character");
}

TEST(ParserErrors, BadStateValueRecoversAtSemicolon) {
  auto p = parse("technique t { pass p { ZEnable = ; CullMode = None; } }\nfloat x;\n");
  EXPECT_EQ(p->text(),
            "test.fx:1:34: error: expected an expression, found ';' [expected-expression]\n"
            "technique t { pass p { ZEnable = ; CullMode = None; } }\n"
            "                                 ^\n");
  ASSERT_EQ(p->effect.decls.size(), 2u);
  EXPECT_EQ(p->decl(0).technique->passes.at(0).states.size(), 1u);
}

TEST(ParserErrors, MissingEqualsInState) {
  expect_one("technique t { pass p { ZEnable TRUE; } }",
             "test.fx:1:32: error: expected '=' after state name 'ZEnable', found 'TRUE' "
             "[expected-token]\n"
             "technique t { pass p { ZEnable TRUE; } }\n"
             "                               ^~~~\n");
}

TEST(ParserErrors, UnterminatedTechnique) {
  expect_one("technique t {\n  pass p { ZEnable = TRUE; }\n",
             "test.fx:3:1: error: expected '}' to close technique [unterminated-block]\n"
             "\n"
             "^\n"
             "test.fx:1:13: note: to match this '{'\n");
}

TEST(ParserErrors, UnterminatedFunctionBody) {
  expect_one("float4 PS() : COLOR {\n  return 1;\n",
             "test.fx:3:1: error: expected '}' to close function body [unterminated-block]\n"
             "\n"
             "^\n"
             "test.fx:1:21: note: to match this '{'\n");
}

TEST(ParserErrors, BadAnnotationKeepsDeclaration) {
  auto p = parse("float g < string a = ; float b = 1; > = 2;\n");
  EXPECT_EQ(p->text(),
            "test.fx:1:22: error: expected an expression, found ';' [expected-expression]\n"
            "float g < string a = ; float b = 1; > = 2;\n"
            "                     ^\n");
  ASSERT_EQ(p->effect.decls.size(), 1u);
  EXPECT_EQ(var(*p, 0).annotations.size(), 1u);
  EXPECT_EQ(var(*p, 0).initializer->number, 2);
}

TEST(ParserErrors, ExpectedPass) {
  expect_one("technique t { ZEnable = TRUE; pass p {} }",
             "test.fx:1:15: error: expected 'pass' in technique body, found 'ZEnable' "
             "[expected-pass]\n"
             "technique t { ZEnable = TRUE; pass p {} }\n"
             "              ^~~~~~~\n");
}

TEST(ParserErrors, InvalidNumber) {
  expect_one("float a = 1.2.3;",
             "test.fx:1:11: error: invalid floating-point literal '1.2.3' [invalid-number]\n"
             "float a = 1.2.3;\n"
             "          ^~~~~\n");
}

TEST(ParserErrors, DeclWithoutAsm) {
  expect_one("technique t { pass { VertexShader = decl { stream 0; }; } }",
             "test.fx:1:55: error: expected 'asm { }' after 'decl { }', found ';' "
             "[expected-token]\n"
             "technique t { pass { VertexShader = decl { stream 0; }; } }\n"
             "                                                      ^\n");
}

TEST(ParserErrors, AttributeOnVariable) {
  expect_one("[unroll] float a;",
             "test.fx:1:1: error: attributes such as [unroll] apply only to functions "
             "[unexpected-attribute]\n"
             "[unroll] float a;\n"
             "^\n");
}

TEST(ParserErrors, UnclosedTemplate) {
  expect_one("Texture2D<float4 t;",
             "test.fx:1:19: error: expected '>' to close the template argument list, found ';' "
             "[expected-token]\n"
             "Texture2D<float4 t;\n"
             "                  ^\n"
             "test.fx:1:10: note: to match this '<'\n");
}

TEST(ParserErrors, OneDiagnosticPerMistake) {
  auto p = parse(
      "float a = ;\n"
      "technique t { pass { A = 1 B = 2; C = 3; } }\n"
      "float ok;\n");
  ASSERT_EQ(p->diags.diagnostics().size(), 2u) << p->text();
  EXPECT_EQ(p->diags.diagnostics()[0].id, "expected-expression");
  EXPECT_EQ(p->diags.diagnostics()[1].id, "expected-token");
  ASSERT_EQ(p->effect.decls.size(), 2u);
  EXPECT_EQ(p->decl(0).technique->passes.at(0).states.back().name, "C");
  EXPECT_EQ(var(*p, 1).name, "ok");
}

TEST(ParserErrors, DeepNestingGivesOneErrorQuickly) {
  for (const char* open_close : {"()", "{}", "-;"}) {
    std::string source = "float a = ";
    source.append(10000, open_close[0]);
    source += "1";
    if (open_close[1] != ';') source.append(10000, open_close[1]);
    source += ";\nfloat b;\n";
    auto start = std::chrono::steady_clock::now();
    auto p = parse(source);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(p->diags.diagnostics().size(), 1u) << p->text();
    EXPECT_EQ(p->diags.diagnostics()[0].id, "nesting-too-deep");
    ASSERT_EQ(p->effect.decls.size(), 1u);
    EXPECT_EQ(var(*p, 0).name, "b");
    // Catches a hang only: a loaded 2-core CI machine must not fail a unit test; the
    // recursion the limit saves is what the single diagnostic above checks.
    EXPECT_LT(s, 20.0);
  }
  // Unbalanced at file scope: also one error, and no second one at end of file.
  auto p = parse(std::string(10000, '{'));
  EXPECT_EQ(p->diags.diagnostics().size(), 1u) << p->text();
}

TEST(ParserErrors, EveryTruncationGivesAtMostOneDiagnostic) {
  const std::string source =
      "float4x4 W : WORLD < string UIName = \"World\"; >;\n"
      "texture T; sampler2D S = sampler_state { Texture = <T>; AddressU = Clamp; };\n"
      "struct V { float4 p : POSITION; };\n"
      "float4 PS(V v) : COLOR { return tex2D(S, v.p.xy); }\n"
      "BlendState B { BlendEnable[0] = TRUE; };\n"
      "technique10 t < int x = 1; > { pass p {\n"
      "  SetPixelShader(CompileShader(ps_4_0, PS()));\n"
      "  VertexShader = decl { stream 0; } asm { vs.1.1 };\n"
      "  Texture[0] = <T>; VertexShaderConstant[0] = (.5f, .5f); } }\n";
  for (size_t n = 0; n <= source.size(); ++n) {
    auto p = parse(source.substr(0, n));
    size_t errors = 0;
    for (const Diagnostic& d : p->diags.diagnostics())
      if (d.id.rfind("unterminated-string", 0) != 0) ++errors;  // the lexer's own
    EXPECT_LE(errors, 1u) << "prefix of " << n << " bytes:\n" << p->text();
  }
}

}  // namespace
