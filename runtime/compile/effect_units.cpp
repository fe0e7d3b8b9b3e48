#include "fx/compile/effect_units.h"

#include <algorithm>
#include <cctype>
#include <optional>

#include "effect_shader_text.h"
#include "lvalue_constructor.h"
#include "fx/ascii_case.h"
#include "fx/compile/hlsl_compat.h"
#include "fx/state_table.h"

namespace fx {

const char* to_string(StageSourceKind kind) {
  switch (kind) {
    case StageSourceKind::hlsl: return "hlsl";
    case StageSourceKind::glsl: return "glsl";
    case StageSourceKind::assembly: return "assembly";
    case StageSourceKind::invalid: return "invalid";
  }
  return "unknown";
}

const StageUnit* EffectPass::find(ShaderStage stage) const {
  for (const StageUnit& s : stages)
    if (s.stage == stage) return &s;
  return nullptr;
}

namespace {

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
  for (std::string_view prefix : {"sampler", "texture", "buffer", "rwbuffer", "rwtexture", "byteaddressbuffer",
                                  "rwbyteaddressbuffer", "structuredbuffer", "rwstructuredbuffer",
                                  "appendstructuredbuffer", "consumestructuredbuffer"})
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
    std::string safe;
    if (t.is(TokenKind::identifier))
      safe = detail::glslang_safe_name(t.text(), i + 1 < span.last && toks[i + 1].is(TokenKind::identifier));
    const std::string_view text = safe.empty() ? t.text() : std::string_view(safe);
    if (!out.empty() && (t.leading_space() || (std::isalnum(static_cast<unsigned char>(out.back())) &&
                                               !text.empty() && std::isalnum(static_cast<unsigned char>(text[0])))))
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

}  // namespace

// Builds EffectUnits from the AST: the shared HLSL text, the GLSL blocks and the passes.
class EffectUnitBuilder {
 public:
  EffectUnitBuilder(EffectUnits& units, const ast::Effect& effect, const SourceManager& sm,
                    DiagnosticSink& sink)
      : u_(units), effect_(effect), toks_(effect.tokens), sm_(sm), sink_(sink) {}

  void build() {
    for (const Token& t : toks_)
      if (t.loc.valid()) {
        u_.name_ = std::string(sm_.presumed(t.loc).file);
        break;
      }
    if (u_.name_.empty()) u_.name_ = "<effect>";
    index_declarations();
    emit_hlsl();
    collect_glsl();
    collect_passes();
    mark_uncalled_functions();
    mark_dynamic_linkage();
  }

  // A stage whose code calls through an interface needs the class bound to each instance
  // per pass (BindInterfaces), which fxkit does not compile: the stage says so, at the pass
  // state, instead of glslang's parse error on `interface`.
  void mark_dynamic_linkage() {
    auto check = [&](StageUnit& stage) {
      if (stage.kind != StageSourceKind::hlsl) return;
      std::vector<bool> r = u_.reached_from(stage.function);
      for (size_t i = 0; i < r.size(); ++i)
        if (r[i] && !u_.functions_[i].dynamic_linkage.empty()) {
          invalid(stage, "fx_5_0 dynamic linkage: '" + u_.functions_[i].name + "' uses " +
                             u_.functions_[i].dynamic_linkage + ", and fxkit does not compile interfaces to SPIR-V");
          return;
        }
    };
    for (EffectPass& pass : u_.passes_)
      for (StageUnit& stage : pass.stages) {
        check(stage);
        for (StageUnit& choice : stage.choices) check(choice);
      }
  }

  // Functions that no HLSL stage of any pass reaches go into every unit (see hlsl_code_for),
  // unless they cannot compile in any (stream or patch parameters, interfaces).
  void mark_uncalled_functions() {
    std::vector<bool> reached(u_.functions_.size(), false);
    auto reach = [&](const StageUnit& stage) {
      if (stage.kind != StageSourceKind::hlsl) return;
      std::vector<bool> r = u_.reached_from(stage.function);
      for (size_t i = 0; i < r.size(); ++i) reached[i] = reached[i] || r[i];
    };
    for (const EffectPass& pass : u_.passes_)
      for (const StageUnit& stage : pass.stages) {
        reach(stage);
        for (const StageUnit& choice : stage.choices) reach(choice);
      }
    for (size_t i = 0; i < reached.size(); ++i)
      u_.functions_[i].in_every_unit =
          !reached[i] && !u_.functions_[i].stage_only && u_.functions_[i].dynamic_linkage.empty();
  }

