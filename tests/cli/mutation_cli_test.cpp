// Broken copies of effects through `fxkit check`, glslang included (fxkit issue #32): the
// project's effects/ and small effects written here, each with a span deleted, duplicated or
// swapped, stray bytes, a truncation, 20,000 open parentheses or braces, a macro bomb or a
// token paste. No run may crash or hang, and every file it rejects has an error located at
// file:line:col. One `fxkit check` run takes them all (a crash there is then narrowed down
// to its file by one run per file). By default each kind once on each small effect and on one
// of effects/ (36 files, one process); FXKIT_SOAK=1 makes twenty of each kind from every
// source.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fxkit_cli.h"

namespace fx::testing {
namespace {

namespace fs = std::filesystem;

// Small effects that reach what the mutations break: functions, a static initialised by a
// call, a struct, a GLSL block, a D3D9 and a D3D10 technique.
const char* const kSmallEffects[] = {
    R"(float4x4 WorldViewProj : WORLDVIEWPROJECTION;
float3 f(float3 x) { return x * 2; }
float3 g(float3 x) { return x + 1; }
float a;
static const float3 K = f(float3(a, a, a));
struct VSOut { float4 pos : POSITION; float3 c : COLOR0; };
VSOut VS(float4 p : POSITION) { VSOut o; o.pos = mul(p, WorldViewProj); o.c = g(K); return o; }
float4 PS(VSOut i) : COLOR { if (i.c.x > 0) { return float4(i.c, 1); } else return float4(K, 1); }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)",
    R"(#define SCALE(x) ((x) * 2)
#define CAT(a, b) a##b
cbuffer Frame { float4x4 ViewProj; float Time; };
Texture2D Tex; SamplerState Linear { Filter = MIN_MAG_MIP_LINEAR; };
float4 VS(float3 p : POSITION) : SV_Position { return mul(float4(p * SCALE(Time), 1), ViewProj); }
float4 PS(float4 p : SV_Position) : SV_Target { float CAT(c, 0) = 0.5; return Tex.Sample(Linear, p.xy) * c0; }
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
)",
    R"(GLSLShader Common { #version 450
  layout(location = 0) in vec3 position;
}
GLSLShader VS { void main() { gl_Position = vec4(position, 1.0); } }
GLSLShader PS { layout(location = 0) out vec4 color; void main() { color = vec4(1.0); } }
technique T { pass P { VertexShader = { Common, VS }; PixelShader = PS; } }
)",
};

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

enum class Mutation { remove, duplicate, swap, stray_bytes, truncate, open_parens, open_braces, macro_bomb, paste };
constexpr int kMutations = 9;

std::string mutate(const std::string& text, Mutation kind, std::mt19937& rng) {
  auto below = [&](size_t n) { return n ? static_cast<size_t>(rng() % n) : 0; };
  const size_t a = below(text.size() + 1), b = std::min(text.size(), a + 1 + below(300));
  switch (kind) {
    case Mutation::remove: return text.substr(0, a) + text.substr(b);
    case Mutation::duplicate: return text.substr(0, b) + text.substr(a, b - a) + text.substr(b);
    case Mutation::swap: {
      const size_t c = b + below(text.size() - b + 1), d = std::min(text.size(), c + 1 + below(300));
      return text.substr(0, a) + text.substr(c, d - c) + text.substr(b, c - b) + text.substr(a, b - a) + text.substr(d);
    }
    case Mutation::stray_bytes: {
      std::string out = text;
      static const char kBytes[] = "#\\\"'`@$\x7f{}()[];<>=!\xff\x80";
      for (size_t n = 1 + below(12); n-- > 0;) {
        const char c = rng() % 4 == 0 ? static_cast<char>(rng() % 256) : kBytes[below(sizeof kBytes - 1)];
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(below(out.size() + 1)), c);
      }
      return out;
    }
    case Mutation::truncate: return text.substr(0, a);
    case Mutation::open_parens: return text.substr(0, a) + std::string(20000, '(') + text.substr(a);
    case Mutation::open_braces: return text.substr(0, a) + std::string(20000, '{') + text.substr(a);
    case Mutation::macro_bomb: {
      std::string bomb = "\n#define B0 (x)\n";
      for (int i = 1; i < 40; ++i)
        bomb += "#define B" + std::to_string(i) + " B" + std::to_string(i - 1) + " B" + std::to_string(i - 1) + "\n";
      return text.substr(0, a) + bomb + "float bomb = B39;\n" + text.substr(a);
    }
    case Mutation::paste:
      return text.substr(0, a) +
             "\n#define P(a, b) a ## b ## #a\n#define H #\nH define Q(x) x##x\nfloat P(x, y) = Q(1);\n" +
             text.substr(a);
  }
  return text;
}

