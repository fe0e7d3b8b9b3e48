#include "fx/compile/program_link.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <optional>
#include <set>

#include "spirv_legalize.h"
#include "spirv_words.h"

namespace fx {
namespace {

// A resource of one stage before linking.
struct StageResource {
  std::string name;
  DescriptorKind kind;
  uint32_t set, binding, count, size;
  std::string members;  // a block's member names and offsets: stages share a block only when they agree
};

// A block's layout as text ("World@0;Tint@64;"): each stage's unit declares only the globals
// it reaches, so two stages' `$Global` blocks may differ even at the same size.
std::string member_layout(const UniformBlock& b) {
  std::string out = std::to_string(b.size) + "|";
  for (const BlockMember& m : b.members)
    out.append(m.name)
        .append("@")
        .append(std::to_string(m.offset))
        .append(":")
        .append(std::to_string(m.size))
        .append(";");
  return out;
}

DescriptorKind descriptor_kind(ImageBinding::Kind k, ImageDim dim) {
  if (dim == ImageDim::buffer)
    return k == ImageBinding::Kind::storage_image ? DescriptorKind::storage_texel_buffer
                                                  : DescriptorKind::uniform_texel_buffer;
  switch (k) {
    case ImageBinding::Kind::combined_image_sampler: return DescriptorKind::combined_image_sampler;
    case ImageBinding::Kind::sampled_image: return DescriptorKind::sampled_image;
    case ImageBinding::Kind::sampler: return DescriptorKind::sampler;
    case ImageBinding::Kind::storage_image: return DescriptorKind::storage_image;
  }
  return DescriptorKind::sampled_image;
}

std::vector<StageResource> resources_of(const ShaderReflection& r) {
  std::vector<StageResource> out;
  for (const UniformBlock& b : r.uniform_blocks)
    out.push_back({b.name, DescriptorKind::uniform_buffer, b.set, b.binding, 1, b.size, member_layout(b)});
  for (const UniformBlock& b : r.storage_blocks)
    out.push_back({b.name, DescriptorKind::storage_buffer, b.set, b.binding, 1, b.size, member_layout(b)});
  for (const ImageBinding& i : r.images)
    out.push_back({i.name, descriptor_kind(i.kind, i.dim), i.set, i.binding, std::max(1u, i.array_size), 0, {}});
  // Declaration order as glslang numbered them.
  std::stable_sort(out.begin(), out.end(), [](const StageResource& a, const StageResource& b) {
    return std::pair(a.set, a.binding) < std::pair(b.set, b.binding);
  });
  return out;
}

void apply_binding(ShaderReflection& r, const StageResource& res, uint32_t binding) {
  auto set_block = [&](std::vector<UniformBlock>& blocks) {
    for (UniformBlock& b : blocks)
      if (b.name == res.name && b.set == res.set && b.binding == res.binding) b.set = 0, b.binding = binding;
  };
  if (res.kind == DescriptorKind::uniform_buffer) set_block(r.uniform_blocks);
  else if (res.kind == DescriptorKind::storage_buffer) set_block(r.storage_blocks);
  else
    for (ImageBinding& i : r.images)
      if (i.name == res.name && i.set == res.set && i.binding == res.binding) i.set = 0, i.binding = binding;
}

// The semantics a varying takes, one per location: its own, and for an array of N
// (`float2 uv[5] : TEXCOORD1`) the next N - 1 too (TEXCOORD2..TEXCOORD5), as Direct3D numbers them.
std::vector<std::string> spanned_semantics(const InterfaceVariable& v) {
  return consecutive_semantics(canonical_semantic(v.semantic), std::max(1u, v.type.array_size));
}

// A consumer that skipped legalization loads every input it declares, used or not, and
// Vulkan rejects a loaded input no stage before writes (D3D code often declares one: the
// vertex shader's output struct, POSITION included, as the pixel shader's input). When the
// producer leaves one unwritten, the consumer is legalized now, which drops the loads of
// inputs its code never uses; those are marked unread.
void legalize_if_inputs_unwritten(const CompiledShader& producer, CompiledShader& consumer, DiagnosticSink& sink) {
  if (consumer.legalized) return;
  std::set<std::string> written;
  for (const InterfaceVariable& v : producer.reflection.outputs) written.insert(canonical_semantic(v.semantic));
  if (std::all_of(consumer.reflection.inputs.begin(), consumer.reflection.inputs.end(),
                  [&](const InterfaceVariable& v) { return written.count(canonical_semantic(v.semantic)); }))
    return;
  if (!spirv::legalize(consumer.spirv)) {
    sink.warning("shader-varying-unwritten", {},
                 std::string(to_string(consumer.reflection.stage)) + " '" + consumer.entry_point +
                     "': spirv-opt could not legalize it, so the inputs the " + to_string(producer.reflection.stage) +
                     " stage does not write stay read; Vulkan calls their values undefined");
    return;
  }
  consumer.legalized = true;
  const std::set<uint32_t> read = spirv::read_input_locations(consumer.spirv);
  for (InterfaceVariable& v : consumer.reflection.inputs) v.unread = !read.count(v.location);
}

// A plain scalar or vector of 32-bit components: what an output can be padded to.
std::optional<spirv::Scalar> paddable(const ReflectedType& t) {
  if (t.rows != 1 || t.array_size || t.is_struct || t.columns > 4) return std::nullopt;
  switch (t.scalar) {
    case ScalarKind::float32: return spirv::Scalar::float32;
    case ScalarKind::int32: return spirv::Scalar::int32;
    case ScalarKind::uint32: return spirv::Scalar::uint32;
    default: return std::nullopt;
  }
}

// Direct3D pads a varying the pixel shader reads wider than the stage before writes it
// (a float2 TEXCOORD0 read as a float4); Vulkan calls the missing components an error, so
// the producer writes them (0, and 1 in w).
void pad_narrow_outputs(CompiledShader& producer, const CompiledShader& consumer) {
  for (const InterfaceVariable& in : consumer.reflection.inputs) {
    if (in.unread) continue;
    const std::optional<spirv::Scalar> scalar = paddable(in.type);
    if (!scalar) continue;
    for (const InterfaceVariable& out : producer.reflection.outputs)
      if (out.location == in.location && canonical_semantic(out.semantic) == canonical_semantic(in.semantic) &&
          paddable(out.type) && out.type.columns < in.type.columns)
        spirv::pad_output(producer.spirv, out.location, out.type.columns, in.type.columns - out.type.columns, *scalar);
  }
}

// The outputs of the stage before the pixel shader that it does not declare: Direct3D ignores
// them, Vulkan without maintenance4 warns about each (Shader-OutputNotConsumed), so they go.
// Every declared input stays written, read or not.
void remove_unconsumed_outputs(CompiledShader& producer, const CompiledShader& consumer,
                               std::span<const std::string> captured) {
  std::set<uint32_t> consumed;
  for (const InterfaceVariable& in : consumer.reflection.inputs)
    for (uint32_t k = 0; k < std::max(1u, in.type.array_size); ++k) consumed.insert(in.location + k);
  for (const InterfaceVariable& out : producer.reflection.outputs)  // stream output keeps them
    if (std::find(captured.begin(), captured.end(), canonical_semantic(out.semantic)) != captured.end())
      consumed.insert(out.location);
  if (std::all_of(producer.reflection.outputs.begin(), producer.reflection.outputs.end(),
                  [&](const InterfaceVariable& out) { return consumed.count(out.location) > 0; }))
    return;
  if (!spirv::remove_unconsumed_outputs(producer.spirv, consumed)) return;  // they stay: a warning, not wrong
  std::erase_if(producer.reflection.outputs,
                [&](const InterfaceVariable& out) { return consumed.count(out.location) == 0; });
}

void link_varyings(CompiledShader& producer, CompiledShader& consumer, std::span<const std::string> captured,
                   DiagnosticSink& sink) {
  std::map<std::string, uint32_t> location_of;  // canonical semantic -> new location
  std::map<uint32_t, uint32_t> out_remap, in_remap;
  auto has_semantic = [](const InterfaceVariable& v) { return !v.semantic.empty(); };
  // GLSL (no semantics): locations are the author's and already agree.
  if (!std::all_of(producer.reflection.outputs.begin(), producer.reflection.outputs.end(), has_semantic) ||
      !std::all_of(consumer.reflection.inputs.begin(), consumer.reflection.inputs.end(), has_semantic))
    return;
  legalize_if_inputs_unwritten(producer, consumer, sink);
  // The outputs in the order the consumer reads their semantics (the rest after), numbered
  // densely: an input array then finds the outputs of its elements' semantics at the
  // consecutive locations it takes.
  std::map<std::string, size_t> read_at;
  for (const InterfaceVariable& v : consumer.reflection.inputs)
    for (const std::string& semantic : spanned_semantics(v)) read_at.emplace(semantic, read_at.size());
  auto order = [&](const InterfaceVariable& v) {
    auto it = read_at.find(canonical_semantic(v.semantic));
    return it == read_at.end() ? read_at.size() : it->second;
  };
  std::stable_sort(producer.reflection.outputs.begin(), producer.reflection.outputs.end(),
                   [&](const InterfaceVariable& a, const InterfaceVariable& b) { return order(a) < order(b); });
  uint32_t next = 0;
  for (InterfaceVariable& v : producer.reflection.outputs) {
    out_remap[v.location] = next;
    v.location = next;
    for (const std::string& semantic : spanned_semantics(v)) location_of[semantic] = next++;
  }
  for (InterfaceVariable& v : consumer.reflection.inputs) {
    auto it = location_of.find(canonical_semantic(v.semantic));
    uint32_t location = it != location_of.end() ? it->second : next;
    if (it == location_of.end()) next += std::max(1u, v.type.array_size);
    if (it == location_of.end() && !v.unread)
      sink.warning("shader-varying-unwritten", {},
                   std::string(to_string(consumer.reflection.stage)) + " input '" + v.name + "' (" + v.semantic +
                       ") is not written by the " + to_string(producer.reflection.stage) +
                       " stage; its value is undefined");
    in_remap[v.location] = location;
    v.location = location;
  }
  spirv::remap_locations(producer.spirv, spirv::Interface::output, out_remap);
  spirv::remap_locations(consumer.spirv, spirv::Interface::input, in_remap);
  if (consumer.reflection.stage == ShaderStage::fragment) {
    pad_narrow_outputs(producer, consumer);
    remove_unconsumed_outputs(producer, consumer, captured);
  }
}

}  // namespace

std::string canonical_semantic(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  constexpr std::string_view kCentroid = "_CENTROID";
  if (s.size() > kCentroid.size() && s.ends_with(kCentroid)) s.resize(s.size() - kCentroid.size());
  if (!s.empty() && !std::isdigit(static_cast<unsigned char>(s.back()))) s += '0';
  return s;
}

std::string offset_semantic(std::string_view semantic, uint32_t k) {
  size_t digits = semantic.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(semantic[digits - 1]))) --digits;
  uint32_t first = 0;  // stays 0 without a number (or with one past 32 bits)
  std::from_chars(semantic.data() + digits, semantic.data() + semantic.size(), first);
  return std::string(semantic.substr(0, digits)) + std::to_string(first + k);
}

