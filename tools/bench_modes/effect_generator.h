// Generates large, valid effect files for throughput benchmarks: many included modules,
// each with macros, annotated parameters, sampler states, structs, shader functions and
// techniques, in the style of DirectX SDK sample effects.
#pragma once
#include <cstddef>
#include <map>
#include <string>

namespace fx::tools {

struct GeneratedEffect {
  std::string main_name;                     // "bench_main.fx"
  std::map<std::string, std::string> files;  // every file, the main one included
  std::string shader_code;                   // the HLSL a shader compiler would see
  size_t effect_bytes = 0;                   // all files together
};

// At least `min_bytes` of effect source, split into modules of about 64 KiB.
GeneratedEffect generate_effect(size_t min_bytes);

}  // namespace fx::tools