// Generous bounds for a hang detector, not timings: a run that needs them has hung.
int seconds_per_file() {
#if defined(__SANITIZE_ADDRESS__)
  return 300;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return 300;
#else
  return 60;
#endif
#else
  return 60;
#endif
}

// `fxkit check` on `paths` with a bound on its time; the exit status (124: timed out, 128+N:
// killed by signal N) and the JSON report.
CliRun check(const std::string& paths, size_t files) {
  const std::string limit = std::to_string(seconds_per_file() * (files + 1));
  return run_fxkit("check -I " + std::string(FXKIT_SOURCE_DIR) + "/effects --format json " + paths, true,
                   "timeout -s KILL " + limit + " ");
}

class Mutants : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("fxkit_mutants_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(Mutants, CheckNeverCrashesAndLocatesEveryRejection) {
  std::vector<std::string> sources;
  for (const auto& e : fs::directory_iterator(fs::path(FXKIT_SOURCE_DIR) / "effects"))
    if (e.path().extension() == ".fx") sources.push_back(read_file(e.path()));
  std::sort(sources.begin(), sources.end());
  for (const char* text : kSmallEffects) sources.push_back(text);
  ASSERT_GE(sources.size(), 6u);

  const bool soak = std::getenv("FXKIT_SOAK") != nullptr;
  const int count = soak ? 10 * 2 * kMutations * static_cast<int>(sources.size()) : 4 * kMutations;
  std::mt19937 rng(32);
  std::vector<fs::path> files;
  for (int i = 0; i < count; ++i) {
    // Every kind on every small effect first, then the project's effects.
    const std::string& source = sources[(sources.size() - 1 - static_cast<size_t>(i / kMutations) % sources.size())];
    const Mutation kind = static_cast<Mutation>(i % kMutations);
    std::ostringstream name;
    name << "m" << i << "_" << i % kMutations << ".fx";
    files.push_back(dir_ / name.str());
    std::ofstream(files.back(), std::ios::binary) << mutate(source, kind, rng);
  }

  CliRun all = check(dir_.string(), files.size());
  if (all.status < 0 || all.status >= 124) {
    // Name the files that crash or hang, one run each.
    std::ostringstream culprits;
    for (const fs::path& f : files) {
      CliRun one = check(f.string(), 1);
      if (one.status < 0 || one.status >= 124) culprits << " " << f.filename().string() << " (" << one.status << ")";
    }
    FAIL() << "fxkit check exited with " << all.status << "; per file:" << culprits.str();
  }
  nlohmann::json report = nlohmann::json::parse(all.out, nullptr, false);
  ASSERT_FALSE(report.is_discarded()) << "exit " << all.status << ": " << all.out.substr(0, 2000)
                                      << all.err.substr(0, 2000);
  ASSERT_EQ(report["files"].get<size_t>(), files.size());

  std::set<std::string> located;  // files with an error at file:line:col
  for (const auto& d : report["diagnostics"]) {
    if (d["severity"] != "error") continue;
    ASSERT_TRUE(d["file"].is_string()) << d.dump();
    EXPECT_GT(d["line"].get<int>(), 0) << d.dump();
    EXPECT_GT(d["column"].get<int>(), 0) << d.dump();
    located.insert(fs::path(d["file"].get<std::string>()).filename().string());
    for (const auto& n : d["notes"])
      if (n["file"].is_string()) located.insert(fs::path(n["file"].get<std::string>()).filename().string());
  }
  size_t rejected = 0;
  for (const auto& e : report["effects"]) {
    if (e["errors"].get<int>() == 0) continue;
    ++rejected;
    EXPECT_TRUE(located.count(fs::path(e["file"].get<std::string>()).filename().string()))
        << e["file"] << " rejected with no error located in it";
  }
  // The mutations that cannot leave an effect valid (20,000 open brackets) did reject.
  EXPECT_GE(rejected, files.size() / kMutations * 2);
}

}  // namespace
}  // namespace fx::testing
