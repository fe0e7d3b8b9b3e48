#include "spirv_legalize.h"

#include <unordered_set>

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

// Every builtin the module decorates (OpDecorate and OpMemberDecorate BuiltIn).
std::unordered_set<uint32_t> decorated_builtins(const std::vector<uint32_t>& words) {
  constexpr uint32_t kOpDecorate = 71, kOpMemberDecorate = 72, kDecorationBuiltIn = 11, kHeader = 5;
  std::unordered_set<uint32_t> out;
  for (size_t i = kHeader; i < words.size();) {
    const uint32_t op = words[i] & 0xffff, count = words[i] >> 16;
    if (count == 0 || i + count > words.size()) break;
    if (op == kOpDecorate && count >= 4 && words[i + 2] == kDecorationBuiltIn) out.insert(words[i + 3]);
    if (op == kOpMemberDecorate && count >= 5 && words[i + 3] == kDecorationBuiltIn) out.insert(words[i + 4]);
    i += count;
  }
  return out;
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

bool remove_unconsumed_outputs(std::vector<uint32_t>& words, const std::set<uint32_t>& consumed) {
  std::unordered_set<uint32_t> live_locations(consumed.begin(), consumed.end());
  std::unordered_set<uint32_t> live_builtins = decorated_builtins(words);
  spvtools::Optimizer optimizer(vulkan_env(words));
  optimizer.RegisterPass(spvtools::CreateEliminateDeadOutputStoresPass(&live_locations, &live_builtins))
      .RegisterPass(spvtools::CreateAggressiveDCEPass(false, true));
  std::vector<uint32_t> out = words;
  if (!run(optimizer, out)) return false;
  words = std::move(out);
  return true;
}

}  // namespace fx::spirv
