// The fixed-function pixel shader: texture stages (every D3DTOP operation, argument
// modifiers, Temp and ResultArg, bump environment mapping), specular add, fog blend and the
// alpha test, generated as HLSL (entry fx_ff_ps). Formulas: docs/fixed-function.md.
#include <string>

#include "fixed_function_hlsl.h"
#include "fixed_function_stages.h"
#include "fx/emulation/fixed_function.h"

namespace fx {
namespace {

using ff_detail::active_stages;
using ff_detail::Declarations;
using ff_detail::is_bump;
using ff_detail::literal;
using ff_detail::reads_register;
using ff_detail::samples;
using ff_detail::uses_arg0;
using ff_detail::uses_arg1;
using ff_detail::uses_arg2;
namespace ta = texture_arg;

// The TEXCOORDn the pixel shader reads for stage `i`.
int texcoord_register(const FixedFunctionState& s, int i) {
  return s.vertex_shader ? static_cast<int>(s.stages[i].tex_coord_index & 0x7) : i;
}

bool table_fog(const FixedFunctionState& s) { return s.fog && s.fog_table_mode != FogMode::none; }

class PixelShaderWriter {
 public:
  explicit PixelShaderWriter(const FixedFunctionState& s) : s_(s), stages_(active_stages(s)), outputs_(outputs_of(s)) {}

  FixedFunctionShader write() {
    body_ += "  float4 fx_current = fx_diffuse;\n";
    body_ += "  float4 fx_temp = float4(0.0, 0.0, 0.0, 0.0);\n";
    body_ += "  float4 fx_tfactor = " + decl_.vector(s_.texture_factor) + ";\n";
    for (int i = 0; i < stages_; ++i)
      if (is_bump(s_.stages[i].color_op)) {
        body_ += "  float2 fx_bump = float2(0.0, 0.0);\n  float fx_luminance = 1.0;\n";
        break;
      }
    // Textures first (a stage may read the next one's: PreModulate), then the blending.
    for (int i = 0; i < stages_; ++i) texture(i);
    for (int i = 0; i < stages_; ++i) stage(i);
    if (s_.specular_enable) body_ += "  fx_current.rgb = saturate(fx_current.rgb + fx_specular.rgb);\n";
    if (s_.fog) fog();
    if (s_.alpha_test) alpha_test();
    body_ += "  return fx_current;\n";

    input("fx_diffuse", "COLOR0", outputs_.diffuse, "1.0, 1.0, 1.0, 1.0");
    input("fx_specular", "COLOR1", outputs_.specular, "0.0, 0.0, 0.0, 0.0");
    // An HLSL vertex shader's outputs are all read, used or not (Vulkan warns about an
    // output no stage reads).
    const bool exact = s_.vertex_shader_outputs.known;
    for (int t = 0; t < 8; ++t)
      if ((texcoords_ & (1u << t)) || (exact && outputs_.texcoords[t]))
        input("fx_tc" + std::to_string(t), "TEXCOORD" + std::to_string(t), outputs_.texcoords[t], "0.0, 0.0, 0.0, 1.0");
    const bool vertex_fog = s_.fog && !table_fog(s_);
    if (outputs_.fog && (vertex_fog || exact)) inputs_ += "  " + vector_type(outputs_.fog) + " fx_fog : FOG;\n";
    if (vertex_fog)
      prologue_ += std::string("  float fx_fog_in = ") +
                   (outputs_.fog == 0   ? "1.0"
                    : outputs_.fog == 1 ? "i.fx_fog"
                                        : "i.fx_fog.x") +
                   ";\n";
    if (table_fog(s_)) inputs_ += "  float4 fx_position : SV_Position;\n";
    // A pass with no input at all still needs a member: SV_Position is always there.
    if (inputs_.empty()) inputs_ = "  float4 fx_position : SV_Position;\n";

    FixedFunctionShader out;
    out.entry = "fx_ff_ps";
    out.profile = "ps_3_0";
    out.source = "// fxkit fixed-function pixel shader (generated)\n" + decl_.text() + "struct fx_ff_ps_in {\n" +
                 inputs_ + "};\nfloat4 fx_ff_ps(fx_ff_ps_in i) : COLOR0 {\n" + prologue_ + body_ + "}\n";
    return out;
  }

