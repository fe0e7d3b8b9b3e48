// Effect translation units and per-pass programs: what glslang gets, where its errors land,
// compile-time arguments, laziness and the cache; every shader of the test and project
// effects compiles or says why.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "compile_test_util.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/spirv_cache.h"
#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

namespace fx {
namespace {

namespace fs = std::filesystem;

// A parsed effect with everything it needs kept alive.
struct Loaded {
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed;
  std::unique_ptr<EffectUnits> units;
};

std::unique_ptr<Loaded> load(const std::string& path, std::vector<std::string> include_dirs = {}) {
  auto l = std::make_unique<Loaded>();
  FrontEndOptions options;
  options.preprocessor.include_dirs = std::move(include_dirs);
  l->parsed = parse_effect_file(path, l->sm, l->diags, options);
  l->units = std::make_unique<EffectUnits>(l->parsed.ast, l->sm, l->diags);
  return l;
}

fs::path temp_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("fxkit_units_" + std::to_string(::getpid())) / name;
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string data(const std::string& rel) { return std::string(FXKIT_SOURCE_DIR) + "/" + rel; }

TEST(EffectUnits, LeavesOutEffectSyntaxAndKeepsShaderCode) {
  auto l = load(data("tests/parser/data/sdk_sample.fx"));
  const std::string& code = l->units->hlsl_code();
  for (const char* gone :
       {"sampler_state", "technique", "UIName", "texture g_MeshTexture", "BlendState", "Filter", "Script ="})
    EXPECT_EQ(code.find(gone), std::string::npos) << gone << " in\n" << code;
  for (const char* kept :
       {"sampler MeshTextureSampler", "SamplerState g_samLinear : register(s0);", "VS_OUTPUT RenderSceneVS(",
        "cbuffer cbPerObject", "Texture2D<float4> g_txDiffuse", "#line "})
    EXPECT_NE(code.find(kept), std::string::npos) << kept << " missing in\n" << code;
  // Lines are kept: the struct VS_OUTPUT is written on its own .fx line.
  ASSERT_EQ(l->units->passes().size(), 3u);
  const EffectPass& p0 = l->units->passes()[0];
  EXPECT_EQ(p0.technique, "RenderSceneWithTexture1Light");
  ASSERT_EQ(p0.stages.size(), 2u);
  EXPECT_EQ(p0.stages[0].entry_point, "RenderSceneVS__fx_args");
  EXPECT_EQ(p0.stages[0].arguments, (std::vector<std::string>{"1", "true", "true"}));
  EXPECT_TRUE(p0.unsupported.empty());
  // PixelShader = NULL in a D3D9 technique: fixed-function pixel processing, generated to
  // read what the HLSL vertex shader writes.
  const EffectPass& p1 = l->units->passes()[1];
  EXPECT_TRUE(p1.unsupported.empty());
  ASSERT_TRUE(p1.find(ShaderStage::fragment));
  EXPECT_EQ(p1.find(ShaderStage::fragment)->kind, StageSourceKind::fixed_function);
  // D3D10: SetGeometryShader(NULL) is no stage and nothing unsupported.
  const EffectPass& p2 = l->units->passes()[2];
  EXPECT_EQ(p2.stages.size(), 2u);
  EXPECT_TRUE(p2.unsupported.empty());
}

TEST(EffectUnits, AStageUnitHoldsTheFunctionsItsEntryReaches) {
  fs::path dir = temp_dir("reach");
  write(dir / "reach.fx", R"(struct V { float4 pos : SV_Position; };
struct Unreached { float4 x; };
float4 VsOnly;
float4 PsOnly, PsToo;
typedef float3 Normal;
cbuffer Lights { float4 LightDir; float4 LightColor; };
cbuffer Other { float4 OtherColor; };
float Scale(float x) { return x * 2; }
static const float kScale = Scale(1);
static const float kUnused = 3;
float3 Shade(Normal n) { return n * kScale * LightDir.xyz; }
float3 Shade(float x) { return x; }
float Unused() { return kUnused; }
V VS(float4 p : POSITION) { V v; v.pos = float4(Shade(p.xyz), 1) + VsOnly; return v; }
float4 PS(V v) : SV_Target { return ddx(v.pos) + PsOnly; }
[maxvertexcount(1)] void GS(point V i[1], inout PointStream<V> s) { s.Append(i[0]); }
[maxvertexcount(1)] void UnusedGS(point V i[1], inout PointStream<V> s) { s.Append(i[0]); }
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS()));
                         SetPixelShader(CompileShader(ps_4_0, PS())); } }
)");
  auto l = load((dir / "reach.fx").string());
  const EffectPass& pass = l->units->passes().at(0);
  auto source = [&](ShaderStage stage) { return l->units->unit(*pass.find(stage))->source; };
  auto has = [](const std::string& code, const char* text) { return code.find(text) != std::string::npos; };
  const std::string vs = source(ShaderStage::vertex);
  // The entry, both overloads of what it calls, what a global initializer calls, the
  // typedef, struct, globals and whole cbuffer its code names.
  for (const char* kept : {"V VS(", "float3 Shade(Normal", "float3 Shade(float x", "float Scale(", "kScale =",
                           "typedef float3 Normal", "struct V", "float4 VsOnly", "cbuffer Lights", "LightColor"})
    EXPECT_TRUE(has(vs, kept)) << kept << " missing in\n" << vs;
  // Other stages' functions and globals, what nothing names, and a function nothing calls.
  for (const char* gone : {"float4 PS(", "void GS(", "void UnusedGS(", "float Unused()", "PsOnly", "Unreached",
                           "cbuffer Other", "kUnused"})
    EXPECT_FALSE(has(vs, gone)) << gone << " in\n" << vs;
  // Declarators of one declaration stay together.
  EXPECT_TRUE(has(source(ShaderStage::fragment), "PsToo")) << source(ShaderStage::fragment);
  const std::string gs = source(ShaderStage::geometry);
  EXPECT_TRUE(has(gs, "void GS(")) << gs;
  EXPECT_FALSE(has(gs, "void UnusedGS(")) << gs;
  EXPECT_FALSE(has(gs, "V VS(")) << gs;
  // The function no stage calls is compiled in the effect's check unit, with what it names;
  // not the stream function, which compiles only as its stage's entry.
  const StageUnit* check = l->units->uncalled_check();
  ASSERT_TRUE(check);
  const std::string checked = l->units->unit(*check)->source;
  EXPECT_TRUE(has(checked, "float Unused()") && has(checked, "kUnused")) << checked;
  EXPECT_FALSE(has(checked, "void UnusedGS(") || has(checked, "V VS(")) << checked;
  // The whole text still holds every function, each after its own #line.
  EXPECT_TRUE(has(l->units->hlsl_code(), "void UnusedGS("));
}

