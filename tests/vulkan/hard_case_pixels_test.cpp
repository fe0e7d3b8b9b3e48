// The strand terms of effects/strand_aniso.fx evaluated per pixel on the device over the hard
// cases of fx::shading::shading_samples (log-spaced near-degenerate angles down to 1e-8 rad,
// exact degeneracies, NaN and Inf components), read back as floats from an RGBA32F target and
// compared with the double reference: outputs finite everywhere and within a float tolerance
// (1e-5 diffuse, 1e-4 specular) that the seed's sqrt(1 - (L.T)^2) form is shown to miss.
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

// The seed's form, sines from sqrt(1 - (L.T)^2): cancels near the ridge. Only here to show
// that the tolerance tells the two apart.
float2 seed_sqrt_terms(float3 l, float3 v, float3 t, float exponent)
{
    float lt = clamp(dot(l, t), -1.0, 1.0);
    float vt = clamp(dot(v, t), -1.0, 1.0);
    float sl = sqrt(saturate(1.0 - lt * lt));
    float sv = sqrt(saturate(1.0 - vt * vt));
    return float2(sl, guarded_pow(sl * sv - lt * vt, exponent));
}

bool bad(float x) { return isnan(x) || isinf(x); }
bool bad3(float3 v) { return bad(v.x) || bad(v.y) || bad(v.z); }

float4 PS(float2 uv : TEXCOORD0) : COLOR0
{
    float3 l = normalize_or(tex2Dlod(LightTex, float4(uv, 0, 0)).xyz, float3(0.0, 0.0, 1.0));
    float3 v = normalize_or(tex2Dlod(ViewTex, float4(uv, 0, 0)).xyz, float3(0.0, 0.0, 1.0));
    float3 t = normalize_or(tex2Dlod(TangentTex, float4(uv, 0, 0)).xyz, float3(1.0, 0.0, 0.0));
    float2 terms = TERMS(l, v, t, kExponent);
    float flag = (bad3(l) || bad3(v) || bad3(t) || bad(terms.x) || bad(terms.y)) ? 1.0 : 0.0;
    return float4(terms.x, terms.y, flag, 1.0);
}
)";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Which sine form the pixel shader uses (the TERMS macro).
enum class SineForm { stable, seed_sqrt };

// The worst absolute error of each term over the finite-input samples.
struct PixelErrors {
  double diffuse = 0, specular = 0;
};

// The effect's normalize_or in double: guarded.h's contract (non-finite or shorter than the
// float degenerate length -> fallback), the length threshold of common.fxh.
glm::dvec3 effect_normalize_or(const glm::dvec3& v, const glm::dvec3& fallback) {
  if (!shading::finite(v)) return fallback;
  const double len = glm::length(v);
  return len > double(shading::degenerate_length<float>()) ? v / len : fallback;
}

// What the shader reads: the sample's vector rounded to float (as the RGBA32F texture stores
// it), so the reference measures the shader's arithmetic and not the input's rounding.
glm::dvec3 as_stored(const glm::dvec3& v) { return glm::dvec3(glm::vec3(v)); }

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

