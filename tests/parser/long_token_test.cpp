// Spellings of Token::kLongText bytes and more, whose length a Token cannot hold itself
// (the SourceManager keeps their views): every kind of token that can be that long keeps
// its exact text and range through the lexer (next() and next_batch()), the preprocessor
// and the parser.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "fx/frontend.h"
#include "fx/lexer.h"
#include "preprocessor_fixture.h"

namespace fx {
namespace {

constexpr size_t kLong = Token::kLongText + 4464;  // 70,000 bytes

struct LongCase {
  std::string name;
  std::string before, spelling, after;  // the text lexed is before + spelling + after
  TokenKind kind;
  std::string clean;  // the token's text when it differs from its spelling (continuations)
};

std::vector<LongCase> long_cases() {
  std::string x(kLong, 'x');
  std::vector<LongCase> cases = {
      {"identifier", "a ", x, " b", TokenKind::identifier, {}},
      {"integer", "a ", std::string(kLong, '7'), " b", TokenKind::integer, {}},
      {"floating", "a ", "1." + std::string(kLong, '5') + "f", " b", TokenKind::floating, {}},
      {"string", "a ", "\"" + x + "\"", " b", TokenKind::string, {}},
      {"unterminated string", "a ", "\"" + x, "\nb", TokenKind::string, {}},
      {"character", "a ", "'" + x + "'", " b", TokenKind::character, {}},
      // One diagnostic for a whole run of UTF-8 continuation bytes, so one token.
      {"unknown", "a ", "\xC3" + std::string(kLong, '\xA9'), " b", TokenKind::unknown, {}},
      {"identifier split by a continuation", "a ", "ab\\\n" + x, " b", TokenKind::identifier, "ab" + x},
  };
  // Around the escape: the longest inline length, the first kept one, the next.
  for (size_t size : {Token::kLongText - 1, Token::kLongText, Token::kLongText + 1})
    cases.push_back(
        {"identifier of " + std::to_string(size), "a ", std::string(size, 'y'), " b", TokenKind::identifier, {}});
  return cases;
}

TEST(LongTokens, LexExactlyThroughNextAndBatches) {
  for (const LongCase& c : long_cases()) {
    SCOPED_TRACE(c.name);
    SourceManager sm;
    DiagnosticSink diags;
    BufferId id = sm.add_buffer("long.fx", c.before + c.spelling + c.after);
    std::string_view source = sm.buffer_text(id);
    Lexer one(sm, id, diags);
    std::vector<Token> expected;
    do expected.push_back(one.next());
    while (!expected.back().is(TokenKind::eof));
    ASSERT_EQ(expected.size(), 4u);  // a, the long token, b, eof
    const Token& t = expected[1];
    EXPECT_EQ(t.kind, c.kind);
    EXPECT_EQ(t.loc, sm.location(id, static_cast<uint32_t>(c.before.size())));
    if (c.clean.empty()) {
      // The very characters of the buffer, not a copy.
      EXPECT_EQ(t.text().data(), source.data() + c.before.size());
      EXPECT_EQ(t.text().size(), c.spelling.size());
    } else {
      EXPECT_EQ(t.text(), c.clean);
    }
    EXPECT_EQ(t.range().end, t.loc.offset(static_cast<uint32_t>(t.text().size())));
    EXPECT_EQ(expected[2].text(), "b");

    DiagnosticSink batch_diags;
    Lexer batched(sm, id, batch_diags);
    std::vector<Token> got;
    Token batch[4];
    while (got.empty() || !got.back().is(TokenKind::eof))
      got.insert(got.end(), batch, batch + batched.next_batch(batch, 4));
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].kind, expected[i].kind) << i;
      EXPECT_EQ(got[i].loc, expected[i].loc) << i;
      EXPECT_EQ(got[i].text(), expected[i].text()) << i;
    }
    EXPECT_EQ(batch_diags.diagnostics().size(), diags.diagnostics().size());
  }
}

TEST(LongTokens, SetTextKeepsShortAndLongSpellings) {
  SourceManager sm;
  std::string_view text = sm.buffer_text(sm.add_buffer("t.fx", std::string(kLong, 'z')));
  Token t;
  t.set_text(text.substr(0, 3), sm);
  EXPECT_EQ(t.text().data(), text.data());
  EXPECT_EQ(t.text().size(), 3u);
  t.set_text(text, sm);
  EXPECT_EQ(t.text().data(), text.data());
  EXPECT_EQ(t.text().size(), kLong);
  Token copy = t;  // the kept view outlives the token it was made for
  t.set_text(text.substr(1, 2), sm);
  EXPECT_EQ(copy.text().size(), kLong);
  EXPECT_EQ(t.text(), "zz");
}

// Tokens the preprocessor makes or reads: kept directive lines, stringized arguments,
// pasted names, long macro names and long header names.
TEST(LongTokens, PreprocessExactly) {
  std::string x(kLong, 'x');
  {
    test::Pp p;
    p.run("#pragma " + x + "\nint a;\n");
    EXPECT_EQ(p.ids(), "");
    ASSERT_GE(p.tokens.size(), 2u);
    EXPECT_EQ(p.tokens[0].kind, TokenKind::directive);
    EXPECT_EQ(p.tokens[0].text(), "#pragma " + x);
    EXPECT_EQ(p.tokens[1].text(), "int");
  }
  {
    test::Pp p;
    EXPECT_EQ(p.run("#define S(a) #a\nS(" + x + ")\n"), "\"" + x + "\"");
    EXPECT_EQ(p.tokens[0].kind, TokenKind::string);
  }
  {
    test::Pp p;
    std::string half(kLong / 2 + 1, 'y');
    EXPECT_EQ(p.run("#define P(a, b) a ## b\nP(" + half + ", " + half + ")\n"), half + half);
    EXPECT_EQ(p.tokens[0].kind, TokenKind::identifier);
  }
  {
    test::Pp p;
    EXPECT_EQ(p.run("#define " + x + " 1\n" + x + " " + x + "y\n"), "1 " + x + "y");
  }
  {
    test::Pp p;  // a header name, and a string literal naming a file
    p.options.include_dirs = {"lib"};
    p.files["lib/" + x + ".fxh"] = "int angled;";
    p.files[x + ".fxh"] = "int quoted;";
    EXPECT_EQ(p.run("#include <" + x + ".fxh>\n#include \"" + x + ".fxh\"\n"), "int angled ; int quoted ;");
    EXPECT_EQ(p.ids(), "");
  }
}

TEST(LongTokens, ParseExactly) {
  std::string x(kLong, 'x');
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect e = parse_effect_text("long.fx", "float " + x + ";\nstring s = \"" + x + "\";\n", sm, diags);
  // The parser takes the name whole; the checker then says it is too long for the shader
  // compiler (glslang cuts names at 1024 characters).
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_TRUE(std::any_of(diags.diagnostics().begin(), diags.diagnostics().end(),
                          [](const Diagnostic& d) { return d.id == "shader-token-too-long"; }));
  ASSERT_EQ(e.ast.decls.size(), 2u);
  EXPECT_EQ(e.ast.decls[0].variable->name, x);
  ASSERT_NE(e.ast.decls[1].variable->initializer, nullptr);
  EXPECT_EQ(e.ast.decls[1].variable->initializer->text, x);
}

}  // namespace
}  // namespace fx
