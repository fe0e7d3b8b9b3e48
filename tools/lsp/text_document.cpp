// Open documents and LSP positions (text_document.h).
#include "text_document.h"

#include <cstdio>

namespace fx::tools::lsp {
namespace {

// Bytes of the UTF-8 sequence starting with `lead` (1 for stray continuation bytes).
size_t sequence_length(unsigned char lead) {
  if (lead >= 0xF0) return 4;
  if (lead >= 0xE0) return 3;
  if (lead >= 0xC0) return 2;
  return 1;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

uint32_t utf16_length(std::string_view line, size_t bytes) {
  uint32_t units = 0;
  for (size_t i = 0; i < bytes && i < line.size();) {
    const size_t n = sequence_length(static_cast<unsigned char>(line[i]));
    units += n == 4 ? 2 : 1;
    i += n;
  }
  return units;
}

size_t byte_offset_of_utf16(std::string_view line, uint32_t units) {
  size_t i = 0;
  for (uint32_t u = 0; u < units && i < line.size();) {
    const size_t n = sequence_length(static_cast<unsigned char>(line[i]));
    u += n == 4 ? 2 : 1;
    i += n;
  }
  return std::min(i, line.size());
}

std::string uri_to_path(std::string_view uri) {
  constexpr std::string_view kScheme = "file://";
  if (!uri.starts_with(kScheme)) return {};
  uri.remove_prefix(kScheme.size());
  std::string path;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 && hex_value(uri[i + 2]) >= 0) {
      path += static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
      i += 2;
    } else {
      path += uri[i];
    }
  }
  return path;
}

std::string path_to_uri(std::string_view path) {
  std::string uri = "file://";
  for (char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (isalnum(u) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      uri += c;
    } else {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", u);
      uri += escaped;
    }
  }
  return uri;
}

std::string_view TextDocument::line(uint32_t n) const {
  size_t start = 0;
  for (uint32_t l = 0; l < n; ++l) {
    start = text.find('\n', start);
    if (start == std::string::npos) return {};
    ++start;
  }
  size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  std::string_view out(text.data() + start, end - start);
  if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
  return out;
}

std::string_view TextDocument::word_at(Position p) const {
  const std::string_view l = line(p.line);
  const size_t at = byte_offset_of_utf16(l, p.character);
  auto word = [](char c) { return isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  size_t begin = at, end = at;
  while (begin > 0 && word(l[begin - 1])) --begin;
  while (end < l.size() && word(l[end])) ++end;
  return l.substr(begin, end - begin);
}

size_t TextDocument::offset_of(Position p) const {
  size_t start = 0;
  for (uint32_t l = 0; l < p.line; ++l) {
    start = text.find('\n', start);
    if (start == std::string::npos) return text.size();
    ++start;
  }
  size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  return start + byte_offset_of_utf16(std::string_view(text).substr(start, end - start), p.character);
}

void TextDocument::replace(Position from, Position to, std::string_view with) {
  size_t a = offset_of(from), b = offset_of(to);
  if (b < a) std::swap(a, b);
  text.replace(a, b - a, with);
}

}  // namespace fx::tools::lsp
