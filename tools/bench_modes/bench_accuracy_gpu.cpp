// GPU cost of the accuracy kernels: each kernel draws `draws` full-screen triangles (or a
// grid) into an offscreen target between two vkCmdWriteTimestamp; the median over repeats
// minus its baseline's median, divided by the pixels drawn, is the cost in ns per pixel.
// Kernels are interleaved within each repeat so a slow phase of a shared machine hits all.
#include <algorithm>
#include <cmath>
#include <memory>

#include "bench.h"
#include "bench_accuracy.h"
#include "fx/compile/shader_compiler.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/graphics_pipeline.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/render_target.h"
#include "fx/vulkan/texture.h"

namespace fx::tools {
namespace {

constexpr uint32_t kDraws = 4;  // overdraw per pass: lifts the signal above timestamp noise

const char* kFullscreenVs = R"(
struct VSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
VSOut VS(uint id : SV_VertexID) {
  VSOut o;
  float2 p = float2((id << 1) & 2, id & 2);
  o.uv = p;
  o.pos = float4(p * 2 - 1, 0, 1);
  return o;
}
)";

// Vulkan objects of one kernel; destroyed with the device's owner in mind (ctx outlives).
struct KernelObjects {
  VkDevice device = VK_NULL_HANDLE;
  VkShaderModule vs = VK_NULL_HANDLE, ps = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  fx::vk::Texture texture;
  VkDescriptorSet set = VK_NULL_HANDLE;
  uint32_t vertices = 3;
  double pixels = 0;
  ~KernelObjects() {
    if (!device) return;
    vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyShaderModule(device, vs, nullptr);
    vkDestroyShaderModule(device, ps, nullptr);
  }
};

VkShaderModule module_from(VkDevice device, const fx::CompiledShader& s) {
  VkShaderModuleCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  ci.codeSize = s.spirv.size() * 4;
  ci.pCode = s.spirv.data();
  VkShaderModule m = VK_NULL_HANDLE;
  vkCreateShaderModule(device, &ci, nullptr, &m);
  return m;
}

}  // namespace