TEST(EffectUnits, AShaderArrayIndexedInAPassOffersEveryElement) {
  auto l = load(data("tests/compile/data/fxc_accepts/shader_array_chosen_by_a_parameter.fx"));
  ASSERT_EQ(l->units->passes().size(), 1u);
  const EffectPass& pass = l->units->passes()[0];
  const StageUnit* vs = pass.find(ShaderStage::vertex);
  const StageUnit* ps = pass.find(ShaderStage::fragment);
  ASSERT_TRUE(vs && ps);
  ASSERT_EQ(vs->choices.size(), 3u);
  ASSERT_EQ(ps->choices.size(), 2u);
  // ShaderIndex = 3: VSIndices[3] = 1, PSIndices[3] = 1.
  EXPECT_EQ(vs->choice, 1u);
  EXPECT_EQ(vs->function, "VSFog");
  EXPECT_EQ(ps->choice, 1u);
  EXPECT_EQ(ps->function, "PSFog");
  EXPECT_EQ(vs->selector, "VSIndices[ShaderIndex]");
  EXPECT_EQ(vs->choices[2].function, "VSVertexColor");
  EXPECT_EQ(vs->choices[2].profile, "vs_2_0");
}

// `StateBlock = <sb>;` brings the stateblock's shaders into the pass; the pass's own
// assignment of a stage after it wins.
TEST(EffectUnits, AStateBlockBringsItsShadersIntoThePass) {
  auto l = load(data("tests/compile/data/fxc_accepts/stateblock_applied_by_a_pass.fx"));
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  for (const char* name : {"Plain", "Lit"}) {
    const EffectPass* pass = l->units->find("StateBlocks", name);
    ASSERT_TRUE(pass) << name;
    const StageUnit* vs = pass->find(ShaderStage::vertex);
    const StageUnit* ps = pass->find(ShaderStage::fragment);
    ASSERT_TRUE(vs && ps) << name;
    EXPECT_EQ(vs->function, "VS");
    EXPECT_EQ(ps->function, "PS");
    EXPECT_EQ(ps->arguments, std::vector<std::string>{std::string(name) == "Lit" ? "true" : "false"}) << name;
  }
}

