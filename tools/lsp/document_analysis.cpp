// The front end and semantic model on an open document (document_analysis.h).
#include "document_analysis.h"

#include <algorithm>
#include <unordered_set>

namespace fx::tools::lsp {

DocumentAnalysis::DocumentAnalysis(const TextDocument& document, const WorkspaceConfig& config,
                                   const std::map<std::string, std::string>& open)
    : DocumentPlaces(sm_, document.path), version_(document.version) {
  // The front end and the semantic model, as fx::EffectFile::parse runs them.
  parsed_ = fx::parse_effect_text(path(), document.text, sm_, diags_, config.document_options(path(), open));
  model_ = std::make_unique<fx::semantic::SemanticModel>(parsed_.ast, sm_);
  model_->report(diags_);
  find_macros();
}

void DocumentAnalysis::find_macros() {
  for (fx::BufferId id = 1; id < sm_.buffer_count(); ++id) {
    const fx::SourceLocation start = sm_.location(id, 0);
    if (!start.valid() || sm_.is_expansion(start) || sm_.is_scratch(start)) continue;
    const std::string_view text = sm_.buffer_text(id);
    for (size_t at = 0; at < text.size();) {
      size_t eol = text.find('\n', at);
      if (eol == std::string_view::npos) eol = text.size();
      std::string_view line = text.substr(at, eol - at);
      size_t i = line.find_first_not_of(" \t");
      if (i != std::string_view::npos && line[i] == '#') {
        i = line.find_first_not_of(" \t", i + 1);
        if (i != std::string_view::npos && line.substr(i, 6) == "define") {
          size_t name = line.find_first_not_of(" \t", i + 6);
          size_t end = name;
          while (end < line.size() && (isalnum(static_cast<unsigned char>(line[end])) || line[end] == '_')) ++end;
          if (name != std::string_view::npos && end > name)
            macros_.push_back({std::string(line.substr(name, end - name)), std::string(line),
                               sm_.location(id, static_cast<uint32_t>(at + name))});
        }
      }
      at = eol + 1;
    }
  }
}

const MacroDefinition* DocumentAnalysis::macro(std::string_view name) const {
  for (auto it = macros_.rbegin(); it != macros_.rend(); ++it)
    if (it->name == name) return &*it;
  return nullptr;
}

void DocumentAnalysis::index_tokens() const {
  if (indexed_) return;
  indexed_ = true;
  // The document's tokens by offset in their buffer, then one walk over each buffer's text
  // that counts lines and UTF-16 columns: linear in the text, with no per-token line lookup.
  struct Spot {
    fx::BufferId buffer;
    uint32_t offset, token;
  };
  std::vector<Spot> spots;
  std::unordered_set<fx::BufferId> mine, others;
  const std::vector<fx::Token>& tokens = parsed_.ast.tokens;
  for (uint32_t i = 0; i < tokens.size(); ++i) {
    const fx::Token& t = tokens[i];
    if (t.kind == fx::TokenKind::eof || (t.flags & fx::kFromMacro) || sm_.is_expansion(t.loc)) continue;
    const fx::BufferId buffer = sm_.buffer_of(t.loc);
    if (others.count(buffer)) continue;
    if (!mine.count(buffer)) {
      if (sm_.buffer_name(buffer) != path()) {
        others.insert(buffer);
        continue;
      }
      mine.insert(buffer);
    }
    spots.push_back({buffer, sm_.offset_in_buffer(t.loc), i});
  }
  std::sort(spots.begin(), spots.end(), [](const Spot& a, const Spot& b) {
    return a.buffer != b.buffer ? a.buffer < b.buffer : a.offset < b.offset;
  });
  fx::BufferId buffer = 0;
  std::string_view text;
  uint32_t at = 0, line = 0, character = 0;
  for (const Spot& s : spots) {
    if (s.buffer != buffer) {
      buffer = s.buffer;
      text = sm_.buffer_text(buffer);
      at = line = character = 0;
    }
    for (; at < s.offset && at < text.size(); ++at) {
      const auto c = static_cast<unsigned char>(text[at]);
      if (c == '\n') {
        ++line;
        character = 0;
      } else if ((c & 0xC0) != 0x80) {
        character += c >= 0xF0 ? 2 : 1;  // one unit per UTF-8 sequence, two beyond the BMP
      }
    }
    const std::string_view spelling = tokens[s.token].text();
    places_.push_back({line, character, utf16_length(spelling, spelling.size()), s.token});
  }
  std::sort(places_.begin(), places_.end(), [](const TokenPlace& a, const TokenPlace& b) {
    return a.line != b.line ? a.line < b.line : a.character < b.character;
  });
}

const fx::semantic::Symbol* DocumentAnalysis::symbol_at(Position p) const {
  const std::vector<fx::Token>& tokens = parsed_.ast.tokens;
  const std::optional<uint32_t> token = token_at(p);
  if (!token || !tokens[*token].is(fx::TokenKind::identifier)) return nullptr;
  if (const fx::semantic::Reference* r = model_->reference_at(*token)) return r->symbol;
  return model_->global(tokens[*token].text());
}

std::optional<uint32_t> DocumentAnalysis::token_before(Position p) const {
  index_tokens();
  auto it = std::lower_bound(places_.begin(), places_.end(), p, [](const TokenPlace& t, Position q) {
    return t.line != q.line ? t.line < q.line : t.character < q.character;
  });
  if (it == places_.begin()) return std::nullopt;
  return std::prev(it)->token;
}

std::optional<uint32_t> DocumentAnalysis::token_at(Position p) const {
  index_tokens();
  // The last token starting at or before p, if p lies inside it or right after its end.
  auto it = std::upper_bound(places_.begin(), places_.end(), p, [](Position q, const TokenPlace& t) {
    return q.line != t.line ? q.line < t.line : q.character < t.character;
  });
  if (it == places_.begin()) return std::nullopt;
  const TokenPlace& t = *std::prev(it);
  if (t.line != p.line || p.character > t.character + t.length) return std::nullopt;
  return t.token;
}

}  // namespace fx::tools::lsp