 private:
  static std::string vector_type(int components) {
    return components == 1 ? "float" : "float" + std::to_string(components);
  }

  // The float4 local `name` from the varying `semantic` the vertex stage writes with
  // `components` components: the rest, or all of it when it writes none, from `fallback`
  // (D3D's defaults for a register a vertex shader leaves unwritten).
  void input(const std::string& name, const std::string& semantic, int components, const std::string& fallback) {
    if (components == 0) {
      prologue_ += "  float4 " + name + " = float4(" + fallback + ");\n";
      return;
    }
    inputs_ += "  " + vector_type(components) + " " + name + " : " + semantic + ";\n";
    std::string value = "i." + name;
    if (components < 4) {
      size_t comma = 0;  // skip the fallback's first `components` values
      for (int c = 0; c < components; ++c) comma = fallback.find(',', comma) + 1;
      value = "float4(" + value + "," + fallback.substr(comma) + ")";
    }
    prologue_ += "  float4 " + name + " = " + value + ";\n";
  }

  // What the vertex stage writes: the exact outputs of an HLSL vertex shader, or D3D's full
  // register set (four components each) from assembly or the generated vertex stage.
  static FixedFunctionState::VertexShaderOutputs outputs_of(const FixedFunctionState& s) {
    if (s.vertex_shader_outputs.known) return s.vertex_shader_outputs;
    FixedFunctionState::VertexShaderOutputs all;
    all.diffuse = all.specular = 4;
    all.fog = 1;
    all.texcoords.fill(4);
    return all;
  }

  // An argument register with its modifiers, as float4.
  std::string arg(uint32_t a, int i) {
    std::string v;
    switch (a & ta::select_mask) {
      case ta::diffuse: v = "fx_diffuse"; break;
      case ta::current: v = "fx_current"; break;
      case ta::texture: v = "fx_tex" + std::to_string(i); break;
      case ta::tfactor: v = "fx_tfactor"; break;
      case ta::specular: v = "fx_specular"; break;
      case ta::temp: v = "fx_temp"; break;
      case ta::constant: v = decl_.vector(s_.stages[i].constant); break;
      default: v = "float4(0.0, 0.0, 0.0, 0.0)"; break;
    }
    if (a & ta::complement) v = "(1.0 - " + v + ")";
    if (a & ta::alpha_replicate) v = v + ".aaaa";
    return v;
  }

  // The operation on float4 arguments a0, a1, a2 (rgb used for colour, a for alpha).
  std::string op_expr(TextureOp op, int i) {
    const std::string n = std::to_string(i);
    const std::string tex_alpha = "fx_tex" + n + ".aaaa";
    switch (op) {
      case TextureOp::disable:
      case TextureOp::bump_env_map:
      case TextureOp::bump_env_map_luminance: return "fx_current";
      case TextureOp::select_arg1: return "fx_a1";
      case TextureOp::select_arg2: return "fx_a2";
      case TextureOp::modulate: return "fx_a1 * fx_a2";
      case TextureOp::modulate_2x: return "fx_a1 * fx_a2 * 2.0";
      case TextureOp::modulate_4x: return "fx_a1 * fx_a2 * 4.0";
      case TextureOp::add: return "fx_a1 + fx_a2";
      case TextureOp::add_signed: return "fx_a1 + fx_a2 - 0.5";
      case TextureOp::add_signed_2x: return "(fx_a1 + fx_a2 - 0.5) * 2.0";
      case TextureOp::subtract: return "fx_a1 - fx_a2";
      case TextureOp::add_smooth: return "fx_a1 + fx_a2 - fx_a1 * fx_a2";
      case TextureOp::blend_diffuse_alpha: return "lerp(fx_a2, fx_a1, fx_diffuse.aaaa)";
      case TextureOp::blend_texture_alpha: return "lerp(fx_a2, fx_a1, " + tex_alpha + ")";
      case TextureOp::blend_factor_alpha: return "lerp(fx_a2, fx_a1, fx_tfactor.aaaa)";
      case TextureOp::blend_texture_alpha_pm: return "fx_a1 + fx_a2 * (1.0 - " + tex_alpha + ")";
      case TextureOp::blend_current_alpha: return "lerp(fx_a2, fx_a1, fx_current.aaaa)";
      case TextureOp::premodulate:
        return i + 1 < stages_ && samples(s_, i + 1) ? "fx_a1 * fx_tex" + std::to_string(i + 1) : "fx_a1";
      case TextureOp::modulate_alpha_add_color: return "fx_a1 + fx_a1.aaaa * fx_a2";
      case TextureOp::modulate_color_add_alpha: return "fx_a1 * fx_a2 + fx_a1.aaaa";
      case TextureOp::modulate_inv_alpha_add_color: return "fx_a1 + (1.0 - fx_a1.aaaa) * fx_a2";
      case TextureOp::modulate_inv_color_add_alpha: return "(1.0 - fx_a1) * fx_a2 + fx_a1.aaaa";
      case TextureOp::dot_product3: return "dot(fx_a1.rgb - 0.5, fx_a2.rgb - 0.5).xxxx * 4.0";
      case TextureOp::multiply_add: return "fx_a0 + fx_a1 * fx_a2";
      case TextureOp::lerp: return "lerp(fx_a2, fx_a1, fx_a0)";
    }
    return "fx_current";
  }

