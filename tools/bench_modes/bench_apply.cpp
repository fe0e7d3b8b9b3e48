// `fxkit bench apply [--repeats N] [--json]`: CPU cost of recording N objects through the
// public API (fxkit::Device on the same VkDevice; per object Effect::set_matrix twice, then
// Technique::apply and a draw per pass; begin/end per technique group) against hand-written
// Vulkan recording the same work into a command buffer: pipelines of the same states, one descriptor set per program
// with dynamic uniform offsets, the same uniform bytes copied into a mapped ring (blocks holding per-object matrices
// per draw, the others once per frame, as fxkit re-packs only changed blocks), the same binds and draws. Both run in
// the same process on the same device, both are submitted (only recording is timed); the ratio is fxkit / raw.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <string_view>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "bench.h"
#include "fx/binding/effect_preview.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/uniform_layout.h"
#include "fx/vulkan/one_shot.h"
#include "fxkit/fxkit.h"

namespace fx::tools {
namespace {

using Clock = std::chrono::steady_clock;
constexpr uint32_t kObjects = 2000;

// A per-object matrix as both paths get it: the app's array, in the layout the shader's
// registers read (see the object transforms below), and that layout for fxkit.
struct AppMatrix {
  fxkit::Param param;
  const glm::mat4* values = nullptr;
  fxkit::MatrixOrder order = fxkit::MatrixOrder::row_major;
};

// One technique group as an engine holds it through the public API.
struct PublicGroup {
  fxkit::Effect effect;
  fxkit::Technique technique;
  fxkit::Param world, wvp;
  fxkit::MatrixOrder world_order, wvp_order;
  const glm::mat4* world_values;
  const glm::mat4* wvp_values;
};

struct Group {
  fx::EffectFile* effect;
  fx::vk::EffectBinding* binding;
  uint32_t technique, layout;
  AppMatrix world, wvp;
};

// What the hand-written path keeps per pass: pipeline, layout, its own descriptor set and
// per block the app's constants (the effect's values, packed as the shader reads them),
// where World / WorldViewProjection sit and whether the shader reads them transposed.
struct RawPass {
  VkPipeline pipeline;
  VkPipelineLayout layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  struct Block {
    uint32_t size, world = UINT32_MAX, wvp = UINT32_MAX;
    bool world_columns = false, wvp_columns = false;  // column_major: registers hold columns
    std::vector<uint8_t> bytes;
    uint32_t offset = 0;  // ring offset of this frame's copy (blocks without per-object data)
    bool per_object() const { return world != UINT32_MAX || wvp != UINT32_MAX; }
  };
  std::vector<Block> blocks;
};

void report(const fx::DiagnosticSink& sink) {
  for (const fx::Diagnostic& d : sink.diagnostics())
    std::fprintf(stderr, "fxkit bench apply: %s [%s]\n", d.message.c_str(), d.id.c_str());
}

}  // namespace

int bench_apply(const BenchArgs& args) {
  fx::DiagnosticSink sink;
  auto ctx = fx::vk::Context::headless({}, sink);
  auto mesh = fx::make_mesh("quad", sink);
  if (!ctx || !mesh) return report(sink), kUsageError;
  int status = kSuccess;
  nlohmann::json out;
  (void)out;
  {
    fx::vk::EffectPreviewDesc pd;
    pd.width = pd.height = 64;
    pd.frames.uniform_bytes_per_frame = 16u << 20;
    pd.frames.sets_per_frame = 1024;
    auto preview = fx::vk::EffectPreview::create(*ctx, *mesh, pd, sink);
    if (!preview) return report(sink), kUsageError;
    fx::FrontEndOptions options;
    options.preprocessor.include_dirs = {args.effects_dir};
    const std::pair<const char*, std::vector<const char*>> wanted[] = {
        {"strand_aniso.fx", {"strand_lut", "strand_analytic", "strand_four_lights"}},
        {"hemisphere.fx", {"hemisphere_sun", "hemisphere_two_term"}},
        {"aniso_lut_ward.fx", {"gaussian_per_pixel", "ln_hn_per_pixel"}}};
    std::vector<std::unique_ptr<fx::EffectFile>> effects;
    std::vector<std::unique_ptr<fx::vk::EffectBinding>> bindings;
    std::vector<Group> groups;
    fx::vk::EffectBindingDesc desc = preview->binding_desc();
    desc.dynamic = fx::vk::DynamicStateSet::none();  // the raw path uses static pipelines too
    for (const auto& [file, techniques] : wanted) {
      auto e = fx::EffectFile::load(args.effects_dir + "/" + file, options, sink);
      if (!e) return report(sink), kInputErrors;
      desc.effect_dir = args.effects_dir;
      auto b = fx::vk::EffectBinding::create(*ctx, *e->model, *e->programs, *e->params, preview->textures(),
                                             preview->frames(), desc, sink);
      if (!b) return report(sink), kInputErrors;
      for (const char* name : techniques) {
        uint32_t t = e->find_technique(name);
        if (!b->technique_ok(t)) {
          std::fprintf(stderr, "fxkit bench apply: %s: %s\n", name, b->technique_reason(t).c_str());
          return kInputErrors;
        }
        auto inputs = fx::vk::technique_vertex_inputs(*e->model, *e->programs, t);
        groups.push_back({e.get(),
                          b.get(),
                          t,
                          b->add_vertex_layout(preview->vertex_layout(inputs)),
                          {e->params->by_semantic("WORLD")},
                          {e->params->by_semantic("WORLDVIEWPROJECTION")}});
      }
      effects.push_back(std::move(e));
      bindings.push_back(std::move(b));
    }
    const fx::vk::RenderingFormats formats = preview->formats();
    const fx::vk::SceneView scene = preview->scene();
    // Object transforms: a grid, the same for both paths. The app keeps them in the layout
    // its shaders' registers read, as an engine choosing its own math would: the transpose
    // for column_major registers. Both paths read the same arrays; fxkit is told their
    // order (fxkit::MatrixOrder), the hand-written path copies them as they are.
    std::vector<glm::mat4> world(kObjects), wvp(kObjects), world_t(kObjects), wvp_t(kObjects);
    for (uint32_t i = 0; i < kObjects; ++i) {
      world[i] =
          glm::translate(glm::mat4(1.0f), glm::vec3(float(i % 50) * 0.02f - 0.5f, float(i / 50) * 0.02f - 0.4f, 0.0f));
      wvp[i] = scene.projection * scene.view * world[i];
      world_t[i] = glm::transpose(world[i]);
      wvp_t[i] = glm::transpose(wvp[i]);
    }
    for (Group& G : groups) {
      auto layout = [&](AppMatrix& m, const std::vector<glm::mat4>& rows, const std::vector<glm::mat4>& columns) {
        const fx::Type* type = G.effect->params->type(m.param);
        const bool registers_are_columns = !type || type->order == fx::MatrixPacking::column_major;
        m.values = registers_are_columns ? columns.data() : rows.data();
        m.order = registers_are_columns ? fxkit::MatrixOrder::column_major : fxkit::MatrixOrder::row_major;
      };
      layout(G.world, world, world_t);
      layout(G.wvp, wvp, wvp_t);
    }
    const uint32_t per_group = kObjects / uint32_t(groups.size());

    // The measured path: the public API on the same device, for the same attachments.
    fxkit::DeviceOptions device_options;
    const fx::vk::RenderingFormats preview_formats = preview->formats();
    device_options.target.formats = {
        .color = {preview_formats.color[0]}, .depth = preview_formats.depth, .stencil = preview_formats.stencil};
    device_options.target.vertex_layout = fxkit::Mesh::vertex_layout();
    device_options.target.default_attribute_binding = 1;  // as the preview's constant stream
    device_options.target.front_faces = fxkit::Winding::counter_clockwise;
    device_options.target.y_flip = fxkit::YFlip::negative_viewport;
    device_options.watch = false;
    device_options.dynamic_state = false;  // static pipelines, as the hand-written path
    device_options.uniform_bytes_per_frame = 16u << 20;
    std::vector<fxkit::Message> errors;
    auto device = fxkit::Device::create(
        {ctx->instance(), ctx->physical_device(), ctx->device(), ctx->queue(), ctx->queue_family()}, device_options,
        errors);
    if (!device) {
      for (const fxkit::Message& m : errors) std::fprintf(stderr, "fxkit bench apply: %s", m.rendered.c_str());
      return kUsageError;
    }
    std::vector<PublicGroup> pub;
    std::map<std::string, fxkit::Effect> loaded;  // one Effect per file, as one EffectBinding per file below
    for (const Group& G : groups) {
      auto [at, fresh] = loaded.try_emplace(G.effect->path);
      if (fresh) at->second = device->load(G.effect->path);
      fxkit::Effect effect = at->second;
      const std::string name = G.effect->model->techniques[G.technique].name;
      fxkit::Technique technique = effect.technique(name);
      if (!technique.valid()) {
        std::fprintf(stderr, "fxkit bench apply: %s: %s\n", name.c_str(), technique.reason().c_str());
        return kInputErrors;
      }
      pub.push_back({effect, technique, effect.param("WORLD"), effect.param("WORLDVIEWPROJECTION"), G.world.order,
                     G.wvp.order, G.world.values, G.wvp.values});
    }

    // The hand-written path's objects: the same pipelines, its own sets and ring.
    const VkDeviceSize align = std::max<VkDeviceSize>(ctx->info().limits.minUniformBufferOffsetAlignment, 16);
    // Its uniform ring has a slice per frame in flight, as fxkit's (DeviceOptions'
    // default of two): an engine cannot overwrite what the GPU may still be reading.
    constexpr VkDeviceSize kRawSlice = 8u << 20;
    constexpr uint32_t kRawFramesInFlight = 2;
    auto ring = fx::vk::Buffer::create(
        *ctx,
        {kRawSlice * kRawFramesInFlight, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, fx::vk::MemoryUsage::upload, "raw ring"},
        sink);
    auto image = fx::Image::blank(1, 1, 4);
    std::fill(image.pixels.begin(), image.pixels.end(), 255);
    auto texture = fx::vk::Texture::from_image(*ctx, image, fx::vk::ColorSpace::linear, sink);
    fx::vk::SamplerCache samplers(*ctx);
    VkSampler sampler = samplers.get({}, sink);
    auto vertices =
        fx::vk::Buffer::create(*ctx,
                               {mesh->vertices.size() * sizeof(fx::Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                fx::vk::MemoryUsage::upload, "bench vertices"},
                               sink);
    auto constants = fx::vk::Buffer::create(
        *ctx, {16, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "bench constants"}, sink);
    if (!ring || !texture || !sampler || !vertices || !constants) return report(sink), kUsageError;
    vertices->write(mesh->vertices.data(), mesh->vertices.size() * sizeof(fx::Vertex));
    const float constant[4] = {0, 0, 0, 1};
    constants->write(constant, 16);
    VkDescriptorPool pool = VK_NULL_HANDLE;
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 256},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 256},
                                          {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 256},
                                          {VK_DESCRIPTOR_TYPE_SAMPLER, 256}};
    const VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr, 0, 64, 4, sizes};
    vkCreateDescriptorPool(ctx->device(), &pool_info, nullptr, &pool);
    std::vector<std::vector<RawPass>> raw(groups.size());
    std::set<VkPipeline> distinct;
    for (size_t g = 0; g < groups.size(); ++g) {
      const Group& G = groups[g];
      // The app's constants: the effect's parameter values (copied from fxkit's store) packed
      // once by a store of the app's own, with the HLSL matrix order of each member.
      fx::ParameterStore values(*G.effect->model);
      fx::remap(*G.effect->params, values);
      uint32_t block_id = 0;
      const uint32_t world = G.effect->model->find_parameter("World");
      const uint32_t wvp = G.effect->model->find_parameter("WorldViewProjection");
      for (uint32_t p = 0; p < G.binding->pass_count(G.technique); ++p) {
        RawPass rp{};
        const auto& units = G.effect->units->passes();
        auto unit = std::find_if(units.begin(), units.end(), [&](const fx::EffectPass& u) {
          return u.technique_index == G.technique && u.pass_index == p;
        });
        if (unit == units.end()) return std::fprintf(stderr, "fxkit bench apply: a pass has no units\n"), kUsageError;
        const std::vector<fx::UniformBlockLayout> layouts =
            fx::uniform_layouts(*G.effect->model, G.effect->programs->program(*unit));
        const fx::vk::ShaderProgram* program = nullptr;
        if (!G.binding->pass_objects(G.technique, p, formats, G.layout, rp.pipeline, program, sink))
          return report(sink), kInputErrors;
        distinct.insert(rp.pipeline);
        rp.layout = program->pipeline_layout();
        VkDescriptorSetLayout set_layout = program->set_layout();
        const VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, nullptr, pool, 1,
                                                &set_layout};
        vkAllocateDescriptorSets(ctx->device(), &alloc, &rp.set);
        std::vector<VkDescriptorBufferInfo> buffers;
        std::vector<VkDescriptorImageInfo> images;
        buffers.reserve(16);
        images.reserve(16);
        std::vector<VkWriteDescriptorSet> writes;
        for (const fx::vk::ProgramUniformBlock& b : program->uniform_blocks()) {
          RawPass::Block block{};
          block.size = b.size;
          block.bytes.assign(b.size, 0);
          auto layout = std::find_if(layouts.begin(), layouts.end(),
                                     [&](const fx::UniformBlockLayout& l) { return l.binding == b.binding; });
          if (layout == layouts.end())
            return std::fprintf(stderr, "fxkit bench apply: a block is not laid out\n"), kUsageError;
          for (const fx::BlockMemberLayout& m : layout->members) {
            const bool whole = m.slice.first_word == 0;
            if (whole && m.slice.parameter == world)
              block.world = m.offset, block.world_columns = m.order == fx::MatrixPacking::column_major;
            if (whole && m.slice.parameter == wvp)
              block.wvp = m.offset, block.wvp_columns = m.order == fx::MatrixPacking::column_major;
          }
          values.bind_layout(block_id, layout->members, b.size);
          values.write_block(block_id++, block.bytes);
          rp.blocks.push_back(std::move(block));
          buffers.push_back({ring->handle(), 0, b.size});
          writes.push_back({VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, rp.set, b.binding, 0, 1,
                            VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, nullptr, &buffers.back(), nullptr});
        }
        for (const fx::vk::ProgramImage& im : program->images()) {
          const VkDescriptorType type = fx::vk::to_vk_descriptor(im.kind, fx::vk::DescriptorMode::sets);
          images.push_back({sampler, texture->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
          writes.push_back({VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, rp.set, im.binding, 0, 1, type,
                            &images.back(), nullptr, nullptr});
        }
        vkUpdateDescriptorSets(ctx->device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
        raw[g].push_back(std::move(rp));
      }
    }

    auto one_shot = fx::vk::OneShotCommands::create(*ctx, sink);
    auto target = fx::vk::RenderTarget::create(
        *ctx, {64, 64, VK_FORMAT_R8G8B8A8_UNORM, fx::vk::DepthAttachment::d24s8, 0, "bench apply"}, sink);
    if (!one_shot || !target) return report(sink), kUsageError;
    const VkViewport viewport{0, 64, 64, -64, 0, 1};
    const VkRect2D scissor{{0, 0}, {64, 64}};
    const VkBuffer vbs[2] = {vertices->handle(), constants->handle()};
    const VkDeviceSize offs[2] = {0, 0};
    const uint32_t vertex_count = uint32_t(mesh->vertices.size());
    bool ok = true;
    // One frame of each path inside the target's dynamic rendering; only the recording of
    // the objects is timed. Not inlined, so a profiler (callgrind) counts each path apart.
    auto frame_fxkit = [&](VkCommandBuffer cmd) __attribute__((noinline)) {
      auto t0 = Clock::now();
      for (size_t g = 0; g < pub.size(); ++g) {
        // What an engine's draw loop holds in locals, as the hand-written loop does.
        PublicGroup& P = pub[g];
        fxkit::Effect& effect = P.effect;
        fxkit::Technique& technique = P.technique;
        const fxkit::Param world = P.world, wvp = P.wvp;
        bool drawn = technique.begin(cmd, viewport, scissor);
        vkCmdBindVertexBuffers(cmd, 0, 2, vbs, offs);
        const uint32_t passes = technique.pass_count();
        for (uint32_t i = uint32_t(g) * per_group; i < uint32_t(g + 1) * per_group; ++i) {
          effect.set_matrix(world, glm::value_ptr(P.world_values[i]), P.world_order);
          effect.set_matrix(wvp, glm::value_ptr(P.wvp_values[i]), P.wvp_order);
          for (uint32_t p = 0; p < passes; ++p) {
            drawn = technique.apply(p) && drawn;
            vkCmdDraw(cmd, vertex_count, 1, 0, 0);
          }
        }
        technique.end();
        ok = ok && drawn;
      }
      return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    };
    // The layer under the public API (EffectBinding with static pipelines), for the overhead
    // the public API adds.
    auto frame_binding = [&](VkCommandBuffer cmd) __attribute__((noinline)) {
      auto t0 = Clock::now();
      for (size_t g = 0; g < groups.size(); ++g) {
        // What an engine's draw loop holds in locals, as the hand-written loop does.
        const Group& G = groups[g];
        fx::ParameterStore& params = *G.effect->params;
        fx::vk::EffectBinding& binding = *G.binding;
        const AppMatrix world = G.world, wvp = G.wvp;
        const uint32_t layout = G.layout;
        bool drawn = binding.begin(cmd, G.technique, formats, viewport, scissor, sink);
        vkCmdBindVertexBuffers(cmd, 0, 2, vbs, offs);
        const uint32_t passes = binding.pass_count(G.technique);
        for (uint32_t i = uint32_t(g) * per_group; i < uint32_t(g + 1) * per_group; ++i) {
          params.set_matrix(world.param, std::span<const float>(glm::value_ptr(world.values[i]), 16), world.order);
          params.set_matrix(wvp.param, std::span<const float>(glm::value_ptr(wvp.values[i]), 16), wvp.order);
          for (uint32_t p = 0; p < passes; ++p) {
            drawn = binding.apply(p, layout, sink) && drawn;
            vkCmdDraw(cmd, vertex_count, 1, 0, 0);
          }
        }
        binding.end();
        ok = ok && drawn;
      }
      return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    };
    uint8_t* ring_bytes = static_cast<uint8_t*>(ring->mapped());
    uint64_t raw_bytes = 0;  // uniform bytes the last raw frame copied into its ring
    uint32_t raw_frame = 0;
    auto frame_raw = [&](VkCommandBuffer cmd) __attribute__((noinline)) {
      auto t0 = Clock::now();
      VkDeviceSize head = kRawSlice * (raw_frame++ % kRawFramesInFlight);
      const VkDeviceSize slice_end = head + kRawSlice;
      VkPipeline bound = VK_NULL_HANDLE;
      uint32_t offsets[8];
      raw_bytes = 0;
      auto upload = [&](const RawPass::Block& block) {
        if (head + block.size > slice_end) [[unlikely]] {  // a bench of more objects: fail, not overwrite
          if (ok) sink.error("bench-raw-ring-full", {}, "the hand-written path's uniform slice is too small");
          ok = false;
          return uint32_t(slice_end - kRawSlice);
        }
        std::memcpy(ring_bytes + head, block.bytes.data(), block.size);
        const auto at = uint32_t(head);
        head += (block.size + align - 1) / align * align;
        raw_bytes += block.size;
        return at;
      };
      for (size_t g = 0; g < groups.size(); ++g) {
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindVertexBuffers(cmd, 0, 2, vbs, offs);
        // The material's constants do not change between objects: one copy per frame.
        for (RawPass& rp : raw[g])
          for (RawPass::Block& block : rp.blocks)
            if (!block.per_object()) block.offset = upload(block);
        for (uint32_t i = uint32_t(g) * per_group; i < uint32_t(g + 1) * per_group; ++i) {
          for (RawPass& rp : raw[g]) {
            // The app's own uniform structs: the two matrices change per object.
            for (size_t b = 0; b < rp.blocks.size(); ++b) {
              RawPass::Block& block = rp.blocks[b];
              if (!block.per_object()) {
                offsets[b] = block.offset;
                continue;
              }
              if (block.world != UINT32_MAX)
                std::memcpy(block.bytes.data() + block.world,
                            glm::value_ptr(block.world_columns ? world_t[i] : world[i]), 64);
              if (block.wvp != UINT32_MAX)
                std::memcpy(block.bytes.data() + block.wvp, glm::value_ptr(block.wvp_columns ? wvp_t[i] : wvp[i]), 64);
              offsets[b] = upload(block);
            }
            if (rp.pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = rp.pipeline);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, rp.layout, 0, 1, &rp.set,
                                    uint32_t(rp.blocks.size()), offsets);
            vkCmdDraw(cmd, vertex_count, 1, 0, 0);
          }
        }
      }
      return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    };
    uint64_t fx_bytes = 0;  // uniform bytes the last fxkit frame packed into its ring
    auto run_binding = [&]() {
      double ms = 0;
      preview->frames().begin_frame();
      ok = one_shot->run(
               [&](VkCommandBuffer cmd) {
                 target->begin(cmd);
                 ms = frame_binding(cmd);
                 target->end(cmd);
               },
               sink) &&
           ok;
      return ms;
    };
    auto run = [&](bool fxkit_path) {
      double ms = 0;
      const uint64_t bytes_before = device->uniform_bytes_written();
      if (fxkit_path) {
        device->begin_frame();
        for (PublicGroup& P : pub) P.effect.reset_stats();
      }
      ok = one_shot->run(
               [&](VkCommandBuffer cmd) {
                 target->begin(cmd);
                 ms = fxkit_path ? frame_fxkit(cmd) : frame_raw(cmd);
                 target->end(cmd);
               },
               sink) &&
           ok;
      if (fxkit_path) fx_bytes = device->uniform_bytes_written() - bytes_before;
      return ms;
    };
    std::vector<double> fx_ms, raw_ms, binding_ms;
    const int frames = std::max(args.repeats, 1) * 6;
    run(true), run(false), run_binding();  // warm-up: texture uploads, first-use pipeline state
    // The three paths in turn, each frame starting with the next one, so none always runs
    // after the same other (what the previous frame left in the caches differs by path).
    for (int f = 0; f < frames; ++f) {
      for (int k = 0; k < 3; ++k) {
        switch ((f + k) % 3) {
          case 0: fx_ms.push_back(run(true)); break;
          case 1: raw_ms.push_back(run(false)); break;
          default: binding_ms.push_back(run_binding()); break;
        }
      }
    }
    if (!ok) return report(sink), kInputErrors;
    fxkit::ApplyStats stats;
    size_t pipelines = 0;
    for (auto& b : bindings) pipelines += b->pipeline_count();
    for (size_t g = 0; g < pub.size(); ++g) {
      if (g > 0 && pub[g].effect.path() == pub[g - 1].effect.path()) continue;  // one effect, counted once
      const fxkit::ApplyStats s = pub[g].effect.stats();
      stats.pipeline_binds += s.pipeline_binds;
      stats.descriptor_binds += s.descriptor_binds;
      stats.uniform_uploads += s.uniform_uploads;
      stats.dynamic_state_calls += s.dynamic_state_calls;
    }
    const double f = median(fx_ms), r = median(raw_ms), b = median(binding_ms);
    out = {{"benchmark", "apply"},
           {"device", ctx->info().name},
           {"objects", kObjects},
           {"techniques", groups.size()},
           {"frames", frames},
           {"fxkit_ms", f},
           {"raw_ms", r},
           {"ratio", f / r},
           {"binding_ms", b},
           {"binding_ratio", b / r},
           {"target_ratio", 1.2},
           {"fxkit_per_draw_ns", f * 1e6 / kObjects},
           {"raw_per_draw_ns", r * 1e6 / kObjects},
           {"pipelines_created", pipelines},
           {"distinct_state_combinations", distinct.size()},
           {"pipeline_binds", stats.pipeline_binds},
           {"descriptor_binds", stats.descriptor_binds},
           {"uniform_uploads", stats.uniform_uploads},
           {"fxkit_uniform_bytes", fx_bytes},
           {"raw_uniform_bytes", raw_bytes},
           {"dynamic_state_calls", stats.dynamic_state_calls}};
    if (args.json) {
      std::printf("%s\n", json_text(out).c_str());
    } else {
      std::printf("fxkit bench apply on %s: %u objects in %zu technique groups, median of %d frames\n",
                  ctx->info().name.c_str(), kObjects, groups.size(), frames);
      std::printf("  public API (set World/WVP + apply + draw):   %.3f ms/frame (%.0f ns/draw)\n", f,
                  f * 1e6 / kObjects);
      std::printf("  hand-written Vulkan (memcpy + bind + draw):   %.3f ms/frame (%.0f ns/draw)\n", r,
                  r * 1e6 / kObjects);
      std::printf("  EffectBinding under it (static pipelines):  %.3f ms/frame (%.0f ns/draw)\n", b,
                  b * 1e6 / kObjects);
      std::printf("  ratio fxkit/raw: %.2fx (target <= 1.2x); EffectBinding/raw %.2fx\n", f / r, b / r);
      std::printf(
          "  pipelines created %zu for %zu distinct state combinations; last frame: %llu pipeline binds, %llu "
          "descriptor binds, %llu uniform uploads\n",
          pipelines, distinct.size(), (unsigned long long)stats.pipeline_binds,
          (unsigned long long)stats.descriptor_binds, (unsigned long long)stats.uniform_uploads);
      std::printf("  uniform bytes per frame: fxkit %llu, hand-written %llu\n", (unsigned long long)fx_bytes,
                  (unsigned long long)raw_bytes);
    }
    ctx->wait_idle();
    vkDestroyDescriptorPool(ctx->device(), pool, nullptr);
  }
  return status;
}

}  // namespace fx::tools
