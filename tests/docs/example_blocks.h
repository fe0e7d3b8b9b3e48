// The code examples of the documentation and of header comments, and where they are
// compiled: what examples_compiled_test checks (tests/README.md, "Examples that compile").
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fx::docs {

// One example: its lines (trailing blanks removed) and where it was found.
struct ExampleBlock {
  std::filesystem::path file;
  size_t line = 0;  // 1-based line of its first code line
  std::vector<std::string> lines;
};

// The ```cpp (or ```c++) fenced blocks of a Markdown text.
std::vector<ExampleBlock> markdown_examples(std::string_view text, const std::filesystem::path& file);

// The C++ examples in the comments of a header: a run of comment lines whose first line is
// `//` and exactly three spaces before code (later lines: three or more), at least one of
// which (after a trailing `// ...` remark) ends in `;`, `{` or `}`. The lines keep the
// indentation past those three spaces.
std::vector<ExampleBlock> header_examples(std::string_view text, const std::filesystem::path& file);

// Whether `source` holds `block` as consecutive lines, every line indented by the same
// prefix (empty lines may be empty).
bool contains_block(std::string_view source, const ExampleBlock& block);

}  // namespace fx::docs
