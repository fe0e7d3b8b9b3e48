// Technique validation from real pass states: shader profiles (HLSL, assembly, GLSL),
// fixed-function and caps-dependent states, texture stages, formats, compiled-program
// limits, compile errors and the Requires annotation, each reason located in the file.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "fx/compile/effect_file.h"
#include "fx/diagnostic_render.h"
#include "fx/frontend.h"
#include "fx/model/effect_model.h"
#include "fx/select/caps_sources.h"
#include "fx/select/technique_validation.h"

namespace {

struct Loaded {
  fx::DiagnosticSink diags;
  std::unique_ptr<fx::EffectFile> file;
};

std::unique_ptr<Loaded> parse(const std::string& text) {
  auto l = std::make_unique<Loaded>();
  l->file = fx::EffectFile::parse_text("v.fx", text, {}, l->diags);
  EXPECT_FALSE(l->diags.has_errors()) << fx::render_text(l->diags.diagnostics(), l->file->sources);
  return l;
}

fx::DeviceCaps caps(const char* name) {
  fx::DiagnosticSink sink;
  auto c = fx::load_caps_profile(name, sink);
  EXPECT_TRUE(c.has_value()) << name;
  return c.value_or(fx::DeviceCaps{});
}

std::vector<fx::TechniqueValidation> validate(Loaded& l, const fx::DeviceCaps& c, bool compile = true) {
  auto out = fx::validate_effect(*l.file, c, l.diags, compile);
  EXPECT_FALSE(l.diags.has_errors()) << fx::render_text(l.diags.diagnostics(), l.file->sources);
  return out;
}

// The line a reason points at.
uint32_t line_of(const Loaded& l, const fx::Diagnostic& d) { return l.file->sources.presumed(d.range.begin).line; }

std::string all(const Loaded& l, const fx::TechniqueValidation& t) {
  return fx::render_text(t.reasons, l.file->sources, {.show_source_line = false});
}

const char* kFixedFunction = R"(texture Height;
float4x4 Wvp;
technique emboss
{
    pass p0
    {
        Texture[0] = <Height>;
        Texture[1] = <Height>;
        ColorOp[0] = SelectArg1;
        ColorArg1[0] = Texture;
        ColorOp[1] = Subtract;
        ColorOp[2] = Disable;
    }
}
technique dot3
{
    pass p0
    {
        Texture[0] = <Height>;
        ColorOp[0] = DotProduct3;
    }
}
)";

TEST(TechniqueValidation, FixedFunctionStatesAreRejectedOnModernWithTheirLines) {
  auto l = parse(kFixedFunction);
  auto v = validate(*l, caps("modern"));
  ASSERT_EQ(v.size(), 2u);
  EXPECT_FALSE(v[0].valid);
  // One reason per pass, the pass's other fixed-function states as located notes.
  ASSERT_EQ(v[0].reasons.size(), 1u) << all(*l, v[0]);
  const fx::Diagnostic& first = v[0].reasons[0];
  EXPECT_EQ(first.id, "fixed-function-state");
  EXPECT_EQ(first.severity, fx::Severity::note);
  EXPECT_EQ(first.message,
            "fixed-function state 'ColorOp[0]' has no Vulkan equivalent (modern has no fixed-function texture "
            "stages); 3 more in pass 'p0'");
  EXPECT_EQ(line_of(*l, first), 9u);
  EXPECT_EQ(fx::located_reason(first, l->file->sources).rfind("v.fx:9: fixed-function state 'ColorOp[0]'", 0), 0u);
  ASSERT_EQ(first.notes.size(), 3u);
  EXPECT_EQ(first.notes[1].message, "fixed-function state 'ColorOp[1]' here too");
  EXPECT_EQ(l->file->sources.presumed(first.notes[1].location).line, 11u);
}

