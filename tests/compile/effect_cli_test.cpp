// `fxkit compile --json` and `fxkit info --json` run as a user would: exit codes, output
// structure, and info's output validated against docs/info.schema.json.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "fxkit_cli.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct CliRun {
  int exit_code = -1;
  std::string out;
};

CliRun run(const std::string& args) {
  fx::testing::CliRun r = fx::testing::run_fxkit(args);
  return {r.status, std::move(r.out)};
}

std::string data(const std::string& rel) { return std::string(FXKIT_SOURCE_DIR) + "/" + rel; }

// A validator for the JSON Schema subset docs/info.schema.json uses: type (string or list),
// required, properties, items, enum, and $ref into #/definitions.
class SchemaValidator {
 public:
  explicit SchemaValidator(json schema) : root_(std::move(schema)) {}
  std::vector<std::string> validate(const json& doc) {
    errors_.clear();
    check(root_, doc, "$");
    return errors_;
  }

 private:
  static bool has_type(const json& v, const std::string& t) {
    if (t == "object") return v.is_object();
    if (t == "array") return v.is_array();
    if (t == "string") return v.is_string();
    if (t == "integer") return v.is_number_integer();
    if (t == "number") return v.is_number();
    if (t == "boolean") return v.is_boolean();
    if (t == "null") return v.is_null();
    return false;
  }
  void check(const json& schema, const json& v, const std::string& path) {
    if (schema.contains("$ref")) {
      std::string ref = schema["$ref"];
      const std::string prefix = "#/definitions/";
      if (ref.rfind(prefix, 0) != 0 || !root_["definitions"].contains(ref.substr(prefix.size()))) {
        errors_.push_back(path + ": unresolvable $ref " + ref);
        return;
      }
      check(root_["definitions"][ref.substr(prefix.size())], v, path);
      return;
    }
    if (schema.contains("type")) {
      bool ok = false;
      if (schema["type"].is_array()) {
        for (const json& t : schema["type"]) ok = ok || has_type(v, t);
      } else {
        ok = has_type(v, schema["type"]);
      }
      if (!ok) {
        errors_.push_back(path + ": expected " + schema["type"].dump() + ", found " + v.dump().substr(0, 80));
        return;
      }
    }
    if (schema.contains("enum")) {
      bool found = false;
      for (const json& e : schema["enum"]) found = found || e == v;
      if (!found) errors_.push_back(path + ": " + v.dump() + " not in " + schema["enum"].dump());
    }
    if (v.is_object()) {
      if (schema.contains("required"))
        for (const json& r : schema["required"])
          if (!v.contains(r.get<std::string>())) errors_.push_back(path + ": missing " + r.get<std::string>());
      if (schema.contains("properties"))
        for (auto& [k, sub] : schema["properties"].items())
          if (v.contains(k)) check(sub, v[k], path + "." + k);
    }
    if (v.is_array() && schema.contains("items"))
      for (size_t i = 0; i < v.size(); ++i) check(schema["items"], v[i], path + "[" + std::to_string(i) + "]");
  }
  json root_;
  std::vector<std::string> errors_;
};

json load_schema() {
  std::ifstream in(data("docs/info.schema.json"));
  return json::parse(in);
}

TEST(SchemaValidator, RejectsWhatTheSchemaForbids) {
  SchemaValidator v(load_schema());
  EXPECT_FALSE(v.validate(json::object()).empty());  // required fields missing
  json bad = {{"file", 3},
              {"ok", true},
              {"profile", "fx_9_0"},
              {"includes", json::array()},
              {"parameters", json::array({{{"name", "x"}}})},
              {"textures", json::array()},
              {"samplers", json::array()},
              {"techniques", json::array()},
              {"diagnostics", json::array()}};
  std::vector<std::string> errors = v.validate(bad);
  std::string all;
  for (const std::string& e : errors) all += e + "\n";
  EXPECT_NE(all.find("$.file"), std::string::npos) << all;
  EXPECT_NE(all.find("$.profile"), std::string::npos) << all;
  EXPECT_NE(all.find("$.parameters[0]: missing type"), std::string::npos) << all;
}

