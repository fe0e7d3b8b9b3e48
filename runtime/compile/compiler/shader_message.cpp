#include "fx/compile/shader_message.h"

#include <cctype>
#include <optional>

namespace fx {
namespace {

struct Prefix {
  std::string_view text;
  Severity severity;
};
// glslang's TInfoSink prefixes (see glslang/Include/InfoSink.h).
constexpr Prefix kPrefixes[] = {
    {"ERROR: ", Severity::error},         {"WARNING: ", Severity::warning}, {"INTERNAL ERROR: ", Severity::fatal},
    {"UNIMPLEMENTED: ", Severity::error}, {"NOTE: ", Severity::note},
};

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

uint32_t to_u32(std::string_view s) {
  uint64_t v = 0;
  for (char c : s) v = std::min<uint64_t>(v * 10 + static_cast<uint64_t>(c - '0'), UINT32_MAX);
  return static_cast<uint32_t>(v);
}

// Splits "file:line[:col]: text". The file may itself contain ':' (C:\x.fx), so the line is
// the first ":<digits>:" field; a column follows only when it is digits up to the next ':'.
void split_location(std::string_view rest, ShaderMessage& m) {
  for (size_t colon = rest.find(':'); colon != std::string_view::npos; colon = rest.find(':', colon + 1)) {
    size_t end = rest.find(':', colon + 1);
    if (end == std::string_view::npos) break;
    std::string_view line = rest.substr(colon + 1, end - colon - 1);
    if (!all_digits(line) || colon == 0) continue;
    m.file = std::string(rest.substr(0, colon));
    m.line = to_u32(line);
    size_t text_begin = end + 1;
    size_t col_end = rest.find(':', text_begin);
    if (col_end != std::string_view::npos && all_digits(rest.substr(text_begin, col_end - text_begin))) {
      m.column = to_u32(rest.substr(text_begin, col_end - text_begin));
      text_begin = col_end + 1;
    }
    while (text_begin < rest.size() && rest[text_begin] == ' ') ++text_begin;
    m.text = std::string(rest.substr(text_begin));
    return;
  }
  m.text = std::string(rest);
}

// glslang's HLSL grammar adds "a.fx(6): error at column 7, HLSL parsing failed." after the
// message it belongs to: the only place it reports a column. Returns true when consumed.
bool merge_column_line(std::string_view line, std::vector<ShaderMessage>& out) {
  size_t open = line.rfind('(', line.find("): "));
  size_t close = line.find("): ");
  if (open == std::string_view::npos || close == std::string_view::npos || close < open) return false;
  std::string_view file = line.substr(0, open);
  std::string_view number = line.substr(open + 1, close - open - 1);
  std::string_view rest = line.substr(close + 3);
  constexpr std::string_view kAt = "error at column ";
  if (!all_digits(number) || rest.substr(0, kAt.size()) != kAt) return false;
  rest.remove_prefix(kAt.size());
  size_t digits = 0;
  while (digits < rest.size() && std::isdigit(static_cast<unsigned char>(rest[digits]))) ++digits;
  if (digits == 0) return false;
  uint32_t line_number = to_u32(number), column = to_u32(rest.substr(0, digits));
  for (auto it = out.rbegin(); it != out.rend(); ++it)
    if (it->file == file && it->line == line_number) {
      if (it->column == 0) it->column = column;
      return true;
    }
  ShaderMessage m;
  m.file = std::string(file);
  m.line = line_number;
  m.column = column;
  std::string_view text = rest.substr(digits);
  while (!text.empty() && (text.front() == ',' || text.front() == ' ')) text.remove_prefix(1);
  m.text = std::string(text);
  out.push_back(std::move(m));
  return true;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.pop_back();
  return s;
}

bool is_summary(std::string_view text) {
  // "1 compilation errors.  No code generated." and friends repeat what the messages say.
  return text.find("compilation errors.") != std::string_view::npos ||
         text.find("compilation terminated") != std::string_view::npos;
}

}  // namespace

std::vector<ShaderMessage> parse_info_log(std::string_view log) {
  std::vector<ShaderMessage> out;
  size_t pos = 0;
  while (pos < log.size()) {
    size_t nl = log.find('\n', pos);
    std::string_view line = log.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? log.size() : nl + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty()) continue;
    const Prefix* prefix = nullptr;
    for (const Prefix& p : kPrefixes)
      if (line.substr(0, p.text.size()) == p.text) {
        prefix = &p;
        break;
      }
    if (!prefix) {
      if (merge_column_line(line, out)) continue;
      // Other continuation lines belong to the previous message.
      if (!out.empty()) out.back().text.append("\n").append(line);
      continue;
    }
    ShaderMessage m;
    m.severity = prefix->severity;
    split_location(line.substr(prefix->text.size()), m);
    m.text = trimmed(std::move(m.text));
    if (m.file.empty() && is_summary(m.text)) continue;
    out.push_back(std::move(m));
  }
  return out;
}

namespace {

// Offset of the first character of 1-based `line` in `text`, or nullopt.
std::optional<uint32_t> line_offset(std::string_view text, uint32_t line) {
  uint32_t current = 1;
  size_t offset = 0;
  while (current < line) {
    size_t nl = text.find('\n', offset);
    if (nl == std::string_view::npos) return std::nullopt;
    offset = nl + 1;
    ++current;
  }
  return static_cast<uint32_t>(offset);
}

}  // namespace

ShaderLocationResolver resolver_for(const SourceManager& sm) {
  return [&sm](std::string_view file, uint32_t line, uint32_t column) -> SourceLocation {
    if (file.empty() || line == 0) return {};
    // Newest buffer first: a reloaded file's latest contents win over older copies.
    for (size_t i = sm.buffer_count(); i-- > 1;) {
      BufferId id = static_cast<BufferId>(i);
      if (sm.buffer_name(id) != file) continue;
      std::string_view text = sm.buffer_text(id);
      std::optional<uint32_t> offset = line_offset(text, line);
      if (!offset) continue;
      size_t line_end = text.find('\n', *offset);
      uint32_t line_length =
          static_cast<uint32_t>((line_end == std::string_view::npos ? text.size() : line_end) - *offset);
      uint32_t col = column ? std::min(column - 1, line_length) : 0;
      return sm.location(id, *offset + col);
    }
    return {};
  };
}

void report_messages(const std::vector<ShaderMessage>& messages, const ShaderLocationResolver& resolve,
                     DiagnosticSink& sink) {
  for (const ShaderMessage& m : messages) {
    SourceLocation loc = resolve ? resolve(m.file, m.line, m.column) : SourceLocation{};
    std::string text = m.text;
    if (!loc.valid() && !m.file.empty()) {
      std::string where = m.file + ":" + std::to_string(m.line);
      if (m.column) where.append(":").append(std::to_string(m.column));
      text = where + ": " + text;
    }
    bool link = m.file.empty() && m.text.find("Linking") != std::string::npos;
    const char* id = !m.id.empty()                     ? m.id.c_str()
                     : m.severity == Severity::warning ? "shader-compile-warning"
                     : m.severity == Severity::note    ? "shader-compile-note"
                     : link                            ? "shader-link-error"
                                                       : "shader-compile-error";
    sink.report(m.severity, id, SourceRange{loc, {}}, std::move(text));
  }
}

}  // namespace fx
