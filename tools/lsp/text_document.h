// An open document as the editor holds it: its text, updated by whole or incremental
// changes, and the conversion between LSP positions (line, UTF-16 code units) and bytes.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace fx::tools::lsp {

// LSP positions count UTF-16 code units; fxkit's columns count bytes.
struct Position {
  uint32_t line = 0;       // 0-based
  uint32_t character = 0;  // 0-based, UTF-16 code units
};

// The UTF-16 length of the first `bytes` bytes of `line` (UTF-8).
uint32_t utf16_length(std::string_view line, size_t bytes);
// The byte offset in `line` of UTF-16 column `units` (clamped to the line).
size_t byte_offset_of_utf16(std::string_view line, uint32_t units);

// file:///a/b%20c.fx -> /a/b c.fx; other schemes give "".
std::string uri_to_path(std::string_view uri);
std::string path_to_uri(std::string_view path);

struct TextDocument {
  std::string uri;
  std::string path;  // the file it stands for
  int64_t version = 0;
  std::string text;

  // Byte offset of a position (clamped to the text).
  size_t offset_of(Position p) const;
  // Replaces the text between two positions (an incremental change).
  void replace(Position from, Position to, std::string_view with);
  // The identifier at or just before `p` ("" if none).
  std::string_view word_at(Position p) const;
  // The whole line `line` without its newline ("" past the end).
  std::string_view line(uint32_t line) const;
};

}  // namespace fx::tools::lsp
