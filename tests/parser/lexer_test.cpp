#include "fx/lexer.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fx {
namespace {

struct Lexed {
  SourceManager sm;
  DiagnosticSink diags;
  std::vector<Token> tokens;  // without the final eof

  explicit Lexed(std::string text) {
    BufferId id = sm.add_buffer("t.fx", std::move(text));
    Lexer lexer(sm, id, diags);
    for (Token t = lexer.next(); !t.is(TokenKind::eof); t = lexer.next()) tokens.push_back(t);
  }
  std::vector<std::string> spellings() const {
    std::vector<std::string> s;
    for (const Token& t : tokens) s.emplace_back(t.text());
    return s;
  }
  std::vector<TokenKind> kinds() const {
    std::vector<TokenKind> k;
    for (const Token& t : tokens) k.push_back(t.kind);
    return k;
  }
};

using S = std::vector<std::string>;
using K = TokenKind;

TEST(Lexer, NumbersWithSuffixes) {
  Lexed l("1.0f 1.h 0x1F 1e-3 10u .5 3l 1e+5 7");
  EXPECT_EQ(l.spellings(), (S{"1.0f", "1.h", "0x1F", "1e-3", "10u", ".5", "3l", "1e+5", "7"}));
  EXPECT_EQ(l.kinds(), (std::vector<K>{K::floating, K::floating, K::integer, K::floating, K::integer, K::floating,
                                       K::integer, K::floating, K::integer}));
  EXPECT_TRUE(l.diags.diagnostics().empty());
}

// fxc skips a UTF-8 byte-order mark; a '#' after one still starts a directive line.
TEST(Lexer, ByteOrderMarkIsSkipped) {
  Lexed l("\xEF\xBB\xBF#define A\nfloat x;");
  EXPECT_EQ(l.spellings(), (S{"#", "define", "A", "float", "x", ";"}));
  EXPECT_TRUE(l.tokens[0].at_line_start());
  EXPECT_TRUE(l.diags.diagnostics().empty());
  Lexed only("\xEF\xBB\xBF");
  EXPECT_TRUE(only.tokens.empty());
  EXPECT_TRUE(only.diags.diagnostics().empty());
}

TEST(Lexer, HexDigitsAreNotFloatSuffixes) {
  Lexed l("0xFE 0x1e+1");
  // 0x1e+1 is 0x1e, +, 1: a sign only continues a decimal exponent.
  EXPECT_EQ(l.spellings(), (S{"0xFE", "0x1e", "+", "1"}));
  EXPECT_EQ(l.tokens[0].kind, K::integer);
}

TEST(Lexer, ParseNumberValues) {
  EXPECT_DOUBLE_EQ(parse_number("1.0f")->as_double(), 1.0);
  EXPECT_DOUBLE_EQ(parse_number("1.h")->as_double(), 1.0);
  EXPECT_DOUBLE_EQ(parse_number("1e-3")->as_double(), 1e-3);
  EXPECT_DOUBLE_EQ(parse_number(".5")->as_double(), 0.5);
  EXPECT_EQ(std::get<int64_t>(parse_number("0x1F")->value), 31);
  EXPECT_EQ(std::get<int64_t>(parse_number("10u")->value), 10);
  EXPECT_EQ(std::get<int64_t>(parse_number("017")->value), 15);
  EXPECT_FALSE(parse_number("1.0f")->value.index() == 0);
  std::string why;
  EXPECT_FALSE(parse_number("09", &why));
  EXPECT_EQ(why, "invalid integer literal");
  EXPECT_FALSE(parse_number("1.0.0"));
  EXPECT_FALSE(parse_number("0x"));
  EXPECT_FALSE(parse_number("99999999999999999999", &why));
  EXPECT_EQ(why, "integer literal out of range");
}

TEST(Lexer, AssemblyVersionIsIdentifierThenPpNumber) {
  Lexed l("vs.1.1\nps.2.0\ntex t0");
  EXPECT_EQ(l.spellings(), (S{"vs", ".1.1", "ps", ".2.0", "tex", "t0"}));
  EXPECT_EQ(l.tokens[0].kind, K::identifier);
  EXPECT_EQ(l.tokens[1].kind, K::floating);
  EXPECT_FALSE(l.tokens[1].leading_space());
}

TEST(Lexer, PunctuatorsTakeTheLongestMatch) {
  Lexed l("a+=b>>=c->d<<e##f#g::h||i&&j!=k<=l>=m==n++ --o");
  EXPECT_EQ(l.spellings(), (S{"a", "+=", "b", ">>=", "c", "->", "d", "<<", "e", "##", "f", "#",  "g",  "::", "h", "||",
                              "i", "&&", "j", "!=",  "k", "<=", "l", ">=", "m", "==", "n", "++", "--", "o"}));
  EXPECT_EQ(l.tokens[9].kind, K::hashhash);
  EXPECT_EQ(l.tokens[3].kind, K::greatergreaterequal);
}

TEST(Lexer, StringsAndCharacters) {
  Lexed l(R"("a \"quoted\" \\ word" 'x' '\n' "")");
  ASSERT_EQ(l.tokens.size(), 4u);
  EXPECT_EQ(l.tokens[0].kind, K::string);
  EXPECT_EQ(l.tokens[0].text(), R"("a \"quoted\" \\ word")");
  EXPECT_EQ(unquote(l.tokens[0].text()), R"(a "quoted" \ word)");
  EXPECT_EQ(l.tokens[1].kind, K::character);
  EXPECT_EQ(unquote(l.tokens[2].text()), "\n");
  EXPECT_EQ(l.tokens[3].text(), "\"\"");
  EXPECT_TRUE(l.diags.diagnostics().empty());
}

// Adjacent literals join: each is appended after the text so far, with or without escapes.
TEST(Lexer, AppendUnquotedKeepsTheTextBefore) {
  std::string out = "ab";
  append_unquoted(out, R"("plain")");
  EXPECT_EQ(out, "abplain");
  append_unquoted(out, R"("x\ty\\")");  // escapes after plain characters
  EXPECT_EQ(out, "abplainx\ty\\");
  append_unquoted(out, R"("")");
  EXPECT_EQ(out, "abplainx\ty\\");
}

TEST(Lexer, CommentsSetLeadingSpaceAndNewlinesSetLineStart) {
  Lexed l("a/*c*/b // line\nc/* multi\nline */d\n  e");
  EXPECT_EQ(l.spellings(), (S{"a", "b", "c", "d", "e"}));
  EXPECT_TRUE(l.tokens[0].at_line_start());
  EXPECT_TRUE(l.tokens[1].leading_space());
  EXPECT_FALSE(l.tokens[1].at_line_start());
  EXPECT_TRUE(l.tokens[2].at_line_start());
  // A block comment spanning lines is one space: `d` is still on c's logical line.
  EXPECT_FALSE(l.tokens[3].at_line_start());
  EXPECT_TRUE(l.tokens[3].leading_space());
  EXPECT_TRUE(l.tokens[4].at_line_start());
}

TEST(Lexer, LineContinuations) {
  Lexed l("ab\\\ncd x\\\r\ny // comment \\\n still comment\nz");
  EXPECT_EQ(l.spellings(), (S{"abcd", "xy", "z"}));
  // The spliced token keeps its real location.
  EXPECT_EQ(l.sm.presumed(l.tokens[0].loc).column, 1u);
  EXPECT_EQ(l.sm.presumed(l.tokens[2].loc).line, 5u);
  EXPECT_TRUE(l.tokens[2].at_line_start());
}

TEST(Lexer, ContinuationJoinsDirectiveLines) {
  Lexed l("#define A 1 \\\n + 2\nB");
  EXPECT_EQ(l.spellings(), (S{"#", "define", "A", "1", "+", "2", "B"}));
  EXPECT_FALSE(l.tokens[4].at_line_start());
  EXPECT_TRUE(l.tokens[6].at_line_start());
}

TEST(Lexer, UnterminatedCommentIsReported) {
  Lexed l("a /* never closed\nb");
  EXPECT_EQ(l.spellings(), (S{"a"}));
  ASSERT_EQ(l.diags.diagnostics().size(), 1u);
  EXPECT_EQ(l.diags.diagnostics()[0].id, "unterminated-comment");
  EXPECT_EQ(l.sm.presumed(l.diags.diagnostics()[0].range.begin).column, 3u);
}

TEST(Lexer, UnterminatedStringStopsAtEndOfLine) {
  Lexed l("\"abc\nnext 'x");
  EXPECT_EQ(l.spellings(), (S{"\"abc", "next", "'x"}));
  ASSERT_EQ(l.diags.diagnostics().size(), 2u);
  EXPECT_EQ(l.diags.diagnostics()[0].id, "unterminated-string");
  EXPECT_EQ(l.diags.diagnostics()[1].id, "unterminated-string");
  EXPECT_TRUE(l.tokens[1].at_line_start());
}

TEST(Lexer, UnknownCharacterIsOneDiagnosticPerUtf8Sequence) {
  Lexed l("a \xC3\xA9 $ b");
  EXPECT_EQ(l.kinds(), (std::vector<K>{K::identifier, K::unknown, K::unknown, K::identifier}));
  EXPECT_EQ(l.tokens[1].text(), "\xC3\xA9");
  EXPECT_EQ(l.diags.error_count(), 2u);
  EXPECT_EQ(l.diags.diagnostics()[0].id, "unknown-character");
}

TEST(Lexer, EofRepeatsAndCarriesLocation) {
  SourceManager sm;
  DiagnosticSink diags;
  BufferId id = sm.add_buffer("t.fx", "x");
  Lexer lexer(sm, id, diags);
  EXPECT_TRUE(lexer.next().is_identifier("x"));
  Token e1 = lexer.next(), e2 = lexer.next();
  EXPECT_TRUE(e1.is(K::eof));
  EXPECT_TRUE(e2.is(K::eof));
  EXPECT_EQ(sm.offset_in_buffer(e1.loc), 1u);
}

TEST(Lexer, HeaderNameOnlyOnTheSameLine) {
  SourceManager sm;
  DiagnosticSink diags;
  BufferId id = sm.add_buffer("t.fx", "include <a/b.fxh> x\ninclude\n<c>");
  Lexer lexer(sm, id, diags);
  lexer.next();
  std::optional<Token> h = lexer.header_name();
  ASSERT_TRUE(h);
  EXPECT_EQ(h->text(), "<a/b.fxh>");
  EXPECT_FALSE(lexer.at_line_end());
  EXPECT_TRUE(lexer.next().is_identifier("x"));
  EXPECT_TRUE(lexer.at_line_end());
  lexer.next();
  EXPECT_FALSE(lexer.header_name());  // `<c>` is on the next line
  EXPECT_TRUE(lexer.next().is(K::less));
}

TEST(Lexer, RestOfLineReturnsRawTextAndEndsTheLine) {
  SourceManager sm;
  DiagnosticSink diags;
  BufferId id = sm.add_buffer("t.fx", "error don't \\\n stop\nnext");
  Lexer lexer(sm, id, diags);
  lexer.next();
  EXPECT_EQ(lexer.rest_of_line(), " don't \\\n stop");
  Token t = lexer.next();
  EXPECT_TRUE(t.is_identifier("next"));
  EXPECT_TRUE(t.at_line_start());
  EXPECT_TRUE(diags.diagnostics().empty());
}

// next_batch lexes common tokens on a path of its own; it must give exactly what next()
// gives, flags, locations and diagnostics included, whatever the batch size, and end a
// batch after each identifier its stop filter may contain (spliced ones too).
TEST(Lexer, BatchesYieldTheTokensOfNext) {
  std::vector<std::string> texts = {
      "float4 x = {0.577, -0.577, .5e+3f, 0x1Fu, 1.h}; a->b; c::d; e <<= f >>= g != h ## i",
      "a/*c*/b // line\nc/* multi\nline */d\n  #  define X 1\n#x\n x # y",
      "ab\\\ncd x\\\r\ny 1\\\n2 .\\\n5 +\\\n= a\\b \\ z // c \\\n c\nz",
      "\"str\\\"ing\" 'c' \"abc\nnext 'x \xC3\xA9 $ @ `",
      std::string("a\0b 1\0 +\0", 9),
      "a /* never closed\nb",
      "x/",
      "7",
      ".",
      "#",
      "\\",
      "",
  };
  for (const char* file : {"brdf.fx", "sdk_sample.fx", "state_snippets.fx", "wood.fx"}) {
    std::ifstream in(std::string(FXKIT_SOURCE_DIR) + "/tests/parser/data/" + file, std::ios::binary);
    std::stringstream contents;
    contents << in.rdbuf();
    texts.push_back(contents.str());
  }
  for (const std::string& text : texts) {
    SourceManager sm;
    DiagnosticSink one_diags;
    BufferId id = sm.add_buffer("t.fx", text);
    Lexer one(sm, id, one_diags);
    std::vector<Token> expected;
    do expected.push_back(one.next());
    while (!expected.back().is(K::eof));
    NameFilter stops;
    for (std::string_view name : {"b", "abcd", "define", "float4", "VS_OUTPUT"}) stops.add(name);
    for (auto [max, filter] :
         {std::pair<size_t, const NameFilter*>{1, nullptr}, {3, nullptr}, {256, nullptr}, {256, &stops}}) {
      DiagnosticSink diags;
      Lexer batched(sm, id, diags);
      std::vector<Token> got;
      Token batch[256];
      while (got.empty() || !got.back().is(K::eof)) {
        size_t n = batched.next_batch(batch, max, filter);
        ASSERT_GE(n, 1u);
        for (size_t i = 0; filter && i + 1 < n; ++i)
          EXPECT_FALSE(batch[i].is(K::identifier) && filter->may_contain(batch[i].text())) << batch[i].text();
        got.insert(got.end(), batch, batch + n);
      }
      ASSERT_EQ(got.size(), expected.size()) << text;
      for (size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].kind, expected[i].kind) << text << " token " << i;
        EXPECT_EQ(got[i].flags, expected[i].flags) << text << " token " << i;
        EXPECT_EQ(got[i].loc, expected[i].loc) << text << " token " << i;
        EXPECT_EQ(got[i].text(), expected[i].text()) << text << " token " << i;
      }
      ASSERT_EQ(diags.diagnostics().size(), one_diags.diagnostics().size()) << text;
      for (size_t i = 0; i < diags.diagnostics().size(); ++i) {
        EXPECT_EQ(diags.diagnostics()[i].id, one_diags.diagnostics()[i].id);
        EXPECT_EQ(diags.diagnostics()[i].range.begin, one_diags.diagnostics()[i].range.begin);
      }
    }
  }
}

}  // namespace
}  // namespace fx