  // Declares a0..a2 for `op` from `args` inside the current block.
  void args(TextureOp op, const std::array<uint32_t, 3>& a, int i) {
    if (uses_arg0(op)) body_ += "    float4 fx_a0 = " + arg(a[0], i) + ";\n";
    if (uses_arg1(op)) body_ += "    float4 fx_a1 = " + arg(a[1], i) + ";\n";
    if (uses_arg2(op)) body_ += "    float4 fx_a2 = " + arg(a[2], i) + ";\n";
  }

  std::string coords(int i) {
    const TextureStageState& st = s_.stages[i];
    const int r = texcoord_register(s_, i);
    texcoords_ |= 1u << r;
    const std::string tc = "fx_tc" + std::to_string(r);
    const bool flat = st.texture == StageTexture::tex2d;
    std::string c = flat ? tc + ".xy" : tc + ".xyz";
    if (st.texture_transform_flags & texture_transform::projected) {
      const uint32_t count = st.texture_transform_flags & texture_transform::count_mask;
      const char* last = count == 2 ? ".y" : count == 3 ? ".z" : ".w";
      c = "(" + c + " / " + tc + last + ")";
    }
    if (i > 0 && is_bump(s_.stages[i - 1].color_op))
      c = flat ? "(" + c + " + fx_bump)" : "(" + c + " + float3(fx_bump, 0.0))";
    return c;
  }

  void sample(int i) {
    const TextureStageState& st = s_.stages[i];
    const std::string n = std::to_string(i);
    const char* type = st.texture == StageTexture::cube     ? "samplerCUBE"
                       : st.texture == StageTexture::volume ? "sampler3D"
                                                            : "sampler2D";
    const char* fn = st.texture == StageTexture::cube     ? "texCUBE"
                     : st.texture == StageTexture::volume ? "tex3D"
                                                          : "tex2D";
    decl_.uniform(type, "fx_stage" + n);
    body_ += "  float4 fx_tex" + n + " = " + fn + "(fx_stage" + n + ", " + coords(i) + ");\n";
    if (i > 0 && s_.stages[i - 1].color_op == TextureOp::bump_env_map_luminance)
      body_ += "  fx_tex" + n + ".rgb *= fx_luminance;\n";
  }

