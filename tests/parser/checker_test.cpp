#include "fx/checker.h"

#include <gtest/gtest.h>

#include "fx/diagnostic_render.h"
#include "fx/parser.h"

namespace fx {
namespace {

// Parses `source` (which must parse cleanly) and checks it.
struct Checked {
  SourceManager sm;
  DiagnosticSink diags;
  std::vector<std::string> ids() const {
    std::vector<std::string> out;
    for (const Diagnostic& d : diags.diagnostics()) out.push_back(d.id);
    return out;
  }
  std::string text() const { return render_text(diags.diagnostics(), sm); }
};

std::unique_ptr<Checked> check(std::string_view source, CheckOptions options = {}) {
  auto c = std::make_unique<Checked>();
  BufferId b = c->sm.add_buffer("t.fx", std::string(source));
  ast::Effect fx = parse_effect(lex_all(c->sm, b, c->diags), c->sm, c->diags);
  EXPECT_FALSE(c->diags.has_errors()) << "parse failed:\n" << c->text();
  check_effect(fx, c->sm, c->diags, options);
  return c;
}

using Ids = std::vector<std::string>;

constexpr std::string_view kD3D9Effect = R"(
float4x4 mWld : WORLD;
float4x4 mTot : WORLDVIEWPROJECTION;
float4 MaterialColor < string UIName = "Material"; float UIMin = 0; float3 Dir = {0, 1, 0}; > = {1, 1, 1, 1};
texture BRDFTexture1;
texture ObjectTexture < string ResourceName = "wood.dds"; >;
DWORD BCLR = 0xff0000ff;
string XFile = "sphere.x";
sampler2D ObjectSampler = sampler_state {
  Texture = <ObjectTexture>;
  AddressU = Clamp; AddressV = D3DTADDRESS_WRAP; MinFilter = Linear; MagFilter = LINEAR;
  MipFilter = None; BorderColor = 0xff000000; MaxAnisotropy = 4; SRGBTexture = true;
};
struct VSOut { float4 pos : POSITION; };
VSOut VS(float4 p : POSITION) { VSOut o; o.pos = mul(p, mTot); return o; }
VSOut VS(float4 p : POSITION, float3 n : NORMAL) { VSOut o; o.pos = p; return o; }
float4 PS() : COLOR { return MaterialColor; }
technique BRDF < string Description = "per-pixel"; > {
  pass p0 {
    VertexShaderConstant[0] = <mWld>;
    VertexShaderConstant[4] = <mTot>;
    Texture[0] = <BRDFTexture1>;
    AddressU[0] = clamp; AddressV[3] = wrap;
    ColorOp[0] = DotProduct3; ColorArg1[0] = Texture | Complement; ColorArg2[0] = Diffuse;
    ColorOp[1] = Disable; AlphaOp[1] = Disable;
    ZEnable = TRUE; ZWriteEnable = false; ZFunc = LessEqual; CullMode = D3DCULL_CCW;
    AlphaBlendEnable = TRUE; SrcBlend = SrcAlpha; DestBlend = INV_SRC_ALPHA;
    ColorWriteEnable = Red | Green | Blue; StencilRef = 1; DepthBias = 0.5f;
    BlendFactor = BCLR; AlphaRef = 0x80;
    VertexShader = compile vs_2_0 VS();
    PixelShader = compile ps_2_0 PS();
  }
  pass p1 {
    VertexShader = asm { vs.1.1 mov oPos, v0 };
    PixelShader = NULL;
  }
}
)";

TEST(Checker, CleanD3D9EffectHasNoDiagnostics) {
  auto c = check(kD3D9Effect);
  EXPECT_EQ(c->text(), "");
  EXPECT_EQ(infer_profile(parse_effect({}, c->sm, c->diags)), EffectProfile::fx_2_0);
}

TEST(Checker, UnknownStateSuggestsTheClosestName) {
  auto c = check("technique t { pass p {\n  CullMod = None;\n} }\n");
  EXPECT_EQ(c->text(),
            "t.fx:2:3: error: unknown state 'CullMod' in a pass; did you mean 'CullMode'? "
            "[unknown-state]\n"
            "  CullMod = None;\n"
            "  ^~~~~~~\n"
            "t.fx:2:3: note: fix-it: replace with 'CullMode'\n");
}

TEST(Checker, UnknownStateInEachBlockUsesThatBlocksNames) {
  auto c = check(
      "sampler s = sampler_state { MinFiltr = Linear; Filter = MIN_MAG_MIP_LINEAR; };\n"
      "technique t { pass p { } }\n");
  ASSERT_EQ(c->ids(), (Ids{"unknown-state", "unknown-state"}));
  const auto& d = c->diags.diagnostics();
  EXPECT_EQ(d[0].message, "unknown state 'MinFiltr' in a sampler_state; did you mean 'MinFilter'?");
  EXPECT_EQ(d[1].message, "unknown state 'Filter' in a sampler_state");  // a D3D10 field
  auto b = check(
      "BlendState b { BlendEnabel[0] = TRUE; ZEnable = TRUE; };\n"
      "technique10 t { pass p { SetBlendState(b, float4(0, 0, 0, 0), 0xffffffff); } }\n");
  ASSERT_EQ(b->ids(), (Ids{"unknown-state", "unknown-state"}));
  const auto& e = b->diags.diagnostics();
  EXPECT_EQ(e[0].message, "unknown state 'BlendEnabel' in a BlendState; did you mean 'BlendEnable'?");
  EXPECT_EQ(e[1].message, "unknown state 'ZEnable' in a BlendState");
}

TEST(Checker, UnknownEnumValueSuggestsTheClosestValue) {
  auto c = check("technique t { pass p {\n  AddressU[0] = Clmp;\n  ZFunc = 9;\n  ZFunc = 0;\n} }\n");
  EXPECT_EQ(c->ids(), (Ids{"unknown-state-value", "unknown-state-value", "duplicate-state", "unknown-state-value"}));
  EXPECT_EQ(c->text().substr(0, c->text().find("t.fx:3")),
            "t.fx:2:17: error: unknown value 'Clmp' for state 'AddressU'; did you mean 'Clamp'? "
            "[unknown-state-value]\n"
            "  AddressU[0] = Clmp;\n"
            "                ^~~~\n"
            "t.fx:2:17: note: fix-it: replace with 'Clamp'\n");
  EXPECT_EQ(c->diags.diagnostics()[1].message, "9 is not a value of state 'ZFunc'");
}

TEST(Checker, WrongValueTypes) {
  auto c = check(
      "texture t; float4 f; VertexShader vs;\n"
      "technique t0 { pass p {\n"
      "  ZWriteEnable = \"yes\";\n"
      "  Texture[0] = <f>;\n"
      "  Texture[1] = 3;\n"
      "  VertexShader = f;\n"
      "  ZEnable = t;\n"
      "  PixelShader = \"ps\";\n"
      "  CullMode = {1, 2};\n"
      "  VertexShader = vs;\n"
      "} }\n");
  EXPECT_EQ(c->ids(), (Ids{"state-type-mismatch", "state-type-mismatch", "state-type-mismatch", "state-type-mismatch",
                           "state-type-mismatch", "state-type-mismatch", "state-type-mismatch", "duplicate-state"}));
  EXPECT_EQ(c->diags.diagnostics()[0].message, "state 'ZWriteEnable' expects a value of type bool, found a string");
  EXPECT_EQ(c->diags.diagnostics()[1].message,
            "state 'Texture' expects a value of type texture, found 'float4' parameter 'f'");
}

TEST(Checker, IndexRules) {
  auto c = check(
      "float4x4 m; texture tx;\n"
      "technique t { pass p {\n"
      "  ColorOp[8] = Modulate;\n"
      "  Texture[16] = <tx>;\n"
      "  ZEnable[0] = TRUE;\n"
      "  VertexShaderConstant = <m>;\n"
      "  AddressU[15] = Clamp;\n"
      "} }\n");
  EXPECT_EQ(c->ids(), (Ids{"state-index-out-of-range", "state-index-out-of-range", "state-not-indexable",
                           "state-index-required"}));
  EXPECT_EQ(c->diags.diagnostics()[0].message, "index 8 is out of range for state 'ColorOp'; valid indices are 0..7");
}

TEST(Checker, DuplicateStateWarnsWithNote) {
  auto c = check("technique t { pass p {\n  CullMode = None;\n  cullmode = CW;\n} }\n");
  ASSERT_EQ(c->ids(), (Ids{"duplicate-state"}));
  EXPECT_EQ(c->text(),
            "t.fx:3:3: warning: state 'CullMode' is set twice in this block; the last value wins "
            "[duplicate-state]\n"
            "  cullmode = CW;\n"
            "  ^~~~~~~~\n"
            "t.fx:2:3: note: previous assignment is here\n");
}

TEST(Checker, DuplicateDefinitionsPointAtThePreviousOne) {
  auto c = check(
      "float4 Color;\n"
      "float4 Color;\n"
      "float f(float a) { return a; }\n"
      "float f(float3 a) { return a.x; }\n"
      "float g(float a);\n"
      "float g(float a) { return a; }\n"
      "float f(float b) { return b; }\n"
      "technique10 t { pass p {} pass p {} }\n"
      "technique u { pass p {} }\n"
      "technique t { pass q {} }\n");
  EXPECT_EQ(c->ids(),
            (Ids{"duplicate-definition", "duplicate-definition", "duplicate-definition", "duplicate-definition"}))
      << c->text();
  EXPECT_NE(c->text().find("t.fx:2:8: error: parameter 'Color' is already defined "
                           "[duplicate-definition]\nfloat4 Color;\n       ^~~~~\n"
                           "t.fx:1:8: note: previous definition is here\n"),
            std::string::npos)
      << c->text();
  EXPECT_NE(c->text().find("t.fx:7:7: error: function 'f' is already defined"), std::string::npos);
  EXPECT_NE(c->text().find("t.fx:8:32: error: pass 'p' is already defined"), std::string::npos) << c->text();
  EXPECT_NE(c->text().find("t.fx:10:11: error: technique 't' is already defined"), std::string::npos);
}

// D3DX9 effects that ship with two passes of one name load (passes are addressed by index):
// a warning in a D3D9 technique of an fx_2_0 effect, an error where the D3D10/11 compilers
// keep passes in a scope per technique.
TEST(Checker, DuplicatePassNamesOfD3D9TechniquesWarn) {
  const char* source = "technique t { pass p {} pass p {} }\n";
  auto c = check(source, {.profile = EffectProfile::fx_2_0});
  EXPECT_EQ(c->ids(), (Ids{"duplicate-pass-name"})) << c->text();
  EXPECT_EQ(c->diags.diagnostics()[0].severity, Severity::warning);
  EXPECT_EQ(check(source)->ids(), (Ids{"duplicate-pass-name"}));
  EXPECT_EQ(check(source, {.profile = EffectProfile::fx_5_0})->ids(), (Ids{"d3d9-technique", "duplicate-definition"}));
}

TEST(Checker, UndefinedReferences) {
  auto c = check(
      "float4x4 mWorld; float4 PSMain() : COLOR { return 0; }\n"
      "technique t { pass p {\n"
      "  VertexShaderConstant[0] = <mWrld>;\n"
      "  VertexShader = compile vs_2_0 VSMain();\n"
      "  PixelShader = compile ps_2_0 PSMan();\n"
      "  Texture[0] = <nothing>;\n"
      "} }\n");
  EXPECT_EQ(c->ids(),
            (Ids{"undefined-reference", "undefined-reference", "undefined-reference", "undefined-reference"}));
  const auto& d = c->diags.diagnostics();
  EXPECT_EQ(d[0].message, "use of undefined parameter 'mWrld'; did you mean 'mWorld'?");
  ASSERT_EQ(d[0].fixits.size(), 1u);
  EXPECT_EQ(c->sm.text_at(d[0].fixits[0].range.begin).substr(0, 5), "mWrld");
  EXPECT_EQ(d[1].message, "use of undefined function 'VSMain'; did you mean 'PSMain'?");
  EXPECT_EQ(d[2].message, "use of undefined function 'PSMan'; did you mean 'PSMain'?");
  ASSERT_EQ(d[2].fixits.size(), 1u);
  EXPECT_EQ(c->sm.text_at(d[2].fixits[0].range.begin).substr(0, 6), "PSMan(");
  EXPECT_EQ(d[3].message, "use of undefined parameter 'nothing'");
}

TEST(Checker, ShaderProfilesAndStages) {
  auto c = check(
      "float4 VS() : POSITION { return 0; }\n"
      "technique t { pass p {\n"
      "  PixelShader = compile vs_2_0 VS();\n"
      "  VertexShader = compile vs_9_0 VS();\n"
      "} }\n");
  EXPECT_EQ(c->ids(), (Ids{"shader-stage-mismatch", "unknown-shader-profile"}));
  EXPECT_EQ(c->diags.diagnostics()[0].message, "state 'PixelShader' needs a ps_* profile, found 'vs_2_0'");
}

// Stream output may capture a vertex shader (no geometry stage); any other stage is still
// a mismatch there.
TEST(Checker, StreamOutputTakesAVertexOrGeometryShader) {
  auto c = check(
      "float4 VS() : SV_Position { return 0; }\n"
      "technique10 t {\n"
      "  pass a { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_4_0, VS()), \"SV_POSITION.xyzw\")); }\n"
      "  pass b { SetGeometryShader(ConstructGSWithSO(CompileShader(ps_4_0, VS()), \"SV_POSITION.xyzw\")); }\n"
      "}\n");
  ASSERT_EQ(c->ids(), (Ids{"shader-stage-mismatch"})) << c->text();
  EXPECT_EQ(c->diags.diagnostics()[0].message, "state 'SetGeometryShader' needs a gs_* profile, found 'ps_4_0'");
}

// Stream-output declarations are parsed as FX11 parses them, each problem located inside
// the string: a slot past 3, a mask that is no run of xyzw/rgba, an unknown $ gap, and a
// rasterized stream past 3 (fx_5_0's form); slots, semantic indices, gaps and rgba pass.
TEST(Checker, StreamOutputDeclarationsAreCheckedWhereTheyAreWritten) {
  auto c = check(
      "struct G { float4 p : SV_Position; float3 n : NORMAL; float2 t : TEXCOORD1; };\n"
      "[maxvertexcount(3)] void GS(triangle G i[3], inout TriangleStream<G> s) { s.Append(i[0]); }\n"
      "technique11 t {\n"
      "  pass ok { SetGeometryShader(ConstructGSWithSO(CompileShader(gs_4_0, GS()), "
      "\"SV_Position.xyz; 1:NORMAL.rgb; $SKIP.x; TEXCOORD1.yz\")); }\n"
      "  pass bad { SetGeometryShader(ConstructGSWithSO(CompileShader(gs_4_0, GS()), "
      "\"4:NORMAL.xyz; SV_Position.xz; $GAP\")); }\n"
      "  pass five { SetGeometryShader(ConstructGSWithSO(CompileShader(gs_5_0, GS()), "
      "\"SV_Position.xyzw\", NULL, NULL, \"0:NORMAL.x\", 7)); }\n"
      "}\n");
  ASSERT_EQ(c->ids(), (Ids{"bad-stream-out-decl", "bad-stream-out-decl", "bad-stream-out-decl", "bad-stream-out-decl"}))
      << c->text();
  const std::string text = c->text();
  EXPECT_NE(text.find("5:80: error: stream-output declaration: output slot 4 is out of range"), std::string::npos)
      << text;
  EXPECT_NE(text.find("5:106: error: stream-output declaration: component mask 'xz'"), std::string::npos) << text;
  EXPECT_NE(text.find("5:110: error: stream-output declaration: unknown '$GAP'"), std::string::npos) << text;
  EXPECT_NE(text.find("6:126: error: rasterized stream 7 is out of range"), std::string::npos) << text;
}

// Profiles match in any case, and only whole: the longest, a prefix or an extension of one,
// and one past the 16 characters the lookup packs are told apart.
TEST(Checker, ShaderProfileNamesMatchWhole) {
  auto profile_ids = [](std::string_view profile) {
    return check(
               "float4 PS() : COLOR { return 0; }\n"
               "technique t { pass p { PixelShader = compile " +
               std::string(profile) + " PS(); } }\n")
        ->ids();
  };
  for (std::string_view known : {"ps_2_0", "PS_3_0", "ps_4_0_level_9_3", "Ps_2_Sw", "ps_5_0"})
    EXPECT_EQ(profile_ids(known), Ids{}) << known;
  for (std::string_view unknown :
       {"ps", "ps_", "ps_2", "ps_2_00", "ps_4_0_level_9_31", "ps_4_0_level_9_3x", "ps_2_0_", "xps_2_0", "ps_9_0"})
    EXPECT_EQ(profile_ids(unknown), (Ids{"unknown-shader-profile"})) << unknown;
}

TEST(Checker, AnnotationAndParameterValueTypes) {
  auto c = check(
      "float4 c < string UIName = 3; float UIMin = \"zero\"; float3 Axis = {1, 2};\n"
      "           int Steps = 4; bool Show = true; string Names[2] = {\"a\", \"b\"};\n"
      "           string UIName = \"dup\"; >;\n"
      "string XFile = 3;\n"
      "float2 uv = {1, 2, 3};\n"
      "technique t { pass p {} }\n");
  EXPECT_EQ(c->ids(), (Ids{"annotation-type-mismatch", "annotation-type-mismatch", "annotation-type-mismatch",
                           "duplicate-definition", "parameter-type-mismatch", "parameter-type-mismatch"}))
      << c->text();
  const auto& d = c->diags.diagnostics();
  EXPECT_EQ(d[0].message, "annotation 'UIName' is a string; its value is not");
  EXPECT_EQ(d[1].message, "annotation 'UIMin' is 'float'; its value is a string");
  EXPECT_EQ(d[2].message, "annotation 'Axis' is 'float3' with 3 components; its value has 2");
  EXPECT_EQ(d[5].message, "parameter 'uv' is 'float2' with 2 components; its value has 3");
}

constexpr std::string_view kD3D11Effect = R"(
BlendState Alpha { BlendEnable[0] = TRUE; SrcBlend = SRC_ALPHA; DestBlend = INV_SRC_ALPHA;
                   RenderTargetWriteMask[0] = 0x0F; AlphaToCoverageEnable = FALSE; };
DepthStencilState Depth { DepthEnable = TRUE; DepthWriteMask = ALL; DepthFunc = LESS_EQUAL;
                          FrontFaceStencilFunc = ALWAYS; BackFaceStencilPass = INCR_SAT; };
RasterizerState Raster { CullMode = BACK; FillMode = SOLID; DepthBias = 0; };
SamplerState Linear { Filter = MIN_MAG_MIP_LINEAR; AddressU = WRAP; MaxLOD = 3.5; };
Texture2D<float4> Tex;
cbuffer PerFrame { float4x4 World; };
float4 VS(float4 p : POSITION) : SV_Position { return mul(p, World); }
float4 PS() : SV_Target { return Tex.Sample(Linear, float2(0, 0)); }
technique11 Main {
  pass P0 {
    SetVertexShader(CompileShader(vs_5_0, VS()));
    SetPixelShader(CompileShader(ps_5_0, PS()));
    SetGeometryShader(NULL);
    SetHullShader(NULL);
    SetBlendState(Alpha, float4(0, 0, 0, 0), 0xFFFFFFFF);
    SetDepthStencilState(Depth, 0);
    SetRasterizerState(Raster);
  }
}
)";