TEST(TechniqueValidation, FixedFunctionStagesRunWhereTheCapsHaveTheOperations) {
  auto l = parse(kFixedFunction);
  auto dx7 = validate(*l, caps("dx7"));
  EXPECT_TRUE(dx7[0].valid) << all(*l, dx7[0]);
  EXPECT_TRUE(dx7[1].valid) << all(*l, dx7[1]);
  // dx6 has subtract but no DOTPRODUCT3.
  auto dx6 = validate(*l, caps("dx6"));
  EXPECT_TRUE(dx6[0].valid) << all(*l, dx6[0]);
  ASSERT_FALSE(dx6[1].valid);
  ASSERT_EQ(dx6[1].reasons.size(), 1u) << all(*l, dx6[1]);
  EXPECT_EQ(dx6[1].reasons[0].id, "state-needs-feature");
  EXPECT_EQ(dx6[1].reasons[0].message,
            "'ColorOp[0] = DotProduct3' needs dot3 (D3DTOP_DOTPRODUCT3), not supported on dx6");
  EXPECT_EQ(line_of(*l, dx6[1].reasons[0]), 20u);
  // Without subtract the emboss stage 1 fails.
  fx::DeviceCaps no_subtract = caps("dx7");
  no_subtract.features.subtract = false;
  auto v = validate(*l, no_subtract);
  ASSERT_FALSE(v[0].valid);
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 11u);
}

TEST(TechniqueValidation, TextureStagesBeyondTheDeviceAreLocatedAtTheState) {
  auto l = parse(R"(texture T;
technique four
{
    pass p0
    {
        Texture[0] = <T>;
        Texture[3] = <T>;
        Texture[1] = NULL;
    }
}
)");
  auto v = validate(*l, caps("dx7"));
  ASSERT_FALSE(v[0].valid);
  ASSERT_EQ(v[0].reasons.size(), 1u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].id, "too-many-textures");
  EXPECT_EQ(v[0].reasons[0].message, "needs 4 simultaneous_textures, dx7 has 2");
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 7u);
  EXPECT_TRUE(validate(*l, caps("dx8"))[0].valid);
}

const char* kHlsl = R"(float4x4 Wvp;
sampler2D S;
struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.pos = mul(p, Wvp); o.uv = uv; return o; }
float4 PS(float2 uv : TEXCOORD0) : COLOR { return tex2D(S, uv); }
technique sm2
< string Requires = "vs_2_0 ps_2_0"; >
{
    pass p0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 PS();
    }
}
)";

TEST(TechniqueValidation, ShaderProfilesAreCheckedAtTheCompileExpression) {
  auto l = parse(kHlsl);
  auto v = validate(*l, caps("dx7"));
  ASSERT_FALSE(v[0].valid);
  // The Requires annotation says the same thing as the passes: reported once, at the pass.
  ASSERT_EQ(v[0].reasons.size(), 2u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].id, "unsupported-shader-profile");
  EXPECT_EQ(v[0].reasons[0].message, "vs_2_0 not supported on dx7");
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 11u);
  EXPECT_EQ(v[0].reasons[1].message, "ps_2_0 not supported on dx7");
  EXPECT_EQ(line_of(*l, v[0].reasons[1]), 12u);
  auto modern = validate(*l, caps("modern"));
  EXPECT_TRUE(modern[0].valid) << all(*l, modern[0]);
}

TEST(TechniqueValidation, AssemblyVersionComesFromTheFirstToken) {
  auto l = parse(R"(technique ps14
{
    pass p0
    {
        PixelShader = asm
        {
            ps.1.4
            texld r0, t0
            mov r0, r0
        };
    }
}
technique ps11
{
    pass p0
    {
        PixelShader = asm
        {
            ps.1.1
            tex t0
            tex t3
            mov r0, t0
        };
    }
}
)");
  auto dx8 = validate(*l, caps("dx8"));
  ASSERT_FALSE(dx8[0].valid);
  EXPECT_EQ(dx8[0].reasons[0].message, "ps_1_4 not supported on dx8");
  EXPECT_EQ(line_of(*l, dx8[0].reasons[0]), 5u);
  EXPECT_TRUE(dx8[1].valid) << all(*l, dx8[1]);
  EXPECT_TRUE(validate(*l, caps("dx8_1"))[0].valid);
  // ps.1.1 samples stage n into tn: t3 needs four texture stages.
  fx::DeviceCaps two = caps("dx8");
  two.limits.simultaneous_textures = 2;
  auto v = validate(*l, two);
  ASSERT_FALSE(v[1].valid);
  EXPECT_EQ(v[1].reasons[0].message, "needs 4 simultaneous_textures, dx8 has 2");
  auto modern = validate(*l, caps("modern"));
  EXPECT_EQ(modern[1].reasons[0].message, "ps_1_1 not supported on modern");
}

