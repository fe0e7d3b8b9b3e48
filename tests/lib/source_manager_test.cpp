#include "fx/source_manager.h"

#include <gtest/gtest.h>

namespace fx {
namespace {

TEST(SourceManager, MapsOffsetsToLineAndColumn) {
  SourceManager sm;
  BufferId f = sm.add_buffer("a.fx", "float x;\n  float y;\n");
  PresumedLocation p = sm.presumed(sm.location(f, 11));
  EXPECT_EQ(p.file, "a.fx");
  EXPECT_EQ(p.line, 2u);
  EXPECT_EQ(p.column, 3u);
  EXPECT_EQ(sm.line_text(sm.location(f, 11)), "  float y;");
  EXPECT_EQ(sm.line_text(sm.location(f, 0)), "float x;");
}

// Windows editors start files with a UTF-8 byte-order mark; it is no column of line 1.
TEST(SourceManager, ColumnsOnLine1CountFromAfterAByteOrderMark) {
  SourceManager sm;
  BufferId f = sm.add_buffer("bom.fx",
                             "\xEF\xBB\xBF"
                             "float x;\nint y;\n");
  PresumedLocation p = sm.presumed(sm.location(f, 9));  // 'x'
  EXPECT_EQ(p.line, 1u);
  EXPECT_EQ(p.column, 7u);
  EXPECT_EQ(sm.line_text(sm.location(f, 9)), "float x;");
  EXPECT_EQ(sm.presumed(sm.location(f, 16)).column, 5u);  // 'y' on line 2
  EXPECT_EQ(sm.presumed(sm.location(f, 1)).column, 1u);   // inside the mark
}

TEST(SourceManager, EndOfBufferBelongsToBuffer) {
  SourceManager sm;
  BufferId a = sm.add_buffer("a.fx", "abc");
  BufferId b = sm.add_buffer("b.fx", "def");
  EXPECT_EQ(sm.buffer_of(sm.location(a, 3)), a);
  EXPECT_EQ(sm.buffer_of(sm.location(b, 0)), b);
}

TEST(SourceManager, IncludeStackIsRecorded) {
  SourceManager sm;
  BufferId main = sm.add_buffer("main.fx", "#include \"b.fxh\"\n");
  SourceLocation at = sm.location(main, 0);
  BufferId inc = sm.add_buffer("b.fxh", "float z;", at);
  EXPECT_EQ(sm.included_from(inc), at);
  EXPECT_FALSE(sm.included_from(main).valid());
}

TEST(SourceManager, LineDirectiveRenamesAndRenumbers) {
  SourceManager sm;
  BufferId f = sm.add_buffer("gen.fx", "a\n#line 100 \"orig.fx\"\nb\nc\n");
  sm.add_line_directive(sm.location(f, 22), 100, "orig.fx");
  PresumedLocation b = sm.presumed(sm.location(f, 22));
  EXPECT_EQ(b.file, "orig.fx");
  EXPECT_EQ(b.line, 100u);
  EXPECT_EQ(sm.presumed(sm.location(f, 24)).line, 101u);
  EXPECT_EQ(sm.presumed(sm.location(f, 0)).line, 1u);
  EXPECT_EQ(sm.physical(sm.location(f, 24)).file, "gen.fx");
}

TEST(SourceManager, MacroExpansionMapsToSpellingAndInvocation) {
  SourceManager sm;
  BufferId f = sm.add_buffer("m.fx", "#define TWO 1 + 1\nfloat x = TWO;\n");
  SourceLocation body = sm.location(f, 12);  // "1 + 1"
  SourceLocation use = sm.location(f, 28);   // "TWO" on line 2
  SourceLocation exp = sm.add_expansion({"TWO", body, {use, use.offset(3)}}, 5);
  EXPECT_TRUE(sm.is_expansion(exp.offset(4)));
  EXPECT_EQ(sm.spelling_location(exp.offset(4)), body.offset(4));
  EXPECT_EQ(sm.file_location(exp.offset(4)), use);
  EXPECT_EQ(sm.presumed(exp).line, 2u);
  EXPECT_EQ(sm.text_at(exp.offset(4)).substr(0, 1), "1");
}

TEST(SourceManager, ScratchTextStaysValid) {
  SourceManager sm;
  std::vector<std::string_view> views;
  for (int i = 0; i < 20000; ++i) {
    std::string s = "tok" + std::to_string(i);
    views.push_back(sm.text_at(sm.add_scratch(s, {})).substr(0, s.size()));
  }
  EXPECT_EQ(views[0], "tok0");
  EXPECT_EQ(views[19999], "tok19999");
}

}  // namespace
}  // namespace fx