TEST(Checker, CleanD3D11EffectHasNoDiagnostics) {
  auto c = check(kD3D11Effect);
  EXPECT_EQ(c->text(), "");
  auto explicit_profile = check(kD3D11Effect, {.profile = EffectProfile::fx_5_0});
  EXPECT_EQ(explicit_profile->text(), "");
}

TEST(Checker, D3D11PassCallRules) {
  auto c = check(
      "RasterizerState R { CullMode = NONE; };\n"
      "float4 VS() : SV_Position { return 0; }\n"
      "technique11 t { pass p {\n"
      "  SetBlendState(R, float4(0, 0, 0, 0), 0xffffffff);\n"
      "  SetRasterizerState(R, 1);\n"
      "  SetVertexShader = CompileShader(vs_5_0, VS());\n"
      "  SetPixelShader(CompileShader(vs_5_0, VS()));\n"
      "  ZEnable = TRUE;\n"
      "} }\n");
  EXPECT_EQ(c->ids(), (Ids{"state-type-mismatch", "state-call-form", "state-call-form", "shader-stage-mismatch",
                           "mixed-state-api"}))
      << c->text();
  EXPECT_EQ(c->diags.diagnostics()[0].message, "state 'SetBlendState' expects a BlendState, found RasterizerState 'R'");
  EXPECT_EQ(c->diags.diagnostics()[1].message, "'SetRasterizerState' takes 1 argument, found 2");
}

