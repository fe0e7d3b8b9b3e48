#include "shader_diagnostics.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include "effect_shader_text.h"

namespace fx::detail {
namespace {

// The name a glslang message starts with: `'undefined_value' : unknown variable`.
std::string_view quoted_word(std::string_view message) {
  if (message.size() < 3 || message[0] != '\'') return {};
  size_t close = message.find('\'', 1);
  if (close == std::string_view::npos) return {};
  std::string_view word = message.substr(1, close - 1);
  if (word.empty() || !std::all_of(word.begin(), word.end(), is_word_char) ||
      std::isdigit(static_cast<unsigned char>(word[0])))
    return {};
  return word;
}

// Offset of `word` as a whole identifier in `line`, or npos.
size_t find_word(std::string_view line, std::string_view word) {
  for (size_t at = line.find(word); at != std::string_view::npos; at = line.find(word, at + 1)) {
    bool starts = at == 0 || !is_word_char(line[at - 1]);
    bool ends = at + word.size() == line.size() || !is_word_char(line[at + word.size()]);
    if (starts && ends) return at;
  }
  return std::string_view::npos;
}

bool names_unknown(std::string_view message) {
  return message.find(": unknown variable") != std::string_view::npos ||
         message.find(": undeclared identifier") != std::string_view::npos;
}

bool is_grammar_error(const Diagnostic& d) {
  return d.severity == Severity::error && d.message.ends_with("' : Expected");
}

// glslang's HLSL grammar reports one parse failure as a chain of "'expression' : Expected",
// "'assignment expression' : Expected", ..., and only the last carries the column. The chain
// becomes one error: the first (innermost) expectation, at that column.
void merge_grammar_chains(std::vector<Diagnostic>& diagnostics, const SourceManager& sm) {
  std::vector<Diagnostic> out;
  for (size_t i = 0; i < diagnostics.size();) {
    if (!is_grammar_error(diagnostics[i]) || !diagnostics[i].range.begin.valid()) {
      out.push_back(std::move(diagnostics[i++]));
      continue;
    }
    const PresumedLocation first = sm.presumed(diagnostics[i].range.begin);
    size_t end = i + 1, located = i;
    for (; end < diagnostics.size() && is_grammar_error(diagnostics[end]) && diagnostics[end].range.begin.valid();
         ++end) {
      const PresumedLocation p = sm.presumed(diagnostics[end].range.begin);
      if (p.file != first.file || p.line != first.line) break;
      if (p.column != 1) located = end;
    }
    Diagnostic merged = std::move(diagnostics[i]);
    merged.range = diagnostics[located].range;
    out.push_back(std::move(merged));
    i = end;
  }
  diagnostics = std::move(out);
}

}  // namespace

void refine_shader_diagnostics(std::vector<Diagnostic>& diagnostics, const SourceManager& sm,
                               const std::vector<std::string>& symbols) {
  merge_grammar_chains(diagnostics, sm);
  std::vector<std::pair<std::string_view, uint32_t>> unknown_at;  // (file, line) of unknown names
  std::vector<Diagnostic> kept;
  for (Diagnostic& d : diagnostics) {
    const PresumedLocation p = d.range.begin.valid() ? sm.presumed(d.range.begin) : PresumedLocation{};
    const std::string_view word = quoted_word(d.message);
    if (p.valid() && d.severity == Severity::error &&
        std::find(unknown_at.begin(), unknown_at.end(), std::pair(p.file, p.line)) != unknown_at.end())
      continue;  // a follow-on of an unknown name on this line ('temp void' operands...)
    // glslang gives HLSL semantic errors no column: the token the message names has one.
    if (p.valid() && p.column == 1 && !word.empty()) {
      size_t at = find_word(sm.line_text(d.range.begin), word);
      if (at != std::string_view::npos) {
        d.range.begin = d.range.begin.offset(static_cast<uint32_t>(at));
        d.range.end = d.range.begin.offset(static_cast<uint32_t>(word.size()));
      }
    }
    if (p.valid() && d.severity == Severity::error && names_unknown(d.message)) {
      unknown_at.emplace_back(p.file, p.line);
      std::vector<std::string_view> candidates(symbols.begin(), symbols.end());
      std::string guess = closest_match(word, candidates);
      if (!guess.empty() && guess != word) {
        d.message += "; did you mean '" + guess + "'?";
        if (d.range.end.valid()) d.fixits.push_back({d.range, guess});
      }
    }
    kept.push_back(std::move(d));
  }
  diagnostics = std::move(kept);
}

}  // namespace fx::detail
