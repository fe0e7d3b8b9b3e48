// Vertex layout matching by semantic, and mesh library layouts in Vulkan formats.
#include "fx/binding/vertex_layout.h"

#include <cstddef>

#define XXH_INLINE_ALL  // xxHash header-only: fxkit links no libxxhash
#include <xxhash.h>

#include <algorithm>
#include <cctype>

#include "fx/compile/program_link.h"  // consecutive_semantics
#include "fx/mesh.h"

namespace fx::vk {
namespace {

VkFormat to_vk_format(VertexFormat format) {
  switch (format) {
    case VertexFormat::float2: return VK_FORMAT_R32G32_SFLOAT;
    case VertexFormat::float3: return VK_FORMAT_R32G32B32_SFLOAT;
    case VertexFormat::float4: return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
  return VK_FORMAT_UNDEFINED;
}

}  // namespace

VertexLayout to_vertex_layout(const MeshVertexLayout& mesh, uint32_t binding) {
  VertexLayout layout;
  layout.bindings = {{binding, mesh.stride, VK_VERTEX_INPUT_RATE_VERTEX}};
  for (const MeshVertexAttribute& a : mesh.attributes) {
    std::string semantic(a.semantic);
    if (a.semantic_index != 0) semantic += std::to_string(a.semantic_index);
    layout.attributes.push_back({std::move(semantic), to_vk_format(a.format), a.offset, binding});
  }
  return layout;
}

std::string canonical_semantic(std::string_view semantic) {
  std::string s(semantic);
  for (char& c : s)
    if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
  size_t digits = s.size();
  while (digits > 0 && s[digits - 1] >= '0' && s[digits - 1] <= '9') --digits;
  if (digits < s.size() && digits > 0 && s.find_first_not_of('0', digits) == std::string::npos) s.resize(digits);
  if (s.starts_with("SV_POSITION")) s.erase(0, 3);
  return s;
}

std::string_view glsl_input_semantic(std::string_view name) {
  std::string n(name);
  for (char& c : n) c = char(std::tolower(static_cast<unsigned char>(c)));
  auto has = [&](const char* s) { return n.find(s) != std::string::npos; };
  if (has("binormal") || has("bitangent")) return "BINORMAL";
  if (has("tangent")) return "TANGENT";
  if (has("normal")) return "NORMAL";
  if (has("pos")) return "POSITION";
  if (has("texcoord") || has("uv")) return "TEXCOORD";
  return {};
}

std::vector<std::string> input_semantics(const InterfaceVariable& input) {
  const std::string semantic = input.semantic.empty() ? input.name : input.semantic;
  const uint32_t slots = input.type.rows > 1 ? std::max<uint32_t>(1, input.type.columns) : 1;
  if (slots == 1) return {canonical_semantic(semantic)};
  std::vector<std::string> out = consecutive_semantics(semantic, slots);
  for (std::string& s : out) s = canonical_semantic(s);
  return out;
}

std::optional<VertexInput> match_vertex_layout(const VertexLayout& layout, const std::vector<InterfaceVariable>& inputs,
                                               DiagnosticSink& sink) {
  VertexInput out;
  bool ok = true;
  std::vector<bool> binding_used(layout.bindings.size(), false);
  for (const InterfaceVariable& in : inputs) {
    const std::vector<std::string> slots = input_semantics(in);
    for (uint32_t slot = 0; slot < slots.size(); ++slot) {
      const std::string& want = slots[slot];
      auto it = std::find_if(layout.attributes.begin(), layout.attributes.end(),
                             [&](const VertexAttribute& a) { return canonical_semantic(a.semantic) == want; });
      const std::string_view guess = in.semantic.empty() ? glsl_input_semantic(in.name) : std::string_view();
      if (it == layout.attributes.end() && !guess.empty())
        it = std::find_if(layout.attributes.begin(), layout.attributes.end(),
                          [&](const VertexAttribute& a) { return canonical_semantic(a.semantic) == guess; });
      if (it == layout.attributes.end()) {
        std::string offered;
        for (const VertexAttribute& a : layout.attributes) offered += (offered.empty() ? "" : ", ") + a.semantic;
        sink.error("vk-vertex-attribute-missing", {},
                   "the vertex shader reads " + want + " ('" + in.name + "', location " +
                       std::to_string(in.location + slot) + ") but the vertex layout provides " +
                       (offered.empty() ? std::string("no attributes") : offered));
        ok = false;
        continue;
      }
      auto b = std::find_if(layout.bindings.begin(), layout.bindings.end(),
                            [&](const VertexBinding& vb) { return vb.binding == it->binding; });
      if (b == layout.bindings.end()) {
        sink.error("vk-vertex-binding-missing", {},
                   "attribute " + it->semantic + " uses vertex binding " + std::to_string(it->binding) +
                       " which the layout does not declare");
        ok = false;
        continue;
      }
      binding_used[size_t(b - layout.bindings.begin())] = true;
      out.attributes.push_back({in.location + slot, it->binding, it->format, it->offset});
    }
  }
  if (!ok) return std::nullopt;
  for (size_t i = 0; i < layout.bindings.size(); ++i)
    if (binding_used[i])
      out.bindings.push_back({layout.bindings[i].binding, layout.bindings[i].stride, layout.bindings[i].rate});
  std::sort(out.attributes.begin(), out.attributes.end(),
            [](const auto& a, const auto& b) { return a.location < b.location; });
  XXH3_state_t* hs = XXH3_createState();
  XXH3_64bits_reset(hs);
  for (const auto& a : out.attributes) {
    const uint32_t w[4] = {a.location, a.binding, uint32_t(a.format), a.offset};
    XXH3_64bits_update(hs, w, sizeof w);
  }
  for (const auto& b : out.bindings) {
    const uint32_t w[3] = {b.binding, b.stride, uint32_t(b.inputRate)};
    XXH3_64bits_update(hs, w, sizeof w);
  }
  out.hash = XXH3_64bits_digest(hs);
  XXH3_freeState(hs);
  return out;
}

VkFormat default_attribute_format(const InterfaceVariable& input) {
  switch (input.type.scalar) {
    case ScalarKind::int32: return VK_FORMAT_R32G32B32A32_SINT;
    case ScalarKind::uint32:
    case ScalarKind::boolean: return VK_FORMAT_R32G32B32A32_UINT;
    default: return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
}

VertexLayout with_default_attributes(VertexLayout layout, std::span<const InterfaceVariable> inputs, uint32_t binding) {
  const size_t declared = layout.attributes.size();
  auto has = [&layout](const std::string& name, bool by_semantic) {
    for (const VertexAttribute& a : layout.attributes)
      if ((by_semantic ? canonical_semantic(a.semantic) : a.semantic) == name) return true;
    return false;
  };
  for (const InterfaceVariable& in : inputs) {
    const VkFormat format = default_attribute_format(in);
    const uint32_t offset =
        format == VK_FORMAT_R32G32B32A32_SFLOAT ? 0 : uint32_t(offsetof(DefaultAttributeData, ints));
    if (in.semantic.empty()) {
      const std::string_view guess = glsl_input_semantic(in.name);
      if (!has(in.name, false) && (guess.empty() || !has(std::string(guess), true)))
        layout.attributes.push_back({in.name, format, offset, binding});
      continue;
    }
    for (const std::string& semantic : input_semantics(in))
      if (!has(semantic, true)) layout.attributes.push_back({semantic, format, offset, binding});
  }
  if (layout.attributes.size() > declared) layout.bindings.push_back({binding, 0, VK_VERTEX_INPUT_RATE_VERTEX});
  return layout;
}

}  // namespace fx::vk