TEST(Checker, ProfileRules) {
  std::string_view d3d11 = "technique11 t { pass p {} }\n";
  EXPECT_EQ(check(d3d11, {.profile = EffectProfile::fx_2_0})->ids(), (Ids{"profile-mismatch"}));
  // fxc takes technique11 under fx_4_0 and technique10 under fx_2_0 (vkd3d's tests).
  EXPECT_EQ(check(d3d11, {.profile = EffectProfile::fx_4_0})->ids(), Ids{});
  EXPECT_EQ(
      check("technique t { pass p {} }\ntechnique10 u { pass p {} }\n", {.profile = EffectProfile::fx_2_0})->ids(),
      Ids{});
  EXPECT_EQ(check(d3d11)->ids(), Ids{});

  auto objects = check("BlendState B { BlendEnable[0] = FALSE; };\ntechnique t { pass p {} }\n",
                       {.profile = EffectProfile::fx_2_0});
  EXPECT_EQ(objects->ids(), (Ids{"profile-mismatch"}));
  EXPECT_EQ(objects->diags.diagnostics()[0].message,
            "BlendState needs effect profile fx_4_0 or later; the effect is fx_2_0");

  auto d3d9 = check("technique t { pass p {} }\n", {.profile = EffectProfile::fx_5_0});
  ASSERT_EQ(d3d9->ids(), (Ids{"d3d9-technique"}));
  EXPECT_EQ(d3d9->diags.diagnostics()[0].severity, Severity::warning);

  auto hull = check("technique10 t { pass p { SetHullShader(NULL); } }\n", {.profile = EffectProfile::fx_4_0});
  EXPECT_EQ(hull->ids(), (Ids{"profile-mismatch"}));
  auto calls9 = check("technique t { pass p { SetPixelShader(NULL); } }\n", {.profile = EffectProfile::fx_2_0});
  EXPECT_EQ(calls9->ids(), (Ids{"profile-mismatch"}));
}