  // Stage `i`'s texture value and, for a bump stage, the offset and luminance it gives the next.
  void texture(int i) {
    const TextureStageState& st = s_.stages[i];
    const std::string n = std::to_string(i);
    if (samples(s_, i)) sample(i);
    else if (ff_detail::reads_texture(s_, i))
      body_ += "  float4 fx_tex" + n + " = float4(1.0, 1.0, 1.0, 1.0);  // no texture bound\n";
    if (!is_bump(st.color_op)) return;
    const auto& m = st.bump_env_mat;
    body_ += "  fx_bump = float2(" + decl_.scalar(m[0]) + " * fx_tex" + n + ".r + " + decl_.scalar(m[2]) + " * fx_tex" +
             n + ".g, " + decl_.scalar(m[1]) + " * fx_tex" + n + ".r + " + decl_.scalar(m[3]) + " * fx_tex" + n +
             ".g);\n";
    if (st.color_op == TextureOp::bump_env_map_luminance)
      body_ += "  fx_luminance = saturate(fx_tex" + n + ".b * " + decl_.scalar(st.bump_env_lscale) + " + " +
               decl_.scalar(st.bump_env_loffset) + ");\n";
  }

  void stage(int i) {
    const TextureStageState& st = s_.stages[i];
    const std::string n = std::to_string(i);
    body_ += "  // stage " + n + ": " + to_string(st.color_op) + " / " + to_string(st.alpha_op) + "\n";
    if (is_bump(st.color_op)) return;  // a bump stage leaves the result registers as they are
    const std::string dest = (st.result_arg & ta::select_mask) == ta::temp ? "fx_temp" : "fx_current";
    body_ += "  {\n";
    args(st.color_op, st.color_arg, i);
    body_ += "    float4 fx_color = saturate(" + op_expr(st.color_op, i) + ");\n";
    body_ += "  {\n";
    if (st.color_op == TextureOp::dot_product3) {
      // D3D9: DotProduct3 as the colour operation replicates into alpha as well.
      body_ += "    float fx_alpha = fx_color.a;\n";
    } else if (st.alpha_op == TextureOp::disable || is_bump(st.alpha_op)) {
      body_ += "    float fx_alpha = fx_current.a;\n";
    } else {
      args(st.alpha_op, st.alpha_arg, i);
      body_ += "    float fx_alpha = saturate(" + op_expr(st.alpha_op, i) + ").a;\n";
    }
    body_ += "    " + dest + " = float4(fx_color.rgb, fx_alpha);\n";
    body_ += "  }\n  }\n";
  }

  void fog() {
    std::string f;
    if (table_fog(s_)) {
      body_ += "  float fx_fog_depth = 1.0 / i.fx_position.w;\n";
      const std::string start = decl_.scalar(s_.fog_start), end = decl_.scalar(s_.fog_end),
                        density = decl_.scalar(s_.fog_density);
      switch (s_.fog_table_mode) {
        case FogMode::linear: f = "(" + end + " - fx_fog_depth) / (" + end + " - " + start + ")"; break;
        case FogMode::exp: f = "exp(-" + density + " * fx_fog_depth)"; break;
        default: f = "exp(-(" + density + " * fx_fog_depth) * (" + density + " * fx_fog_depth))"; break;
      }
    } else {
      f = "fx_fog_in";
    }
    body_ += "  float fx_fog = saturate(" + f + ");\n";
    body_ += "  fx_current.rgb = lerp(" + decl_.vector(s_.fog_color) + ".rgb, fx_current.rgb, fx_fog);\n";
  }

  void alpha_test() {
    static const char* cmp[] = {"false", "<", "==", "<=", ">", "!=", ">=", "true"};
    const int c = static_cast<int>(s_.alpha_func);
    if (s_.alpha_func == CompareOp::always) return;
    if (s_.alpha_func == CompareOp::never) {
      body_ += "  discard;\n";
      return;
    }
    body_ += "  float fx_alpha_8bit = floor(saturate(fx_current.a) * 255.0 + 0.5);\n";
    body_ += "  if (!(fx_alpha_8bit " + std::string(cmp[c]) + " " + decl_.scalar(s_.alpha_ref) + ")) discard;\n";
  }

  const FixedFunctionState& s_;
  const int stages_;
  const FixedFunctionState::VertexShaderOutputs outputs_;
  Declarations decl_;
  std::string inputs_, prologue_, body_;
  uint32_t texcoords_ = 0;
};

}  // namespace

FixedFunctionShader generate_fixed_function_pixel_shader(const FixedFunctionState& state) {
  return PixelShaderWriter(state).write();
}

}  // namespace fx