TEST(TechniqueValidation, GlslVersionComesFromTheBlocks) {
  auto l = parse(R"(GLSLShader Header
{
#version 450
}
GLSLShader VS
{
layout(location = 0) in vec4 p;
void main() { gl_Position = p; }
}
GLSLShader FS
{
layout(location = 0) out vec4 c;
void main() { c = vec4(1); }
}
technique g
{
    pass p0
    {
        VertexShader = { Header, VS };
        PixelShader = { Header, FS };
    }
}
)");
  auto dx9 = validate(*l, caps("dx9"));
  ASSERT_FALSE(dx9[0].valid);
  EXPECT_EQ(dx9[0].reasons[0].message, "glsl_450 not supported on dx9");
  EXPECT_EQ(line_of(*l, dx9[0].reasons[0]), 19u);
  auto modern = validate(*l, caps("modern"));
  EXPECT_TRUE(modern[0].valid) << all(*l, modern[0]);
}

TEST(TechniqueValidation, RequiresAnnotationIsLocatedAtTheAnnotation) {
  auto l = parse(R"(technique t
< string Requires = "dot3 textures>=3 bogus_feature"; >
{
    pass p0 { }
}
)");
  auto v = validate(*l, caps("dx6"));
  ASSERT_FALSE(v[0].valid);
  ASSERT_EQ(v[0].reasons.size(), 3u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].id, "unmet-requirement");
  EXPECT_EQ(v[0].reasons[0].message, "Requires: dot3 not supported on dx6");
  EXPECT_EQ(v[0].reasons[1].message, "Requires: needs 3 simultaneous_textures, dx6 has 2");
  EXPECT_EQ(v[0].reasons[2].id, "bad-requires");
  for (const auto& r : v[0].reasons) EXPECT_EQ(line_of(*l, r), 2u);
}

TEST(TechniqueValidation, CompileErrorsAreRejectionsWithTheCompilersMessage) {
  auto l = parse(R"(float4 PS() : COLOR
{
    return float3(1, 2);
}
technique broken
{
    pass p0
    {
        PixelShader = compile ps_2_0 PS();
    }
}
)");
  auto v = validate(*l, caps("modern"));
  ASSERT_FALSE(v[0].valid);
  ASSERT_FALSE(v[0].reasons.empty());
  EXPECT_EQ(v[0].reasons[0].id, "shader-compile-failed");
  EXPECT_NE(v[0].reasons[0].message.find("not enough data provided for construction"), std::string::npos)
      << v[0].reasons[0].message;
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 3u);
  ASSERT_EQ(v[0].reasons[0].notes.size(), 1u);
  EXPECT_EQ(l->file->sources.presumed(v[0].reasons[0].notes[0].location).line, 9u);
  // Without compiling, the same technique looks valid: the profile is fine.
  EXPECT_TRUE(validate(*l, caps("modern"), /*compile=*/false)[0].valid);
}

TEST(TechniqueValidation, CompiledProgramsStayWithinTheDeviceLimits) {
  auto l = parse(R"(float4x4 Bones[8];
struct V { float4 pos : POSITION; float4 a : TEXCOORD0; float4 b : TEXCOORD1; float4 c : TEXCOORD2; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, Bones[0]); o.a = p; o.b = p; o.c = p; return o; }
float4 PS(float4 a : TEXCOORD0, float4 b : TEXCOORD1, float4 c : TEXCOORD2) : COLOR { return a + b + c; }
technique t
{
    pass p0
    {
        VertexShader = compile vs_2_0 VS();
        PixelShader = compile ps_2_0 PS();
    }
}
)");
  fx::DeviceCaps small = caps("modern");
  EXPECT_TRUE(validate(*l, small)[0].valid);
  small.limits.interpolators = 2;
  small.limits.uniform_bytes = 256;
  auto v = validate(*l, small);
  ASSERT_FALSE(v[0].valid);
  std::string text = all(*l, v[0]);
  ASSERT_EQ(v[0].reasons.size(), 2u) << text;
  EXPECT_EQ(v[0].reasons[0].id, "shader-exceeds-limit");
  EXPECT_EQ(v[0].reasons[0].message, "vertex shader: needs 512 uniform_bytes, modern has 256");
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 9u);
  EXPECT_EQ(v[0].reasons[1].message, "fragment shader inputs: needs 3 interpolators, modern has 2");
  EXPECT_EQ(line_of(*l, v[0].reasons[1]), 10u);
}