 private:
  void index_declarations() {
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

  // ---- HLSL ----------------------------------------------------------------------------

  void emit_hlsl() {
    detail::ShaderTextWriter w(sm_);
    u_.pre_release_ = !effect_.profile_header.empty();
    if (u_.pre_release_) w.out() += pre_release_hlsl_prelude();
    uint32_t last_span = UINT32_MAX;
    for (const ast::Decl& d : effect_.decls) {
      switch (d.kind) {
        case ast::DeclKind::variable: {
          const ast::Variable& v = *d.variable;
          // An interface instance is bound per pass (BindInterfaces): no shader declaration.
          if (std::find(interfaces_.begin(), interfaces_.end(), std::string_view(v.type.name)) != interfaces_.end()) {
            interface_instances_.push_back(v.name);
            break;
          }
          if (v.tokens.first == last_span || v.tokens.empty()) break;  // declarators share a span
          last_span = v.tokens.first;
          if (!is_effect_only_type(v.type.name)) emit_filtered(w, v.tokens, !is_shader_object_type(v.type.name));
          break;
        }
        case ast::DeclKind::type_alias:
          if (d.type_alias->tokens.first == last_span) break;
          last_span = d.type_alias->tokens.first;
          emit_tokens(w, d.type_alias->tokens);
          break;
        case ast::DeclKind::structure: emit_structure(w, *d.structure); break;
        case ast::DeclKind::function: emit_function(w, *d.function); break;
        case ast::DeclKind::constant_buffer: emit_filtered(w, d.constant_buffer->tokens); break;
        case ast::DeclKind::state_object: emit_sampler_object(w, *d.state_object); break;
        case ast::DeclKind::directive:
          // #version/#extension belong to GLSL; HLSL gets the #pragma lines (pack_matrix, ...).
          if (d.directive->text.rfind("#pragma", 0) == 0) emit_tokens(w, d.directive->tokens);
          break;
        case ast::DeclKind::technique:
        case ast::DeclKind::group:
        case ast::DeclKind::glsl_block: break;
      }
    }
    w.end_line();
    u_.hlsl_ = std::move(w.out());
    for (const ast::Decl& d : effect_.decls) {
      ast::TokenSpan span = d.kind == ast::DeclKind::variable          ? d.variable->tokens
                            : d.kind == ast::DeclKind::structure       ? d.structure->tokens
                            : d.kind == ast::DeclKind::constant_buffer ? d.constant_buffer->tokens
                                                                        : ast::TokenSpan{};
      for (std::string& name : calls_in(span)) u_.called_outside_functions_.push_back(std::move(name));
    }
  }

  // fx_5_0 dynamic linkage: glslang has no interfaces, so an interface declaration is left
  // out, and a class is written as the struct with methods it otherwise is (`class C : I {`
  // -> `struct C {`). Functions that use an interface fail their stages (see
  // mark_dynamic_linkage).
  void emit_structure(detail::ShaderTextWriter& w, const ast::Struct& s) {
    if (s.kind == ast::StructKind::interface_type) {
      interfaces_.push_back(s.name);
      return;
    }
    if (s.kind == ast::StructKind::structure) return emit_tokens(w, s.tokens);
    bool in_bases = false, body = false;
    for (uint32_t i = s.tokens.first; i < s.tokens.last && i < toks_.size(); ++i) {
      const Token& t = toks_[i];
      if (i == s.tokens.first && t.is(TokenKind::identifier)) {
        w.token(t, "struct");
        continue;
      }
      if (!body && t.is(TokenKind::colon)) in_bases = true;
      if (t.is(TokenKind::l_brace)) body = true, in_bases = false;
      if (!in_bases) put_hlsl(w, i, s.tokens.last);
    }
  }

  // The first interface or interface instance a function's tokens name ("" for none).
  std::string dynamic_linkage_in(ast::TokenSpan span) const {
    for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
      if (!toks_[i].is(TokenKind::identifier)) continue;
      const std::string_view word = toks_[i].text();
      for (const std::string& name : interfaces_)
        if (word == name) return "interface '" + name + "'";
      for (const std::string& name : interface_instances_)
        if (word == name) return "interface instance '" + name + "'";
    }
    return {};
  }