// Renders `samples` (one pixel each) with the given sine form and returns the worst error of
// each term against the effect's path evaluated in double; every pixel must be finite (no
// NaN/Inf flagged, no non-finite value written).
PixelErrors render_errors(Context& ctx, const std::vector<shading::ShadingSample>& samples, SineForm form) {
  PixelErrors worst;
  EXPECT_FALSE(samples.empty());
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
    u.defines = {{"TERMS", form == SineForm::stable ? "strand_terms" : "seed_sqrt_terms"}};
    return u;
  };
  CompiledShader vs = compiler.compile(unit(ShaderStage::vertex, "VS", "vs_3_0"));
  CompiledShader ps = compiler.compile(unit(ShaderStage::fragment, "PS", "ps_3_0"));
  EXPECT_TRUE(vs.ok && ps.ok) << vs.info_log << ps.info_log;
  if (!vs.ok || !ps.ok) return worst;
  DiagnosticSink sink;
  ProgramLayout layout = link_program({&vs, &ps}, sink);
  auto program = ShaderProgram::create(ctx, {&vs, &ps}, layout, DescriptorMode::sets, sink);
  auto input = program ? match_vertex_layout(quad_layout(), program->vertex_inputs(), sink) : std::nullopt;
  auto light = Texture::from_table(ctx, vector_table(samples, size, &shading::ShadingSample::l), sink);
  auto view = Texture::from_table(ctx, vector_table(samples, size, &shading::ShadingSample::v), sink);
  auto tangent = Texture::from_table(ctx, vector_table(samples, size, &shading::ShadingSample::t), sink);
  EXPECT_TRUE(program && input && light && view && tangent) << describe(sink);
  if (!program || !input || !light || !view || !tangent) return worst;
  SamplerCache samplers(ctx);
  SamplerKey nearest;
  nearest.min_filter = nearest.mag_filter = VK_FILTER_NEAREST;
  nearest.mip_filter = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  nearest.address_u = nearest.address_v = nearest.address_w = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSampler sampler = samplers.get(nearest, sink);
  PassResources res(*program);
  EXPECT_TRUE(res.bind("LightTex", *light, sampler, sink) && res.bind("ViewTex", *view, sampler, sink) &&
              res.bind("TangentTex", *tangent, sampler, sink))
      << describe(sink);

  PassHarness h(ctx, DynamicStateSet::none(), uint32_t(size), DepthAttachment::none, VK_FORMAT_R32G32B32A32_SFLOAT);
  std::vector<Vertex> quad;
  add_quad(quad, -1, -1, 1, 1, 0.5f);  // uv = (x + 0.5) / size at pixel centres: texel x
  VkBuffer vb = h.vertices(quad);
  fx::ImageF img = h.render_floats([&](VkCommandBuffer cmd, PassRecorder& r) {
    draw(cmd, r, {&*program, PipelineState{}, &*input, &res}, vb, 6);
  });
  EXPECT_EQ(img.width, uint32_t(size));
  if (img.width != uint32_t(size)) return worst;

  for (size_t i = 0; i < samples.size(); ++i) {
    const float* px = img.at(uint32_t(i % size_t(size)), uint32_t(i / size_t(size)));
    const shading::ShadingSample& s = samples[i];
    EXPECT_TRUE(px[2] == 0.f && std::isfinite(px[0]) && std::isfinite(px[1]))
        << "non-finite strand term at sample " << i << " kind " << int(s.kind) << " degeneracy " << int(s.degeneracy)
        << ": " << px[0] << ", " << px[1] << " flag " << px[2];
    // The effect's path in double on the stored inputs: guarded normalize_or (non-finite ->
    // the fallback), then the analytic reference.
    const auto ref = shading::strand_reference(effect_normalize_or(as_stored(s.l), {0, 0, 1}),
                                               effect_normalize_or(as_stored(s.v), {0, 0, 1}),
                                               effect_normalize_or(as_stored(s.t), {1, 0, 0}), kExponent);
    worst.diffuse = std::max(worst.diffuse, std::fabs(double(px[0]) - ref.diffuse));
    worst.specular = std::max(worst.specular, std::fabs(double(px[1]) - ref.specular));
  }
  return worst;
}

// Tolerances, absolute (the terms are in [0, 1]). Diffuse is a float length of a cross
// product of unit vectors: a few ULPs of 1 (6e-8 each) from the normalisations and the cross
// product, plus inversesqrt's 2 ULP; 1e-5 leaves two orders of magnitude. Specular goes
// through pow = exp2(32 log2 x): DESIGN.md's 1e-4 absolute for pow-based terms. The seed's
// sqrt(1 - (L.T)^2) loses the sine once (L.T)^2 rounds near 1: about sqrt(2^-24) = 2.4e-4 at
// 1e-4 rad, which both tolerances catch (SeedSqrtFormMissesTheTolerance).
constexpr double kDiffuseTolerance = 1e-5;
constexpr double kSpecularTolerance = 1e-4;

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
TEST_F(HardCasePixels, StrandTermsAreFiniteAndWithinFloatToleranceOfTheDoubleReference) {
  const PixelErrors e = render_errors(ctx(), hard_samples(false), SineForm::stable);
  std::printf("hard-case pixels, stable form: worst |diffuse| %.3g, worst |specular| %.3g\n", e.diffuse, e.specular);
  EXPECT_LE(e.diffuse, kDiffuseTolerance);
  EXPECT_LE(e.specular, kSpecularTolerance);
}

// Infinite components: normalize_or must fall back (len = Inf would make v / len NaN, which
// lavapipe's min/clamp/saturate then turn into arbitrary finite colours).
TEST_F(HardCasePixels, InfiniteInputsFallBackAsGuardedHDocuments) {
  const PixelErrors e = render_errors(ctx(), hard_samples(true), SineForm::stable);
  EXPECT_LE(e.diffuse, kDiffuseTolerance);
  EXPECT_LE(e.specular, kSpecularTolerance);
}

// The same pixels with the seed's sqrt(1 - (L.T)^2): still finite, but the near-degenerate
// samples put it outside the tolerance, so the test above would catch a regression to it.
TEST_F(HardCasePixels, SeedSqrtFormMissesTheTolerance) {
  const PixelErrors e = render_errors(ctx(), hard_samples(false), SineForm::seed_sqrt);
  std::printf("hard-case pixels, seed sqrt form: worst |diffuse| %.3g, worst |specular| %.3g\n", e.diffuse, e.specular);
  EXPECT_GT(e.diffuse, kDiffuseTolerance);
  EXPECT_GT(e.specular, kSpecularTolerance);
}

}  // namespace
}  // namespace fx::vk
