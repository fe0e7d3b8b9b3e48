#include "entry_location.h"

#include <charconv>
#include <string_view>

#include "effect_shader_text.h"

namespace fx {
namespace {

struct Position {
  std::string file;
  uint32_t line = 1;
};

// `#line N "file"` or `#line N`: the position of the line after it.
bool read_line_directive(std::string_view line, Position& at) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string_view::npos || line.substr(i, 5) != "#line") return false;
  i = line.find_first_not_of(" \t", i + 5);
  if (i == std::string_view::npos) return false;
  uint32_t n = 0;
  auto [end, ec] = std::from_chars(line.data() + i, line.data() + line.size(), n);
  if (ec != std::errc()) return false;
  at.line = n;
  std::string_view rest = line.substr(static_cast<size_t>(end - line.data()));
  size_t open = rest.find('"'), close = rest.rfind('"');
  if (open != std::string_view::npos && close > open) at.file = std::string(rest.substr(open + 1, close - open - 1));
  return true;
}

// The column (0-based) where `line` defines `name`: `name` as a whole word followed by `(`,
// after a return type (a word other than `return`); npos when it does not.
size_t definition_column(std::string_view line, std::string_view name) {
  for (size_t at = line.find(name); at != std::string_view::npos; at = line.find(name, at + 1)) {
    size_t after = at + name.size();
    if ((at > 0 && detail::is_word_char(line[at - 1])) || (after < line.size() && detail::is_word_char(line[after])))
      continue;
    size_t paren = line.find_first_not_of(" \t", after);
    if (paren == std::string_view::npos || line[paren] != '(') continue;
    size_t type_end = line.find_last_not_of(" \t", at == 0 ? 0 : at - 1);
    if (at == 0 || type_end == std::string_view::npos || !detail::is_word_char(line[type_end])) continue;
    size_t type_start = type_end;
    while (type_start > 0 && detail::is_word_char(line[type_start - 1])) --type_start;
    if (line.substr(type_start, type_end + 1 - type_start) != "return") return at;
  }
  return std::string_view::npos;
}

}  // namespace

ShaderMessage entry_location(const TranslationUnit& unit) {
  ShaderMessage first;
  Position at{unit.name, 1};
  std::string_view source = unit.source;
  for (size_t pos = 0; pos < source.size();) {
    size_t nl = source.find('\n', pos);
    std::string_view line = source.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? source.size() : nl + 1;
    if (read_line_directive(line, at)) {
      if (first.file.empty()) first.file = at.file, first.line = at.line;
      continue;
    }
    if (size_t column = definition_column(line, unit.entry_point); column != std::string_view::npos) {
      ShaderMessage m;
      m.file = at.file;
      m.line = at.line;
      m.column = static_cast<uint32_t>(column + 1);
      return m;
    }
    ++at.line;
  }
  if (first.file.empty()) first.file = unit.name, first.line = 1;
  return first;
}

}  // namespace fx
