// Stream output: ConstructGSWithSO's declarations read, and the capture patched into SPIR-V.
#include "fx/compile/stream_output.h"

#include <algorithm>

#include "fx/compile/program_link.h"
#include "spirv_words.h"

namespace fx {
namespace {

// fx_5_0's rasterized stream: `0`, `-1` (none).
std::optional<int32_t> stream_number(const ast::Expr& e) {
  if (e.kind == ast::ExprKind::int_literal) return int32_t(e.number);
  if (e.kind == ast::ExprKind::unary && e.text == "-" && e.args.size() == 1 && e.args[0] &&
      e.args[0]->kind == ast::ExprKind::int_literal)
    return -int32_t(e.args[0]->number);
  return std::nullopt;
}

std::string entry_text(const StreamOutEntry& e) {
  std::string s = e.semantic;
  if (e.semantic_index) s += std::to_string(e.semantic_index);
  return s;
}

}  // namespace

StreamOutputDecl stream_output_decl(const ast::Expr& construct, const SourceManager& sm) {
  StreamOutputDecl decl;
  decl.range = construct.range;
  for (size_t i = 1; i < construct.args.size(); ++i) {
    const ast::Expr* arg = construct.args[i];
    if (!arg) continue;
    if (std::optional<int32_t> n = stream_number(*arg)) {
      decl.rasterized_stream = *n;
      continue;
    }
    if (arg->kind != ast::ExprKind::string_literal) continue;
    const std::string_view text = arg->text;
    for (const StreamOutEntry& e : parse_stream_out_decl(text).entries)
      decl.entries.push_back({e, uint32_t(i - 1), stream_out_text_range(sm, arg->range, text, e.offset, e.length)});
  }
  return decl;
}

std::optional<StreamOutputLayout> capture_stream_output(CompiledShader& shader, const StreamOutputDecl& decl,
                                                        DiagnosticSink& sink) {
  constexpr const char* kId = "unsupported-stream-output-decl";
  const std::string stage = to_string(shader.reflection.stage);
  bool ok = true;
  StreamOutputLayout layout;
  // What Vulkan or glslang cannot capture as declared: the pass compiles (fxc accepts it) and
  // is refused at run time.
  const auto refuse = [&](const char* id, SourceRange range, const std::string& message) {
    sink.warning(id, range, message);
    if (layout.unsupported.empty()) layout.unsupported = message, layout.unsupported_range = range;
  };
  const auto one_stream = [&](SourceRange range, const std::string& what) {
    refuse("unsupported-stream-output-stream", range,
           what + ": the shader writes stream 0 only (glslang's HLSL front end has one output stream)");
  };
  if (decl.rasterized_stream > 0) one_stream(decl.range, "rasterized stream " + std::to_string(decl.rasterized_stream));
  layout.rasterized = decl.rasterized_stream >= 0;
  std::array<uint32_t, kStreamOutSlots> offsets{};
  std::array<bool, kStreamOutSlots> used{};
  std::vector<spirv::XfbOutput> captures;
  for (const StreamOutputEntry& item : decl.entries) {
    const StreamOutEntry& e = item.entry;
    used[e.slot] = true;
    if (item.stream != 0) {
      one_stream(item.range, "stream " + std::to_string(item.stream) + "'s declaration");
      continue;
    }
    if (e.semantic.empty()) {  // $SKIP: a gap the capture leaves as it was
      offsets[e.slot] += 4 * e.component_count;
      continue;
    }
    const std::string name = entry_text(e);
    const std::string wanted = canonical_semantic(name);
    std::optional<uint32_t> location;
    uint32_t components = 0;
    ScalarKind scalar = ScalarKind::float32;
    bool found = false;
    for (const InterfaceVariable& out : shader.reflection.outputs)
      if (!out.semantic.empty() && canonical_semantic(out.semantic) == wanted) {
        const ReflectedType& t = out.type;
        if (t.rows != 1 || t.array_size || t.is_struct ||
            (t.scalar != ScalarKind::float32 && t.scalar != ScalarKind::int32 && t.scalar != ScalarKind::uint32)) {
          sink.error(kId, item.range,
                     "'" + name + "' is a " + t.glsl_name +
                         ": only 32-bit scalars and vectors are captured, one output variable each");
          ok = false;
        }
        location = out.location, components = t.columns, scalar = t.scalar, found = true;
      }
    // SV_Position (and a Direct3D 9 POSITION output) is the stage's position builtin.
    if (!found && (wanted == "SV_POSITION0" || wanted == "POSITION0")) components = 4, found = true;
    if (!found) {
      sink.error(kId, item.range, "the " + stage + " shader writes no output '" + name + "' to capture");
      ok = false;
      continue;
    }
    if (e.masked && (e.start_component != 0 || e.component_count != components)) {
      refuse("unsupported-stream-output-mask", item.range,
             "'" + name + "' is captured whole: Vulkan captures output variables, not components, and this " +
                 "mask names " + std::to_string(e.component_count) + " of its " + std::to_string(components) +
                 " components, starting at component " + std::to_string(e.start_component) +
                 "; write all of them (or none)");
      continue;
    }
    layout.outputs.push_back({name, e.slot, offsets[e.slot], components, scalar});
    captures.push_back({location, e.slot, offsets[e.slot], 0});
    offsets[e.slot] += 4 * components;
  }
  if (!ok) return std::nullopt;
  for (uint32_t slot = 0; slot < kStreamOutSlots; ++slot) layout.strides[slot] = used[slot] ? offsets[slot] : 0;
  for (spirv::XfbOutput& c : captures) c.stride = layout.strides[c.buffer];
  if (!spirv::decorate_transform_feedback(shader.spirv, captures)) {
    sink.error(kId, decl.range,
               "the " + stage + " shader's position is a member of an output block, which fxkit cannot capture");
    return std::nullopt;
  }
  return layout;
}

}  // namespace fx