// The checker infers the profile only when a state needs it (see Checker::profile_): with
// `automatic` it must report what it reports when given the inferred profile, except the
// d3d9-technique warning, which only a given profile raises.
TEST(Checker, AnInferredProfileChecksAsTheSameProfileGiven) {
  const std::string_view effects[] = {
      "technique t { pass p { ZEnable = TRUE; } }\n",
      "technique11 t { pass p { SetHullShader(NULL); } }\n",
      "technique10 t { pass p { SetGeometryShader(NULL); } }\n",
      "technique t { pass p { SetComputeShader(NULL); } }\n",
      "BlendState B { BlendEnable[0] = FALSE; };\ntechnique t { pass p {} }\n",
      "cbuffer C { float4 c; };\ntbuffer T { float4 t; };\ntechnique t { pass p {} }\n",
      "fxgroup g { technique11 t { pass p {} } }\n",
      // Inference reads no stateblock_state, so its D3D10 state is too new for fx_2_0.
      "stateblock S = stateblock_state { SetPixelShader(NULL); };\ntechnique t { pass p {} }\n",
      "stateblock S = stateblock_state { SetHullShader(NULL); };\n"
      "technique10 t { pass p { SetGeometryShader(NULL); } }\n",
  };
  auto findings = [](const Checked& c) {
    std::vector<std::string> out;
    for (const Diagnostic& d : c.diags.diagnostics())
      if (d.id != "d3d9-technique") out.push_back(d.id + ": " + d.message);
    return out;
  };
  for (std::string_view source : effects) {
    SourceManager sm;
    DiagnosticSink diags;
    BufferId b = sm.add_buffer("t.fx", std::string(source));
    EffectProfile inferred = infer_profile(parse_effect(lex_all(sm, b, diags), sm, diags));
    EXPECT_EQ(findings(*check(source)), findings(*check(source, {.profile = inferred}))) << source;
  }
  EXPECT_EQ(check(effects[7])->ids(), (Ids{"profile-mismatch"}));
  EXPECT_EQ(check(effects[8])->ids(), (Ids{"profile-mismatch"}));
}