// A D3D9 pass with an HLSL vertex shader and no pixel shader: the generated texture stages
// read the colours, texture coordinates and fog the vertex shader writes (return value or
// struct, out and inout parameters, SV_ forms), each with its own components.
TEST(EffectUnits, AGeneratedPixelStageReadsWhatTheHlslVertexShaderWrites) {
  fs::path dir = temp_dir("ff_pixel");
  write(dir / "ff_pixel.fx",
        R"(struct VsOut { float4 p : SV_Position; float3 c : COLOR0; float2 t : TEXCOORD2; float3 n : NORMAL; };
VsOut Struct(float4 p : POSITION) { VsOut o; o.p = p; o.c = p.xyz; o.t = p.xy; o.n = p.xyz; return o; }
void Params(inout float4 p : POSITION0, inout float2 uv : TEXCOORD, out float4 s : color1, out float f : FOG) { s = p; f = p.x; }
float4 Returned(float4 p : POSITION, uniform float k) : POSITION { return p * k; }
struct Wide { float4 p : POSITION; float4 t : TEXCOORD2; };
Wide WideStruct(float4 p : POSITION) { Wide o; o.p = p; o.t = p; return o; }
VertexShader Either[2] = { compile vs_2_0 Struct(), compile vs_2_0 WideStruct() };
int Pick = 0;
void Array(float4 p : POSITION, out float4 o : POSITION, out float2 t[2] : TEXCOORD0) { o = p; t[0] = p.xy; t[1] = p.zw; }
technique T {
  pass S { VertexShader = compile vs_2_0 Struct(); ColorOp[0] = SelectArg1; ColorArg1[0] = Diffuse; }
  pass P { VertexShader = compile vs_2_0 Params(); PixelShader = NULL; FogEnable = TRUE; }
  pass R { VertexShader = compile vs_2_0 Returned(2.0); }
  pass E { VertexShader = (Either[Pick]); }
  pass A { VertexShader = compile vs_2_0 Array(); }
}
)");
  auto l = load((dir / "ff_pixel.fx").string());
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  auto generated = [&](const char* pass) -> std::string {
    const StageUnit* ps = l->units->find("T", pass)->find(ShaderStage::fragment);
    return ps && ps->kind == StageSourceKind::fixed_function ? ps->translated : "";
  };
  const std::string s = generated("S"), p = generated("P"), r = generated("R"), e = generated("E");
  EXPECT_NE(s.find("float3 fx_diffuse : COLOR0;"), std::string::npos) << s;
  EXPECT_NE(s.find("float2 fx_tc2 : TEXCOORD2;"), std::string::npos) << s;
  EXPECT_EQ(s.find("COLOR1"), std::string::npos) << s;
  EXPECT_NE(p.find("float2 fx_tc0 : TEXCOORD0;"), std::string::npos) << p;
  EXPECT_NE(p.find("float4 fx_specular : COLOR1;"), std::string::npos) << p;
  EXPECT_NE(p.find("float fx_fog : FOG;"), std::string::npos) << p;
  EXPECT_EQ(p.find("COLOR0;"), std::string::npos) << p;
  EXPECT_NE(p.find("float4 fx_diffuse = float4(1.0, 1.0, 1.0, 1.0);"), std::string::npos) << p;
  EXPECT_EQ(r.find("TEXCOORD"), std::string::npos) << r;
  EXPECT_EQ(r.find("COLOR1"), std::string::npos) << r;
  // A shader array: what every element writes, at the fewest components.
  EXPECT_NE(e.find("float2 fx_tc2 : TEXCOORD2;"), std::string::npos) << e;
  EXPECT_EQ(e.find("COLOR0;"), std::string::npos) << e;
  // An output array: the pass says why it has no pixel stage.
  const EffectPass* a = l->units->find("T", "A");
  ASSERT_EQ(a->unsupported.size(), 1u);
  EXPECT_NE(a->unsupported[0].find("fixed-function pixel processing"), std::string::npos);
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  for (const char* pass : {"S", "P", "R", "E"}) {
    const PassProgram* program = programs.program("T", pass);
    ASSERT_TRUE(program);
    for (const StageProgram& st : program->stages)
      EXPECT_TRUE(st.shader.ok) << pass << " " << to_string(st.stage) << "\n"
                                << render_text(st.diagnostics, l->sm) << st.unit.source;
    EXPECT_TRUE(program->ok()) << pass;
  }
}

