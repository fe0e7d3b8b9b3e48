// Every C++ example in the documentation (```cpp blocks of every *.md) and in header
// comments is found verbatim, up to a common indentation, in one of the compiled example
// files of tests/docs (*_example.cpp); an example that is not fails here with its place.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "example_blocks.h"

namespace fx::docs {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The repository's own files: build trees and hidden folders are skipped.
std::vector<fs::path> source_files(const fs::path& root) {
  std::vector<fs::path> out;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.starts_with(".") || name.starts_with("build"))) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) out.push_back(it->path());
  }
  return out;
}

TEST(ExampleBlocks, MarkdownCppFencesAreExamples) {
  const auto blocks = markdown_examples("text\n```cpp\nint a = 1;\n  f(a);\n```\n```\nfxkit render\n```\n", "x.md");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].line, 3u);
  EXPECT_EQ(blocks[0].lines, (std::vector<std::string>{"int a = 1;", "  f(a);"}));
}

TEST(ExampleBlocks, HeaderExamplesAreIndentedCodeComments) {
  const auto blocks = header_examples(
      "// Text.\n//\n//   auto x = make();   // remark\n//   for (;;)\n//     use(x);\n// More text.\n"
      "// A table:\n//   ps_2_0 | vs.1.1     shader profile\n"
      "// 1. A list item whose\n//    continuation ends in a semicolon;\n",
      "x.h");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].line, 3u);
  EXPECT_EQ(blocks[0].lines, (std::vector<std::string>{"auto x = make();   // remark", "for (;;)", "  use(x);"}));
}

TEST(ExampleBlocks, ABlockIsFoundUnderOneIndentation) {
  const ExampleBlock block{"x.md", 1, {"int a = 1;", "", "  f(a);"}};
  EXPECT_TRUE(contains_block("void g() {\n    int a = 1;\n\n      f(a);\n}\n", block));
  EXPECT_FALSE(contains_block("void g() {\n    int a = 1;\n\n  f(a);\n}\n", block));
  EXPECT_FALSE(contains_block("void g() {\n    int a = 2;\n\n      f(a);\n}\n", block));
  EXPECT_FALSE(contains_block("// int a = 1;\n//\n//   f(a);\n", block));
}

TEST(ExamplesCompiled, EveryDocAndHeaderExampleIsInACompiledExampleFile) {
  const fs::path root = FXKIT_SOURCE_DIR;
  std::vector<std::pair<fs::path, std::string>> compiled;
  std::vector<ExampleBlock> examples;
  for (const fs::path& p : source_files(root)) {
    const std::string ext = p.extension().string();
    if (p.parent_path() == root / "tests" / "docs" && p.filename().string().ends_with("_example.cpp"))
      compiled.emplace_back(p, read(p));
    else if (ext == ".md")
      for (ExampleBlock& b : markdown_examples(read(p), p)) examples.push_back(std::move(b));
    else if (ext == ".h" && p.parent_path() != root / "tests" / "docs")
      for (ExampleBlock& b : header_examples(read(p), p)) examples.push_back(std::move(b));
  }
  EXPECT_FALSE(compiled.empty());
  EXPECT_FALSE(examples.empty());
  for (const ExampleBlock& b : examples) {
    bool found = false;
    for (const auto& [path, text] : compiled) found = found || contains_block(text, b);
    EXPECT_TRUE(found) << fs::relative(b.file, root).string() << ":" << b.line
                       << ": this example is in no tests/docs/*_example.cpp; copy it there into a "
                          "function that compiles (and runs, where cheap), or replace it by a link";
  }
}

}  // namespace
}  // namespace fx::docs
