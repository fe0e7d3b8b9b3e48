// measure_techniques: for each effect, a G-buffer pass appended to the effect's own source
// (so its samplers, textures and tangent frame are the effect's), the techniques rendered
// into RGBA32F over the scene set and compared per pixel with the effect's reference model,
// then timed: full target and 1x1 scissor (vertex work only), empty technique subtracted.
#include "fx/bench/technique_accuracy.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "fx/binding/effect_preview.h"
#include "fx/compile/effect_file.h"
#include "reference_models.h"

namespace fx::bench {
namespace {

constexpr const char* kPrefix = "fxkit_measure_";
const char* const kMeshes[] = {"sphere", "torus"};

// Object rotations of the scene set: the camera stays, the object turns under it.
std::vector<std::pair<std::string, glm::mat4>> rotations() {
  return {{"front", glm::mat4(1.0f)},
          {"turned", glm::rotate(glm::rotate(glm::mat4(1.0f), 2.1f, {0, 1, 0}), 0.6f, {1, 0, 0})},
          {"from below", glm::rotate(glm::mat4(1.0f), -1.2f, {1, 0, 0})}};
}

// G-buffer channels 0..4, then one per reference texture expression.
enum Channel { ch_position, ch_tangent, ch_binormal, ch_normal, ch_uv, ch_textures };

// HLSL appended to an effect that includes common.fxh: the G-buffer technique per channel
// (the effect's WorldViewProjection and tangent_frame, so coverage and frame match) and
// the empty technique whose time is subtracted.
std::string hlsl_measurement_block(const ReferenceModel& m) {
  std::ostringstream s;
  s << R"(
struct FxkitMeasureIn { float4 position : POSITION; float3 normal : NORMAL; float3 tangent : TANGENT; float3 binormal : BINORMAL; float2 uv : TEXCOORD0; };
struct FxkitMeasureOut { float4 position : POSITION; float3 world : TEXCOORD0; float3 t : TEXCOORD1; float3 b : TEXCOORD2; float3 n : TEXCOORD3; float2 uv : TEXCOORD4; float3 object : TEXCOORD5; };
FxkitMeasureOut FxkitGbufferVS(FxkitMeasureIn IN)
{
    FxkitMeasureOut OUT;
    OUT.position = mul(IN.position, WorldViewProjection);
    OUT.world = mul(IN.position, World).xyz;
    float3x3 frame = tangent_frame(IN.normal, IN.tangent, IN.binormal);
    OUT.t = frame[0];
    OUT.b = frame[1];
    OUT.n = frame[2];
    OUT.uv = IN.uv;
    OUT.object = IN.position.xyz;
    return OUT;
}
float4 FxkitGbufferPS(FxkitMeasureOut IN, uniform int channel) : COLOR0
{
    float2 uv = IN.uv;
    float3 object = IN.object;
    if (channel == 0) return float4(IN.world, 1.0);
    if (channel == 1) return float4(IN.t, 1.0);
    if (channel == 2) return float4(IN.b, 1.0);
    if (channel == 3) return float4(IN.n, 1.0);
    if (channel == 4) return float4(IN.uv, 0.0, 1.0);
)";
  for (size_t i = 0; i < m.textures.size(); ++i)
    s << "    if (channel == " << ch_textures + i << ") return " << m.textures[i] << ";\n";
  s << R"(    return float4(0.0, 0.0, 0.0, 1.0);
}
float4 FxkitEmptyVS(float4 position : POSITION) : POSITION { return mul(position, WorldViewProjection); }
float4 FxkitEmptyPS() : COLOR0 { return float4(0.0, 0.0, 0.0, 1.0); }
technique fxkit_measure_empty < string Requires = "vs_2_0 ps_2_0"; > { pass p0 { VertexShader = compile vs_3_0 FxkitEmptyVS(); PixelShader = compile ps_3_0 FxkitEmptyPS(); } }
)";
  for (size_t c = 0; c < ch_textures + m.textures.size(); ++c)
    s << "technique fxkit_measure_gbuffer" << c
      << " < string Requires = \"vs_2_0 ps_2_0\"; > { pass p0 { VertexShader = compile vs_3_0 FxkitGbufferVS(); "
         "PixelShader = compile ps_3_0 FxkitGbufferPS("
      << c << "); } }\n";
  return s.str();
}