TEST(Checker, NoTechniqueIsAWarningUnlessTheEffectIsALibrary) {
  EXPECT_EQ(check("float4 c;\n")->ids(), (Ids{"no-technique"}));
  EXPECT_EQ(check("float4 c;\n")->diags.diagnostics()[0].severity, Severity::warning);
  EXPECT_EQ(check("float4 c;\n", {.require_technique = false})->ids(), Ids{});
  EXPECT_EQ(check("fxgroup g { technique11 t { pass p {} } }\n")->ids(), Ids{});
}

TEST(Checker, InfersTheProfileFromWhatTheEffectUses) {
  SourceManager sm;
  DiagnosticSink diags;
  auto infer = [&](std::string src) {
    BufferId b = sm.add_buffer("i.fx", std::move(src));
    return infer_profile(parse_effect(lex_all(sm, b, diags), sm, diags));
  };
  EXPECT_EQ(infer("technique t { pass p { ZEnable = TRUE; } }"), EffectProfile::fx_2_0);
  EXPECT_EQ(infer("technique10 t { pass p {} }"), EffectProfile::fx_4_0);
  EXPECT_EQ(infer("RasterizerState r { CullMode = NONE; }; technique t { pass p {} }"), EffectProfile::fx_4_0);
  EXPECT_EQ(infer("technique t { pass p { SetComputeShader(NULL); } }"), EffectProfile::fx_5_0);
  // State names are matched ignoring case, here too.
  EXPECT_EQ(infer("technique t { pass p { setcomputeshader(NULL); } }"), EffectProfile::fx_5_0);
  EXPECT_EQ(infer("technique t { pass p { SETGEOMETRYSHADER(NULL); } }"), EffectProfile::fx_4_0);
  EXPECT_EQ(infer("fxgroup g { technique11 t { pass p {} } }"), EffectProfile::fx_5_0);
  EXPECT_EQ(parse_effect_profile("fx.2.0"), EffectProfile::fx_2_0);
  EXPECT_EQ(parse_effect_profile("FX_4_1"), EffectProfile::fx_4_1);
  EXPECT_EQ(parse_effect_profile("fx_6_0"), std::nullopt);
}