  // A function as a range of the text that can be left out: it starts with its own #line,
  // and what follows it starts with one too.
  void emit_function(detail::ShaderTextWriter& w, const ast::Function& f) {
    w.end_line();
    w.desync();
    EffectUnits::FunctionText text;
    text.name = f.name;
    text.begin = w.out().size();
    emit_function_tokens(w, f.tokens);
    w.end_line();
    w.desync();
    text.end = w.out().size();
    text.calls = calls_in(f.tokens);
    text.dynamic_linkage = dynamic_linkage_in(f.tokens);
    for (const ast::Variable& param : f.params)
      for (std::string_view t : {"PointStream", "LineStream", "TriangleStream", "InputPatch", "OutputPatch"})
        text.stage_only = text.stage_only || param.type.name == t;
    u_.functions_.push_back(std::move(text));
  }

  // A function's tokens, with fxc's assignments to constructors of l-values written as a
  // temporary and one assignment per part (`{ float4 t = v; a = t.xy; b = t.zw; }`).
  void emit_function_tokens(detail::ShaderTextWriter& w, ast::TokenSpan span) {
    std::vector<detail::LvalueConstructor> rewrites = detail::find_lvalue_constructors(toks_, span);
    auto next = rewrites.begin();
    for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
      if (next == rewrites.end() || i < next->type) {
        put_hlsl(w, i, span.last);
      } else if (i == next->type) {
        w.token(toks_[i], "{ " + std::string(toks_[i].text()) + " " + next->temporary);
      } else if (i < next->equal) {
        w.token(toks_[i], " ");  // the constructor's parts, assigned after the value
      } else if (i < next->semi) {
        put_hlsl(w, i, span.last);
      } else {
        w.token(toks_[i], ";" + next->assignments + " }");
        ++next;
      }
    }
  }

  // The names called in a span: identifiers followed by `(` (constructors and intrinsics
  // too, which name no function of the effect and so reach nothing).
  std::vector<std::string> calls_in(ast::TokenSpan span) const {
    std::vector<std::string> out;
    for (uint32_t i = span.first; i + 1 < span.last && i + 1 < toks_.size(); ++i)
      if (toks_[i].is(TokenKind::identifier) && toks_[i + 1].is(TokenKind::l_paren)) {
        std::string name(toks_[i].text());
        if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(std::move(name));
      }
    return out;
  }

  // Writes the token at `i` as HLSL: a name glslang reserves is renamed (reflection maps
  // it back).
  void put_hlsl(detail::ShaderTextWriter& w, uint32_t i, uint32_t last) {
    const Token& t = toks_[i];
    if (!t.is(TokenKind::identifier)) return w.token(t);
    bool identifier_follows = i + 1 < last && toks_[i + 1].is(TokenKind::identifier);
    std::string safe = detail::glslang_safe_name(t.text(), identifier_follows);
    w.token(t, safe);
  }