// SV_ClipDistance compiles to SPIR-V's ClipDistance capability, which a Vulkan device runs
// only with shaderClipDistance: without it the technique is rejected at the vertex shader.
TEST(TechniqueValidation, ShaderCapabilitiesNeedTheirVulkanFeature) {
  auto l = parse(R"(float4x4 Wvp;
struct V { float4 pos : SV_Position; float clip : SV_ClipDistance0; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, Wvp); o.clip = p.y; return o; }
float4 PS(V i) : SV_Target { return 1; }
technique10 t
{
    pass p0
    {
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, PS()));
    }
}
)");
  fx::DeviceCaps device = caps("modern");
  device.name = "gpu";
  EXPECT_TRUE(validate(*l, device)[0].valid) << "caps without a Vulkan device list no features";
  device.vulkan.present = true;
  auto v = validate(*l, device);
  ASSERT_FALSE(v[0].valid);
  // The pixel shader reads the same struct, so its module declares the capability too.
  ASSERT_EQ(v[0].reasons.size(), 2u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].id, "shader-needs-feature");
  EXPECT_EQ(v[0].reasons[0].message,
            "vertex shader uses SV_ClipDistance (SPIR-V capability ClipDistance): "
            "Vulkan feature shaderClipDistance not supported on gpu");
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 9u);
  EXPECT_EQ(v[0].reasons[1].message.substr(0, 36), "fragment shader uses SV_ClipDistance");
  EXPECT_EQ(line_of(*l, v[0].reasons[1]), 10u);
  device.vulkan.features = {"shaderClipDistance"};
  EXPECT_TRUE(validate(*l, device)[0].valid) << all(*l, validate(*l, device)[0]);
}

// Hull and domain shaders compile to SPIR-V's Tessellation capability: a Vulkan device
// without tessellationShader rejects the technique at each tessellation stage instead of
// calling it valid and failing when its pipeline is made.
constexpr const char* kTessellationEffect = R"(float4x4 Wvp;
struct V { float4 pos : SV_Position; };
struct F { float edges[3] : SV_TessFactor; float inside : SV_InsideTessFactor; };
V VS(float4 p : POSITION) { V o; o.pos = mul(p, Wvp); return o; }
F Factors(InputPatch<V, 3> patch) { F f; f.edges[0] = f.edges[1] = f.edges[2] = 2; f.inside = 2; return f; }
[domain("tri")] [partitioning("integer")] [outputtopology("triangle_cw")] [outputcontrolpoints(3)]
[patchconstantfunc("Factors")]
V HS(InputPatch<V, 3> patch, uint i : SV_OutputControlPointID) { return patch[i]; }
[domain("tri")] V DS(F f, float3 uvw : SV_DomainLocation, const OutputPatch<V, 3> patch) {
  V o; o.pos = uvw.x * patch[0].pos + uvw.y * patch[1].pos + uvw.z * patch[2].pos; return o; }
