#include "clip_distance_inputs.h"

#include <algorithm>

#include "fx/ascii_case.h"

namespace fx::detail {

namespace {

// The unit's names end in the suffix reflection strips (effect_shader_text.h): `input__fx` is
// reflected as `input`.
constexpr std::string_view kSuffix = "__fx";

bool is_stream(const ast::Variable& p) {
  const std::string_view t = p.type.name;
  return t == "PointStream" || t == "LineStream" || t == "TriangleStream";
}

// The text of toks[first, last), tokens joined by single spaces.
std::string spelled(const std::vector<Token>& toks, uint32_t first, uint32_t last) {
  std::string out;
  for (uint32_t i = first; i < last && i < toks.size(); ++i) {
    if (!out.empty()) out += ' ';
    out += toks[i].text();
  }
  return out;
}

// The token index of `name` inside `span`, or span.last.
uint32_t find_name(const std::vector<Token>& toks, ast::TokenSpan span, std::string_view name) {
  for (uint32_t i = span.first; i < span.last && i < toks.size(); ++i)
    if (toks[i].is_identifier(name)) return i;
  return span.last;
}

using StructLookup = std::function<const ast::Struct*(std::string_view)>;

// Whether a member of a struct type carries a distance somewhere inside.
bool nests_distance(const ast::Variable& v, const StructLookup& structure, int depth) {
  const ast::Struct* s = v.type.definition ? v.type.definition : structure(v.type.name);
  if (!s || depth > 8) return false;
  for (const ast::Variable& m : s->members)
    if (is_clip_or_cull_distance(m.semantic) || nests_distance(m, structure, depth + 1)) return true;
  return false;
}

// The rewrite of one geometry shader's input parameter `p` of struct `s`; false when the
// struct's distances are not plain members declared alone.
bool rewrite(const std::vector<Token>& toks, const ast::Function& f, const ast::Variable& p, const ast::Struct& s,
             const StructLookup& structure, std::unordered_map<uint32_t, std::string>& out) {
  std::vector<const ast::Variable*> kept, distances;
  for (const ast::Variable& m : s.members) {
    if (nests_distance(m, structure, 0)) return false;
    const bool shared = std::count_if(s.members.begin(), s.members.end(),
                                      [&](const ast::Variable& o) { return o.tokens.first == m.tokens.first; }) > 1;
    if (is_clip_or_cull_distance(m.semantic)) {
      if (shared || !m.array_dims.empty()) return false;
      distances.push_back(&m);
    } else if (!shared || kept.empty() || kept.back()->tokens.first != m.tokens.first) {
      kept.push_back(&m);
    }
  }
  const uint32_t open = find_name(toks, p.tokens, p.name) + 1;
  if (distances.empty() || open >= p.tokens.last || !toks[open].is(TokenKind::l_square)) return false;
  uint32_t close = open;
  while (close < p.tokens.last && !toks[close].is(TokenKind::r_square)) ++close;
  if (close >= p.tokens.last || f.body.first == 0 || !toks[f.body.first - 1].is(TokenKind::l_brace)) return false;
  const std::string count = spelled(toks, open + 1, close);
  const std::string type = std::string(s.name) + std::string(kSuffix);
  const std::string input = std::string(p.name) + std::string(kSuffix);

  // The struct without the distances, written in front of the function.
  std::string prefix = "struct " + type + " {";
  for (const ast::Variable* m : kept) prefix += " " + spelled(toks, m->tokens.first, m->tokens.last);
  out[f.tokens.first] = prefix + " }; " + std::string(toks[f.tokens.first].text());

  // The parameter: the input array of that struct, then one array per distance member.
  std::string param;
  for (uint32_t i = p.tokens.first; i < p.tokens.last; ++i) {
    std::string_view t = toks[i].text();
    std::string word = t == s.name ? type : t == p.name ? input : std::string(t);
    param += (param.empty() ? "" : " ") + word;
    if (i != p.tokens.first) out[i] = " ";
  }
  for (const ast::Variable* m : distances)
    param += ", in " + spelled(toks, m->tokens.first, find_name(toks, m->tokens, m->name)) + " " + std::string(p.name) +
             "_" + std::string(m->name) + std::string(kSuffix) + "[" + count + "] : " + std::string(m->semantic);
  out[p.tokens.first] = param;

  // The body first rebuilds the array the code reads.
  std::string body = "{ " + std::string(s.name) + " " + std::string(p.name) + "[" + count +
                     "]; for (int i__fx = 0; i__fx < " + count + "; ++i__fx) {";
  for (const ast::Variable* m : kept)
    for (const ast::Variable& member : s.members)
      if (member.tokens.first == m->tokens.first && !is_clip_or_cull_distance(member.semantic))
        body += " " + std::string(p.name) + "[i__fx]." + std::string(member.name) + " = " + input + "[i__fx]." +
                std::string(member.name) + ";";
  for (const ast::Variable* m : distances)
    body += " " + std::string(p.name) + "[i__fx]." + std::string(m->name) + " = " + std::string(p.name) + "_" +
            std::string(m->name) + std::string(kSuffix) + "[i__fx];";
  out[f.body.first - 1] = body + " }";
  return true;
}

}  // namespace

bool is_clip_or_cull_distance(std::string_view semantic) {
  const std::string s = ascii_lower(semantic);
  return s.starts_with("sv_clipdistance") || s.starts_with("sv_culldistance");
}

std::unordered_map<uint32_t, std::string> clip_distance_input_spellings(
    const std::vector<Token>& toks, const std::vector<const ast::Function*>& functions, const StructLookup& structure,
    std::unordered_set<const ast::Function*>& rewritten) {
  std::unordered_map<uint32_t, std::string> out;
  for (const ast::Function* f : functions) {
    if (f->body.empty() || std::none_of(f->params.begin(), f->params.end(), is_stream)) continue;
    for (const ast::Variable& p : f->params) {
      if ((p.storage & (ast::kOut | ast::kUniform)) || p.array_dims.size() != 1) continue;
      const ast::Struct* s = p.type.definition ? p.type.definition : structure(p.type.name);
      if (!s || s->name.empty()) continue;
      std::unordered_map<uint32_t, std::string> spellings;
      if (!rewrite(toks, *f, p, *s, structure, spellings)) continue;
      out.merge(spellings);
      rewritten.insert(f);
      break;  // one input array per geometry shader
    }
  }
  return out;
}

}  // namespace fx::detail