std::optional<GpuRun> time_kernels(const std::vector<GpuKernel>& kernels, uint32_t size, int repeats,
                                   fx::DiagnosticSink& sink) {
  fx::vk::ContextOptions co;
  co.validation = true;
  auto ctx = fx::vk::Context::headless(co, sink);
  if (!ctx) return std::nullopt;
  GpuRun run;
  run.device = ctx->info().name;
  run.width = run.height = size;
  run.draws = kDraws;
  run.repeats = uint32_t(repeats);
  run.timestamp_period_ns = ctx->info().limits.timestampPeriod;
  uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical_device(), &families, nullptr);
  std::vector<VkQueueFamilyProperties> props(families);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical_device(), &families, props.data());
  run.timestamp_valid_bits = props[ctx->queue_family()].timestampValidBits;
  if (run.timestamp_valid_bits == 0 || run.timestamp_period_ns <= 0) {
    sink.error("accuracy-no-timestamps", {}, "the device's graphics queue has no timestamps (" + run.device + ")");
    return std::nullopt;
  }
  VkDevice dev = ctx->device();
  auto target = fx::vk::RenderTarget::create(*ctx, {size, size}, sink);
  auto commands = fx::vk::OneShotCommands::create(*ctx, sink);
  if (!target || !commands) return std::nullopt;

  // Shared layout: binding 0 sampled image, the sampler (clamp or wrap), fragment stage. The
  // compiler gives each D3D register class its own binding base (samplers from 128), so the
  // kernels' [[vk::binding(1)]] SamplerState lands on 129.
  constexpr uint32_t kSamplerBinding = 128 + 1;
  VkDescriptorSetLayoutBinding b[2] = {
      {0, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {kSamplerBinding, VK_DESCRIPTOR_TYPE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo dl{};
  dl.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dl.bindingCount = 2;
  dl.pBindings = b;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  vkCreateDescriptorSetLayout(dev, &dl, nullptr, &set_layout);
  VkPipelineLayoutCreateInfo pl{};
  pl.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pl.setLayoutCount = 1;
  pl.pSetLayouts = &set_layout;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vkCreatePipelineLayout(dev, &pl, nullptr, &layout);
  VkSampler samplers[2] = {};
  for (int w = 0; w < 2; ++w) {
    VkSamplerCreateInfo sc{};
    sc.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    sc.magFilter = sc.minFilter = VK_FILTER_LINEAR;
    sc.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sc.addressModeU = sc.addressModeV = sc.addressModeW =
        w ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sc.maxLod = 0;
    vkCreateSampler(dev, &sc, nullptr, &samplers[w]);
  }
  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, uint32_t(kernels.size())},
                                   {VK_DESCRIPTOR_TYPE_SAMPLER, uint32_t(kernels.size())}};
  VkDescriptorPoolCreateInfo dp{};
  dp.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dp.maxSets = uint32_t(kernels.size());
  dp.poolSizeCount = 2;
  dp.pPoolSizes = sizes;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vkCreateDescriptorPool(dev, &dp, nullptr, &pool);
  VkQueryPoolCreateInfo qp{};
  qp.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
  qp.queryType = VK_QUERY_TYPE_TIMESTAMP;
  qp.queryCount = 2;
  VkQueryPool queries = VK_NULL_HANDLE;
  vkCreateQueryPool(dev, &qp, nullptr, &queries);

  fx::shading::Table dummy = fx::shading::Table::make(2, 2, 1, 4, fx::shading::TableFormat::unorm8);
  fx::ShaderCompiler compiler;
  std::vector<std::unique_ptr<KernelObjects>> objects;
  bool ok = true;
  for (const GpuKernel& k : kernels) {
    auto o = std::make_unique<KernelObjects>();
    o->device = dev;
    fx::TranslationUnit vs{k.vs.empty() ? kFullscreenVs : k.vs,
                           fx::ShaderStage::vertex,
                           fx::ShaderLanguage::hlsl,
                           "VS",
                           "vs_5_0",
                           {},
                           k.id + ".vs"};
    fx::TranslationUnit ps{k.ps, fx::ShaderStage::fragment, fx::ShaderLanguage::hlsl, "PS", "ps_5_0", {}, k.id + ".ps"};
    fx::CompiledShader cv = compiler.compile(vs), cp = compiler.compile(ps);
    if (!cv.ok || !cp.ok) {
      sink.error("accuracy-kernel-compile", {},
                 "kernel '" + k.id + "' does not compile:\n" + cv.info_log + cp.info_log);
      ok = false;
      break;
    }
    o->vs = module_from(dev, cv);
    o->ps = module_from(dev, cp);
    auto tex = fx::vk::Texture::from_table(*ctx, k.table.width ? k.table : dummy, sink);
    if (!tex) {
      ok = false;
      break;
    }
    o->texture = std::move(*tex);
    VkDescriptorSetAllocateInfo ai{};
    ai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &set_layout;
    vkAllocateDescriptorSets(dev, &ai, &o->set);
    VkDescriptorImageInfo image{VK_NULL_HANDLE, o->texture.view(), o->texture.layout()};
    VkDescriptorImageInfo sampler{samplers[k.wrap ? 1 : 0], VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
    VkWriteDescriptorSet w[2] = {};
    w[0].sType = w[1].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w[0].dstSet = w[1].dstSet = o->set;
    w[0].dstBinding = 0, w[1].dstBinding = kSamplerBinding;
    w[0].descriptorCount = w[1].descriptorCount = 1;
    w[0].descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, w[0].pImageInfo = &image;
    w[1].descriptorType = VK_DESCRIPTOR_TYPE_SAMPLER, w[1].pImageInfo = &sampler;
    vkUpdateDescriptorSets(dev, 2, w, 0, nullptr);

    VkPipelineShaderStageCreateInfo stages[2] = {};
    stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT, stages[0].module = o->vs, stages[0].pName = cv.entry_point.c_str();
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT, stages[1].module = o->ps, stages[1].pName = cp.entry_point.c_str();
    const VkDynamicState dyn[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    fx::vk::GraphicsPipelineDesc gp;  // the full-screen defaults
    gp.stages = stages;
    gp.layout = layout;
    gp.formats = target->formats();
    gp.dynamic_states = dyn;
    o->pipeline = fx::vk::create_graphics_pipeline(dev, VK_NULL_HANDLE, gp, sink);
    if (!o->pipeline) {
      sink.error("accuracy-kernel-pipeline", {}, "kernel '" + k.id + "': vkCreateGraphicsPipelines failed");
      ok = false;
      break;
    }
    if (k.grid_px > 0) {
      uint32_t cells = (size + uint32_t(k.grid_px) - 1) / uint32_t(k.grid_px);
      o->vertices = cells * cells * 6;
    }
    o->pixels = double(size) * size * kDraws;
    objects.push_back(std::move(o));
  }

  // One timed pass per kernel; index -1 times nothing (warm-up of the pipeline's JIT).
  auto time_pass = [&](const KernelObjects& o) -> std::optional<double> {
    bool submitted = commands->run(
        [&](VkCommandBuffer cmd) {
          vkCmdResetQueryPool(cmd, queries, 0, 2);
          // Outside the rendering scope: a tiling or binning device (lavapipe bins the whole
          // scope and rasterizes at its end) only finishes the draws when the scope ends.
          vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
          target->begin(cmd);
          VkViewport v = target->viewport();
          VkRect2D s = target->scissor();
          vkCmdSetViewport(cmd, 0, 1, &v);
          vkCmdSetScissor(cmd, 0, 1, &s);
          vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, o.pipeline);
          vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &o.set, 0, nullptr);
          for (uint32_t d = 0; d < kDraws; ++d) vkCmdDraw(cmd, o.vertices, 1, 0, 0);
          target->end(cmd);
          vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
        },
        sink);
    if (!submitted) return std::nullopt;
    uint64_t ts[2] = {};
    if (vkGetQueryPoolResults(dev, queries, 0, 2, sizeof ts, ts, sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT) != VK_SUCCESS)
      return std::nullopt;
    uint64_t mask = run.timestamp_valid_bits >= 64 ? ~0ull : ((1ull << run.timestamp_valid_bits) - 1);
    return double((ts[1] - ts[0]) & mask) * run.timestamp_period_ns * 1e-6;
  };
  std::vector<std::vector<double>> ms(objects.size());
  if (ok) {
    for (const auto& o : objects) ok = ok && time_pass(*o).has_value();  // warm-up
    for (int r = 0; ok && r < repeats; ++r) {
      for (size_t i = 0; ok && i < objects.size(); ++i) {
        auto t = time_pass(*objects[i]);
        if (!t) ok = false;
        else ms[i].push_back(*t);
      }
    }
  }
  if (ok) {
    for (size_t i = 0; i < objects.size(); ++i) {
      GpuTiming t{kernels[i].id, interpolated_median(ms[i])};
      run.timings.push_back(t);
    }
    for (size_t i = 0; i < objects.size(); ++i) {
      GpuTiming& t = run.timings[i];
      for (const GpuTiming& b : run.timings)
        if (b.id == kernels[i].baseline) t.baseline_ms = b.median_ms;
      if (kernels[i].id == kernels[i].baseline) t.baseline_ms = t.median_ms;
      t.ns_per_pixel = (t.median_ms - t.baseline_ms) * 1e6 / objects[i]->pixels;
    }
  }
  ctx->wait_idle();
  objects.clear();
  vkDestroyQueryPool(dev, queries, nullptr);
  vkDestroyDescriptorPool(dev, pool, nullptr);
  for (VkSampler s : samplers) vkDestroySampler(dev, s, nullptr);
  vkDestroyPipelineLayout(dev, layout, nullptr);
  vkDestroyDescriptorSetLayout(dev, set_layout, nullptr);
  run.validation_messages = ctx->validation_messages().size();
  ctx->drain_validation_into(sink);
  if (!ok) return std::nullopt;
  return run;
}

}  // namespace fx::tools