  void emit_tokens(detail::ShaderTextWriter& w, ast::TokenSpan span) {
    for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) put_hlsl(w, i, span.last);
  }

  // The index of the `>` closing an annotation opened at `open`, or 0 when the `<` is not an
  // annotation (a template argument such as Texture2D<float4> never contains a ';').
  uint32_t annotation_end(uint32_t open, uint32_t last) const {
    bool semi = false;
    int depth = 0;
    for (uint32_t i = open + 1; i < last; ++i) {
      const Token& t = toks_[i];
      if (t.is(TokenKind::l_brace) || t.is(TokenKind::l_paren)) ++depth;
      if (t.is(TokenKind::r_brace) || t.is(TokenKind::r_paren)) --depth;
      if (t.is(TokenKind::semi)) semi = true;
      if (t.is(TokenKind::greater) && depth == 0) return semi || i == open + 1 ? i : 0;
    }
    return 0;
  }

  // The index of the token closing the bracket at `open` (or `last` if unbalanced).
  uint32_t matching_close(uint32_t open, uint32_t last) const {
    int depth = 0;
    for (uint32_t i = open; i < last; ++i) {
      TokenKind k = toks_[i].kind;
      if (k == TokenKind::l_brace || k == TokenKind::l_paren || k == TokenKind::l_square) ++depth;
      if (k == TokenKind::r_brace || k == TokenKind::r_paren || k == TokenKind::r_square) --depth;
      if (depth == 0) return i;
    }
    return last;
  }

  // The index of the `)` closing a `: register(...)` that starts at the `:` at `colon`, or
  // 0 when no register binding starts there.
  uint32_t register_end(uint32_t colon, uint32_t last) const {
    if (colon + 2 >= last || !toks_[colon + 1].is_identifier("register") || !toks_[colon + 2].is(TokenKind::l_paren))
      return 0;
    uint32_t close = matching_close(colon + 2, last);
    return close < last ? close : 0;
  }

  // A global or cbuffer declaration without its effect-only parts: annotations,
  // `= sampler_state { }` initializers and cbuffer member initializers (which glslang
  // ignores with a warning; the effect model keeps them as defaults). With
  // `drop_constant_registers`, a global constant's `: register(c0)` / `register(vs, c0)` goes
  // too: D3D9 assigns constant registers per shader profile, so two constants may share c0
  // (one for vs, one for ps), and glslang would turn both into the same offset of one
  // $Global block, which SPIR-V validation rejects. Parameters are matched by name, so
  // glslang's own packing loses nothing.
  void emit_filtered(detail::ShaderTextWriter& w, ast::TokenSpan span, bool drop_constant_registers = false) {
    int depth = 0, init_depth = -1;
    for (uint32_t i = span.first; i < span.last && i < toks_.size(); ++i) {
      const Token& t = toks_[i];
      bool in_init = init_depth >= 0;
      if (drop_constant_registers && !in_init && depth == 0 && t.is(TokenKind::colon)) {
        if (uint32_t end = register_end(i, span.last)) {
          i = end;
          continue;
        }
      }
      if (!in_init && t.is(TokenKind::less)) {
        if (uint32_t end = annotation_end(i, span.last)) {
          i = end;
          continue;
        }
      }
      if (!in_init && t.is(TokenKind::equal)) {
        const Token* next = i + 1 < span.last ? &toks_[i + 1] : nullptr;
        if (next && next->is(TokenKind::identifier) &&
            (iequals(next->text(), "sampler_state") || iequals(next->text(), "stateblock_state"))) {
          uint32_t open = i + 2;
          i = open < span.last && toks_[open].is(TokenKind::l_brace) ? matching_close(open, span.last) : i + 1;
          continue;
        }
        // `sampler s[2] = { sampler_state {...}, sampler_state {...} };`: an array of them.
        if (next && next->is(TokenKind::l_brace) && i + 2 < span.last && toks_[i + 2].is(TokenKind::identifier) &&
            iequals(toks_[i + 2].text(), "sampler_state")) {
          i = matching_close(i + 1, span.last);
          continue;
        }
        if (depth > 0) {  // cbuffer member initializer: skip to its ';'
          int d = 0;
          uint32_t j = i + 1;
          for (; j < span.last; ++j) {
            TokenKind k = toks_[j].kind;
            if (k == TokenKind::l_brace || k == TokenKind::l_paren || k == TokenKind::l_square) ++d;
            if (k == TokenKind::r_brace || k == TokenKind::r_paren || k == TokenKind::r_square) --d;
            if (d == 0 && k == TokenKind::semi) break;
          }
          i = j - 1;
          continue;
        }
        init_depth = depth;
      }
      if (t.is(TokenKind::l_brace) || t.is(TokenKind::l_paren) || t.is(TokenKind::l_square)) ++depth;
      if (t.is(TokenKind::r_brace) || t.is(TokenKind::r_paren) || t.is(TokenKind::r_square)) --depth;
      if ((t.is(TokenKind::semi) || t.is(TokenKind::comma)) && depth == init_depth) init_depth = -1;
      if (t.is(TokenKind::l_brace) && !in_init) init_depth = -1;
      put_hlsl(w, i, span.last);
    }
  }

  // D3D10 `SamplerState s { Filter = ...; };` -> `SamplerState s;` (the states are ours).
  void emit_sampler_object(detail::ShaderTextWriter& w, const ast::StateObject& so) {
    if (!iequals(so.kind, "SamplerState") && !iequals(so.kind, "SamplerComparisonState")) return;
    std::string text = so.kind + " " + so.name;
    for (const ast::ExprPtr& dim : so.array_dims) {
      text += "[";
      if (dim) spell(dim, text);
      text += "]";
    }
    if (!so.register_binding.empty()) text += " : register(" + so.register_binding + ")";
    PresumedLocation p = sm_.presumed(so.name_range.begin);
    if (p.valid()) w.line(detail::line_directive(p.line, p.file));
    w.line(text + ";");
  }

  // ---- GLSL ----------------------------------------------------------------------------

  void collect_glsl() {
    for (const ast::Decl& d : effect_.decls) {
      if (d.kind != ast::DeclKind::glsl_block) continue;
      const ast::GlslBlock& b = *d.glsl_block;
      EffectUnits::GlslBlockText text;
      text.name = b.name;
      ast::TokenSpan code = b.code;
      if (!code.empty() && toks_[code.first].is(TokenKind::directive) &&
          toks_[code.first].text().rfind("#version", 0) == 0) {
        text.version = std::string(toks_[code.first].text());
        ++code.first;
      } else if (code.last - code.first >= 3 && toks_[code.first].is(TokenKind::hash) &&
                 toks_[code.first + 1].is_identifier("version") &&
                 toks_[code.first + 2].is(TokenKind::integer)) {
        // `GLSLShader X { #version 450` : not at a line start, so the preprocessor left it as
        // tokens; a profile word (`core`, `es`) may follow on the same line.
        text.version = "#version " + std::string(toks_[code.first + 2].text());
        code.first += 3;
        PresumedLocation at = sm_.presumed(toks_[code.first - 1].loc);
        while (code.first < code.last && toks_[code.first].is(TokenKind::identifier) &&
               sm_.presumed(toks_[code.first].loc).line == at.line)
          text.version += " " + std::string(toks_[code.first++].text());
      }
      detail::ShaderTextWriter w(sm_);
      for (uint32_t i = code.first; i < code.last && i < toks_.size(); ++i) w.token(toks_[i]);
      w.end_line();
      text.body = std::move(w.out());
      u_.glsl_blocks_.push_back(std::move(text));
    }
  }

  // ---- passes --------------------------------------------------------------------------

  void collect_passes() {
    uint32_t technique_index = 0;
    for (const ast::Decl& d : effect_.decls) {
      if (d.kind == ast::DeclKind::technique) add_technique(*d.technique, "", technique_index++);
      if (d.kind == ast::DeclKind::group)
        for (const ast::Technique& t : d.group->techniques) add_technique(t, d.group->name, technique_index++);
    }
  }

  void add_technique(const ast::Technique& t, const std::string& group, uint32_t index) {
    uint32_t pass_index = 0;
    for (const ast::Pass& p : t.passes) {
      EffectPass pass;
      pass.group = group;
      pass.technique = t.name.empty() ? "technique" + std::to_string(index) : t.name;
      pass.pass = p.name.empty() ? "pass" + std::to_string(pass_index) : p.name;
      pass.technique_index = index;
      pass.pass_index = pass_index++;
      pass.range = p.range;
      bool null_pixel = false;
      for (const ast::StateAssignment& s : p.states) {
        std::optional<ShaderStage> stage = stage_of_state(s.name);
        if (!stage || !s.value) continue;
        StageUnit ps;
        ps.stage = *stage;
        ps.range = s.range;
        const ast::Expr* value = s.value;
        if (s.call_style) value = value->args.empty() ? nullptr : value->args[0];
        if (!value || !resolve(*value, ps, 0)) {
          null_pixel = null_pixel || *stage == ShaderStage::fragment;
          continue;
        }
        // `SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), "..."))`: stream
        // output straight from a vertex shader, with no geometry stage. It is that pass's
        // vertex shader unless the pass sets one itself.
        if (ps.stage == ShaderStage::geometry && ps.kind == StageSourceKind::hlsl &&
            ascii_lower(ps.profile).rfind("vs_", 0) == 0) {
          if (pass.find(ShaderStage::vertex)) continue;
          ps.stage = ShaderStage::vertex;
        }
        // A later assignment of the same stage wins, as in D3D.
        std::erase_if(pass.stages, [&](const StageUnit& o) { return o.stage == ps.stage; });
        pass.stages.push_back(std::move(ps));
      }
      std::stable_sort(pass.stages.begin(), pass.stages.end(),
                       [](const StageUnit& a, const StageUnit& b) { return a.stage < b.stage; });
      add_fixed_function_reasons(t, pass, null_pixel);
      u_.passes_.push_back(std::move(pass));
    }
  }

  // D3D9 passes without a vertex or pixel shader use the fixed-function pipeline there.
  static void add_fixed_function_reasons(const ast::Technique& t, EffectPass& pass, bool null_pixel) {
    if (t.version != 9) return;  // technique10/11: no pixel shader means no fragment stage
    bool glsl = false, compute = false;
    for (const StageUnit& s : pass.stages) {
      glsl = glsl || s.kind == StageSourceKind::glsl;
      compute = compute || s.stage == ShaderStage::compute;
    }
    if (glsl || compute) return;
    if (!pass.find(ShaderStage::vertex))
      pass.unsupported.push_back("fixed-function vertex processing: the pass sets no VertexShader");
    if (!pass.find(ShaderStage::fragment))
      pass.unsupported.push_back(std::string("fixed-function pixel processing (texture stage states): ") +
                                 (null_pixel ? "PixelShader = NULL" : "the pass sets no PixelShader"));
  }

  const ast::Variable* shader_variable(std::string_view name) const {
    for (const ast::Variable* v : variables_)
      if (v->name == name && shader_type_stage(v->type.name)) return v;
    return nullptr;
  }

  // Fills `stage` from a shader value. False when the value names no shader (NULL).
  bool resolve(const ast::Expr& e, StageUnit& stage, int depth) {
    if (depth > 8) return invalid(stage, "shader variables refer to each other in a cycle");
    switch (e.kind) {
      case ast::ExprKind::null: return false;
      case ast::ExprKind::int_literal: return e.number != 0 && invalid(stage, "a number is not a shader");
      case ast::ExprKind::compile: {
        std::vector<const ast::Expr*> args;
        for (const ast::ExprPtr& a : e.args) args.push_back(a);
        return hlsl(stage, e.text, e.callee, args, e.range);
      }
      case ast::ExprKind::call: {
        if (iequals(e.text, "CompileShader") && e.args.size() == 2 && e.args[0] && e.args[1] &&
            e.args[1]->kind == ast::ExprKind::call) {
          std::vector<const ast::Expr*> args;
          for (const ast::ExprPtr& a : e.args[1]->args) args.push_back(a);
          return hlsl(stage, e.args[0]->text, e.args[1]->text, args, e.range);
        }
        // ConstructGSWithSO(shader, ...), BindInterfaces(shader, instances...), SetXShader(shader).
        if ((iequals(e.text, "ConstructGSWithSO") || iequals(e.text, "BindInterfaces") || stage_of_state(e.text)) &&
            !e.args.empty() && e.args[0])
          return resolve(*e.args[0], stage, depth + 1);
        return invalid(stage, "'" + e.text + "(...)' does not name a shader");
      }
      case ast::ExprKind::identifier:
      case ast::ExprKind::reference: {
        if (iequals(e.text, "NULL")) return false;
        for (const std::string& g : glsl_names_)
          if (g == e.text) return glsl(stage, {e.text});
        if (const ast::Variable* v = shader_variable(e.text)) {
          if (v->initializer) return resolve(*v->initializer, stage, depth + 1);
          return invalid(stage, "shader variable '" + e.text + "' has no initializer");
        }
        return invalid(stage, "'" + e.text + "' names no shader");
      }
      case ast::ExprKind::glsl_list: {
        std::vector<std::string> names;
        for (const ast::ExprPtr& a : e.args) names.push_back(a->text);
        return glsl(stage, std::move(names));
      }
      case ast::ExprKind::asm_block:
        stage.kind = StageSourceKind::assembly;
        stage.unsupported = "shader model 1 assembly (asm { }) is not compiled; the legacy path emulates it";
        return true;
      case ast::ExprKind::index: return shader_array(e, stage, depth);
      default: return invalid(stage, "the value does not name a shader");
    }
  }

  // `VSArray[VSIndices[ShaderIndex]]`: every element of a shader array becomes a choice,
  // the one the index selects with the initial parameter values the stage itself.
  bool shader_array(const ast::Expr& e, StageUnit& stage, int depth) {
    const ast::Expr* base = e.args.size() == 2 ? e.args[0] : nullptr;
    const ast::Variable* array =
        base && (base->kind == ast::ExprKind::identifier || base->kind == ast::ExprKind::reference)
            ? shader_variable(base->text)
            : nullptr;
    if (!array || array->array_dims.empty() || !array->initializer ||
        array->initializer->kind != ast::ExprKind::init_list)
      return invalid(stage, "an indexed shader must be an element of a shader array with an initializer");
    std::vector<StageUnit> choices;
    for (const ast::ExprPtr& element : array->initializer->args) {
      StageUnit c;
      c.stage = stage.stage;
      c.range = element ? element->range : stage.range;
      if (!element || !resolve(*element, c, depth + 1)) invalid(c, "the array element is NULL");
      choices.push_back(std::move(c));
    }
    if (choices.empty()) return invalid(stage, "the shader array '" + base->text + "' is empty");
    std::optional<int64_t> index = initial_value(*e.args[1], 0);
    size_t choice = index && *index >= 0 && static_cast<size_t>(*index) < choices.size() ? static_cast<size_t>(*index) : 0;
    SourceRange range = stage.range;
    stage = choices[choice];
    stage.range = range;
    stage.choice = choice;
    spell(e.args[1], stage.selector);
    stage.choices = std::move(choices);
    return true;
  }

  // An integer expression's value with every parameter at its initial value: literals,
  // parameters and elements of parameter arrays (`VSIndices[ShaderIndex]`). nullopt when it
  // depends on anything else.
  std::optional<int64_t> initial_value(const ast::Expr& e, int depth) const {
    if (depth > 8) return std::nullopt;
    auto variable = [&](std::string_view name) -> const ast::Variable* {
      for (const ast::Variable* v : variables_)
        if (v->name == name && v->initializer) return v;
      return nullptr;
    };
    switch (e.kind) {
      case ast::ExprKind::int_literal:
      case ast::ExprKind::float_literal: return static_cast<int64_t>(e.number);
      case ast::ExprKind::identifier:
      case ast::ExprKind::reference:
        if (const ast::Variable* v = variable(e.text); v && v->array_dims.empty())
          return initial_value(*v->initializer, depth + 1);
        return std::nullopt;
      case ast::ExprKind::index: {
        if (e.args.size() != 2 || !e.args[0] || !e.args[1]) return std::nullopt;
        const ast::Variable* v = variable(e.args[0]->text);
        std::optional<int64_t> i = initial_value(*e.args[1], depth + 1);
        if (!v || !i || v->initializer->kind != ast::ExprKind::init_list || *i < 0 ||
            static_cast<size_t>(*i) >= v->initializer->args.size() || !v->initializer->args[*i])
          return std::nullopt;
        return initial_value(*v->initializer->args[*i], depth + 1);
      }
      default: return std::nullopt;
    }
  }

  static bool invalid(StageUnit& stage, std::string reason) {
    stage.kind = StageSourceKind::invalid;
    stage.unsupported = std::move(reason);
    return true;
  }

  bool glsl(StageUnit& stage, std::vector<std::string> names) {
    stage.kind = StageSourceKind::glsl;
    stage.entry_point = "main";
    for (const std::string& n : names) {
      bool known = false;
      for (const std::string& g : glsl_names_) known = known || g == n;
      // The checker reports unknown block names (undefined-reference).
      if (!known) return invalid(stage, "no GLSL block named '" + n + "'");
    }
    stage.glsl_blocks = std::move(names);
    stage.profile = "glsl";
    for (const EffectUnits::GlslBlockText& b : u_.glsl_blocks_)
      if (b.name == stage.glsl_blocks.front() && !b.version.empty()) {
        std::string digits;
        for (char c : b.version.substr(8))
          if (std::isdigit(static_cast<unsigned char>(c))) digits.push_back(c);
          else if (!digits.empty()) break;
        if (!digits.empty()) stage.profile = digits;
      }
    return true;
  }

  // The overload of `name` that takes `args` compile-time arguments (D3D picks the same way).
  const ast::Function* function(std::string_view name, size_t args) const {
    const ast::Function* first = nullptr;
    for (const ast::Function* f : functions_) {
      if (f->name != name || f->body.empty()) continue;
      size_t uniforms = 0;
      for (const ast::Variable& p : f->params) uniforms += (p.storage & ast::kUniform) != 0;
      if (uniforms == args) return f;
      if (!first && uniforms >= args) first = f;
    }
    return first;
  }

  bool hlsl(StageUnit& stage, const std::string& profile, const std::string& name,
            const std::vector<const ast::Expr*>& args, SourceRange range) {
    stage.kind = StageSourceKind::hlsl;
    stage.profile = profile;
    stage.function = name;
    stage.entry_point = name;
    const ast::Function* f = function(name, args.size());
    // The checker reports unknown functions (undefined-reference).
    if (!f) return invalid(stage, "no shader function '" + name + "' with a body");
    if (args.empty()) return true;
    size_t uniforms = 0;
    for (const ast::Variable& p : f->params) uniforms += (p.storage & ast::kUniform) != 0;
    if (args.size() > uniforms) {
      sink_.error("effect-shader-arguments", range,
                  "'" + name + "' takes " + std::to_string(uniforms) + " uniform parameter(s), but " +
                      std::to_string(args.size()) + " compile-time argument(s) are given");
      return invalid(stage, "too many compile-time arguments");
    }
    for (const ast::Expr* a : args) {
      std::string text;
      if (!a || a->kind == ast::ExprKind::compile || a->kind == ast::ExprKind::asm_block ||
          a->kind == ast::ExprKind::state_block || !spell(a, text)) {
        sink_.error("effect-shader-argument", a ? a->range : range,
                    "a compile-time argument of '" + name + "' must be a constant expression");
        return invalid(stage, "a compile-time argument is not a constant expression");
      }
      stage.arguments.push_back(std::move(text));
    }
    stage.entry_point = name + "__fx_args";
    for (const EffectUnits::Wrapper& w : u_.wrappers_)
      if (w.function == name && w.arguments == stage.arguments) return true;
    u_.wrappers_.push_back({name, stage.arguments, wrapper(*f, stage.arguments)});
    return true;
  }

  // `R F__fx_args(varying params) : SEM { return F(varying..., literal...); }`, placed at the
  // function's own line so errors in the wrapper point at the function.
  std::string wrapper(const ast::Function& f, const std::vector<std::string>& args) const {
    std::string text;
    PresumedLocation at = sm_.presumed(f.name_range.begin);
    if (at.valid()) text += detail::line_directive(at.line, at.file) + "\n";
    for (const ast::Text& a : f.attributes) text += "[" + a + "] ";
    text += f.return_type.name;
    if (!f.return_type.template_arg.empty()) text += "<" + f.return_type.template_arg + ">";
    text += " " + f.name + "__fx_args(";
    std::string call = f.name + "(";
    size_t bound = 0;
    bool first_param = true;
    for (size_t i = 0; i < f.params.size(); ++i) {
      const ast::Variable& p = f.params[i];
      if (i) call += ", ";
      if ((p.storage & ast::kUniform) && bound < args.size()) {
        call += args[bound++];
        continue;
      }
      if (!first_param) text += ", ";
      first_param = false;
      text += join_tokens(toks_, p.tokens);
      std::string safe = detail::glslang_safe_name(p.name, false);
      call += safe.empty() ? std::string(p.name) : safe;
    }
    text += ")";
    if (!f.semantic.empty()) text += " : " + f.semantic;
    text += f.return_type.name == "void" ? " { " + call + "); }\n" : " { return " + call + "); }\n";
    return text;
  }

  EffectUnits& u_;
  const ast::Effect& effect_;
  const std::vector<Token>& toks_;
  const SourceManager& sm_;
  DiagnosticSink& sink_;
  std::vector<const ast::Function*> functions_;
  std::vector<const ast::Variable*> variables_;
  std::vector<std::string> glsl_names_;
  std::vector<std::string> interfaces_;           // fx_5_0 interface type names
  std::vector<std::string> interface_instances_;  // globals of an interface type
};

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