// GLSL appended to a GLSL effect: the same techniques, each stage the model's glsl_blocks
// (the effect's #version and uniform interface) then the measurement's own. The frame is the
// one a GLSL effect's vertex shader builds (World's upper 3x3 on each vector, normalized).
std::string glsl_measurement_block(const ReferenceModel& m) {
  std::string prelude;
  for (const std::string& b : m.glsl_blocks) prelude += b + ", ";
  std::ostringstream s;
  s << R"(
GLSLShader FxkitMeasureVS
{
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec3 inBinormal;
layout(location = 4) in vec2 inTexCoord;
layout(location = 0) out vec3 fxkitWorld;
layout(location = 1) out vec3 fxkitT;
layout(location = 2) out vec3 fxkitB;
layout(location = 3) out vec3 fxkitN;
layout(location = 4) out vec2 fxkitUv;
layout(location = 5) out vec3 fxkitObject;
void main()
{
    fxkitWorld = (World * vec4(inPosition, 1.0)).xyz;
    fxkitT = normalize(mat3(World) * inTangent);
    fxkitB = normalize(mat3(World) * inBinormal);
    fxkitN = normalize(mat3(World) * inNormal);
    fxkitUv = inTexCoord;
    fxkitObject = inPosition;
    gl_Position = WorldViewProjection * vec4(inPosition, 1.0);
}
}
GLSLShader FxkitMeasureFS
{
layout(location = 0) in vec3 fxkitWorld;
layout(location = 1) in vec3 fxkitT;
layout(location = 2) in vec3 fxkitB;
layout(location = 3) in vec3 fxkitN;
layout(location = 4) in vec2 fxkitUv;
layout(location = 5) in vec3 fxkitObject;
layout(location = 0) out vec4 fxkitColor;
vec4 fxkitChannel()
{
    vec2 uv = fxkitUv;
    vec3 object = fxkitObject;
    if (kFxkitChannel == 0) return vec4(fxkitWorld, 1.0);
    if (kFxkitChannel == 1) return vec4(fxkitT, 1.0);
    if (kFxkitChannel == 2) return vec4(fxkitB, 1.0);
    if (kFxkitChannel == 3) return vec4(fxkitN, 1.0);
    if (kFxkitChannel == 4) return vec4(uv, 0.0, 1.0);
)";
  for (size_t i = 0; i < m.textures.size(); ++i)
    s << "    if (kFxkitChannel == " << ch_textures + i << ") return " << m.textures[i] << ";\n";
  s << R"(    return vec4(0.0, 0.0, 0.0, 1.0);
}
void main() { fxkitColor = fxkitChannel(); }
}
GLSLShader FxkitEmptyVS
{
layout(location = 0) in vec3 inPosition;
void main() { gl_Position = WorldViewProjection * vec4(inPosition, 1.0); }
}
GLSLShader FxkitEmptyFS
{
layout(location = 0) out vec4 fxkitColor;
void main() { fxkitColor = vec4(0.0, 0.0, 0.0, 1.0); }
}
)";
  s << "technique fxkit_measure_empty < string Requires = \"glsl_450\"; > { pass p0 { VertexShader = { " << prelude
    << "FxkitEmptyVS }; PixelShader = { " << prelude << "FxkitEmptyFS }; } }\n";
  for (size_t c = 0; c < ch_textures + m.textures.size(); ++c)
    s << "GLSLShader FxkitChannel" << c << " { const int kFxkitChannel = " << c << "; }\n"
      << "technique fxkit_measure_gbuffer" << c << " < string Requires = \"glsl_450\"; > { pass p0 { VertexShader = { "
      << prelude << "FxkitMeasureVS }; PixelShader = { " << prelude << "FxkitChannel" << c
      << ", FxkitMeasureFS }; } }\n";
  return s.str();
}

