// Open documents: incremental edits in UTF-16 positions, and file URIs.
#include "text_document.h"

#include <gtest/gtest.h>

namespace {

using fx::tools::lsp::TextDocument;

TEST(TextDocument, IncrementalEditsCountUtf16Units) {
  // "é" is 2 bytes and 1 UTF-16 unit; "𝄞" is 4 bytes and 2 units.
  TextDocument d;
  d.text = "float a; // \xC3\xA9\xF0\x9D\x84\x9E x\nfloat b;\n";
  d.replace({0, 16}, {0, 17}, "y");  // the x after the two characters and a space
  EXPECT_EQ(d.line(0), "float a; // \xC3\xA9\xF0\x9D\x84\x9E y");
  d.replace({1, 6}, {1, 7}, "bee");
  EXPECT_EQ(d.line(1), "float bee;");
  d.replace({0, 8}, {1, 0}, "");  // join lines
  EXPECT_EQ(d.line(0), "float a;float bee;");
  d.replace({5, 0}, {9, 0}, "!");  // past the end: clamped
  EXPECT_EQ(d.text.back(), '!');
  EXPECT_EQ(fx::tools::lsp::utf16_length("\xC3\xA9\xF0\x9D\x84\x9E", 6), 3u);
}

TEST(TextDocument, WordAtAPosition) {
  TextDocument d;
  d.text = "return Gloss * 2;\n";
  EXPECT_EQ(d.word_at({0, 9}), "Gloss");
  EXPECT_EQ(d.word_at({0, 12}), "Gloss");  // just after it
  EXPECT_EQ(d.word_at({0, 13}), "");
}

TEST(TextDocument, FileUris) {
  EXPECT_EQ(fx::tools::lsp::uri_to_path("file:///work/my%20effects/a.fx"), "/work/my effects/a.fx");
  EXPECT_EQ(fx::tools::lsp::path_to_uri("/work/my effects/a.fx"), "file:///work/my%20effects/a.fx");
  EXPECT_EQ(fx::tools::lsp::uri_to_path("untitled:1"), "");
}

}  // namespace
