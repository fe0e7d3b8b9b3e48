#include "fx/compile/hlsl_compat.h"

#include "effect_shader_text.h"

namespace fx {

std::string_view pre_release_hlsl_prelude() {
  // Macros rather than typedefs: they also rename constructor calls (vec3(1, 0, 0)).
  return R"(// fxkit pre-release HLSL prelude
#define vec2 float2
#define vec3 float3
#define vec4 float4
#define len(v) length(v)
#define frc(v) frac(v)
#define volumetexture sampler3D
#define texture3d sampler3D
float4 sample1d(sampler1D s, float t) { return tex1D(s, t); }
float4 sample1d(sampler3D s, float t) { return tex3D(s, float3(t, 0.0, 0.0)); }
float4 sample2d(sampler2D s, float2 t) { return tex2D(s, t); }
float4 sample3d(sampler3D s, float3 t) { return tex3D(s, t); }
)";
}

namespace {

struct KnownIssue {
  std::string_view name;
  std::string_view reason;
};
constexpr KnownIssue kIssues[] = {
    {"sample1d", "a 1D lookup of a volume texture has no modern equivalent; fxkit samples it along x at (t, 0, 0)"},
    {"volumetexture",
     "pre-release code sampled texture objects directly; fxkit declares them as sampler3D with "
     "default sampler state"},
    {"smoothstep",
     "the source defines its own smoothstep, which overloads the intrinsic; its (a, b, s) argument "
     "order differs from HLSL's smoothstep(min, max, x)"},
};

}  // namespace

std::vector<CompatIssue> pre_release_hlsl_issues(std::string_view src) {
  std::vector<CompatIssue> out;
  std::vector<bool> seen(std::size(kIssues), false);
  for (size_t i = 0; i < src.size();) {
    if (src.compare(i, 2, "//") == 0) {
      i = src.find('\n', i);
      if (i == std::string_view::npos) break;
      continue;
    }
    if (src.compare(i, 2, "/*") == 0) {
      i = src.find("*/", i + 2);
      if (i == std::string_view::npos) break;
      i += 2;
      continue;
    }
    if (!detail::is_word_char(src[i]) || (i > 0 && detail::is_word_char(src[i - 1]))) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < src.size() && detail::is_word_char(src[end])) ++end;
    std::string_view word = src.substr(i, end - i);
    for (size_t k = 0; k < std::size(kIssues); ++k)
      if (!seen[k] && word == kIssues[k].name) {
        seen[k] = true;
        out.push_back({std::string(word), i, std::string(kIssues[k].reason)});
      }
    i = end;
  }
  return out;
}

}  // namespace fx
