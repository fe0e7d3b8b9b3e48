// Completion (language_features.h): state names and values in state blocks; members after `.`;
// elsewhere the names in scope, intrinsics and built-in types.
#include <regex>

#include "language_features.h"
#include "state_context.h"
#include "symbol_text.h"

namespace fx::tools::lsp {
namespace {

using fx::semantic::SymbolKind;

// LSP CompletionItemKind numbers.
enum Kind { kFunction = 3, kField = 5, kVariable = 6, kProperty = 10, kKeyword = 14, kEnumMember = 20, kStruct = 22 };

json item(std::string_view label, int kind, std::string detail = {}) {
  json i = {{"label", std::string(label)}, {"kind", kind}};
  if (!detail.empty()) i["detail"] = std::move(detail);
  return i;
}

int kind_of(const fx::semantic::Symbol& s) {
  switch (s.kind) {
    case SymbolKind::function: return kFunction;
    case SymbolKind::structure:
    case SymbolKind::type_alias: return kStruct;
    case SymbolKind::member:
    case SymbolKind::cbuffer_member: return kField;
    default: return kVariable;
  }
}

constexpr const char* kBuiltinTypes[] = {"void",
                                         "bool",
                                         "int",
                                         "uint",
                                         "half",
                                         "float",
                                         "double",
                                         "float2",
                                         "float3",
                                         "float4",
                                         "half2",
                                         "half3",
                                         "half4",
                                         "int2",
                                         "int3",
                                         "int4",
                                         "uint2",
                                         "uint3",
                                         "uint4",
                                         "bool2",
                                         "bool3",
                                         "bool4",
                                         "float2x2",
                                         "float3x3",
                                         "float4x4",
                                         "float4x3",
                                         "float3x4",
                                         "texture",
                                         "sampler",
                                         "sampler2D",
                                         "sampler3D",
                                         "samplerCUBE",
                                         "Texture2D",
                                         "Texture3D",
                                         "TextureCube",
                                         "SamplerState",
                                         "SamplerComparisonState"};

json state_completion(const StateBlockSite& site, std::string_view prefix, const DocumentAnalysis& a) {
  json items = json::array();
  static const std::regex kValue(R"((\w+)\s*(\[[^\]]*\])?\s*=\s*<?\s*\w*$)");
  std::match_results<std::string_view::const_iterator> m;
  if (std::regex_search(prefix.begin(), prefix.end(), m, kValue)) {
    const fx::StateInfo* row = state_row(site, std::string_view(&*m[1].first, m[1].length()));
    if (!row) return items;
    if (row->enums)
      for (std::string_view v : fx::enum_names(*row)) items.push_back(item(v, kEnumMember, std::string(row->name)));
    else if (row->type == fx::StateValueType::boolean)
      for (const char* v : {"TRUE", "FALSE"}) items.push_back(item(v, kEnumMember, std::string(row->name)));
    else
      for (const fx::semantic::Symbol* s : a.model().globals())
        if (s->kind == SymbolKind::parameter || s->kind == SymbolKind::state_object ||
            s->kind == SymbolKind::glsl_block)
          items.push_back(item(s->name, kVariable, symbol_detail(*s)));
    return items;
  }
  std::vector<std::string_view> names = fx::state_names(site.block);
  if (site.also)
    for (std::string_view n : fx::state_names(*site.also)) names.push_back(n);
  for (std::string_view n : names) {
    const fx::StateInfo* row = state_row(site, n);
    items.push_back(item(n, kProperty, row ? std::string(fx::to_string(row->type)) : std::string()));
  }
  return items;
}

// Members of the value before a `.` at the end of `prefix`; nullopt when no `.` is there.
std::optional<json> member_completion(const DocumentAnalysis& a, std::string_view prefix, Position at) {
  size_t end = prefix.size();
  while (end > 0 && (isalnum(static_cast<unsigned char>(prefix[end - 1])) || prefix[end - 1] == '_')) --end;
  if (end == 0 || prefix[end - 1] != '.') return std::nullopt;
  json items = json::array();
  // The token before the `.`: at the column of the `.`, minus one.
  const Position dot{at.line, utf16_length(prefix, end - 1)};
  const std::optional<uint32_t> base = a.token_before(dot);
  if (!base) return items;
  const fx::semantic::Reference* r = a.model().reference_at(*base);
  if (!r) return items;
  const fx::semantic::ShaderType& type = r->type;
  if (type.kind == fx::semantic::TypeClass::structure && type.structure && type.array_rank == 0) {
    for (const fx::semantic::Symbol* m : a.model().members(*type.structure))
      items.push_back(item(m->name, kField, symbol_detail(*m)));
    for (const fx::ast::Function& f : type.structure->methods) items.push_back(item(f.name, kFunction));
  } else if (type.kind == fx::semantic::TypeClass::vector || type.kind == fx::semantic::TypeClass::scalar) {
    static constexpr const char* kSwizzles[] = {"x", "y", "z", "w", "xy", "xyz", "xyzw", "rgb", "rgba", "a"};
    for (const char* s : kSwizzles)
      if (auto t = fx::semantic::swizzle_type(type, s)) items.push_back(item(s, kField, t->name));
  }
  return items;
}

}  // namespace

json completion(const DocumentAnalysis& a, const TextDocument& document, Position at) {
  const std::string_view line = document.line(at.line);
  const std::string_view prefix = line.substr(0, byte_offset_of_utf16(line, at.character));
  if (const std::optional<StateBlockSite> site = state_block_in_text(document, at))
    return state_completion(*site, prefix, a);
  if (std::optional<json> members = member_completion(a, prefix, at)) return *members;
  json items = json::array();
  const std::optional<uint32_t> token = a.token_before(at);
  const bool in_body = token && a.model().function_at(*token);
  const std::vector<const fx::semantic::Symbol*> names = in_body ? a.model().visible_at(*token) : a.model().globals();
  for (const fx::semantic::Symbol* s : names) items.push_back(item(s->name, kind_of(*s), symbol_detail(*s)));
  if (in_body)
    for (const fx::semantic::Intrinsic& in : fx::semantic::all_intrinsics())
      items.push_back(item(in.name, kFunction, std::string(in.signature)));
  for (const char* t : kBuiltinTypes) items.push_back(item(t, kKeyword));
  return items;
}

}  // namespace fx::tools::lsp