TEST(FxkitInfo, JsonMatchesTheSchemaAndReflectsTheEffect) {
  CliRun r = run("info --json " + data("tests/parser/data/sdk_sample.fx"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  json doc = json::parse(r.out);
  SchemaValidator v(load_schema());
  std::vector<std::string> errors = v.validate(doc);
  for (const std::string& e : errors) ADD_FAILURE() << e;
  // Parameters carry their place in the compiled uniform blocks.
  bool gloss = false;
  for (const json& p : doc["parameters"])
    if (p["name"] == "g_LightDir") {
      gloss = true;
      EXPECT_EQ(p["block"], "$Global");
      EXPECT_EQ(p["size"], 12);
      EXPECT_EQ(p["semantic"], "DIRECTION");
      EXPECT_EQ(p["annotations"].size(), 3u);
    }
  EXPECT_TRUE(gloss);
  // Defaults as written and folded to the parameter's type.
  auto parameter = [&](const std::string& name) {
    for (const json& p : doc["parameters"])
      if (p["name"] == name) return p;
    return json();
  };
  const json dir = parameter("g_LightDir"), range = parameter("g_Range"), lights = parameter("g_nNumLights");
  EXPECT_EQ(dir["default"], "{0.577f, (-0.577f), 0.577f}");  // spell_expression brackets unary operands
  EXPECT_EQ(dir["value"].get<std::vector<double>>(),
            (std::vector<double>{double(0.577f), double(-0.577f), double(0.577f)}));
  EXPECT_EQ(range["value"].get<std::vector<double>>(), (std::vector<double>{0, 1, 0, 2}));
  EXPECT_EQ(lights["value"].get<std::vector<double>>(), std::vector<double>{1});
  EXPECT_EQ(lights["value_text"], "1");
  EXPECT_TRUE(parameter("g_mWorld")["value"].is_null());
  ASSERT_EQ(doc["samplers"].size(), 2u);
  EXPECT_EQ(doc["samplers"][0]["texture"], "g_MeshTexture");
  ASSERT_EQ(doc["techniques"].size(), 3u);
  const json& pass = doc["techniques"][0]["passes"][0];
  EXPECT_TRUE(pass["ok"].get<bool>());
  EXPECT_EQ(pass["vertex_inputs"].size(), 3u);
  EXPECT_TRUE(doc["techniques"][1]["passes"][0]["ok"].get<bool>());  // fixed-function pixel, generated
}

// D3D11 buffers and unordered-access views are listed with their element layout: each
// stage's storage blocks (an AppendStructuredBuffer's counter a block of its own) and its
// storage images, as the linked bindings' kinds say.
TEST(FxkitInfo, ListsStorageBuffersWithTheirElementLayoutAndStorageImages) {
  const std::string file =
      (fs::path(::testing::TempDir()) / ("info_storage_" + std::to_string(::getpid()) + ".fx")).string();
  std::ofstream(file) << R"(struct Particle { float3 pos; float size; };
StructuredBuffer<Particle> Particles;
AppendStructuredBuffer<Particle> Born;
RWTexture2D<float4> Canvas;
[numthreads(8, 8, 1)] void CS(uint3 id : SV_DispatchThreadID) {
  Particle p = Particles[id.x];
  Born.Append(p);
  Canvas[id.xy] = float4(p.pos, p.size);
}
technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, CS())); } }
)";
  CliRun r = run("info --json " + file);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  json doc = json::parse(r.out);
  SchemaValidator v(load_schema());
  for (const std::string& e : v.validate(doc)) ADD_FAILURE() << e;
  const json& pass = doc["techniques"][0]["passes"][0];
  ASSERT_EQ(pass["shaders"].size(), 1u);
  const json& cs = pass["shaders"][0];
  EXPECT_EQ(cs["stage"], "compute");
  std::map<std::string, json> blocks;
  for (const json& b : cs["storage_blocks"]) blocks[b["name"]] = b;
  ASSERT_TRUE(blocks.count("Particles")) << cs.dump(1);
  ASSERT_TRUE(blocks.count("Born@count")) << cs.dump(1);
  std::map<std::string, uint32_t> offsets;
  for (const json& m : blocks["Particles"]["members"]) offsets[m["name"]] = m["offset"];
  EXPECT_EQ(offsets.size(), 2u) << blocks["Particles"].dump(1);
  std::map<std::string, std::string> kinds;
  for (const json& b : pass["bindings"]) kinds[b["name"]] = b["kind"];
  EXPECT_EQ(kinds["Particles"], "storage_buffer");
  EXPECT_EQ(kinds["Born"], "storage_buffer");
  EXPECT_EQ(kinds["Canvas"], "storage_image");
  fs::remove(file);
}