// The measurement techniques in the effect's own shader language.
std::string measurement_block(const ReferenceModel& m) {
  return m.glsl_blocks.empty() ? hlsl_measurement_block(m) : glsl_measurement_block(m);
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string scheme_of(const TechniqueInfo& t) {
  const Annotation* a = find_annotation(t.annotations, "Scheme");
  return a && a->value.is_string() ? a->value.text : std::string();
}

// How the binding draws technique t when it is legacy (its assembly and fixed-function
// stages' emulation, "; "-joined), and whether a pixel stage is ps.1.x assembly (the stages
// the precision model changes).
struct Legacy {
  std::string emulation;
  bool ps1x = false;
};
Legacy legacy_of(const EffectUnits& units, uint32_t t) {
  Legacy l;
  for (const EffectPass& pass : units.passes()) {
    if (pass.technique_index != t) continue;
    for (const StageUnit& stage : pass.stages) {
      if (stage.kind != StageSourceKind::assembly && stage.kind != StageSourceKind::fixed_function) continue;
      l.ps1x |= stage.kind == StageSourceKind::assembly && stage.stage == ShaderStage::fragment;
      if (!stage.emulation.empty() && l.emulation.find(stage.emulation) == std::string::npos)
        l.emulation += (l.emulation.empty() ? "" : "; ") + stage.emulation;
    }
  }
  return l;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// An effect bound to a preview on one mesh, with a vertex layout per technique.
struct Bound {
  std::unique_ptr<EffectFile> effect;
  std::unique_ptr<vk::EffectPreview> preview;
  std::unique_ptr<vk::EffectBinding> binding;
  std::vector<uint32_t> layouts;
  size_t vertices = 0;
};

// precision: compiled with the ps.1.x precision model (FXKIT_PS1X_PRECISION).
std::optional<Bound> bind_on_mesh(const vk::Context& ctx, const std::string& path, const std::string& effects_dir,
                                  const char* mesh_name, uint32_t size, DiagnosticSink& sink, bool precision = false) {
  Bound b;
  FrontEndOptions fe;
  fe.preprocessor.include_dirs = {effects_dir};
  if (precision) fe.preprocessor.defines.emplace_back(kPs1xPrecisionMacro, "1");
  b.effect = EffectFile::load(path, fe, sink);
  auto mesh = make_mesh(mesh_name, sink);
  if (!b.effect || !mesh) return std::nullopt;
  b.vertices = mesh->vertices.size();
  vk::EffectPreviewDesc desc;
  desc.width = desc.height = size;
  desc.color_format = VK_FORMAT_R32G32B32A32_SFLOAT;
  desc.clear = {0, 0, 0, 0};
  b.preview = vk::EffectPreview::create(ctx, *mesh, desc, sink);
  if (!b.preview) return std::nullopt;
  vk::EffectBindingDesc bd = b.preview->binding_desc();
  bd.effect_dir = effects_dir;
  b.binding = vk::EffectBinding::create(ctx, *b.effect->model, *b.effect->programs, *b.effect->params,
                                        b.preview->textures(), b.preview->frames(), bd, sink);
  if (!b.binding) return std::nullopt;
  for (uint32_t t = 0; t < b.binding->technique_count(); ++t) {
    uint32_t layout = 0;
    if (b.binding->technique_ok(t)) {
      auto inputs = vk::technique_vertex_inputs(*b.effect->model, *b.effect->programs, t);
      layout = b.binding->add_vertex_layout(b.preview->vertex_layout(inputs));
    }
    b.layouts.push_back(layout);
  }
  return b;
}

// Parameter values by name, to put the defaults back between parameter sets.
using Saved = std::map<std::string, std::vector<float>>;

Saved save(const ParameterStore& params, const ReferenceModel& m) {
  Saved out;
  for (const ParameterSet& set : m.parameter_sets)
    for (const auto& [name, values] : set.values) {
      std::vector<float> v(values.size());
      if (params.get(params.find(name), std::span<float>(v))) out[name] = v;
    }
  return out;
}

bool apply(ParameterStore& params, const Saved& defaults, const ParameterSet& set, DiagnosticSink& sink) {
  for (const auto& [name, v] : defaults) params.set(params.find(name), std::span<const float>(v));
  for (const auto& [name, v] : set.values) {
    if (!params.set(params.find(name), std::span<const float>(v))) {
      sink.error("accuracy-parameter", {}, "parameter set '" + set.name + "': cannot set '" + name + "'");
      return false;
    }
  }
  return true;
}

// The displayed value of a colour channel: what a UNORM target stores (NaN is counted as a
// full-scale error by the caller, not clamped).
double displayed(double v) { return std::clamp(v, 0.0, 1.0); }

// Puts a parameter set and the scene's standard semantics into a bound effect.
bool prepare(Bound& b, const Saved& defaults, const ParameterSet& set, const vk::SceneView& scene,
             DiagnosticSink& sink) {
  if (!apply(*b.effect->params, defaults, set, sink)) return false;
  vk::set_standard_semantics(*b.effect->params, *b.effect->model, scene);
  return true;
}

// One effect with a reference model: errors over the scene set, then timing. Techniques with
// a ps.1.x pixel stage are measured twice: as compiled by default, and from a second binding
// of the effect compiled with the ps.1.x precision model (their precision_model rows).
bool measure_effect(const vk::Context& ctx, const ReferenceModel& model, const std::filesystem::path& source,
                    const TechniqueAccuracyOptions& options, std::vector<TechniqueAccuracy>& rows,
                    DiagnosticSink& sink) {
  // The effect with the measurement block appended, beside a temporary copy.
  const auto dir = std::filesystem::temp_directory_path() / ("fxkit_technique_accuracy_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / source.filename();
  std::ofstream(path) << read_text(source) << "\n" << measurement_block(model);
  const size_t first = rows.size();
  std::map<size_t, std::vector<double>> errors;   // per row: per-pixel worst channel
  std::map<size_t, std::vector<double>> banding;  // precision rows: against the row before
  uint32_t gbuffer0 = kNoIndex, empty = kNoIndex;
  bool any_precision = false;
  // The binding a row is drawn with.
  auto bound_for = [](const TechniqueAccuracy& r, Bound& plain, std::optional<Bound>& precise) -> Bound& {
    return r.precision_model ? *precise : plain;
  };

  for (const char* mesh : kMeshes) {
    auto b = bind_on_mesh(ctx, path.string(), options.effects_dir, mesh, options.error_size, sink);
    if (!b) return false;
    const EffectModel& em = *b->effect->model;
    gbuffer0 = b->effect->find_technique(std::string(kPrefix) + "gbuffer0");
    empty = b->effect->find_technique(std::string(kPrefix) + "empty");
    if (rows.size() == first) {
      for (uint32_t t = 0; t < em.techniques.size(); ++t) {
        if (em.techniques[t].name.rfind(kPrefix, 0) == 0) continue;
        TechniqueAccuracy r;
        r.effect = source.filename().string();
        r.technique = em.techniques[t].name;
        r.scheme = scheme_of(em.techniques[t]);
        r.drawable = b->binding->technique_ok(t);
        r.model = model.description;
        r.substitutes = model.group({r.technique, r.scheme});
        const Legacy legacy = legacy_of(*b->effect->units, t);
        r.emulation = legacy.emulation;
        if (!r.drawable) r.reason = "not drawable on Vulkan: " + b->binding->technique_reason(t);
        else if (!model.covers({r.technique, r.scheme})) r.reason = "its reference model does not cover this technique";
        r.measured = r.reason.empty();
        rows.push_back(r);
        if (r.measured && legacy.ps1x) {
          r.precision_model = true;
          rows.push_back(r);
          any_precision = true;
        }
      }
    }
    std::optional<Bound> bp;
    if (any_precision) {
      bp = bind_on_mesh(ctx, path.string(), options.effects_dir, mesh, options.error_size, sink, true);
      if (!bp) return false;
    }
    const Saved defaults = save(*b->effect->params, model);
    const size_t channels = ch_textures + model.textures.size();
    for (const auto& [rotation_name, world] : rotations()) {
      vk::SceneView scene = b->preview->scene();
      scene.world = world;
      for (const ParameterSet& set : model.parameter_sets) {
        if (!prepare(*b, defaults, set, scene, sink) || (bp && !prepare(*bp, defaults, set, scene, sink))) return false;
        std::vector<ImageF> gb;
        for (size_t c = 0; c < channels; ++c) {
          auto img = b->preview->render_floats(*b->binding, gbuffer0 + uint32_t(c), b->layouts[gbuffer0 + c], sink);
          if (!img) return false;
          gb.push_back(std::move(*img));
        }
        const ImageF& pos = gb[ch_position];
        auto covered = [&](int x, int y) {
          return x >= 0 && y >= 0 && x < int(pos.width) && y < int(pos.height) &&
                 pos.at(uint32_t(x), uint32_t(y))[3] > 0.5f;
        };
        std::optional<ImageF> previous;  // the row before's image (a precision row's float twin)
        for (size_t k = first; k < rows.size(); ++k) {
          if (!rows[k].measured) continue;
          Bound& on = bound_for(rows[k], *b, bp);
          const uint32_t t = on.effect->find_technique(rows[k].technique);
          auto img = on.preview->render_floats(*on.binding, t, on.layouts[t], sink);
          if (!img) return false;
          const bool twin = rows[k].precision_model && previous;
          for (uint32_t y = 0; y < pos.height; ++y)
            for (uint32_t x = 0; x < pos.width; ++x) {
              // Interior pixels only: an edge pixel may be covered by one pass and not the other.
              if (!covered(int(x), int(y)) || !covered(int(x) - 1, int(y)) || !covered(int(x) + 1, int(y)) ||
                  !covered(int(x), int(y) - 1) || !covered(int(x), int(y) + 1))
                continue;
              PixelInputs in;
              auto v3 = [&](size_t c) {
                const float* p = gb[c].at(x, y);
                return glm::dvec3(p[0], p[1], p[2]);
              };
              in.position = v3(ch_position);
              in.tangent = v3(ch_tangent);
              in.binormal = v3(ch_binormal);
              in.normal = v3(ch_normal);
              in.uv = glm::dvec2(v3(ch_uv));
              for (size_t c = ch_textures; c < channels; ++c) {
                const float* p = gb[c].at(x, y);
                in.textures.emplace_back(p[0], p[1], p[2], p[3]);
              }
              in.eye = glm::dvec3(scene.eye);
              const glm::dvec3 ref = model.shade(in, *b->effect->params, {rows[k].technique, rows[k].scheme});
              const float* g = img->at(x, y);
              double worst = 0;
              for (int c = 0; c < 3; ++c) {
                const double d =
                    std::isfinite(g[c]) ? std::fabs(displayed(double(g[c])) - displayed(ref[c])) * 255.0 : 255.0;
                worst = std::max(worst, d);
              }
              errors[k].push_back(worst);
              if (twin) {
                const float* f = previous->at(x, y);
                double band = 0;
                for (int c = 0; c < 3; ++c)
                  band = std::max(band, std::isfinite(g[c]) && std::isfinite(f[c])
                                            ? std::fabs(displayed(g[c]) - displayed(f[c])) * 255.0
                                            : 255.0);
                banding[k].push_back(band);
              }
            }
          previous = std::move(img);
        }
      }
    }
  }
  // Error statistics.
  for (size_t k = first; k < rows.size(); ++k) {
    if (!rows[k].measured) continue;
    std::vector<double>& e = errors[k];
    if (e.empty()) {
      rows[k].measured = false;
      rows[k].reason = "no covered pixels";
      continue;
    }
    std::sort(e.begin(), e.end());
    double sq = 0;
    for (double v : e) sq += v * v;
    rows[k].pixels_compared = e.size();
    rows[k].max_error_lsb = e.back();
    rows[k].p99_error_lsb = e[std::min(e.size() - 1, size_t(std::ceil(0.99 * double(e.size()))) - 1)];
    rows[k].rmse_lsb = std::sqrt(sq / double(e.size()));
    if (const auto it = banding.find(k); it != banding.end() && !it->second.empty()) {
      double band_sq = 0;
      for (double v : it->second) {
        rows[k].banding_max_lsb = std::max(rows[k].banding_max_lsb, v);
        band_sq += v * v;
      }
      rows[k].banding_rmse_lsb = std::sqrt(band_sq / double(it->second.size()));
    }
  }
  // Timing: the sphere, default parameters, front view. Covered pixels from the G-buffer.
  {
    auto b = bind_on_mesh(ctx, path.string(), options.effects_dir, kMeshes[0], options.timing_size, sink);
    if (!b) return false;
    std::optional<Bound> bp;
    if (any_precision) {
      bp = bind_on_mesh(ctx, path.string(), options.effects_dir, kMeshes[0], options.timing_size, sink, true);
      if (!bp) return false;
      vk::set_standard_semantics(*bp->effect->params, *bp->effect->model, bp->preview->scene());
    }
    vk::set_standard_semantics(*b->effect->params, *b->effect->model, b->preview->scene());
    auto pos = b->preview->render_floats(*b->binding, gbuffer0, b->layouts[gbuffer0], sink);
    if (!pos) return false;
    double pixels = 0;
    for (uint32_t y = 0; y < pos->height; ++y)
      for (uint32_t x = 0; x < pos->width; ++x) pixels += pos->at(x, y)[3] > 0.5f;
    struct Timed {
      Bound* on;
      uint32_t technique;
      size_t row;
    };
    std::vector<Timed> timed = {{&*b, empty, size_t(-1)}};
    for (size_t k = first; k < rows.size(); ++k)
      if (rows[k].drawable) {
        Bound& on = bound_for(rows[k], *b, bp);
        timed.push_back({&on, on.effect->find_technique(rows[k].technique), k});
      }
    const VkRect2D full{{0, 0}, {options.timing_size, options.timing_size}};
    const VkRect2D corner{{0, 0}, {1, 1}};  // off the mesh: the vertex work alone
    // Vertex work is small beside a frame's pixels: many more draws lift it above the noise.
    const uint32_t vertex_draws = options.draws * 16;
    std::vector<std::vector<double>> full_ns(timed.size()), vertex_ns(timed.size());
    for (int r = -1; r < options.repeats; ++r) {  // r = -1 warms the pipelines up
      for (size_t i = 0; i < timed.size(); ++i) {
        Bound& on = *timed[i].on;
        const uint32_t t = timed[i].technique;
        auto f = on.preview->time_passes(*on.binding, t, on.layouts[t], options.draws, full, sink);
        auto v = on.preview->time_passes(*on.binding, t, on.layouts[t], vertex_draws, corner, sink);
        if (!f || !v) return false;
        if (r >= 0) full_ns[i].push_back(*f), vertex_ns[i].push_back(*v);
      }
    }
    const double empty_full = median(full_ns[0]), empty_vertex = median(vertex_ns[0]);
    for (size_t i = 1; i < timed.size(); ++i) {
      TechniqueAccuracy& row = rows[timed[i].row];
      const double vertex = (median(vertex_ns[i]) - empty_vertex) / vertex_draws;  // per draw
      const double pixel = (median(full_ns[i]) - empty_full) / options.draws - vertex;
      row.ns_per_vertex = vertex / double(b->vertices);
      row.ns_per_pixel = pixels > 0 ? pixel / pixels : 0;
      row.timed = pixels > 0;
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  return true;
}

// An effect without a reference model: every technique listed, none measured.
bool list_effect(const vk::Context& ctx, const std::filesystem::path& source, const TechniqueAccuracyOptions& options,
                 std::vector<TechniqueAccuracy>& rows, DiagnosticSink& sink) {
  auto b = bind_on_mesh(ctx, source.string(), options.effects_dir, kMeshes[0], 16, sink);
  if (!b) return false;
  const EffectModel& em = *b->effect->model;
  for (uint32_t t = 0; t < em.techniques.size(); ++t) {
    TechniqueAccuracy r;
    r.effect = source.filename().string();
    r.technique = em.techniques[t].name;
    r.scheme = scheme_of(em.techniques[t]);
    r.drawable = b->binding->technique_ok(t);
    r.emulation = legacy_of(*b->effect->units, t).emulation;
    r.reason = r.drawable ? "no double-precision reference model for this effect yet"
                          : "not drawable on Vulkan: " + b->binding->technique_reason(t);
    rows.push_back(r);
  }
  return true;
}

}  // namespace

std::string describe_scene_set() {
  std::string s = "meshes";
  for (const char* m : kMeshes) s += std::string(" ") + m;
  s += "; object rotations";
  for (const auto& [name, m] : rotations()) s += " '" + name + "'";
  s += "; per effect, its parameter sets:";
  for (const ReferenceModel& m : reference_models()) {
    s += " " + m.effect + " (";
    for (size_t i = 0; i < m.parameter_sets.size(); ++i) s += (i ? ", " : "") + m.parameter_sets[i].name;
    s += ")";
  }
  return s;
}

std::optional<std::vector<TechniqueAccuracy>> measure_techniques(const vk::Context& ctx,
                                                                 const TechniqueAccuracyOptions& options,
                                                                 DiagnosticSink& sink) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(options.effects_dir))
    if (e.path().extension() == ".fx" &&
        (options.only.empty() ||
         std::find(options.only.begin(), options.only.end(), e.path().filename().string()) != options.only.end()))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const std::string& name : options.only)
    if (std::none_of(files.begin(), files.end(), [&](const auto& f) { return f.filename().string() == name; })) {
      sink.error("accuracy-effect", {}, "no effect '" + name + "' in " + options.effects_dir);
      return std::nullopt;
    }
  std::vector<TechniqueAccuracy> rows;
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    auto m = std::find_if(reference_models().begin(), reference_models().end(),
                          [&](const ReferenceModel& r) { return r.effect == name; });
    const bool ok = m != reference_models().end() ? measure_effect(ctx, *m, f, options, rows, sink)
                                                  : list_effect(ctx, f, options, rows, sink);
    if (!ok) {
      sink.error("accuracy-effect", {}, "measuring the techniques of " + f.string() + " failed");
      return std::nullopt;
    }
  }
  return rows;
}

}  // namespace fx::bench
