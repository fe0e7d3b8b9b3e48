// Internals of `fxkit bench accuracy`: the GPU kernels that mirror each approximation and
// their timing with Vulkan timestamps.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/shading/table.h"

namespace fx::tools {

// One full-screen (or gridded) pass that mirrors an approximation's shader code.
struct GpuKernel {
  std::string id;                  // "strand_lut/dot/unorm8/s256"
  std::string vs;                  // HLSL vertex shader body; empty = full-screen triangle
  std::string ps;                  // HLSL pixel shader (entry PS)
  fx::shading::Table table = {};   // bound at t0 (a 2x2 dummy when empty)
  bool wrap = false;               // sampler address mode (clamp otherwise)
  int grid_px = 0;                 // >0: draw a grid of cells this many pixels wide instead
  std::string baseline = "empty";  // kernel whose time is subtracted
};

struct GpuTiming {
  std::string id;
  double median_ms = 0;     // the kernel's own pass, median of repeats
  double baseline_ms = 0;   // its baseline's median
  double ns_per_pixel = 0;  // (median - baseline) / pixels drawn
};

struct GpuRun {
  std::string device;  // physical device name
  uint32_t width = 0, height = 0, draws = 0, repeats = 0;
  double timestamp_period_ns = 0;
  uint32_t timestamp_valid_bits = 0;
  size_t validation_messages = 0;
  std::vector<GpuTiming> timings;
};

// The kernels for every timed approximation (the catalogue's ids where they match), for
// a size x size target (grid kernels need it).
std::vector<GpuKernel> accuracy_kernels(int size);

// Times every kernel (validation on). nullopt with diagnostics when Vulkan, timestamps or
// a shader fails.
std::optional<GpuRun> time_kernels(const std::vector<GpuKernel>& kernels, uint32_t size, int repeats,
                                   fx::DiagnosticSink& sink);

}  // namespace fx::tools