float4 PS(V i) : SV_Target { return 1; }
technique11 t
{
    pass p0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetHullShader(CompileShader(hs_5_0, HS()));
        SetDomainShader(CompileShader(ds_5_0, DS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
)";

TEST(TechniqueValidation, TessellationNeedsTheDevicesTessellationShaderFeature) {
  auto l = parse(kTessellationEffect);
  fx::DeviceCaps device = caps("modern");
  device.name = "gpu";
  device.vulkan.present = true;
  auto v = validate(*l, device);
  ASSERT_FALSE(v[0].valid);
  ASSERT_EQ(v[0].reasons.size(), 2u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].id, "shader-needs-feature");
  EXPECT_EQ(v[0].reasons[0].message,
            "hull shader uses tessellation (SPIR-V capability Tessellation): "
            "Vulkan feature tessellationShader not supported on gpu");
  EXPECT_EQ(v[0].reasons[1].message.substr(0, 31), "domain shader uses tessellation");
  device.vulkan.features = {"tessellationShader"};
  EXPECT_TRUE(validate(*l, device)[0].valid) << all(*l, validate(*l, device)[0]);

  // A hull shader without its domain shader cannot tessellate, on any device.
  std::string text = kTessellationEffect;
  const std::string domain_line = "        SetDomainShader(CompileShader(ds_5_0, DS()));\n";
  text.erase(text.find(domain_line), domain_line.size());
  auto hull_only = parse(text);
  auto h = validate(*hull_only, device);
  ASSERT_FALSE(h[0].valid);
  ASSERT_EQ(h[0].reasons.size(), 1u) << all(*hull_only, h[0]);
  EXPECT_EQ(h[0].reasons[0].id, "missing-tessellation-stage");
  EXPECT_EQ(h[0].reasons[0].message, "pass sets a hull shader but no domain shader; tessellation needs both");
  EXPECT_EQ(line_of(*hull_only, h[0].reasons[0]), 17u);
}

// Direct3D 10/11 and Vulkan draw only with a vertex shader; a Direct3D 9 pass without one
// gets the fixed-function vertex stage.
TEST(TechniqueValidation, ADirect3D10PassWithoutAVertexShaderCannotDraw) {
  auto l = parse(R"(struct V { float4 pos : SV_Position; };
[maxvertexcount(1)]
void GS(point V input[1], inout PointStream<V> s) { s.Append(input[0]); }
float4 PS(V i) : SV_Target { return 1; }
float4 VS(float4 p : POSITION) : SV_Position { return p; }
technique11 stream_out { pass p0 { SetVertexShader(NULL); SetGeometryShader(CompileShader(gs_5_0, GS())); } }
technique11 drawn { pass p0 { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
technique d3d9 { pass p0 { PixelShader = compile ps_2_0 PS(); } }
)");
  auto v = validate(*l, caps("modern"), /*compile=*/false);
  ASSERT_EQ(v.size(), 3u);
  ASSERT_EQ(v[0].reasons.size(), 1u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].id, "missing-vertex-shader");
  EXPECT_EQ(v[0].reasons[0].message, "pass sets a geometry shader but no vertex shader, which drawing needs");
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 6u);
  EXPECT_TRUE(v[1].valid) << all(*l, v[1]);
  EXPECT_TRUE(v[2].valid) << all(*l, v[2]);
}

TEST(TechniqueValidation, TextureFormatsAndCapsDependentStates) {
  auto l = parse(R"(texture F < string Format = "float32"; >;
technique t
{
    pass p0
    {
        Texture[0] = <F>;
        AlphaTestEnable = TRUE;
        SeparateAlphaBlendEnable = TRUE;
    }
}
)");
  auto dx8 = validate(*l, caps("dx8"));
  ASSERT_FALSE(dx8[0].valid);
  ASSERT_EQ(dx8[0].reasons.size(), 2u) << all(*l, dx8[0]);
  EXPECT_EQ(dx8[0].reasons[0].id, "unsupported-format");
  EXPECT_EQ(dx8[0].reasons[0].message, "texture 'F' is float32: float_textures not supported on dx8");
  EXPECT_EQ(line_of(*l, dx8[0].reasons[0]), 1u);
  EXPECT_EQ(dx8[0].reasons[1].message,
            "'SeparateAlphaBlendEnable = TRUE' needs separate_alpha_blend, not supported on dx8");
  EXPECT_TRUE(validate(*l, caps("dx9"))[0].valid);
  auto modern = validate(*l, caps("modern"));
  ASSERT_EQ(modern[0].reasons.size(), 1u) << all(*l, modern[0]);
  EXPECT_EQ(line_of(*l, modern[0].reasons[0]), 7u);
  // A Vulkan device is asked for the format itself.
  fx::DeviceCaps device = caps("dx9");
  device.vulkan.present = true;
  device.vulkan.formats = {{.format = "R32G32B32A32_SFLOAT", .sampled = false}};
  auto v = validate(*l, device);
  ASSERT_EQ(v[0].reasons.size(), 1u) << all(*l, v[0]);
  EXPECT_EQ(v[0].reasons[0].message, "texture 'F': format R32G32B32A32_SFLOAT not usable for sampled on dx9");
}

TEST(TechniqueValidation, FindNextValidWalksInDeclarationOrder) {
  auto l = parse(std::string(kFixedFunction) + R"(technique last { pass p0 { } }
)");
  auto v = validate(*l, caps("dx6"));
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(fx::find_next_valid(v), 0u);
  EXPECT_EQ(fx::find_next_valid(v, 0), 2u);  // dot3 is invalid on dx6
  EXPECT_EQ(fx::find_next_valid(v, 2), std::nullopt);
  EXPECT_EQ(fx::find_next_valid(v, 7), std::nullopt);
}

TEST(TechniqueValidation, ValidateTechniqueOnAModelAndItsAnnotations) {
  auto l = parse(
      R"(technique a < string Scheme = "quality"; float MaxDistance = 20; int Priority = 2; bool B = true; float2 V = {1, 2}; > { pass p0 { } })");
  fx::EffectModel model = fx::build_effect_model(l->file->parsed, l->file->sources, l->diags);
  ASSERT_EQ(model.techniques.size(), 1u);
  fx::TechniqueValidation t = fx::validate_technique(model, model.techniques[0], caps("dx6"));
  EXPECT_TRUE(t.valid);
  EXPECT_EQ(t.name, "a");
  ASSERT_EQ(t.annotations.size(), 4u);  // the vector is not a selection value
  EXPECT_EQ(std::get<std::string>(t.annotations[0].second), "quality");
  EXPECT_EQ(std::get<float>(t.annotations[1].second), 20.f);
  EXPECT_EQ(std::get<int32_t>(t.annotations[2].second), 2);
  EXPECT_EQ(std::get<bool>(t.annotations[3].second), true);
}

}  // namespace

