// `fxkit bench MODE`: benchmarks that measure fxkit against a baseline in the same run and
// print both and their ratio.
#pragma once
#include "command.h"

namespace fxkit {

struct BenchArgs {
  std::string mode;     // frontend, ...
  double size_mb = 10;  // frontend: size of the generated effect
  int repeats = 5;
  bool json = false;
};

int bench_frontend(const BenchArgs& args);

}  // namespace fxkit
