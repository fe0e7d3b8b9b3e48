// Lookup over the state table: one open-addressing hash on (lower-cased name, block), built
// once on first use, so a lookup neither allocates nor scans.
#include <algorithm>
#include <array>
#include <cstring>

#include "fx/ascii_case.h"
#include "name_hash.h"
#include "state_table_data.h"

namespace fx {
namespace {

// Hashes the length and five characters (the first two, the middle, the last two): that
// tells the table's names apart (MinFilter/MagFilter, AddressU/AddressV) at a fixed cost,
// and the few collisions are settled by the stored hash and one iequals.
uint64_t state_hash(std::string_view name, StateBlock block) {
  uint64_t h = (name.size() * 1099511628211ull) ^ static_cast<uint64_t>(block);
  auto mix = [&](char c) { h = (h ^ static_cast<unsigned char>(ascii_lower(c))) * 1099511628211ull; };
  // Written out rather than looped over an index list, which cost more than the mixing.
  const size_t n = name.size();
  if (n >= 2) {
    mix(name[0]);
    mix(name[1]);
    mix(name[n / 2]);
    mix(name[n - 2]);
    mix(name[n - 1]);
  } else if (n == 1) {
    mix(name[0]);
  }
  return h;
}

class StateIndex {
 public:
  StateIndex() {
    auto add = [&](std::span<const StateInfo> rows) { rows_.insert(rows_.end(), rows.begin(), rows.end()); };
    add(state_data::d3d9_pass_states());
    // A pass sets D3D9 sampler states per stage: `AddressU[1] = Clamp;`.
    for (StateInfo s : state_data::d3d9_sampler_states()) {
      bool in_pass = std::any_of(rows_.begin(), rows_.end(), [&](const StateInfo& r) {
        return r.block == StateBlock::pass && iequals(r.name, s.name);
      });
      if (in_pass) continue;
      s.block = StateBlock::pass;
      s.index_count = state_data::kSamplerStages;
      rows_.push_back(s);
    }
    add(state_data::d3d9_sampler_states());
    add(state_data::d3d10_states());
    std::stable_sort(rows_.begin(), rows_.end(),
                     [](const StateInfo& a, const StateInfo& b) { return a.block < b.block; });
    size_t capacity = 1;
    while (capacity < rows_.size() * 2) capacity *= 2;
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    for (size_t i = 0; i < rows_.size(); ++i) {
      uint64_t hash = state_hash(rows_[i].name, rows_[i].block);
      size_t slot = hash & mask_;
      while (slots_[slot].row >= 0) slot = (slot + 1) & mask_;
      slots_[slot] = {hash, static_cast<int32_t>(i)};
    }
  }

  const StateInfo* find(std::string_view name, StateBlock block) const {
    uint64_t hash = state_hash(name, block);
    for (size_t slot = hash & mask_; slots_[slot].row >= 0; slot = (slot + 1) & mask_) {
      // The stored hash rejects colliding rows without comparing their names.
      if (slots_[slot].hash != hash) continue;
      const StateInfo& s = rows_[static_cast<size_t>(slots_[slot].row)];
      // Effects mostly spell states as the table does: one memcmp before folding case.
      if (s.block == block && (s.name == name || iequals(s.name, name))) return &s;
    }
    return nullptr;
  }

  std::span<const StateInfo> rows() const { return rows_; }

