// LSP places of an effect's source locations (document_places.h).
#include "document_places.h"

namespace fx::tools::lsp {

std::string DocumentPlaces::file_of(fx::SourceLocation loc) const {
  return std::string(sm_->physical(sm_->file_location(loc)).file);
}

Position DocumentPlaces::position_of(fx::SourceLocation loc) const {
  const fx::SourceLocation file = sm_->file_location(loc);
  const fx::PresumedLocation p = sm_->physical(file);
  if (!p.valid()) return {};
  return {p.line - 1, utf16_length(sm_->line_text(file), p.column - 1)};
}

json DocumentPlaces::range_json(fx::SourceRange range) const {
  const Position begin = position_of(range.begin);
  Position end = begin;
  if (range.end.valid() &&
      sm_->buffer_of(sm_->file_location(range.end)) == sm_->buffer_of(sm_->file_location(range.begin)))
    end = position_of(range.end);
  if (end.line < begin.line || (end.line == begin.line && end.character < begin.character)) end = begin;
  return {{"start", {{"line", begin.line}, {"character", begin.character}}},
          {"end", {{"line", end.line}, {"character", end.character}}}};
}

json DocumentPlaces::location_json(fx::SourceRange range) const {
  return {{"uri", path_to_uri(file_of(range.begin))}, {"range", range_json(range)}};
}

std::string_view DocumentPlaces::text_of(fx::SourceRange range) const {
  const fx::SourceLocation b = sm_->file_location(range.begin), e = sm_->file_location(range.end);
  const fx::BufferId buffer = sm_->buffer_of(b);
  if (!b.valid() || !e.valid() || buffer != sm_->buffer_of(e)) return {};
  const uint32_t from = sm_->offset_in_buffer(b), to = sm_->offset_in_buffer(e);
  const std::string_view text = sm_->buffer_text(buffer);
  if (to < from || to > text.size()) return {};
  return text.substr(from, to - from);
}

}  // namespace fx::tools::lsp