std::vector<bool> EffectUnits::reached_from(std::string_view entry) const {
  std::vector<bool> reached(functions_.size(), false);
  std::vector<std::string_view> pending(called_outside_functions_.begin(), called_outside_functions_.end());
  pending.push_back(entry);
  for (const FunctionText& f : functions_)
    if (f.in_every_unit) pending.push_back(f.name);
  while (!pending.empty()) {
    std::string_view name = pending.back();
    pending.pop_back();
    // Every overload of a name: glslang resolves the call.
    for (size_t i = 0; i < functions_.size(); ++i)
      if (!reached[i] && functions_[i].name == name) {
        reached[i] = true;
        pending.insert(pending.end(), functions_[i].calls.begin(), functions_[i].calls.end());
      }
  }
  return reached;
}

std::string EffectUnits::hlsl_code_for(std::string_view entry) const {
  std::vector<bool> reached = reached_from(entry);
  std::string out;
  out.reserve(hlsl_.size());
  size_t from = 0;
  for (size_t i = 0; i < functions_.size(); ++i) {
    if (reached[i]) continue;
    out.append(hlsl_, from, functions_[i].begin - from);
    from = functions_[i].end;
  }
  out.append(hlsl_, from, std::string::npos);
  return out;
}

std::optional<TranslationUnit> EffectUnits::unit(const StageUnit& stage) const {
  TranslationUnit u;
  u.stage = stage.stage;
  u.entry_point = stage.entry_point;
  u.defines = options_.defines;
  u.name = name_;
  if (stage.kind == StageSourceKind::hlsl) {
    u.language = ShaderLanguage::hlsl;
    u.profile = normalize_profile(stage.profile);
    u.source = hlsl_code_for(stage.function);
    if (!stage.arguments.empty())
      for (const Wrapper& w : wrappers_)
        if (w.function == stage.function && w.arguments == stage.arguments) u.source += w.text;
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
