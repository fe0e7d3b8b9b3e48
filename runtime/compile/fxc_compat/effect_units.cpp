#include "fx/compile/effect_units.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "case_insensitive_types.h"
#include "clip_distance_inputs.h"
#include "effect_unit_builder.h"
#include "flat_initializer.h"
#include "fx/ascii_case.h"
#include "fx/state_table.h"
#include "multisample_operator.h"
#include "one_component_swizzle.h"
#include "texture_noise.h"
#include "untyped_sampler.h"

namespace fx {

const char* to_string(StageSourceKind kind) {
  switch (kind) {
    case StageSourceKind::hlsl: return "hlsl";
    case StageSourceKind::glsl: return "glsl";
    case StageSourceKind::assembly: return "assembly";
    case StageSourceKind::fixed_function: return "fixed_function";
    case StageSourceKind::invalid: return "invalid";
  }
  return "unknown";
}

const StageUnit* EffectPass::find(ShaderStage stage) const {
  for (const StageUnit& s : stages)
    if (s.stage == stage) return &s;
  return nullptr;
}

namespace detail {

// The pipeline stage a pass state sets (the state table's rows: D3D9 assignments, D3D10/11
// calls, the GLSL and nvFX spellings), in the compiler's names.
std::optional<ShaderStage> stage_of_state(std::string_view name) {
  const std::optional<PassStage> stage = shader_state_stage(name);
  if (!stage) return std::nullopt;
  switch (*stage) {
    case PassStage::vertex: return ShaderStage::vertex;
    case PassStage::pixel: return ShaderStage::fragment;
    case PassStage::geometry: return ShaderStage::geometry;
    case PassStage::hull: return ShaderStage::tess_control;
    case PassStage::domain: return ShaderStage::tess_evaluation;
    case PassStage::compute: return ShaderStage::compute;
  }
  return std::nullopt;
}

// Effect-only variable types: glslang has no such HLSL types (D3D9 texture objects,
// strings, shader objects). D3D10's `Texture2D` is real HLSL and stays.
bool is_effect_only_type(std::string_view type) {
  if (shader_type_stage(type)) return true;
  // D3D10 effects may declare views for the application to set; shaders never read them.
  for (std::string_view t : {"texture", "string", "stateblock", "RenderTargetView", "DepthStencilView"})
    if (iequals(type, t)) return true;
  for (std::string_view t : {"texture1D", "texture2D", "texture3D", "textureCUBE"})
    if (type == t) return true;
  return false;
}

// Types that are resources rather than constants (samplers, textures, buffers): their
// `register(s0)`/`register(t0)` becomes a binding, which glslang keeps per kind.
bool is_shader_object_type(std::string_view type) {
  for (std::string_view prefix :
       {"sampler", "texture", "buffer", "rwbuffer", "rwtexture", "byteaddressbuffer", "rwbyteaddressbuffer",
        "structuredbuffer", "rwstructuredbuffer", "appendstructuredbuffer", "consumestructuredbuffer"})
    if (type.size() >= prefix.size() && iequals(type.substr(0, prefix.size()), prefix)) return true;
  return false;
}

// Spells a constant expression as HLSL (compile-time arguments). False for what cannot be
// a compile-time argument (compile expressions, state blocks, asm).
bool spell(const ast::Expr* e, std::string& out) {
  if (!e) return false;
  auto list = [&](size_t from, const char* open, const char* close) {
    out += open;
    for (size_t i = from; i < e->args.size(); ++i) {
      if (i > from) out += ", ";
      if (!spell(e->args[i], out)) return false;
    }
    out += close;
    return true;
  };
  switch (e->kind) {
    case ast::ExprKind::int_literal:
    case ast::ExprKind::float_literal:
    case ast::ExprKind::identifier: out += e->text; return true;
    case ast::ExprKind::bool_literal: out += e->number != 0 ? "true" : "false"; return true;
    case ast::ExprKind::unary:
      out += "(" + e->text;
      if (e->args.empty() || !spell(e->args[0], out)) return false;
      out += ")";
      return true;
    case ast::ExprKind::binary:
      if (e->args.size() != 2) return false;
      out += "(";
      if (!spell(e->args[0], out)) return false;
      out += " " + e->text + " ";
      if (!spell(e->args[1], out)) return false;
      out += ")";
      return true;
    case ast::ExprKind::ternary:
      if (e->args.size() != 3) return false;
      out += "(";
      if (!spell(e->args[0], out)) return false;
      out += " ? ";
      if (!spell(e->args[1], out)) return false;
      out += " : ";
      if (!spell(e->args[2], out)) return false;
      out += ")";
      return true;
    case ast::ExprKind::call: out += e->text; return list(0, "(", ")");
    case ast::ExprKind::init_list: return list(0, "{", "}");
    case ast::ExprKind::cast:
      out += "((" + e->text + ")";
      if (e->args.empty() || !spell(e->args[0], out)) return false;
      out += ")";
      return true;
    case ast::ExprKind::member:
      if (e->args.empty() || !spell(e->args[0], out)) return false;
      out += "." + e->text;
      return true;
    case ast::ExprKind::index:
      if (e->args.size() != 2 || !spell(e->args[0], out)) return false;
      out += "[";
      if (!spell(e->args[1], out)) return false;
      out += "]";
      return true;
    case ast::ExprKind::string_literal: out += "\"" + e->text + "\""; return true;
    case ast::ExprKind::reference: out += "<" + e->text + ">"; return true;
    case ast::ExprKind::null: out += "NULL"; return true;
    case ast::ExprKind::compile: out += "compile " + e->text + " " + e->callee; return list(0, "(", ")");
    case ast::ExprKind::glsl_list: return list(0, "{", "}");
    case ast::ExprKind::asm_block: out += "asm { }"; return true;
    case ast::ExprKind::state_block: out += e->text + " { }"; return true;
  }
  return false;
}

// HLSL tokens joined with single spaces where the source had space: a one-line spelling,
// with the names glslang reserves renamed as in the unit's text.
std::string join_tokens(const std::vector<Token>& toks, ast::TokenSpan span) {
  std::string out;
  for (uint32_t i = span.first; i < span.last && i < toks.size(); ++i) {
    const Token& t = toks[i];
    const std::string safe = glslang_spelling(toks, i, span.last);
    const std::string_view text = safe.empty() ? t.text() : std::string_view(safe);
    if (!out.empty() && (t.leading_space() || (std::isalnum(static_cast<unsigned char>(out.back())) && !text.empty() &&
                                               std::isalnum(static_cast<unsigned char>(text[0])))))
      out.push_back(' ');
    out.append(text);
  }
  return out;
}

// "ps_2_a"/"ps_2_b" -> "ps_2_x" (glslang has one SM2 extended profile); lower case.
std::string normalize_profile(std::string_view profile) {
  std::string p = ascii_lower(profile);
  if (p.size() >= 6 && p[4] == '_' && (p[5] == 'a' || p[5] == 'b')) p[5] = 'x';
  return p;
}

}  // namespace detail

using namespace detail;

void EffectUnitBuilder::build() {
  for (const Token& t : toks_)
    if (t.loc.valid()) {
      u_.name_ = std::string(sm_.presumed(t.loc).file);
      break;
    }
  if (u_.name_.empty()) u_.name_ = "<effect>";
  index_declarations();
  linkage_ = detail::class_linkage(effect_);
  find_lowered_globals();
  respelled_ = detail::flat_initializer_spellings(toks_);
  respelled_.merge(detail::case_insensitive_type_spellings(toks_, u_.symbols_));
  respelled_.merge(detail::multisample_operator_spellings(toks_));
  respelled_.merge(detail::texture_noise_spellings(toks_, functions_));
  respelled_.merge(detail::untyped_sampler_spellings(toks_));
  respelled_.merge(detail::one_component_swizzle_spellings(toks_));
  respelled_.merge(detail::class_linkage_spellings(toks_, linkage_, functions_));
  respelled_.merge(detail::clip_distance_input_spellings(
      toks_, functions_, [&](std::string_view name) { return structure(name); }, clip_distance_rewritten_));
  respell_helper_uniforms();
  emit_hlsl();
  for (uint32_t i = 0; i < u_.decls_.size(); ++i) {
    for (const std::string& name : u_.decls_[i].names) u_.decls_by_name_[name].push_back(i);
    if (u_.decls_[i].always) u_.always_.push_back(i);
  }
  collect_glsl();
  collect_passes();
  mark_uncalled_functions();
  mark_dynamic_linkage();
  mark_clip_distance_inputs();
  if (effect_.front_end_failed) {
    // Its errors are reported; a partial tree or unchecked shader code never reaches glslang.
    for_each_stage([&](StageUnit& stage) {
      if (stage.kind != StageSourceKind::invalid) invalid(stage, "the effect has front-end errors");
    });
    u_.check_.reset();
    u_.front_end_failed_ = true;
  }
}

bool EffectUnitBuilder::carries_clip_distance(const ast::Variable& v, int depth) const {
  if (detail::is_clip_or_cull_distance(v.semantic)) return true;
  const ast::Struct* s = v.type.definition ? v.type.definition : structure(v.type.name);
  if (!s || depth > 8) return false;
  for (const ast::Variable& m : s->members)
    if (carries_clip_distance(m, depth + 1)) return true;
  return false;
}

void EffectUnitBuilder::mark_clip_distance_inputs() {
  auto check = [&](StageUnit& stage) {
    if (stage.kind != StageSourceKind::hlsl || stage.stage != ShaderStage::geometry) return;
    const ast::Function* f = entry_function(stage);
    if (!f || clip_distance_rewritten_.count(f)) return;
    for (const ast::Variable& p : f->params)
      if (!(p.storage & (ast::kOut | ast::kUniform)) && !p.array_dims.empty() && carries_clip_distance(p, 0)) {
        invalid(stage, "geometry shader '" + std::string(f->name) +
                           "' reads SV_ClipDistance/SV_CullDistance in its input '" + std::string(p.name) +
                           "', which glslang cannot compile (KhronosGroup/glslang#2392)");
        return;
      }
  };
  for_each_stage(check);
}

void EffectUnitBuilder::respell_helper_uniforms() {
  std::unordered_set<std::string_view> direct;  // `compile vs_2_0 F()`, `CompileShader(vs_4_0, F())`
  const size_t n = toks_.size();
  for (size_t i = 0; i + 4 < n; ++i) {
    if (toks_[i].is_identifier("compile") && toks_[i + 2].is(TokenKind::identifier) &&
        toks_[i + 3].is(TokenKind::l_paren) && toks_[i + 4].is(TokenKind::r_paren))
      direct.insert(toks_[i + 2].text());
    if (i + 6 < n && toks_[i].is_identifier("CompileShader") && toks_[i + 3].is(TokenKind::comma) &&
        toks_[i + 4].is(TokenKind::identifier) && toks_[i + 5].is(TokenKind::l_paren) &&
        toks_[i + 6].is(TokenKind::r_paren))
      direct.insert(toks_[i + 4].text());
  }
  for (const ast::Function* f : functions_) {
    if (f->body.empty() || direct.count(f->name)) continue;
    uint32_t open = f->tokens.first;
    while (open + 1 < f->tokens.last && !(toks_[open].is_identifier(f->name) && toks_[open + 1].is(TokenKind::l_paren)))
      ++open;
    const uint32_t close = matching_close(open + 1, f->tokens.last);
    for (uint32_t i = open + 1; i < close; ++i)
      if (toks_[i].is_identifier("uniform")) respelled_.insert_or_assign(i, std::string(" "));
  }
}

void EffectUnitBuilder::mark_dynamic_linkage() {
  std::unordered_map<std::string, std::vector<uint32_t>> reach;  // by entry: passes share shaders
  auto check = [&](StageUnit& stage) {
    if (stage.kind != StageSourceKind::hlsl) return;
    auto [it, fresh] = reach.try_emplace(stage.function);
    if (fresh) it->second = u_.reached_from({stage.function});
    for (uint32_t i : it->second)
      if (!u_.decls_[i].dynamic_linkage.empty()) {
        invalid(stage, "fx_5_0 dynamic linkage: '" + u_.decls_[i].names.front() + "' calls through " +
                           u_.decls_[i].dynamic_linkage +
                           ", which no class instance implements: declare an instance of a class that does");
        return;
      }
  };
  for_each_stage(check);
}

void EffectUnitBuilder::mark_uncalled_functions() {
  std::vector<std::string_view> entries;
  std::unordered_set<std::string_view> seen;  // passes share shaders
  const StageUnit* first = nullptr;
  auto add = [&](const StageUnit& stage) {
    if (stage.kind != StageSourceKind::hlsl) return;
    if (!first) first = &stage;
    if (seen.insert(stage.function).second) entries.push_back(stage.function);
  };
  for_each_stage(add);
  if (!first) return;  // nothing compiles: no unit to check the functions in
  // A texture shader (`string function = "F"` on a texture) and what it reaches compile in its
  // own fill unit (fx/compile/texture_fill_unit.h), whose errors leave the texture a stand-in:
  // D3DX compiles it apart from the passes too (tx_1_0), so they do not fail the passes.
  for (const ast::Variable* v : variables_)
    if (v->type.name.size() >= 7 && iequals(v->type.name.substr(0, 7), "texture"))
      for (const ast::Annotation& a : v->annotations)
        if (iequals(a.name, "function") && a.value && a.value->kind == ast::ExprKind::string_literal &&
            seen.insert(a.value->text).second)
          entries.push_back(a.value->text);
  std::vector<bool> reached(u_.decls_.size(), false);
  for (uint32_t i : u_.reached_from(entries)) reached[i] = true;
  const ast::Function* located = nullptr;
  for (size_t i = 0; i < reached.size(); ++i) {
    const EffectUnits::DeclText& d = u_.decls_[i];
    if (!d.function || reached[i] || d.stage_only || !d.dynamic_linkage.empty()) continue;
    if (std::find(u_.uncalled_.begin(), u_.uncalled_.end(), d.names.front()) == u_.uncalled_.end())
      u_.uncalled_.push_back(d.names.front());
    for (const ast::Function* f : functions_)
      if (!located && f->name == d.names.front()) located = f;
  }
  if (u_.uncalled_.empty()) return;
  // A fragment unit is the one where any function compiles (derivatives, clip); the profile's
  // shader model is the effect's first HLSL stage's, so its DX9 mode matches the code.
  StageUnit check;
  check.stage = ShaderStage::fragment;
  check.kind = StageSourceKind::hlsl;
  check.profile = first->profile;
  if (check.profile.size() > 2 && check.profile[1] == 's') check.profile.replace(0, 2, "ps");
  check.entry_point = "uncalled__fx";
  check.range = located ? located->name_range : first->range;
  u_.check_ = std::move(check);
}

void EffectUnitBuilder::index_declarations() {
  for (const ast::Decl& d : effect_.decls) {
    if (d.kind == ast::DeclKind::function) functions_.push_back(d.function), u_.symbols_.push_back(d.function->name);
    if (d.kind == ast::DeclKind::variable) variables_.push_back(d.variable), u_.symbols_.push_back(d.variable->name);
    if (d.kind == ast::DeclKind::glsl_block) glsl_names_.push_back(d.glsl_block->name);
    if (d.kind == ast::DeclKind::structure) u_.symbols_.push_back(d.structure->name);
    if (d.kind == ast::DeclKind::type_alias) u_.symbols_.push_back(d.type_alias->name);
    if (d.kind == ast::DeclKind::constant_buffer)
      for (const ast::Variable& m : d.constant_buffer->members) u_.symbols_.push_back(m.name);
  }
  std::sort(u_.symbols_.begin(), u_.symbols_.end());
  u_.symbols_.erase(std::unique(u_.symbols_.begin(), u_.symbols_.end()), u_.symbols_.end());
}

std::string spell_expression(const ast::Expr& e) {
  std::string out;
  spell(&e, out);
  return out;
}

EffectUnits::EffectUnits(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& sink,
                         EffectUnitOptions options)
    : options_(std::move(options)) {
  EffectUnitBuilder(*this, effect, sm, sink).build();
}

const EffectPass* EffectUnits::find(std::string_view technique, std::string_view pass) const {
  for (const EffectPass& p : passes_)
    if (p.technique == technique && p.pass == pass) return &p;
  return nullptr;
}

std::vector<uint32_t> EffectUnits::reached_from(const std::vector<std::string_view>& roots) const {
  std::vector<uint32_t> reached(always_);
  std::unordered_set<uint32_t> seen(always_.begin(), always_.end());
  std::vector<std::string_view> pending(roots);
  while (!pending.empty()) {
    std::string_view name = pending.back();
    pending.pop_back();
    // Every declaration of a name (each overload: glslang resolves the call).
    auto found = decls_by_name_.find(name);
    if (found == decls_by_name_.end()) continue;
    for (uint32_t i : found->second)
      if (seen.insert(i).second) {
        reached.push_back(i);
        pending.insert(pending.end(), decls_[i].refs.begin(), decls_[i].refs.end());
      }
  }
  std::sort(reached.begin(), reached.end());
  return reached;
}

std::string EffectUnits::initializations(const std::vector<uint32_t>& reached, uint32_t before) const {
  std::string out;
  for (uint32_t i : reached)
    if (i < before) out += decls_[i].initialization;
  return out;
}

std::string EffectUnits::code_for(const std::vector<uint32_t>& reached, std::string_view entry) const {
  std::string out;
  // What comes before the first declaration (the pre-release prelude) is in every unit.
  out.append(hlsl_, 0, decls_.empty() ? hlsl_.size() : decls_.front().begin);
  for (uint32_t i : reached) {
    const DeclText& d = decls_[i];
    if (d.prologue && !entry.empty() && d.function && d.names.front() == entry) {
      out.append(hlsl_, d.begin, d.prologue - d.begin);
      out += initializations(reached, i);
      out.append(hlsl_, d.prologue, d.end - d.prologue);
    } else {
      out.append(hlsl_, d.begin, d.end - d.begin);
    }
  }
  return out;
}

std::string EffectUnits::hlsl_code_for(std::string_view entry) const { return code_for(reached_from({entry}), entry); }

std::optional<TranslationUnit> EffectUnits::compute_unit(std::string_view function, std::string_view entry,
                                                         std::string_view entry_text) const {
  if (front_end_failed_ || !decls_by_name_.count(function)) return std::nullopt;
  TranslationUnit u;
  u.stage = ShaderStage::compute;
  u.language = ShaderLanguage::hlsl;
  u.profile = "cs_5_0";
  u.entry_point = std::string(entry);
  u.name = name_;
  u.source = hlsl_code_for(function);
  // tx_1_0's noise(), which the effect's code calls by this name (texture_noise.h).
  if (u.source.find(detail::kTextureNoise) != std::string::npos) u.source.insert(0, detail::texture_noise_definition());
  u.source += entry_text;
  return u;
}

std::optional<TranslationUnit> EffectUnits::unit(const StageUnit& stage) const {
  TranslationUnit u;
  u.stage = stage.stage;
  u.entry_point = stage.entry_point;
  u.name = name_;
  if (check_ && &stage == &*check_) {
    u.language = ShaderLanguage::hlsl;
    u.profile = normalize_profile(stage.profile);
    std::vector<std::string_view> roots(uncalled_.begin(), uncalled_.end());
    const std::vector<uint32_t> reached = reached_from(roots);
    u.source = code_for(reached);
    u.source += "void " + stage.entry_point + "() {\n" + initializations(reached, UINT32_MAX) + "}\n";
    return u;
  }
  if (stage.kind == StageSourceKind::hlsl) {
    u.language = ShaderLanguage::hlsl;
    u.profile = normalize_profile(stage.profile);
    // A compile-time argument may name a parameter (`compile vs_2_0 VS(g_NumBones)`): the
    // wrapper reads it, so the unit declares it too.
    std::vector<std::string> argument_names;
    for (const std::string& a : stage.arguments)
      for (size_t i = 0; i < a.size();) {
        if (!is_word_char(a[i])) {
          ++i;
          continue;
        }
        size_t end = i;
        while (end < a.size() && is_word_char(a[end])) ++end;
        if (!std::isdigit(static_cast<unsigned char>(a[i]))) argument_names.push_back(a.substr(i, end - i));
        i = end;
      }
    std::vector<std::string_view> roots{stage.function};
    roots.insert(roots.end(), argument_names.begin(), argument_names.end());
    u.source = code_for(reached_from(roots), stage.function);
    if (stage.entry_point != stage.function)  // a wrapper: compile-time arguments, D3D9 system values
      for (const Wrapper& w : wrappers_)
        if (w.function == stage.function && w.arguments == stage.arguments) u.source += w.text;
    return u;
  }
  if ((stage.kind == StageSourceKind::assembly || stage.kind == StageSourceKind::fixed_function) &&
      !stage.translated.empty()) {
    u.language = ShaderLanguage::hlsl;
    u.profile = stage.stage == ShaderStage::vertex ? "vs_3_0" : "ps_3_0";
    u.source = stage.translated;
    return u;
  }
  if (stage.kind != StageSourceKind::glsl) return std::nullopt;
  u.language = ShaderLanguage::glsl;
  u.profile = stage.profile;
  std::string version = "#version 450";
  std::string body;
  for (const std::string& name : stage.glsl_blocks)
    for (const GlslBlockText& b : glsl_blocks_)
      if (b.name == name) {
        if (&name == &stage.glsl_blocks.front() && !b.version.empty()) version = b.version;
        body += b.body;
      }
  u.source = version + "\n#extension GL_GOOGLE_cpp_style_line_directive : require\n" + body;
  return u;
}

}  // namespace fx