// `info --json` and `check --json` describe the same declarations alike: locations under one
// key at the same column, annotation values typed (a string without its quotes), and a
// parameter's block offset with the stage whose block it is.
TEST(FxkitInfo, JsonAgreesWithCheckJsonOnLocationsAndValues) {
  const std::string file =
      (fs::path(::testing::TempDir()) / ("info_check_" + std::to_string(::getpid()) + ".fx")).string();
  std::ofstream(file) << R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float4 Sky < string UIName = "Sky"; float UIMin = -1; bool Hidden = true; > = {0.2, 0.4, 0.8, 1};
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return Sky; }
technique T < string Scheme = "preview"; > { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";
  CliRun info = run("info --json " + file);
  CliRun check = run("check --json " + file);
  ASSERT_EQ(info.exit_code, 0) << info.out;
  ASSERT_EQ(check.exit_code, 0) << check.out;
  const json i = json::parse(info.out), c = json::parse(check.out)["effects"][0];
  auto named = [](const json& list, const std::string& name) {
    for (const json& e : list)
      if (e["name"] == name) return e;
    return json();
  };
  const json info_sky = named(i["parameters"], "Sky"), check_sky = named(c["parameters"], "Sky");
  ASSERT_FALSE(info_sky.is_null() || check_sky.is_null()) << info.out << check.out;
  EXPECT_EQ(info_sky["location"], check_sky["location"]);
  EXPECT_EQ(info_sky["location"]["column"], 8) << "the name's column";
  for (const json* sky : {&info_sky, &check_sky}) {
    EXPECT_EQ(named((*sky)["annotations"], "UIName")["value"], "Sky") << *sky;
    EXPECT_EQ(named((*sky)["annotations"], "UIMin")["value"], -1.0) << *sky;
    EXPECT_EQ(named((*sky)["annotations"], "Hidden")["value"], true) << *sky;
  }
  EXPECT_EQ(named(info_sky["annotations"], "UIName")["value_text"], "\"Sky\"");
  EXPECT_EQ(named(i["techniques"], "T")["location"], named(c["techniques"], "T")["location"]);
  EXPECT_EQ(named(named(i["techniques"], "T")["annotations"], "Scheme")["value"], "preview");
  // WorldViewProjection and Sky both start their stage's $Global: the stage tells them apart.
  const json wvp = named(i["parameters"], "WorldViewProjection");
  EXPECT_EQ(wvp["offset"], 0);
  EXPECT_EQ(info_sky["offset"], 0);
  EXPECT_EQ(wvp["stage"], "vertex");
  EXPECT_EQ(info_sky["stage"], "fragment");
  ASSERT_EQ(info_sky["placements"].size(), 1u);
  EXPECT_EQ(info_sky["placements"][0]["block"], "$Global");
  fs::remove(file);
}