// fx_5_0 dynamic linkage: classes compile as the structs with methods they are; a stage
// that calls through an interface no class instance implements has nothing to dispatch to,
// is not compiled and says why; other stages are unaffected.
TEST(EffectUnits, InterfacesWithoutAnInstanceFailOnlyTheStagesThatCallThem) {
  fs::path dir = temp_dir("interfaces");
  write(dir / "linkage.fx", R"(interface ILight { float3 Shade(float3 n); };
class Ambient : ILight { float3 color; float3 Shade(float3 n) { return color; } };
ILight g_light;
float4 Through(float3 n : NORMAL) : SV_Target { return float4(g_light.Shade(n), 1); }
float4 Direct(float3 n : NORMAL) : SV_Target { Ambient a; a.color = n; return float4(a.Shade(n), 1); }
float4 VS(float4 p : POSITION, inout float3 n : NORMAL) : SV_Position { return p; }
technique11 T {
  pass Interface { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Through())); }
  pass Class { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Direct())); }
}
)");
  auto l = load((dir / "linkage.fx").string());
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  const StageUnit* through = l->units->find("T", "Interface")->find(ShaderStage::fragment);
  ASSERT_TRUE(through);
  EXPECT_EQ(through->kind, StageSourceKind::invalid);
  EXPECT_EQ(
      through->unsupported,
      "fx_5_0 dynamic linkage: 'Through' calls through interface variable 'g_light' of interface 'ILight', which no "
      "class instance implements: declare an instance of a class that does");
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  const PassProgram* with_class = programs.program("T", "Class");
  ASSERT_TRUE(with_class);
  for (const StageProgram& s : with_class->stages)
    EXPECT_TRUE(s.shader.ok) << to_string(s.stage) << "\n" << render_text(s.diagnostics, l->sm) << s.unit.source;
  EXPECT_TRUE(with_class->ok());
  EXPECT_TRUE(programs.program("T", "Interface")->find(ShaderStage::vertex)->shader.ok);
}

// Methods defined after their class (`float3 Ambient::Shade(...) { }`; glslang takes member
// functions only inside their struct) are written where they are defined, as functions of an
// instance (`Ambient__Shade__fxm(inout Ambient self, ...)`): overloads, a call of another
// method, a call on a local instance compile; the interface stage still says why not.
TEST(EffectUnits, MethodsDefinedOutsideTheirClassCompileAsFunctionsOfAnInstance) {
  fs::path dir = temp_dir("out_of_class");
  write(dir / "methods.fx", R"(interface ILight { float3 Shade(float3 n); float3 Tint(); };
float3 g_scale = float3(0.5, 0.5, 0.5);
class Ambient : ILight {
  float3 color;
  float3 Shade(float3 n);
  float3 Shade(float3 n, float k);
  float3 Tint() { return color; }
};
float3 Ambient::Shade(float3 n) { return color * n.x * g_scale + Tint(); }
float3 Ambient::Shade(float3 n, float k) { return Shade(n) * k; }
ILight g_light;
float4 Through(float3 n : NORMAL) : SV_Target { return float4(g_light.Shade(n), 1); }
float4 Direct(float3 n : NORMAL) : SV_Target { Ambient a; a.color = n; return float4(a.Shade(n, 2), 1); }
float4 Plain(float3 n : NORMAL) : SV_Target { return float4(n, 1); }
float4 VS(float4 p : POSITION, inout float3 n : NORMAL) : SV_Position { return p; }
technique11 T {
  pass Interface { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Through())); }
  pass Class { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Direct())); }
  pass Other { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, Plain())); }
}
)");
  auto l = load((dir / "methods.fx").string());
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  EXPECT_EQ(l->units->find("T", "Interface")->find(ShaderStage::fragment)->kind, StageSourceKind::invalid);
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  for (const char* pass : {"Class", "Other"}) {
    const PassProgram* program = programs.program("T", pass);
    ASSERT_TRUE(program) << pass;
    for (const StageProgram& s : program->stages)
      EXPECT_TRUE(s.shader.ok) << pass << " " << to_string(s.stage) << "\n"
                               << render_text(s.diagnostics, l->sm) << s.unit.source;
  }
  const std::string direct = programs.program("T", "Class")->find(ShaderStage::fragment)->unit.source;
  EXPECT_EQ(direct.find("Ambient::"), std::string::npos) << direct;
  EXPECT_NE(direct.find("g_scale"), std::string::npos) << "what the methods use comes along\n" << direct;
  EXPECT_EQ(programs.program("T", "Other")->find(ShaderStage::fragment)->unit.source.find("Ambient"), std::string::npos)
      << "a stage that does not use the class leaves it out";
}

// An interface parameter no BindInterfaces binds, and a bound instance that is no class
// instance or interface variable, are errors at the pass state and the argument; the pass
// that binds its parameter compiles.
TEST(EffectUnits, InterfaceParametersMustEachBeBoundToAnInstance) {
  fs::path dir = temp_dir("interface_binding");
  write(dir / "binding.fx", R"(interface ILight { float3 Shade(float3 n); };
class Ambient : ILight { float3 color; float3 Shade(float3 n) { return color; } };
Ambient g_ambient;
float3 g_colour;
float4 PS(float3 n : NORMAL, ILight light) : SV_Target { return float4(light.Shade(n), 1); }
float4 VS(float4 p : POSITION, inout float3 n : NORMAL) : SV_Position { return p; }
technique11 T {
  pass Bound { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), g_ambient)); }
  pass Unbound { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); }
  pass NotAnInstance { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(BindInterfaces(CompileShader(ps_5_0, PS()), g_colour)); }
}
)");
  auto l = load((dir / "binding.fx").string());
  const std::string text = render_text(l->diags.diagnostics(), l->sm);
  EXPECT_NE(text.find("binding.fx:9:79: error: 'PS' takes 1 interface parameter(s), but 0 instance(s) are bound"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("binding.fx:10:129: error: BindInterfaces binds an interface variable or a class instance"),
            std::string::npos)
      << text;
  EXPECT_EQ(l->units->find("T", "Unbound")->find(ShaderStage::fragment)->kind, StageSourceKind::invalid);
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  const PassProgram* bound = programs.program("T", "Bound");
  ASSERT_TRUE(bound);
  for (const StageProgram& s : bound->stages)
    EXPECT_TRUE(s.shader.ok) << to_string(s.stage) << "\n" << render_text(s.diagnostics, l->sm) << s.unit.source;
}