TEST(Checker, GlslBlocksAsShaders) {
  auto c = check(
      "GLSLShader Common { vec3 f() { return vec3(0); } }\n"
      "GLSLShader Lighting { void main() {} }\n"
      "technique t { pass p { VertexShader = { Common, Lighting }; PixelShader = { Common, Lightning }; } }\n");
  ASSERT_EQ(c->ids(), (Ids{"undefined-reference"})) << c->text();
  EXPECT_EQ(c->diags.diagnostics()[0].message, "use of undefined GLSL block 'Lightning'; did you mean 'Lighting'?");
}

// docs/effect-format.md's GLSL example, and every stage spelling the state table gives.
TEST(Checker, GlslBlocksTakeEveryStageSpelling) {
  auto c = check(
      "GLSLShader Common { uniform vec3 LightDir; varying vec3 T, V; }\n"
      "GLSLShader HairVS { void main() { gl_Position = vec4(0.0); } }\n"
      "GLSLShader HairFS { void main() { gl_FragColor = vec4(LightDir, 1.0); } }\n"
      "technique Hair { pass p0 { VertexShader = HairVS; FragmentShader = { Common, HairFS }; } }\n"
      "technique nvfx { pass p0 { VertexProgram = HairVS; FragmentProgram = { Common, HairFS }; } }\n");
  EXPECT_EQ(c->ids(), Ids{}) << c->text();
}

