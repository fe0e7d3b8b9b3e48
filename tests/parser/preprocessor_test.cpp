// Macros, conditionals and the other directives.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "preprocessor_fixture.h"

namespace fx {
namespace {

using test::Pp;
using test::spelled;

// ---- macros ---------------------------------------------------------------------------

TEST(PreprocessorMacros, ObjectAndFunctionLike) {
  Pp p;
  EXPECT_EQ(p.run("#define N 4\n#define SQ(x) ((x)*(x))\nfloat a[N] = SQ(SQ(N+1));\n"),
            spelled("float a[4] = ((((4+1)*(4+1)))*(((4+1)*(4+1))));"));
  EXPECT_TRUE(p.ok);
  EXPECT_EQ(p.ids(), "");
}

// A character that starts no token is reported once, where it is lexed (here in a macro
// body), and is not passed on: the parser would only report it again.
TEST(PreprocessorMacros, StrayCharacterInAMacroIsReportedOnce) {
  Pp p;
  EXPECT_EQ(p.run("#define BAD $\nfloat x = BAD BAD 1;\n@ float y;\n"), spelled("float x = 1; float y;"));
  EXPECT_EQ(p.ids(), "unknown-character unknown-character");
}

// C11 6.10.3.5 EXAMPLE 3: rescanning, nested invocations, empty arguments.
TEST(PreprocessorMacros, StandardExampleRescanning) {
  Pp p;
  std::string out = p.run(R"(#define x 3
#define f(a) f(x * (a))
#undef x
#define x 2
#define g f
#define z z[0]
#define h g(~
#define m(a) a(w)
#define w 0,1
#define t(a) a
#define p() int
#define q(x) x
#define r(x,y) x ## y
#define str(x) # x
f(y+1) + f(f(z)) % t(t(g)(0) + t)(1);
g(x+(3,4)-w) | h 5) & m
(f)^m(m);
p() i[q()] = { q(1), r(2,3), r(4,), r(,5), r(,) };
char c[2][6] = { str(hello), str() };
)");
  EXPECT_EQ(out, spelled(R"(f(2 * (y+1)) + f(2 * (f(2 * (z[0])))) % f(2 * (0)) + t(1);
f(2 * (2+(3,4)-0,1)) | f(2 * (~ 5)) & f(2 * (0,1))^m(0,1);
int i[] = { 1, 23, 4, 5, };
char c[2][6] = { "hello", "" };)"));
  EXPECT_EQ(p.ids(), "");
}

// C11 6.10.3.5 EXAMPLE 4 (# and ##) without its `@` line, which is not an HLSL token.
TEST(PreprocessorMacros, StandardExampleStringizeAndPaste) {
  Pp p;
  std::string out = p.run(R"(#define str(s) # s
#define xstr(s) str(s)
#define debug(s, t) printf("x" # s "= %d, x" # t "= %s", \
 x ## s, x ## t)
#define INCFILE(n) vers ## n
#define glue(a, b) a ## b
#define xglue(a, b) glue(a, b)
#define HIGHLOW "hello"
#define LOW LOW ", world"
debug(1, 2);
fputs(str(strncmp("abc\0d", "abc", '\4') // this goes away
 == 0), s);
xstr(INCFILE(2).h)
glue(HIGH, LOW);
xglue(HIGH, LOW)
)");
  EXPECT_EQ(out, spelled(R"(printf("x" "1" "= %d, x" "2" "= %s", x1, x2);
fputs("strncmp(\"abc\\0d\", \"abc\", '\\4') == 0", s);
"vers2.h"
"hello";
"hello" ", world")"));
  EXPECT_EQ(p.ids(), "");
}

// C11 6.10.3.5 EXAMPLE 5: placemarkers.
TEST(PreprocessorMacros, StandardExamplePlacemarkers) {
  Pp p;
  EXPECT_EQ(p.run("#define t(x,y,z) x ## y ## z\n"
                  "int j[] = { t(1,2,3), t(,4,5), t(6,,7), t(8,9,),\n"
                  "t(10,,), t(,11,), t(,,12), t(,,) };\n"),
            spelled("int j[] = { 123, 45, 67, 89, 10, 11, 12, };"));
}

// C11 6.10.3.5 EXAMPLE 7: variadic macros, plus the GNU `, ## __VA_ARGS__` comma.
TEST(PreprocessorMacros, Variadic) {
  Pp p;
  std::string out = p.run(R"(#define debug(...) fprintf(stderr, __VA_ARGS__)
#define showlist(...) puts(#__VA_ARGS__)
#define report(test, ...) ((test)?puts(#test): printf(__VA_ARGS__))
#define log(fmt, ...) print(fmt, ## __VA_ARGS__)
debug("Flag");
debug("X = %d\n", x);
showlist(The first, second, and third items.);
report(x>y, "x is %d but y is %d", x, y);
log("a"); log("b", 1, 2);
)");
  EXPECT_EQ(out, spelled(R"(fprintf(stderr, "Flag");
fprintf(stderr, "X = %d\n", x);
puts("The first, second, and third items.");
((x>y)?puts("x>y"): printf("x is %d but y is %d", x, y));
print("a"); print("b", 1, 2);)"));
  EXPECT_EQ(p.ids(), "");
}

TEST(PreprocessorMacros, SelfReferenceDoesNotRecurse) {
  Pp p;
  EXPECT_EQ(p.run("#define foo foo\n#define A B\n#define B A\n#define f(x) x f\n"
                  "foo A B f(1)(2)\n"),
            "foo A B 1 f ( 2 )");
  EXPECT_TRUE(p.tokens[0].flags & kNoExpand);
  EXPECT_TRUE(p.tokens[1].flags & kNoExpand);
  EXPECT_EQ(p.ids(), "");
  // A disabled name stays disabled when passed on through another macro's argument.
  EXPECT_EQ(p.run("#define id(x) x\n#define loop id(loop)\nloop\n"), "loop");
}

// Macro names anywhere in a long run of plain tokens expand, a name spliced by a
// continuation included, whatever the lexer's batches look like.
TEST(PreprocessorMacros, NamesAmongManyPlainTokensExpand) {
  Pp p;
  std::string plain;
  for (int i = 0; i < 300; ++i) plain.append("a").append(std::to_string(i)).append(" ");
  const std::string& expected = plain;
  EXPECT_EQ(p.run("#define N 4\n#define SCALE(x) (x)\n" + plain + "N " + plain + "SC\\\nALE(1) " + plain + "N\n"),
            expected + "4 " + expected + "( 1 ) " + expected + "4");
  EXPECT_TRUE(p.ok);
}

TEST(PreprocessorMacros, FunctionLikeNameWithoutParensIsAnIdentifier) {
  Pp p;
  EXPECT_EQ(p.run("#define f(x) [x]\nf; f\n(1) f ( 2 )\n#define g (y)\ng\n"), "f ; [ 1 ] [ 2 ] ( y )");
}

TEST(PreprocessorMacros, Redefinition) {
  Pp p;
  p.run("#define A 1 + 2\n#define A 1 + 2\n#define A 1  +  2\n");
  EXPECT_EQ(p.ids(), "");
  p.run("#define A 1 + 2\n#define A 1+2\n");
  const Diagnostic& d = p.only();
  EXPECT_EQ(d.id, "macro-redefined");
  EXPECT_EQ(d.severity, Severity::warning);
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(p.where(d.notes[0].location), "main.fx:1:9");
  EXPECT_EQ(p.run("#define A 1\n#undef A\nA\n"), "A");
}

TEST(PreprocessorMacros, ArgumentErrors) {
  Pp p;
  EXPECT_EQ(p.run("#define f(a, b) a b\nx f(1) y\n"), "x y");
  EXPECT_EQ(p.only().id, "macro-args");
  EXPECT_EQ(p.only().message, "macro 'f' takes 2 arguments, but 1 was given");
  EXPECT_FALSE(p.ok);
  Pp q;
  q.run("#define f(a) a\nf(1,\n2");
  EXPECT_EQ(q.ids(), "unterminated-macro-call");
  Pp r;
  r.run("#define f(a, a) a\n#define g(x) #y\n#define h ## x\n#define 3 x\n#define defined\n");
  EXPECT_EQ(r.ids(),
            "macro-definition macro-definition macro-definition invalid-macro-name "
            "invalid-macro-name");
}

TEST(PreprocessorMacros, InvalidPasteKeepsBothTokens) {
  Pp p;
  EXPECT_EQ(p.run("#define cat(a, b) a ## b\ncat(+, /)\ncat(x, 1) cat(1, .5e) cat(-, =)\n"), "+ / x1 1.5e -=");
  EXPECT_EQ(p.ids(), "invalid-paste");
  EXPECT_EQ(p.tokens[2].kind, TokenKind::identifier);
  EXPECT_EQ(p.tokens[3].kind, TokenKind::floating);
  EXPECT_EQ(p.tokens[4].kind, TokenKind::minusequal);
}

TEST(PreprocessorMacros, PastedIdentifierIsRescanned) {
  Pp p;
  EXPECT_EQ(p.run("#define VS_main 42\n#define cat(a, b) a ## b\ncat(VS, _main)\n"), "42");
}

TEST(PreprocessorMacros, ExpansionLocationsAndFlags) {
  Pp p;
  p.run("#define TWO(x) x + 1\nfloat y =\nTWO(z);\n");
  ASSERT_EQ(p.spell(p.tokens), "float y = z + 1 ;");
  const Token& z = p.tokens[3];
  const Token& plus = p.tokens[4];
  // The argument keeps its own location; body tokens live in the expansion.
  EXPECT_FALSE(p.sm.is_expansion(z.loc));
  EXPECT_EQ(p.where(z.loc), "main.fx:3:5");
  ASSERT_TRUE(p.sm.is_expansion(plus.loc));
  EXPECT_EQ(p.sm.expansion_of(plus.loc)->macro_name, "TWO");
  EXPECT_EQ(p.where(plus.loc), "main.fx:3:1");
  EXPECT_EQ(p.sm.text_at(p.sm.spelling_location(plus.loc)).substr(0, 5), "+ 1\nf");
  EXPECT_EQ(p.where(p.sm.spelling_location(plus.loc)), "main.fx:1:18");
  EXPECT_TRUE(plus.flags & kFromMacro);
  EXPECT_TRUE(z.flags & kFromMacro);
  // The first token of the expansion stands where the invocation stood.
  EXPECT_TRUE(z.at_line_start());
  EXPECT_FALSE(plus.at_line_start());
  EXPECT_TRUE(plus.leading_space());
  EXPECT_FALSE(p.tokens[0].flags & kFromMacro);
}

TEST(PreprocessorMacros, Builtins) {
  Pp p;
  p.options.defines = {parse_define("QUALITY=2"), parse_define("FAST")};
  EXPECT_EQ(p.run("__LINE__ __FILE__\n#line 50 \"orig.fx\"\n__LINE__ __FILE__ __COUNTER__ "
                  "__COUNTER__ FXKIT FXKIT_VERSION QUALITY FAST\n",
                  "dir\\my.fx"),
            "1 \"dir\\\\my.fx\" 50 \"orig.fx\" 0 1 1 100 2 1");
  EXPECT_EQ(p.ids(), "");
  EXPECT_EQ(parse_define("A=").second, "");
  EXPECT_EQ(parse_define("F(x)=x*2").first, "F(x)");
  p.options.defines = {{"F(x)", "x*2"}};
  EXPECT_EQ(p.run("F(3)"), "3 * 2");
  p.options.defines = {{"1bad", "x"}};
  p.run("");
  EXPECT_EQ(p.ids(), "invalid-macro-name");
  EXPECT_EQ(p.where(p.only().range.begin), "<command line>:1:9");
}

TEST(PreprocessorMacros, EachRunStartsFresh) {
  Pp p;
  p.run("#define LEAK 1\n");
  EXPECT_EQ(p.run("LEAK"), "LEAK");
}

// ---- conditionals -----------------------------------------------------------------------

TEST(PreprocessorConditionals, Arithmetic) {
  struct Case {
    const char* expr;
    bool value;
  };
  const Case cases[] = {
      {"1 + 2 * 3 == 7", true},
      {"(1 + 2) * 3 == 9", true},
      {"(1 << 4) == 16", true},
      {"-1 < 0", true},
      {"-1 < 0u", false},
      {"0x10 == 16 && 010 == 8", true},
      {"10 / 3 == 3", true},
      {"-7 % 3 == -1", true},
      {"!defined(FOO)", false},
      {"defined FOO && FOO == 5", true},
      {"defined(BAR)", false},
      {"1 ? 2 : 0", true},
      {"0 ? 1 : 0", false},
      {"0 && 1 / 0", true == false},
      {"1 || 1 / 0", true},
      {"UNKNOWN == 0", true},
      {"'A' == 65", true},
      {"true && !false", true},
      {"~0 == -1", true},
      {"(2 || 0) == 1", true},
      {"1, 0", false},
      {"3 > 2 > 1", false},
      {"(5 & 3) == 1 && (5 | 3) == 7 && (5 ^ 3) == 6", true},
      {"-9223372036854775807 - 1 < 0", true},
      {"18446744073709551615 == -1", true},
      {"(1 >> 70) == 0 && (-8 >> 1) == -4 && (1 << -1) == 0", true},
      {"TWICE(3) == 6", true},
      {"FOO >= 5 ? FOO <= 5 : 0", true},
  };
  for (const Case& c : cases) {
    Pp p;
    std::string src =
        "#define FOO 5\n#define TWICE(x) ((x) * 2)\n#if " + std::string(c.expr) + "\nyes\n#else\nno\n#endif\n";
    EXPECT_EQ(p.run(src), c.value ? "yes" : "no") << c.expr;
    EXPECT_EQ(p.ids(), "") << c.expr;
  }
}

TEST(PreprocessorConditionals, ExpressionErrors) {
  const char* bad[] = {"1 / 0", "5 % 0", "1.5", "(1", "1 +", "", "defined", "defined(X", "1 2", "1 ? 2"};
  for (const char* expr : bad) {
    Pp p;
    EXPECT_EQ(p.run("#if " + std::string(expr) + "\nyes\n#else\nno\n#endif\n"), "no") << expr;
    EXPECT_EQ(p.ids(), "pp-expression") << expr;
    EXPECT_FALSE(p.ok);
  }
  Pp p;
  p.run("#if 1 / 0\n#endif\n");
  EXPECT_EQ(p.only().message, "division by zero in preprocessor expression");
  EXPECT_EQ(p.where(p.only().range.begin), "main.fx:1:7");
}

TEST(PreprocessorConditionals, Chains) {
  Pp p;
  const char* src = R"(#define B
#ifdef A
a
#elif defined(B)
b
#  ifndef B
never
#  else
b2
#  endif
#elif 1
notc
#else
notd
#endif
#ifndef A
e
#endif
)";
  EXPECT_EQ(p.run(src), "b b2 e");
  EXPECT_EQ(p.ids(), "");
}

TEST(PreprocessorConditionals, SkippedGroupsAreOnlyTokenized) {
  Pp p;
  EXPECT_EQ(p.run("#if 0\ndon't $ \"open\n#foo bar\n#error no\n#if garbage (\n#endif\n"
                  "/* #endif */\n#elif 0 && 1/0\n#else\nkept\n#endif\n"),
            "kept");
  EXPECT_EQ(p.ids(), "");
}

TEST(PreprocessorConditionals, StructureErrors) {
  Pp p;
  p.run("#if 1\nx\n");
  EXPECT_EQ(p.ids(), "unterminated-conditional");
  EXPECT_EQ(p.where(p.only().range.begin), "main.fx:1:1");
  Pp q;
  q.run("#endif\n#else\n#elif 1\n");
  EXPECT_EQ(q.ids(), "unmatched-endif unmatched-conditional unmatched-conditional");
  Pp r;
  EXPECT_EQ(r.run("#if 0\n#else\na\n#else\nb\n#endif\n"), "a");
  EXPECT_EQ(r.ids(), "invalid-directive");
  // A conditional may not span files.
  Pp s;
  s.files["inc.fxh"] = "#if 1\n";
  EXPECT_EQ(s.run("#include \"inc.fxh\"\nx\n#endif\n"), "x");
  EXPECT_EQ(s.ids(), "unterminated-conditional unmatched-endif");
}

TEST(PreprocessorConditionals, TenThousandNestedIfs) {
  std::string src;
  for (int i = 0; i < 10000; ++i) src += "#if 1\n";
  src += "deep\n";
  for (int i = 0; i < 10000; ++i) src += "#endif\n";
  src += "#if 0\n" + src + "#endif\n";
  Pp p;
  EXPECT_EQ(p.run(src), "deep");
  EXPECT_EQ(p.ids(), "");
}

// ---- other directives ---------------------------------------------------------------------

TEST(PreprocessorDirectives, ErrorAndWarning) {
  Pp p;
  p.run("#error Shader model 3 isn't available // why\n#warning \"slow path\"\n#error\n");
  ASSERT_EQ(p.ids(), "error-directive warning-directive error-directive");
  EXPECT_EQ(p.diags.diagnostics()[0].message, "Shader model 3 isn't available");
  EXPECT_EQ(p.diags.diagnostics()[1].message, "\"slow path\"");
  EXPECT_EQ(p.diags.diagnostics()[1].severity, Severity::warning);
  EXPECT_EQ(p.diags.diagnostics()[2].message, "#error");
  EXPECT_FALSE(p.ok);
}

TEST(PreprocessorDirectives, KeptDirectivesAreSingleTokens) {
  Pp p;
  std::string out = p.run(
      "#pragma pack_matrix(row_major)\n#  version 450 core\n#extension GL_EXT_x : enable\n"
      "#pragma warning( disable : 3571 )\n#pragma once\nx\n");
  EXPECT_EQ(out,
            "#pragma pack_matrix(row_major) #version 450 core #extension GL_EXT_x : enable "
            "#pragma warning( disable : 3571 ) x");
  ASSERT_EQ(p.tokens.size(), 6u);
  EXPECT_EQ(p.tokens[0].kind, TokenKind::directive);
  EXPECT_EQ(p.where(p.tokens[1].loc), "main.fx:2:1");
  EXPECT_EQ(p.ids(), "");
}

TEST(PreprocessorDirectives, UnknownDirectiveAndStrayHash) {
  Pp p;
  EXPECT_EQ(p.run("#foo bar\n#\nx # y\n#  \n"), "x # y");
  EXPECT_EQ(p.ids(), "unknown-directive");
  EXPECT_EQ(p.only().message, "unknown preprocessing directive '#foo'");
  EXPECT_EQ(p.tokens[1].kind, TokenKind::hash);
}

TEST(PreprocessorDirectives, LineChangesPresumedLocations) {
  Pp p;
  p.run("a\n#line 100 \"orig.fx\"\nb\n\nc\n#line 7\nd\n# 20 \"m.fx\"\ne\n");
  ASSERT_EQ(p.spell(p.tokens), "a b c d e");
  EXPECT_EQ(p.where(p.tokens[0].loc), "main.fx:1:1");
  EXPECT_EQ(p.where(p.tokens[1].loc), "orig.fx:100:1");
  EXPECT_EQ(p.where(p.tokens[2].loc), "orig.fx:102:1");
  EXPECT_EQ(p.where(p.tokens[3].loc), "orig.fx:7:1");
  EXPECT_EQ(p.where(p.tokens[4].loc), "m.fx:20:1");
  EXPECT_EQ(p.sm.physical(p.tokens[4].loc).line, 9u);
  p.run("#line x\n");
  EXPECT_EQ(p.ids(), "invalid-directive");
}
}  // namespace
}  // namespace fx