// glslang crashes on a geometry shader whose input array carries SV_ClipDistance
// (KhronosGroup/glslang#2392). A struct member is rewritten (the rule file
// geometry_shader_reading_clip_distances.fx); one nested deeper (here in `Inner`) makes the
// stage say why instead of reaching glslang; a geometry shader that only writes it, and the
// vertex shader, still compile.
TEST(EffectUnits, GeometryInputWithClipDistanceSaysWhyInsteadOfCrashing) {
  fs::path dir = temp_dir("clip_input");
  write(dir / "clip.fx", R"(float4 g_plane;
struct Inner { float2 d : SV_CullDistance1; };
struct V { float4 pos : SV_Position; float d : SV_ClipDistance0; Inner inner; };
struct G { float4 pos : SV_Position; float d : SV_ClipDistance0; };
V VS(float4 p : POSITION) { V v; v.pos = p; v.d = dot(p, g_plane); v.inner.d = p.xy; return v; }
struct P { float4 pos : SV_Position; };
P VP(float4 p : POSITION) { P v; v.pos = p; return v; }
[maxvertexcount(3)] void Reads(triangle V input[3], inout TriangleStream<V> s) { s.Append(input[0]); }
[maxvertexcount(3)] void Writes(triangle P input[3], inout TriangleStream<G> s) {
  G g; g.pos = input[0].pos; g.d = dot(input[0].pos, g_plane); s.Append(g); }
float4 PS(float4 p : SV_Position) : SV_Target { return 1; }
technique10 T {
  pass Read { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, Reads())); SetPixelShader(CompileShader(ps_4_0, PS())); }
  pass Write { SetVertexShader(CompileShader(vs_4_0, VP())); SetGeometryShader(CompileShader(gs_4_0, Writes())); SetPixelShader(CompileShader(ps_4_0, PS())); }
}
)");
  auto l = load((dir / "clip.fx").string());
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  const StageUnit* reads = l->units->find("T", "Read")->find(ShaderStage::geometry);
  ASSERT_TRUE(reads);
  EXPECT_EQ(reads->kind, StageSourceKind::invalid);
  EXPECT_NE(reads->unsupported.find("'Reads' reads SV_ClipDistance/SV_CullDistance in its input 'input'"),
            std::string::npos)
      << reads->unsupported;
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  EXPECT_TRUE(programs.program("T", "Read")->find(ShaderStage::vertex)->shader.ok);
  const PassProgram* writes = programs.program("T", "Write");
  ASSERT_TRUE(writes);
  for (const StageProgram& s : writes->stages)
    EXPECT_TRUE(s.shader.ok) << to_string(s.stage) << "\n" << render_text(s.diagnostics, l->sm) << s.unit.source;
}

TEST(EffectPrograms, SdkSampleCompilesAndLinks) {
  auto l = load(data("tests/parser/data/sdk_sample.fx"));
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  for (const EffectPass& pass : l->units->passes()) {
    const PassProgram& p = programs.program(pass);
    for (const StageProgram& s : p.stages) {
      EXPECT_TRUE(s.shader.ok) << pass.technique << "." << pass.pass << " " << to_string(s.stage) << "\n"
                               << render_text(s.diagnostics, l->sm);
      if (s.shader.ok) {
        EXPECT_EQ(test::spirv_val(s.shader.spirv), "");
      }
    }
    EXPECT_TRUE(p.compiled) << pass.technique;
  }
  // Vertex inputs by semantic, from the wrapper entry's varying parameters.
  const PassProgram* p = programs.program("RenderSceneWithTexture1Light", "P0");
  ASSERT_NE(p, nullptr);
  std::vector<std::string> semantics;
  for (const InterfaceVariable& v : p->find(ShaderStage::vertex)->shader.reflection.inputs)
    semantics.push_back(v.semantic);
  EXPECT_EQ(semantics, (std::vector<std::string>{"POSITION", "NORMAL", "TEXCOORD0"}));
}