 private:
  struct Slot {
    uint64_t hash = 0;
    int32_t row = -1;  // index into rows_, or -1 for an empty slot
  };
  std::vector<StateInfo> rows_;
  std::vector<Slot> slots_;  // load factor <= 1/2
  size_t mask_ = 0;
};

const StateIndex& state_index() {
  static const StateIndex index;
  return index;
}

// Lower-case without underscores: `D3D10_BLEND_SRC_ALPHA` -> `d3d10blendsrcalpha`.
// Returns false when the name does not fit (no enum name is that long).
bool normalize(std::string_view in, std::array<char, 96>& out, size_t& size) {
  size = 0;
  for (char c : in) {
    if (c == '_') continue;
    if (size == out.size()) return false;
    out[size++] = ascii_lower(c);
  }
  return true;
}

// The same, for the table's own names, which are far shorter than the buffer.
std::string normalized(std::string_view name) {
  std::array<char, 96> out;
  size_t size = 0;
  normalize(name, out, size);
  return std::string(out.data(), size);
}

// The set a state's values come from: its own, or TRUE/FALSE for a boolean state.
const EnumSet* value_set(const StateInfo& state) {
  if (!state.enums && state.type == StateValueType::boolean) return &state_data::kBoolean;
  return state.enums;
}

// Every value name of every set the table uses, normalized, once bare and once after each
// of its set's prefixes, in one open-addressing hash on (set, name): a lookup is one probe
// sequence instead of a scan of the set per prefix, which mispredicted on every character.
class EnumIndex {
 public:
  EnumIndex() {
    std::vector<const EnumSet*> sets = {&state_data::kBoolean};
    for (const StateInfo& s : state_index().rows())
      if (s.enums && std::find(sets.begin(), sets.end(), s.enums) == sets.end()) sets.push_back(s.enums);
    // Keys already present keep their value, so a bare name wins over a prefixed one, and
    // earlier prefixes and values over later ones, as in a scan in the table's order.
    for (const EnumSet* set : sets) {
      for (const EnumValue& v : set->values) add(set, normalized(v.name), v.value);
      for (std::string_view prefix : set->prefixes) {
        std::string p = normalized(prefix);
        if (p.empty()) continue;
        for (const EnumValue& v : set->values)
          if (std::string name = normalized(v.name); !name.empty()) add(set, p + name, v.value);
      }
    }
  }

  std::optional<int64_t> find(const EnumSet* set, std::string_view normalized) const {
    uint32_t hash = key_hash(set, normalized);
    for (size_t slot = hash & mask_; slots_[slot].entry >= 0; slot = (slot + 1) & mask_) {
      if (slots_[slot].hash != hash) continue;
      const Entry& e = entries_[static_cast<size_t>(slots_[slot].entry)];
      if (e.set == set && e.name == normalized) return e.value;
    }
    return std::nullopt;
  }

 private:
  struct Entry {
    const EnumSet* set;
    std::string name;  // normalized
    int64_t value;
  };
  struct Slot {
    uint32_t hash = 0;
    int32_t entry = -1;  // index into entries_, or -1 for an empty slot
  };

  // The name's hash (mixed into every bit), told apart per set by the set's address.
  static uint32_t key_hash(const EnumSet* set, std::string_view name) {
    const uint64_t h = name_hash(name) ^ reinterpret_cast<uintptr_t>(set) * 0x9E3779B97F4A7C15ull;
    return static_cast<uint32_t>(h ^ (h >> 32));
  }

  void add(const EnumSet* set, std::string name, int64_t value) {
    if (find(set, name)) return;
    entries_.push_back({set, std::move(name), value});
    if (2 * entries_.size() > slots_.size()) rehash(4 * entries_.size());
    else place(entries_.size() - 1);
  }
  void rehash(size_t capacity_at_least) {
    size_t capacity = 16;
    while (capacity < capacity_at_least) capacity *= 2;
    slots_.assign(capacity, Slot{});
    mask_ = capacity - 1;
    for (size_t i = 0; i < entries_.size(); ++i) place(i);
  }
  void place(size_t i) {
    uint32_t hash = key_hash(entries_[i].set, entries_[i].name);
    size_t slot = hash & mask_;
    while (slots_[slot].entry >= 0) slot = (slot + 1) & mask_;
    slots_[slot] = {hash, static_cast<int32_t>(i)};
  }

