// The strand terms of effects/strand_aniso.fx evaluated per pixel on the device over the hard
// cases of fx::shading::shading_samples (log-spaced near-degenerate angles down to 1e-8 rad,
// exact degeneracies, NaN and Inf components), read back from an RGBA8 target and compared
// with the double reference: outputs finite everywhere, within 2 LSB where inputs are finite.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "fx/shading/error_measure.h"
#include "fx/shading/strand.h"
#include "fx/shading/table.h"
#include "fx/vulkan/texture.h"
#include "pass_test_util.h"

namespace fx::vk {
namespace {

using namespace testing;

constexpr double kExponent = 32.0;  // STRAND_EXPONENT in effects/strand_aniso.fx

// The pixel shader: fetches one sample's L, V, T (RGBA32F, nearest, texel = pixel) and runs
// the effect's own path, StrandAnalyticPS for one light: normalize_or with the effect's
// fallbacks, then strand_terms from common.fxh/strand_aniso.fx. B flags any NaN or Inf in
// the inputs to the output conversion (the unorm store would hide them).
const char* kHardCaseShader = R"(
sampler2D LightTex;
sampler2D ViewTex;
sampler2D TangentTex;
static const float kExponent = 32.0;
struct VSIn { float4 pos : POSITION; float2 uv : TEXCOORD0; };
struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };
VSOut VS(VSIn i) { VSOut o; o.pos = i.pos; o.uv = i.uv; return o; }

// strand_terms from effects/strand_aniso.fx, verbatim.
float2 strand_terms(float3 l, float3 v, float3 t, float exponent)
{
    float sl = min(length(cross(l, t)), 1.0);
    float sv = min(length(cross(v, t)), 1.0);
    float lt = clamp(dot(l, t), -1.0, 1.0);
    float vt = clamp(dot(v, t), -1.0, 1.0);
    return float2(sl, guarded_pow(sl * sv - lt * vt, exponent));
}

bool bad(float x) { return isnan(x) || isinf(x); }
bool bad3(float3 v) { return bad(v.x) || bad(v.y) || bad(v.z); }

float4 PS(float2 uv : TEXCOORD0) : COLOR0
{
    float3 l = normalize_or(tex2Dlod(LightTex, float4(uv, 0, 0)).xyz, float3(0.0, 0.0, 1.0));
    float3 v = normalize_or(tex2Dlod(ViewTex, float4(uv, 0, 0)).xyz, float3(0.0, 0.0, 1.0));
    float3 t = normalize_or(tex2Dlod(TangentTex, float4(uv, 0, 0)).xyz, float3(1.0, 0.0, 0.0));
    float sl = length(cross(l, t)), sv = length(cross(v, t));
    float2 terms = strand_terms(l, v, t, kExponent);
    float flag = (bad3(l) || bad3(v) || bad3(t) || bad(sl) || bad(sv) || bad(terms.x) || bad(terms.y)) ? 1.0 : 0.0;
    return float4(saturate(terms.x), saturate(terms.y), flag, 1.0);
}
)";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The effect's normalize_or in double: guarded.h's contract (non-finite or shorter than the
// float degenerate length -> fallback), the length threshold of common.fxh.
glm::dvec3 effect_normalize_or(const glm::dvec3& v, const glm::dvec3& fallback) {
  if (!shading::finite(v)) return fallback;
  const double len = glm::length(v);
  return len > double(shading::degenerate_length<float>()) ? v / len : fallback;
}

// One RGBA32F texel per sample, x fastest; padding texels repeat sample 0.
shading::Table vector_table(const std::vector<shading::ShadingSample>& samples, int size,
                            glm::dvec3 shading::ShadingSample::*member) {
  shading::Table t = shading::Table::make(size, size, 1, 4, shading::TableFormat::float32);
  for (int i = 0; i < size * size; ++i) {
    const glm::dvec3& d = samples[size_t(i) < samples.size() ? size_t(i) : 0].*member;
    for (int c = 0; c < 3; ++c) t.float32[size_t(i) * 4 + size_t(c)] = float(d[c]);
    t.float32[size_t(i) * 4 + 3] = 1.0f;
  }
  return t;
}

class HardCasePixels : public VulkanTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(ctx().validation_warning_count(), 0u) << describe_messages(ctx());
    VulkanTest::TearDown();
  }
};

