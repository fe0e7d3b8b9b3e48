#include "spirv_legalize.h"

#include <spirv-tools/optimizer.hpp>

#include "spirv_words.h"

namespace fx::spirv {
namespace {

bool run(spvtools::Optimizer& optimizer, std::vector<uint32_t>& words) {
  // The input is invalid until these passes ran (that is why they run): no validation first.
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);
  std::vector<uint32_t> out;
  if (!optimizer.Run(words.data(), words.size(), &out, options)) return false;
  words = std::move(out);
  return true;
}

}  // namespace

spv_target_env vulkan_env(const std::vector<uint32_t>& words) {
  const uint32_t version = words.size() > 1 ? words[1] : 0;
  if (version >= 0x00010600) return SPV_ENV_VULKAN_1_3;
  if (version >= 0x00010500) return SPV_ENV_VULKAN_1_2;
  if (version >= 0x00010300) return SPV_ENV_VULKAN_1_1;
  return SPV_ENV_VULKAN_1_0;
}

bool legalize(std::vector<uint32_t>& words) {
  spvtools::Optimizer optimizer(vulkan_env(words));
  optimizer.RegisterLegalizationPasses();
  return run(optimizer, words);
}

void unroll_and_fold(std::vector<uint32_t>& words, spv_target_env env) {
  request_loop_unroll(words);
  spvtools::Optimizer optimizer(env);
  optimizer.RegisterPass(spvtools::CreateLoopUnrollPass(true))
      .RegisterPass(spvtools::CreateCCPPass())
      .RegisterPass(spvtools::CreateSimplificationPass())
      .RegisterPass(spvtools::CreateAggressiveDCEPass());
  run(optimizer, words);
}

}  // namespace fx::spirv