std::vector<std::string> consecutive_semantics(std::string_view semantic, uint32_t count) {
  std::vector<std::string> out;
  for (uint32_t k = 0; k < count; ++k) out.push_back(offset_semantic(semantic, k));
  return out;
}

const ProgramBinding* ProgramLayout::find(std::string_view name) const {
  for (const ProgramBinding& b : bindings)
    if (b.name == name) return &b;
  return nullptr;
}

ProgramLayout link_program(const std::vector<CompiledShader*>& input, DiagnosticSink& sink,
                           std::span<const std::string> captured) {
  std::vector<CompiledShader*> stages;
  for (CompiledShader* s : input)
    if (s && s->ok) stages.push_back(s);
  std::stable_sort(stages.begin(), stages.end(), [](const CompiledShader* a, const CompiledShader* b) {
    return a->reflection.stage < b->reflection.stage;
  });

  ProgramLayout layout;
  std::vector<std::string> layouts;  // block layout per layout entry, to tell same-named blocks apart
  for (CompiledShader* s : stages) {
    std::map<spirv::SetBinding, spirv::SetBinding> remap;
    for (const StageResource& res : resources_of(s->reflection)) {
      uint32_t stage_bit = 1u << static_cast<unsigned>(s->reflection.stage);
      size_t index = 0;
      for (; index < layout.bindings.size(); ++index) {
        const ProgramBinding& b = layout.bindings[index];
        if (b.name == res.name && b.kind == res.kind && b.count == res.count && layouts[index] == res.members &&
            !(b.stage_mask & stage_bit))
          break;
      }
      if (index == layout.bindings.size()) {
        layout.bindings.push_back({res.name, res.kind, 0, static_cast<uint32_t>(index), res.count, 0});
        layouts.push_back(res.members);
      }
      layout.bindings[index].stage_mask |= stage_bit;
      remap[{res.set, res.binding}] = {0, layout.bindings[index].binding};
      apply_binding(s->reflection, res, layout.bindings[index].binding);
    }
    spirv::remap_bindings(s->spirv, remap);
  }
  for (size_t i = 0; i + 1 < stages.size(); ++i)
    if (stages[i]->reflection.stage != ShaderStage::compute && stages[i + 1]->reflection.stage != ShaderStage::compute)
      link_varyings(*stages[i], *stages[i + 1], captured, sink);
  return layout;
}

}  // namespace fx