TEST(EffectPrograms, CompileTimeArgumentsGiveDifferentSpirv) {
  fs::path dir = temp_dir("args");
  write(dir / "args.fx", R"(float4 Tint;
float4 PS(float2 uv : TEXCOORD0, uniform bool bright, uniform int n) : COLOR0 {
  float4 c = Tint;
  for (int i = 0; i < n; ++i) c *= 0.5;
  return bright ? c * 2 : c;
}
technique A { pass P { PixelShader = compile ps_2_0 PS(true, 3); } }
technique B { pass P { PixelShader = compile ps_2_0 PS(false, 1); } }
technique C { pass P { PixelShader = compile ps_2_0 PS(true, 3); } }
)");
  auto l = load((dir / "args.fx").string());
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  const StageProgram* a = programs.program("A", "P")->find(ShaderStage::fragment);
  const StageProgram* b = programs.program("B", "P")->find(ShaderStage::fragment);
  ASSERT_TRUE(a && b);
  ASSERT_TRUE(a->shader.ok) << a->shader.info_log;
  ASSERT_TRUE(b->shader.ok) << b->shader.info_log;
  EXPECT_EQ(a->shader.entry_point, "PS__fx_args");
  EXPECT_NE(a->shader.spirv, b->shader.spirv);
  // The uniform parameters are bound: no uniform block needs them.
  for (const UniformBlock& blk : a->shader.reflection.uniform_blocks)
    for (const BlockMember& m : blk.members) EXPECT_NE(m.name, "bright");
  // C has the same unit as A: compiled once.
  const StageProgram* c = programs.program("C", "P")->find(ShaderStage::fragment);
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->reused);
  EXPECT_EQ(c->shader.spirv, a->shader.spirv);
  // Two pixel shaders, and the generated fixed-function vertex stage the three passes share.
  EXPECT_EQ(compiler.glslang_runs(), 3u);
}

TEST(EffectPrograms, CompilesLazilyAndReloadHitsTheCache) {
  auto l = load(data("tests/parser/data/sdk_sample.fx"));
  SpirvCache cache;
  ShaderCompiler compiler({}, &cache);
  {
    EffectPrograms programs(*l->units, compiler, l->sm);
    EXPECT_EQ(compiler.glslang_runs(), 0u);  // nothing compiled until asked
    const PassProgram* p = programs.program("Render10", "P0");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(compiler.glslang_runs(), 2u);  // only that pass's two stages
    EXPECT_FALSE(programs.is_compiled(l->units->passes()[0]));
    for (const EffectPass& pass : l->units->passes()) programs.program(pass);
  }
  uint64_t runs = compiler.glslang_runs();
  // Reload of the unchanged file: a new parse, new units, the same cache: no glslang.
  auto again = load(data("tests/parser/data/sdk_sample.fx"));
  EffectPrograms programs(*again->units, compiler, again->sm);
  for (const EffectPass& pass : again->units->passes()) {
    const PassProgram& p = programs.program(pass);
    for (const StageProgram& s : p.stages) EXPECT_TRUE(s.shader.from_cache || s.reused);
  }
  EXPECT_EQ(compiler.glslang_runs(), runs);
  EXPECT_GT(cache.stats().memory_hits, 0u);
}

// The presumed location of the first error diagnostic with `id`.
PresumedLocation first_error(const std::vector<Diagnostic>& ds, const SourceManager& sm) {
  for (const Diagnostic& d : ds)
    if (d.severity >= Severity::error) return sm.presumed(d.range.begin);
  return {};
}

TEST(EffectErrors, HlslErrorInTheEffectIncludeAndMacroLandOnTheirLines) {
  fs::path dir = temp_dir("hlsl_err");
  write(dir / "lib.fxh", "// helpers\nfloat3 Helper(float3 v)\n{\n    return v * undefined_thing;\n}\n");
  write(dir / "main.fx", R"(#include "lib.fxh"
#define BROKEN(x) (x + missing_in_macro)
float4 Color;
float4 PS(float2 uv : TEXCOORD0) : COLOR0 {
  float4 c = Color;
  c.xyz = Helper(c.xyz);
  return c;
}
float4 PS2(float2 uv : TEXCOORD0) : COLOR0 {
  float4 c = Color;
      c.x = BROKEN(c.y);
  return c;
}
technique T1 { pass P { PixelShader = compile ps_2_0 PS(); } }
technique T2 { pass P { PixelShader = compile ps_2_0 PS2(); } }
)");
  auto l = load((dir / "main.fx").string());
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  // T1's unit holds PS and what it calls: the include's error is its own.
  const StageProgram* s1 = programs.program("T1", "P")->find(ShaderStage::fragment);
  ASSERT_TRUE(s1);
  EXPECT_FALSE(s1->shader.ok);
  PresumedLocation inc = first_error(s1->diagnostics, l->sm);
  EXPECT_EQ(fs::path(std::string(inc.file)).filename(), "lib.fxh") << render_text(s1->diagnostics, l->sm);
  EXPECT_EQ(inc.line, 4u);
  // PS2 is another pass's function: its error is not T1's ...
  for (const Diagnostic& d : s1->diagnostics)
    EXPECT_EQ(d.message.find("missing_in_macro"), std::string::npos) << render_text(s1->diagnostics, l->sm);
  // ... but T2's, reported at the line that invokes the macro, in main.fx.
  const StageProgram* s2 = programs.program("T2", "P")->find(ShaderStage::fragment);
  ASSERT_TRUE(s2);
  EXPECT_FALSE(s2->shader.ok);
  bool macro_line = false;
  for (const Diagnostic& d : s2->diagnostics) {
    PresumedLocation p = l->sm.presumed(d.range.begin);
    EXPECT_NE(fs::path(std::string(p.file)).filename(), "lib.fxh") << "PS2 does not call Helper";
    if (d.message.find("missing_in_macro") != std::string::npos) {
      EXPECT_EQ(fs::path(std::string(p.file)).filename(), "main.fx");
      EXPECT_EQ(p.line, 11u);
      macro_line = true;
    }
  }
  EXPECT_TRUE(macro_line) << render_text(s2->diagnostics, l->sm);
}