  std::vector<Entry> entries_;
  std::vector<Slot> slots_ = std::vector<Slot>(16);  // load factor <= 1/2
  size_t mask_ = 15;
};

const EnumIndex& enum_index() {
  static const EnumIndex index;
  return index;
}

}  // namespace

std::string_view to_string(StateBlock block) {
  switch (block) {
    case StateBlock::pass: return "pass";
    case StateBlock::sampler_state: return "sampler_state";
    case StateBlock::blend_state: return "BlendState";
    case StateBlock::depth_stencil_state: return "DepthStencilState";
    case StateBlock::rasterizer_state: return "RasterizerState";
    case StateBlock::sampler_object: return "SamplerState";
  }
  return "pass";
}

std::optional<StateBlock> state_object_block(std::string_view type_name) {
  if (iequals(type_name, "BlendState")) return StateBlock::blend_state;
  if (iequals(type_name, "DepthStencilState")) return StateBlock::depth_stencil_state;
  if (iequals(type_name, "RasterizerState")) return StateBlock::rasterizer_state;
  if (iequals(type_name, "SamplerState") || iequals(type_name, "SamplerComparisonState"))
    return StateBlock::sampler_object;
  return std::nullopt;
}

std::string_view to_string(StateValueType type) {
  switch (type) {
    case StateValueType::boolean: return "bool";
    case StateValueType::integer: return "int";
    case StateValueType::floating: return "float";
    case StateValueType::enumeration: return "enum";
    case StateValueType::flags: return "flags";
    case StateValueType::color: return "color";
    case StateValueType::float4: return "float4";
    case StateValueType::matrix: return "matrix";
    case StateValueType::texture: return "texture";
    case StateValueType::sampler: return "sampler";
    case StateValueType::shader: return "shader";
    case StateValueType::shader_constant: return "constant";
    case StateValueType::state_object: return "state object";
  }
  return "int";
}

std::string_view to_string(StateApi api) {
  switch (api) {
    case StateApi::d3d9: return "D3D9";
    case StateApi::d3d10: return "D3D10";
    case StateApi::d3d11: return "D3D11";
  }
  return "D3D9";
}

std::string_view to_string(VulkanMeaning meaning) {
  switch (meaning) {
    case VulkanMeaning::maps_to_vulkan: return "maps_to_vulkan";
    case VulkanMeaning::emulated: return "emulated";
    case VulkanMeaning::fixed_function: return "fixed_function";
    case VulkanMeaning::ignored: return "ignored";
  }
  return "ignored";
}

std::string_view to_string(VulkanArea area) {
  switch (area) {
    case VulkanArea::none: return "none";
    case VulkanArea::shader_stage: return "shader_stage";
    case VulkanArea::shader_constants: return "shader_constants";
    case VulkanArea::resource_binding: return "resource_binding";
    case VulkanArea::input_assembly: return "input_assembly";
    case VulkanArea::rasterization: return "rasterization";
    case VulkanArea::depth_stencil: return "depth_stencil";
    case VulkanArea::color_blend: return "color_blend";
    case VulkanArea::multisample: return "multisample";
    case VulkanArea::sampler: return "sampler";
  }
  return "none";
}

std::string_view to_string(StateLanding landing) {
  switch (landing) {
    case StateLanding::pipeline: return "pipeline";
    case StateLanding::dynamic: return "dynamic";
    case StateLanding::sampler: return "sampler";
    case StateLanding::binding: return "binding";
    case StateLanding::fixed_function: return "fixed_function";
    case StateLanding::unsupported: return "unsupported";
  }
  return "unsupported";
}

std::string_view to_string(StateField field) {
  static constexpr std::string_view kNames[] = {
      "none",
      "depth_test",
      "depth_write",
      "depth_compare",
      "stencil_test",
      "stencil_read_mask",
      "stencil_write_mask",
      "stencil_front_fail",
      "stencil_front_depth_fail",
      "stencil_front_pass",
      "stencil_front_compare",
      "stencil_back_fail",
      "stencil_back_depth_fail",
      "stencil_back_pass",
      "stencil_back_compare",
      "stencil_two_sided",
      "stencil_ref",
      "fill",
      "cull",
      "front_face_ccw",
      "depth_bias_d3d9",
      "depth_bias_units",
      "depth_bias_clamp",
      "depth_bias_slope",
      "depth_clip",
      "scissor",
      "multisample",
      "antialiased_lines",
      "blend_enable",
      "src_color",
      "dst_color",
      "color_op",
      "src_alpha",
      "dst_alpha",
      "alpha_op",
      "separate_alpha",
      "write_mask",
      "blend_constants",
      "alpha_to_coverage",
      "sample_mask",
      "srgb_write",
      "alpha_test",
      "alpha_compare",
      "alpha_ref",
      "state_object",
      "shader",
      "shader_constants",
      "texture",
      "sampler",
      "address_u",
      "address_v",
      "address_w",
      "border_color",
      "mag_filter",
      "min_filter",
      "mip_filter",
      "lod_bias",
      "max_mip_level",
      "max_anisotropy",
      "srgb_texture",
      "min_lod",
      "max_lod",
      "compare",
      "filter_bits",
      "stage_color_op",
      "stage_alpha_op",
  };
  static_assert(std::size(kNames) == static_cast<size_t>(StateField::stage_alpha_op) + 1);
  return kNames[static_cast<size_t>(field)];
}

std::span<const StateInfo> all_states() { return state_index().rows(); }

const StateInfo* find_state(std::string_view name, StateBlock block) { return state_index().find(name, block); }

namespace {
constexpr std::string_view kShaderTypes[] = {"VertexShader", "PixelShader",  "GeometryShader",
                                             "HullShader",   "DomainShader", "ComputeShader"};
}  // namespace

std::string_view to_string(PassStage stage) {
  static constexpr std::string_view kNames[] = {"vertex", "pixel", "geometry", "hull", "domain", "compute"};
  return kNames[static_cast<size_t>(stage)];
}

std::optional<PassStage> shader_state_stage(std::string_view state) {
  const StateInfo* row = find_state(state, StateBlock::pass);
  return row ? row->stage : std::nullopt;
}

std::optional<PassStage> shader_type_stage(std::string_view type) {
  for (size_t s = 0; s < std::size(kShaderTypes); ++s)
    if (iequals(type, kShaderTypes[s])) return static_cast<PassStage>(s);
  return std::nullopt;
}

std::string_view shader_type_name(PassStage stage) { return kShaderTypes[static_cast<size_t>(stage)]; }

std::string_view profile_prefix(PassStage stage) {
  static constexpr std::string_view kPrefixes[] = {"vs", "ps", "gs", "hs", "ds", "cs"};
  return kPrefixes[static_cast<size_t>(stage)];
}

std::optional<int64_t> find_enum(const StateInfo& state, std::string_view name) {
  const EnumSet* set = value_set(state);
  if (!set) return std::nullopt;
  std::array<char, 96> buffer;
  size_t size = 0;
  if (!normalize(name, buffer, size)) return std::nullopt;
  return enum_index().find(set, std::string_view(buffer.data(), size));
}

std::vector<std::string_view> state_names(StateBlock block) {
  std::vector<std::string_view> names;
  for (const StateInfo& s : all_states())
    if (s.block == block) names.push_back(s.name);
  return names;
}

std::vector<std::string_view> enum_names(const StateInfo& state) {
  std::vector<std::string_view> names;
  if (const EnumSet* set = value_set(state))
    for (const EnumValue& v : set->values) names.push_back(v.name);
  return names;
}

namespace {
// The Lands column: `pipeline: depth_test`, `dynamic: blend_constants`, `unsupported: why`.
std::string landing_text(const StateInfo& s) {
  std::string text(to_string(s.lands));
  if (s.field != StateField::none) text += ": `" + std::string(to_string(s.field)) + "`";
  for (StateField f : s.call_fields)
    if (f != StateField::none) text += " + `" + std::string(to_string(f)) + "`";
  if (s.lands == StateLanding::unsupported && !s.reason.empty()) text += ": " + std::string(s.reason);
  return text;
}
}  // namespace

std::string render_state_table_markdown() {
  std::string out =
      "# Effect states\n\n"
      "Generated from the state table (`parser/fx/state_table.h`, rows in\n"
      "`parser/src/state_table_*.cpp`) by `render_state_table_markdown()`; the test\n"
      "`StateTable.DocIsCurrent` fails when this file is stale (rerun it with\n"
      "`FXKIT_UPDATE_DOCS=1` to rewrite it).\n\n"
      "State names match case-insensitively. Enumeration values match case-insensitively,\n"
      "ignoring underscores and the set's prefixes, so `D3DBLEND_SRCALPHA`, `SrcAlpha` and\n"
      "`SRC_ALPHA` are the same value; an integer equal to a value is accepted too. `flags`\n"
      "values combine names and integers with `|`. An index range `[0..N-1]` marked\n"
      "*required* must be written; otherwise it defaults to 0.\n\n"
      "Vulkan meaning: `maps_to_vulkan` has a direct Vulkan equivalent; `emulated` has none\n"
      "and fxkit reproduces it (alpha test as a discard, sRGB through image views, clip\n"
      "planes through clip distances); `fixed_function` is D3D9 fixed-function state that\n"
      "fxkit parses but cannot apply, so technique validation rejects passes that set it;\n"
      "`ignored` states have nothing visible to reproduce.\n\n"
      "Lands: where the runtime writes the value, read from the same row: a `pipeline`\n"
      "field of the pass state (`fx::PassStateSummary`, then `fx::vk::PipelineState`), a\n"
      "`dynamic` state recorded with the draw, a `sampler` field (`fx::SamplerDesc`), a\n"
      "`binding` (shader code, constants, textures, samplers, state objects), a\n"
      "`fixed_function` stage field, or `unsupported` with the reason. A pass call's extra\n"
      "arguments land in the fields listed after `+`.\n";
  for (int b = 0; b < kStateBlockCount; ++b) {
    StateBlock block = static_cast<StateBlock>(b);
    out += "\n## `" + std::string(to_string(block)) + "`\n\n";
    out += "| State | Index | Value | API | Vulkan | Area | Lands |\n|---|---|---|---|---|---|---|\n";
    for (const StateInfo& s : all_states()) {
      if (s.block != block) continue;
      std::string index = "-";
      if (s.index_count)
        index = "[0.." + std::to_string(s.index_count - 1) + "]" + (s.index_required ? " required" : "");
      std::string value(to_string(s.type));
      if (s.enums) value += " (`" + std::string(s.enums->name) + "`)";
      if (s.call_args) value = std::to_string(s.call_args) + "-argument call: " + value;
      if (!s.object_kind.empty()) value += " `" + std::string(s.object_kind) + "`";
      out += "| " + std::string(s.name) + " | " + index + " | " + value + " | " + std::string(to_string(s.api)) +
             " | " + std::string(to_string(s.vulkan)) + " | " + std::string(to_string(s.area)) + " | " +
             landing_text(s) + " |\n";
    }
  }
  out += "\n## Enumerations\n\n| Set | Prefixes | Values |\n|---|---|---|\n";
  std::vector<const EnumSet*> sets;
  for (const StateInfo& s : all_states())
    if (s.enums && std::find(sets.begin(), sets.end(), s.enums) == sets.end()) sets.push_back(s.enums);
  for (const EnumSet* set : sets) {
    std::string prefixes, values;
    for (std::string_view p : set->prefixes) prefixes += (prefixes.empty() ? "`" : ", `") + std::string(p) + "`";
    for (const EnumValue& v : set->values)
      values += (values.empty() ? "" : ", ") + std::string(v.name) + "=" + std::to_string(v.value);
    out += "| `" + std::string(set->name) + "` | " + prefixes + " | " + values + " |\n";
  }
  return out;
}

}  // namespace fx