TEST(Checker, CompileProfileMatchesTheStageOfEverySpelling) {
  auto c = check(
      "float4 VS() : POSITION { return 0; }\n"
      "float4 PS() : COLOR { return 0; }\n"
      "technique a { pass p { VertexShader = compile vs_2_0 VS(); FragmentShader = compile vs_2_0 PS(); } }\n"
      "technique b { pass p { VertexProgram = compile ps_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
  ASSERT_EQ(c->ids(), (Ids{"shader-stage-mismatch", "shader-stage-mismatch"})) << c->text();
  EXPECT_EQ(c->diags.diagnostics()[0].message, "state 'FragmentShader' needs a ps_* profile, found 'vs_2_0'");
  EXPECT_EQ(c->diags.diagnostics()[1].message, "state 'VertexProgram' needs a vs_* profile, found 'ps_2_0'");
}

// The checker must take whatever a failed parse leaves: missing values, names, indices.
TEST(Checker, PartialHandBuiltTreesDoNotCrash) {
  ast::Effect fx;
  ast::Decl d;
  d.kind = ast::DeclKind::technique;
  d.technique = fx.declarations.make<ast::Technique>();
  ast::Pass p;
  ast::StateAssignment no_value;
  no_value.name = "ZEnable";
  p.states.push_back(fx.arena, no_value);
  ast::StateAssignment call;
  call.name = "SetBlendState";
  call.call_style = true;
  call.value = fx.expressions.make(ast::ExprKind::call);
  call.value->args = fx.expressions.list({nullptr});
  p.states.push_back(fx.arena, call);
  ast::StateAssignment binary;
  binary.name = "ColorArg1";
  binary.value = fx.expressions.make(ast::ExprKind::binary);
  binary.value->text = "|";
  binary.value->args = fx.expressions.list({nullptr});
  p.states.push_back(fx.arena, binary);
  d.technique->passes.push_back(fx.arena, p);
  d.technique->passes.emplace_back(fx.arena);
  d.technique->passes.emplace_back(fx.arena);  // two unnamed passes are not duplicates
  fx.decls.push_back(d);
  SourceManager sm;
  DiagnosticSink diags;
  check_effect(fx, sm, diags, {.profile = EffectProfile::fx_4_0});
  std::vector<std::string> ids;
  for (const Diagnostic& x : diags.diagnostics()) ids.push_back(x.id);
  // A D3D9 technique under fx_4_0, and SetBlendState with 1 of 3 arguments.
  EXPECT_EQ(ids, (Ids{"d3d9-technique", "state-call-form"}));
}

}  // namespace
}  // namespace fx
