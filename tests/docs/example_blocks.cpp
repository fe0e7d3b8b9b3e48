// Finding code examples in Markdown and header comments, and finding them in sources.
#include "example_blocks.h"

#include <optional>

namespace fx::docs {
namespace {

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(start, end - start));
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r' || line.back() == '\t')) line.pop_back();
    out.push_back(std::move(line));
    start = end + 1;
  }
  return out;
}

std::string_view trim_left(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  return s;
}

// The code part of an example line: without a trailing `// remark`, right-trimmed.
std::string_view code_part(std::string_view line) {
  const size_t remark = line.find("//");
  if (remark != std::string_view::npos) line = line.substr(0, remark);
  while (!line.empty() && line.back() == ' ') line.remove_suffix(1);
  return line;
}

bool looks_like_code(const std::vector<std::string>& lines) {
  for (const std::string& l : lines) {
    const std::string_view c = code_part(l);
    if (!c.empty() && (c.back() == ';' || c.back() == '{' || c.back() == '}')) return true;
  }
  return false;
}

}  // namespace

std::vector<ExampleBlock> markdown_examples(std::string_view text, const std::filesystem::path& file) {
  std::vector<ExampleBlock> out;
  const std::vector<std::string> lines = split_lines(text);
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string_view fence = trim_left(lines[i]);
    if (fence != "```cpp" && fence != "```c++") continue;
    ExampleBlock block{file, i + 2, {}};
    for (++i; i < lines.size() && trim_left(lines[i]) != "```"; ++i) block.lines.push_back(lines[i]);
    out.push_back(std::move(block));
  }
  return out;
}

std::vector<ExampleBlock> header_examples(std::string_view text, const std::filesystem::path& file) {
  std::vector<ExampleBlock> out;
  const std::vector<std::string> lines = split_lines(text);
  auto example_text = [](std::string_view line, bool first) -> std::optional<std::string_view> {
    line = trim_left(line);
    if (!line.starts_with("//   ")) return std::nullopt;
    line.remove_prefix(5);
    if (line.empty() || (first && line.front() == ' ')) return std::nullopt;
    return line;
  };
  for (size_t i = 0; i < lines.size(); ++i) {
    if (!example_text(lines[i], true)) continue;
    ExampleBlock block{file, i + 1, {}};
    for (; i < lines.size(); ++i) {
      auto t = example_text(lines[i], false);
      if (!t) break;
      block.lines.emplace_back(*t);
    }
    if (looks_like_code(block.lines)) out.push_back(std::move(block));
  }
  return out;
}

bool contains_block(std::string_view source, const ExampleBlock& block) {
  if (block.lines.empty()) return true;
  const std::vector<std::string> lines = split_lines(source);
  const std::string& first = block.lines.front();
  for (size_t i = 0; i + block.lines.size() <= lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.size() < first.size() || l.compare(l.size() - first.size(), first.size(), first) != 0) continue;
    const std::string indent = l.substr(0, l.size() - first.size());
    if (indent.find_first_not_of(" \t") != std::string::npos) continue;
    bool all = true;
    for (size_t k = 1; k < block.lines.size() && all; ++k) {
      const std::string& want = block.lines[k];
      const std::string& have = lines[i + k];
      all = want.empty() ? have.empty() : have == indent + want;
    }
    if (all) return true;
  }
  return false;
}

}  // namespace fx::docs