// Renders `samples` (one pixel each) and checks every pixel: no NaN/Inf flagged, and both
// terms within 2 LSB of the effect's path evaluated in double.
void check_pixels(Context& ctx, const std::vector<shading::ShadingSample>& samples) {
  ASSERT_FALSE(samples.empty());
  const int size = int(std::ceil(std::sqrt(double(samples.size()))));

  // Program: common.fxh's guarded helpers, prepended (the compiler takes one source string).
  const std::string source = read_text(std::string(FXKIT_SOURCE_DIR) + "/effects/common.fxh") + kHardCaseShader;
  ShaderCompiler compiler;
  auto unit = [&](ShaderStage stage, const char* entry, const char* profile) {
    TranslationUnit u;
    u.source = source;
    u.stage = stage;
    u.entry_point = entry;
    u.profile = profile;
    u.name = "hard_case_pixels.fx";
    return u;
  };
  CompiledShader vs = compiler.compile(unit(ShaderStage::vertex, "VS", "vs_3_0"));
  CompiledShader ps = compiler.compile(unit(ShaderStage::fragment, "PS", "ps_3_0"));
  ASSERT_TRUE(vs.ok && ps.ok) << vs.info_log << ps.info_log;
  DiagnosticSink sink;
  ProgramLayout layout = link_program({&vs, &ps}, sink);
  auto program = ShaderProgram::create(ctx, {&vs, &ps}, layout, DescriptorMode::sets, sink);
  ASSERT_TRUE(program.has_value()) << describe(sink);
  auto input = match_vertex_layout(quad_layout(), program->vertex_inputs(), sink);
  ASSERT_TRUE(input) << describe(sink);

  auto light = Texture::from_table(ctx, vector_table(samples, size, &shading::ShadingSample::l), sink);
  auto view = Texture::from_table(ctx, vector_table(samples, size, &shading::ShadingSample::v), sink);
  auto tangent = Texture::from_table(ctx, vector_table(samples, size, &shading::ShadingSample::t), sink);
  ASSERT_TRUE(light && view && tangent) << describe(sink);
  SamplerCache samplers(ctx);
  SamplerDesc nearest;
  nearest.min_filter = nearest.mag_filter = VK_FILTER_NEAREST;
  nearest.mip_filter = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  nearest.address_u = nearest.address_v = nearest.address_w = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSampler sampler = samplers.get(nearest, sink);
  PassResources res(*program);
  ASSERT_TRUE(res.bind("LightTex", *light, sampler, sink) && res.bind("ViewTex", *view, sampler, sink) &&
              res.bind("TangentTex", *tangent, sampler, sink))
      << describe(sink);

  PassHarness h(ctx, DynamicStateSet::none(), uint32_t(size), DepthAttachment::none);
  std::vector<Vertex> quad;
  add_quad(quad, -1, -1, 1, 1, 0.5f);  // uv = (x + 0.5) / size at pixel centres: texel x
  VkBuffer vb = h.vertices(quad);
  fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
    draw(cmd, r, {&*program, PipelineState{}, &*input, &res}, vb, 6);
  });
  ASSERT_EQ(img.width, uint32_t(size));

  // Tolerance 2 LSB: the reference is rounded to the nearest 8-bit level and so is the
  // device's float result, so a value near a rounding boundary may land 1 level apart; the
  // float shader's own error is far below 1 LSB (DESIGN.md: pow-based terms ~1e-4 absolute
  // = 0.03 LSB; the sines come from |L x T|, which keeps full relative precision at small
  // angles). The second LSB is headroom for a unorm conversion that truncates; a wrong
  // formula or a cancelled sine misses by far more near the ridge (tens of levels).
  constexpr int kTolerance = 2;
  int worst[2] = {0, 0};
  size_t checked = 0;
  for (int i = 0; i < size * size; ++i) {
    const auto px = pixel(img, uint32_t(i % size), uint32_t(i / size));
    ASSERT_EQ(px[2], 0) << "non-finite strand term at sample " << i;
    ASSERT_EQ(px[3], 255);
    if (size_t(i) >= samples.size()) continue;
    const shading::ShadingSample& s = samples[size_t(i)];
    // The effect's path in double: guarded normalize_or (non-finite -> the fallback), then the
    // analytic reference.
    const auto ref = shading::strand_reference(effect_normalize_or(s.l, {0, 0, 1}), effect_normalize_or(s.v, {0, 0, 1}),
                                               effect_normalize_or(s.t, {1, 0, 0}), kExponent);
    const int want[2] = {int(std::lround(shading::quantize_unorm8(ref.diffuse) * 255)),
                         int(std::lround(shading::quantize_unorm8(ref.specular) * 255))};
    for (int c = 0; c < 2; ++c) {
      const int err = std::abs(px[c] - want[c]);
      worst[c] = std::max(worst[c], err);
      EXPECT_LE(err, kTolerance) << (c ? "specular" : "diffuse") << " at sample " << i << " kind "
                                 << int(s.kind) << " degeneracy " << int(s.degeneracy) << " angle " << s.angle
                                 << ": got " << px[c] << " want " << want[c];
    }
    ++checked;
  }
  EXPECT_EQ(checked, samples.size());
  std::printf("hard-case pixels: %zu samples, worst |diffuse| %d LSB, worst |specular| %d LSB\n", checked, worst[0],
              worst[1]);
}

bool has_infinity(const glm::dvec3& v) { return std::isinf(v.x) || std::isinf(v.y) || std::isinf(v.z); }

// The hard cases, split by whether a vector has an infinite component.
std::vector<shading::ShadingSample> hard_samples(bool with_infinity) {
  shading::SampleSetOptions options;
  options.uniform = 1024;  // the hard cases are the point; 1024 uniform ones cover the rest
  options.include_non_finite = true;
  std::vector<shading::ShadingSample> out;
  for (const auto& s : shading::shading_samples(options))
    if ((has_infinity(s.l) || has_infinity(s.v) || has_infinity(s.t) || has_infinity(s.n)) == with_infinity)
      out.push_back(s);
  return out;
}

// Uniform, log-spaced near-degenerate (1e-1 .. 1e-8 rad), exact degenerate, and NaN inputs
// (NaN fails normalize_or's length test, so the effect falls back as guarded.h documents).
TEST_F(HardCasePixels, StrandTermsAreFiniteAndWithinTwoLsbOfTheDoubleReference) {
  check_pixels(ctx(), hard_samples(false));
}

// Infinite components: normalize_or must fall back (len = Inf would make v / len NaN, which
// lavapipe's min/clamp/saturate then turn into arbitrary finite colours).
TEST_F(HardCasePixels, InfiniteInputsFallBackAsGuardedHDocuments) {
  check_pixels(ctx(), hard_samples(true));
}

}  // namespace
}  // namespace fx::vk