// An fx_5_0 interface variable lists the class instances it can be bound to, in id order (as
// ParamInfo::class_instances and Effect::set_class_instance take them); others list none.
TEST(FxkitInfo, InterfaceVariablesListTheirClassInstances) {
  const std::string file =
      (fs::path(::testing::TempDir()) / ("info_classes_" + std::to_string(::getpid()) + ".fx")).string();
  std::ofstream(file) << R"(interface iLight { float3 Illuminate(float3 n); };
class cSun : iLight { float3 colour; float3 Illuminate(float3 n) { return colour * n.y; } };
class cSky : iLight { float3 Illuminate(float3 n) { return n; } };
cSun g_sun;
cSky g_skies[2];
iLight g_light;
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS(float4 p : SV_Position) : SV_Target { return float4(g_light.Illuminate(p.xyz), 1); }
technique11 T { pass P { SetVertexShader(CompileShader(vs_5_0, VS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
)";
  CliRun info = run("info --json " + file);
  ASSERT_EQ(info.exit_code, 0) << info.out;
  const json i = json::parse(info.out);
  auto instances = [&](const std::string& name) {
    for (const json& p : i["parameters"])
      if (p["name"] == name) return p["class_instances"];
    return json();
  };
  EXPECT_EQ(instances("g_light"), json({"g_sun", "g_skies[0]", "g_skies[1]"})) << info.out;
  EXPECT_EQ(instances("g_sun"), json::array());
  fs::remove(file);
}

TEST(FxkitInfo, ExitCodes) {
  EXPECT_EQ(run("info --json /nonexistent.fx").exit_code, 2);
  fs::path bad = fs::temp_directory_path() / ("fxkit_cli_bad_" + std::to_string(::getpid()) + ".fx");
  std::ofstream(bad) << "technique T { pass P { NoSuchState = 1; } }\n";
  EXPECT_EQ(run("info --json " + bad.string()).exit_code, 1);
  fs::remove(bad);
}

TEST(FxkitCompile, JsonListsEveryShaderAndWritesSpirv) {
  fs::path dir = fs::temp_directory_path() / ("fxkit_cli_out_" + std::to_string(::getpid()));
  CliRun r =
      run("compile --json --technique Render10 -o " + dir.string() + " " + data("tests/parser/data/sdk_sample.fx"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  json doc = json::parse(r.out);
  ASSERT_EQ(doc["shaders"].size(), 2u);
  for (const json& s : doc["shaders"]) {
    for (const char* key : {"technique", "pass", "stage", "entry", "profile", "ok", "ms", "diagnostics"})
      EXPECT_TRUE(s.contains(key)) << key;
    EXPECT_TRUE(s["ok"].get<bool>());
    EXPECT_EQ(s["technique"], "Render10");
  }
  EXPECT_TRUE(fs::exists(dir / "Render10.P0.vertex.spv"));
  EXPECT_TRUE(fs::exists(dir / "Render10.P0.fragment.spv"));
  EXPECT_GT(fs::file_size(dir / "Render10.P0.fragment.spv"), 20u);
  fs::remove_all(dir);
}

TEST(FxkitCompile, AWarmCacheNeverStartsGlslang) {
  fs::path cache = fs::temp_directory_path() / ("fxkit_cli_cache_" + std::to_string(::getpid()));
  fs::remove_all(cache);
  const std::string args = "compile --json --cache " + cache.string() + " " + data("tests/parser/data/sdk_sample.fx");
  CliRun cold = run(args);
  ASSERT_EQ(cold.exit_code, 0) << cold.out;
  json first = json::parse(cold.out);
  EXPECT_TRUE(first["glslang_started"].get<bool>());
  // A new process, the same effect: every shader from the disk cache, glslang never started.
  CliRun warm = run(args);
  ASSERT_EQ(warm.exit_code, 0) << warm.out;
  json second = json::parse(warm.out);
  EXPECT_FALSE(second["glslang_started"].get<bool>());
  ASSERT_EQ(second["shaders"].size(), first["shaders"].size());
  for (const json& s : second["shaders"]) {
    if (s["stage"].is_string()) {
      EXPECT_TRUE(s["cached"].get<bool>()) << s.dump();
    }
  }
  fs::remove_all(cache);
}

TEST(FxkitCompile, ExitsOneWhenAShaderFails) {
  fs::path bad = fs::temp_directory_path() / ("fxkit_cli_fail_" + std::to_string(::getpid()) + ".fx");
  // A NORMAL input: no fixed-function vertex stage writes one, so none is generated.
  std::ofstream(bad) << "float4 PS(float3 n : NORMAL) : COLOR0 { return undefined_value; }\n"
                        "technique T { pass P { PixelShader = compile ps_2_0 PS(); } }\n";
  CliRun r = run("compile --json " + bad.string());
  EXPECT_EQ(r.exit_code, 1);
  json doc = json::parse(r.out);
  ASSERT_EQ(doc["shaders"].size(), 2u);  // the pixel shader, and the fixed-function vertex stage
  const json& ps = doc["shaders"][0];
  EXPECT_FALSE(ps["ok"].get<bool>());
  ASSERT_FALSE(ps["diagnostics"].empty());
  EXPECT_EQ(ps["diagnostics"][0]["line"], 1);
  // The fixed-function vertex stage says why it is not compiled, at the pass.
  const json& ff = doc["shaders"][1];
  EXPECT_TRUE(ff["stage"].is_null());
  ASSERT_EQ(ff["diagnostics"].size(), 1u) << r.out;
  EXPECT_EQ(ff["diagnostics"][0]["line"], 2);
  EXPECT_EQ(ff["diagnostics"][0]["column"], 15);
  EXPECT_NE(ff["diagnostics"][0]["message"].get<std::string>().find("fixed-function vertex processing"),
            std::string::npos);
  EXPECT_EQ(run("compile --json --technique Missing " + bad.string()).exit_code, 2);
  fs::remove(bad);
}

TEST(FxkitCompile, AStageIsNotBlamedForTheOtherStagesError) {
  fs::path bad = fs::temp_directory_path() / ("fxkit_cli_blame_" + std::to_string(::getpid()) + ".fx");
  // Derivatives exist only in pixel shaders: the vertex stage alone fails.
  std::ofstream(bad) << "float4 VS(float4 p : POSITION) : POSITION { return ddx(p); }\n"
                        "float4 PS() : COLOR0 { return 1; }\n"
                        "technique T { pass P { VertexShader = compile vs_2_0 VS();\n"
                        "                       PixelShader = compile ps_2_0 PS(); } }\n";
  CliRun r = run("compile --json " + bad.string());
  EXPECT_EQ(r.exit_code, 1);
  json doc = json::parse(r.out);
  ASSERT_EQ(doc["shaders"].size(), 2u);
  EXPECT_EQ(doc["shaders"][0]["stage"], "vertex");
  EXPECT_FALSE(doc["shaders"][0]["ok"].get<bool>());
  // SPIR-V validation knows no source line: the error lands on the pass state naming the
  // shader, once, saying what is wrong and where in the module.
  const json& d = doc["shaders"][0]["diagnostics"];
  ASSERT_EQ(d.size(), 1u) << r.out;
  EXPECT_EQ(d[0]["line"], 3);
  EXPECT_EQ(d[0]["column"], 24);
  const std::string message = d[0]["message"];
  EXPECT_NE(message.find("'VS'"), std::string::npos) << message;
  EXPECT_NE(message.find("Derivative"), std::string::npos) << message;
  EXPECT_EQ(doc["shaders"][1]["stage"], "fragment");
  EXPECT_TRUE(doc["shaders"][1]["ok"].get<bool>()) << r.out;
  fs::remove(bad);
}

// A function the shaders of several passes call has one compile error, shown once with where
// else it was reported, not once per stage. (An unknown name would be the semantic model's
// finding, reported once before any stage is compiled.)
TEST(FxkitCompile, AnErrorInASharedFunctionIsShownOnce) {
  fs::path bad = fs::temp_directory_path() / ("fxkit_cli_shared_" + std::to_string(::getpid()) + ".fx");
  std::ofstream(bad)
      << "float3 Helper(float3 v) { return v * float2(1, 2, 3).x; }\n"
         "float4 VS(float4 p : POSITION) : POSITION { return Helper(p.xyz).xyzz; }\n"
         "float4 PS(float4 c : COLOR0) : COLOR0 { return Helper(c.rgb).xyzz; }\n"
         "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n"
         "technique U { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
  fx::testing::CliRun r = fx::testing::run_fxkit("compile " + bad.string(), true);
  EXPECT_EQ(r.status, 1);
  size_t errors = 0;
  for (size_t at = r.err.find(": error: "); at != std::string::npos; at = r.err.find(": error: ", at + 1)) ++errors;
  EXPECT_EQ(errors, 1u) << r.err;
  EXPECT_NE(r.err.find(":1:1: error: 'constructor' : too many arguments"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("note: also reported for T.P fragment, U.P vertex, U.P fragment"), std::string::npos) << r.err;
  fs::remove(bad);
}

}  // namespace