// One typo, one error: at the token's column (glslang gives HLSL semantic errors none), with
// the effect's closest name as a fix-it, and none of glslang's follow-on errors.
TEST(EffectErrors, AnErrorInAFunctionNoStageCallsIsReportedOnceOnItsLineAndFailsThePasses) {
  fs::path dir = temp_dir("uncalled_err");
  write(dir / "u.fx", R"(float4 Color;
float4 Broken(float4 c)
{
  return c * not_declared;
}
float4 Fine() { return 1; }
float4 PS() : COLOR0 { return Color; }
float4 VS(float4 p : POSITION) : POSITION { return p; }
technique T1 { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
technique T2 { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  auto l = load((dir / "u.fx").string());
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  for (const char* technique : {"T1", "T2"}) {
    const PassProgram* p = programs.program(technique, "P");
    ASSERT_TRUE(p);
    // The stages themselves compile: Broken is not in their units ...
    for (const StageProgram& s : p->stages) EXPECT_TRUE(s.shader.ok) << render_text(s.diagnostics, l->sm);
    // ... but the pass fails with Broken's error, on its line, as fxc fails the effect.
    EXPECT_FALSE(p->ok());
    ASSERT_FALSE(p->diagnostics.empty());
    PresumedLocation at = first_error(p->diagnostics, l->sm);
    EXPECT_EQ(at.line, 4u) << render_text(p->diagnostics, l->sm);
  }
  EXPECT_EQ(programs.stats().stages_compiled, 3u);  // VS, PS and the check unit, once each
  const std::string checked = l->units->unit(*l->units->uncalled_check())->source;
  EXPECT_NE(checked.find("float4 Fine()"), std::string::npos) << checked;
  EXPECT_EQ(checked.find("float4 PS()"), std::string::npos) << checked;
}

TEST(EffectErrors, AnUnknownNameIsOneErrorAtItsColumnWithDidYouMean) {
  fs::path dir = temp_dir("typo");
  write(dir / "typo.fx", R"(float4x4 WorldViewProj;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjj); }
float4 PS() : COLOR0 { return 1; }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)");
  auto l = load((dir / "typo.fx").string());
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  const PassProgram& p = programs.program(l->units->passes().at(0));
  const StageProgram* vs = p.find(ShaderStage::vertex);
  ASSERT_TRUE(vs);
  EXPECT_FALSE(vs->shader.ok);
  std::vector<const Diagnostic*> errors;
  for (const Diagnostic& d : vs->diagnostics)
    if (d.severity == Severity::error) errors.push_back(&d);
  ASSERT_EQ(errors.size(), 1u) << render_text(vs->diagnostics, l->sm);
  PresumedLocation at = l->sm.presumed(errors[0]->range.begin);
  EXPECT_EQ(at.line, 2u);
  EXPECT_EQ(at.column, 59u);
  EXPECT_EQ(errors[0]->message, "'WorldViewProjj' : unknown variable; did you mean 'WorldViewProj'?");
  ASSERT_EQ(errors[0]->fixits.size(), 1u);
  EXPECT_EQ(errors[0]->fixits[0].replacement, "WorldViewProj");
  EXPECT_TRUE(p.find(ShaderStage::fragment)->shader.ok) << "the pixel shader does not use VS";
}

TEST(EffectErrors, HlslGrammarErrorKeepsItsColumn) {
  fs::path dir = temp_dir("hlsl_grammar");
  write(dir / "gram.fx", R"(float4 Color;
float4 PS(float2 uv : TEXCOORD0) : COLOR0 {
  float4 c = Color; c.x = (c.y + * 2);
  return c;
}
technique T { pass P { PixelShader = compile ps_2_0 PS(); } }
)");
  auto l = load((dir / "gram.fx").string());
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  const StageProgram* s = programs.program("T", "P")->find(ShaderStage::fragment);
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->shader.ok);
  // glslang reports the failure as a chain of "Expected" messages, only the last with a
  // column (the stray '*'): one error, the innermost expectation, at that column.
  ASSERT_EQ(s->diagnostics.size(), 1u) << render_text(s->diagnostics, l->sm) << s->unit.source;
  PresumedLocation at = l->sm.presumed(s->diagnostics[0].range.begin);
  EXPECT_EQ(fs::path(std::string(at.file)).filename(), "gram.fx");
  EXPECT_EQ(at.line, 3u);
  EXPECT_EQ(at.column, 34u);
  EXPECT_EQ(s->diagnostics[0].message, "'expression' : Expected");
}

TEST(EffectErrors, GlslErrorLandsOnTheBlockLine) {
  fs::path dir = temp_dir("glsl_err");
  write(dir / "g.fx", R"(GLSLShader Common { #version 450
  vec3 shade(vec3 n) { return n * 0.5 + 0.5; }
}
GLSLShader FS {
  layout(location = 0) out vec4 color;
  void main() {
    color = vec4(shade(vec3(1)), 1) + not_declared;
  }
}
GLSLShader VS {
  void main() { gl_Position = vec4(0, 0, 0, 1); }
}
technique Good { pass { VertexShader = VS; PixelShader = { Common, FS }; } }
)");
  auto l = load((dir / "g.fx").string());
  ASSERT_FALSE(l->diags.has_errors()) << render_text(l->diags.diagnostics(), l->sm);
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  const PassProgram* p = programs.program("Good", "pass0");
  ASSERT_NE(p, nullptr);
  const StageProgram* vs = p->find(ShaderStage::vertex);
  const StageProgram* fs = p->find(ShaderStage::fragment);
  ASSERT_TRUE(vs && fs);
  EXPECT_TRUE(vs->shader.ok) << vs->shader.info_log << vs->unit.source;
  EXPECT_FALSE(fs->shader.ok);
  PresumedLocation at = first_error(fs->diagnostics, l->sm);
  EXPECT_EQ(fs::path(std::string(at.file)).filename(), "g.fx") << fs->shader.info_log;
  EXPECT_EQ(at.line, 7u) << fs->shader.info_log << fs->unit.source;
  EXPECT_EQ(fs->unit.source.rfind("#version 450", 0), 0u);
}

// Every pass stage of every effect either compiles or fails with a diagnostic saying why;
// returns (stages compiled, stages with a unit).
std::pair<size_t, size_t> compile_all(const std::string& path, std::string& report) {
  auto l = load(path, {fs::path(path).parent_path().string()});
  ShaderCompiler compiler;
  EffectPrograms programs(*l->units, compiler, l->sm);
  size_t ok = 0, total = 0;
  for (const EffectPass& pass : l->units->passes()) {
    const PassProgram& p = programs.program(pass);
    for (const StageProgram& s : p.stages) {
      ++total;
      if (s.shader.ok) {
        ++ok;
        continue;
      }
      EXPECT_FALSE(s.diagnostics.empty()) << path << " " << pass.technique << "." << pass.pass;
      report += path + " " + pass.technique + "." + pass.pass + " " + to_string(s.stage) + ":\n" +
                render_text(s.diagnostics, l->sm, {.show_source_line = false});
    }
    for (const std::string& why : p.unsupported) EXPECT_FALSE(why.empty());
  }
  return {ok, total};
}

TEST(EffectCorpus, EveryShaderCompilesOrSaysWhy) {
  std::vector<std::string> files;
  for (const char* dir : {"tests/parser/data", "tests/fuzz/corpus", "effects", "effects/seeds"}) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(data(dir), ec))
      if (e.path().extension() == ".fx") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  size_t ok = 0, total = 0, project_ok = 0, project_total = 0;
  std::string report;
  for (const std::string& f : files) {
    auto [o, t] = compile_all(f, report);
    ok += o, total += t;
    if (f.find("/effects/") != std::string::npos) project_ok += o, project_total += t;
  }
  std::printf("[corpus] %zu file(s): %zu of %zu stages compiled; project effects %zu of %zu\n%s", files.size(), ok,
              total, project_ok, project_total, report.c_str());
  EXPECT_GT(total, 10u);
  // The acceptance bar: at least 95% of the project's shader entry points reach SPIR-V.
  if (project_total) {
    EXPECT_GE(project_ok * 100, project_total * 95) << report;
  }
}

}  // namespace
}  // namespace fx