// Stream output needs VK_EXT_transform_feedback on a Vulkan device: without it the technique
// is refused at ConstructGSWithSO (also for a vertex shader handed to it); a Direct3D 10/11
// profile describes hardware that has it.
TEST(TechniqueValidation, StreamOutputNeedsTransformFeedback) {
  auto l = parse(R"(struct V { float4 pos : POSITION; };
V VS(V v) { return v; }
[maxvertexcount(1)] void GS(point V v[1], inout PointStream<V> s) { s.Append(v[0]); }
technique10 particles { pass p0 {
  SetVertexShader(CompileShader(vs_4_0, VS()));
  SetGeometryShader(ConstructGSWithSO(CompileShader(gs_4_0, GS()), "POSITION.xyzw"));
} }
technique11 vertices { pass p0 { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()), "POSITION")); } }
)");
  fx::DeviceCaps device = caps("modern");
  device.name = "gpu";
  device.vulkan.present = true;
  auto v = validate(*l, device, /*compile=*/false);
  ASSERT_EQ(v.size(), 2u);
  for (const auto& t : v) {
    ASSERT_EQ(t.reasons.size(), 1u) << all(*l, t);
    EXPECT_EQ(t.reasons[0].id, "unsupported-stream-output");
    EXPECT_EQ(t.reasons[0].message,
              "stream output (ConstructGSWithSO) needs VK_EXT_transform_feedback with transform feedback draws, "
              "not enabled on gpu");
  }
  EXPECT_EQ(line_of(*l, v[0].reasons[0]), 6u);
  EXPECT_EQ(line_of(*l, v[1].reasons[0]), 8u);
  device.vulkan.extensions = {"VK_EXT_transform_feedback"};
  for (const auto& t : validate(*l, device, /*compile=*/false)) EXPECT_TRUE(t.valid) << all(*l, t);
  for (const auto& t : validate(*l, caps("modern"), /*compile=*/false)) EXPECT_TRUE(t.valid) << all(*l, t);
}
