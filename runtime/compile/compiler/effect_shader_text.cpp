#include "effect_shader_text.h"

#include <cctype>

namespace fx::detail {
namespace {

// Up to this many blank lines are written instead of a #line directive.
constexpr uint32_t kMaxBlankLines = 8;

}  // namespace

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string line_directive(uint32_t line, std::string_view file) {
  std::string out = "#line " + std::to_string(line) + " \"";
  for (char c : file) {
    // glslang's #line takes the string as written: keep it one token with '/' separators.
    if (c == '"') continue;
    out.push_back(c == '\\' ? '/' : c);
  }
  out += "\"";
  return out;
}

void ShaderTextWriter::end_line() {
  if (column_ == 1) return;
  out_.push_back('\n');
  last_ = '\n';
  column_ = 1;
  if (line_) ++line_;
}

void ShaderTextWriter::line(std::string_view text) {
  end_line();
  out_.append(text);
  out_.push_back('\n');
  last_ = '\n';
  column_ = 1;
  file_.clear();
}

void ShaderTextWriter::text(std::string_view text) {
  if (text.empty()) return;
  if (column_ > 1 && is_word_char(last_) && is_word_char(text.front())) out_.push_back(' ');
  out_.append(text);
  column_ += static_cast<uint32_t>(text.size());
  last_ = text.back();
}

void ShaderTextWriter::sync(std::string_view file, uint32_t line) {
  if (!file_.empty() && file == file_ && line >= line_ && line - line_ <= kMaxBlankLines) {
    while (line_ < line) {
      out_.push_back('\n');
      ++line_;
      column_ = 1;
      last_ = '\n';
    }
    return;
  }
  if (column_ > 1) out_.push_back('\n');
  out_ += line_directive(line, file);
  out_.push_back('\n');
  file_.assign(file);
  line_ = line;
  column_ = 1;
  last_ = '\n';
}

// Appended to a renamed word; reflection strips it again.
constexpr std::string_view kRenamed = "__fx";

std::string glslang_safe_name(std::string_view word, bool identifier_follows) {
  if (identifier_follows) return {};
  for (std::string_view w : {"point", "line", "triangle", "lineadj", "triangleadj", "linear", "centroid",
                             "nointerpolation", "noperspective", "precise", "snorm", "unorm"})
    if (word == w) return std::string(word) + std::string(kRenamed);
  return {};
}

std::string glslang_spelling(const std::vector<Token>& toks, uint32_t i, uint32_t last) {
  if (!toks[i].is(TokenKind::identifier)) return {};
  // fxc takes C's `unsigned int` (and `unsigned` alone) for uint; glslang reserves `unsigned`.
  if (toks[i].text() == "unsigned") return "uint";
  if (toks[i].text() == "int" && i > 0 && toks[i - 1].is_identifier("unsigned")) return " ";
  return glslang_safe_name(toks[i].text(), i + 1 < last && toks[i + 1].is(TokenKind::identifier));
}

std::string effect_name(std::string_view name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    if (name.compare(i, kRenamed.size(), kRenamed) == 0 &&
        (i + kRenamed.size() == name.size() || !is_word_char(name[i + kRenamed.size()])) && i > 0 &&
        is_word_char(name[i - 1])) {
      i += kRenamed.size() - 1;
      continue;
    }
    out.push_back(name[i]);
  }
  return out;
}

void ShaderTextWriter::token(const Token& t, std::string_view spelling) {
  const std::string_view text = spelling.empty() ? t.text() : spelling;
  PresumedLocation p = t.loc.valid() ? sm_.presumed(t.loc) : PresumedLocation{};
  bool directive = t.kind == TokenKind::directive;
  if (p.valid()) sync(p.file, p.line);
  if (directive && column_ > 1) {
    // A directive must start its line; the line number moves on by one, so re-sync after.
    out_.push_back('\n');
    column_ = 1;
    file_.clear();
    if (p.valid()) sync(p.file, p.line);
  }
  if (p.valid() && column_ < p.column && !directive) {
    out_.append(p.column - column_, ' ');
    column_ = p.column;
  } else if (column_ > 1 &&
             (t.leading_space() || (is_word_char(last_) && !text.empty() && is_word_char(text.front())))) {
    out_.push_back(' ');
    ++column_;
  }
  out_.append(text);
  column_ += static_cast<uint32_t>(text.size());
  if (!text.empty()) last_ = text.back();
  if (directive) {
    out_.push_back('\n');
    column_ = 1;
    last_ = '\n';
    if (line_) ++line_;
  }
}

}  // namespace fx::detail
