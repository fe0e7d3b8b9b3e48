// Pipeline keying and pass application bookkeeping: dynamic vs static paths give byte-equal
// images, pipeline counts per distinct state, redundant state not re-recorded, dirty-only
// uniform uploads, caller-written uniforms, descriptor sets kept across frames, push descriptors, vertex layout
// diagnostics, pipeline cache persistence,
// lookup-table textures.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "fx/shading/generator.h"
#include "pass_test_util.h"

namespace fx::vk {
namespace {

using namespace testing;

void set_color_for(PassResources& r) {
  DiagnosticSink sink;
  const float c[4] = {1, 1, 1, 1};
  EXPECT_TRUE(r.set_uniform("Color", c, sizeof c, sink));
}

class PassRecorderTest : public VulkanTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(ctx().validation_warning_count(), 0u) << describe_messages(ctx());
    VulkanTest::TearDown();
  }
};

// N distinct pass states over one program: blend, depth, stencil, cull and bias variations.
std::vector<PipelineState> distinct_states() {
  std::vector<PipelineState> out;
  for (int blend = 0; blend < 3; ++blend)
    for (int depth = 0; depth < 2; ++depth)
      for (int cull = 0; cull < 2; ++cull) {
        PipelineState s;
        s.blend[0].blend_enable = blend != 0;
        s.blend[0].src_color = blend == 2 ? VK_BLEND_FACTOR_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
        s.blend[0].dst_color = blend == 2 ? VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA : VK_BLEND_FACTOR_ONE;
        s.depth_test = 1;
        s.depth_write = depth;
        s.depth_compare = depth ? VK_COMPARE_OP_LESS : VK_COMPARE_OP_LESS_OR_EQUAL;
        s.cull_mode = cull ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_NONE;
        s.stencil_test = cull;
        s.front_pass = s.back_pass = VK_STENCIL_OP_INCREMENT_AND_CLAMP;
        out.push_back(s);
      }
  return out;
}

TEST_F(PassRecorderTest, DynamicAndStaticPathsRenderIdenticalImagesWithFewerPipelines) {
  const std::vector<PipelineState> states = distinct_states();
  std::vector<Vertex> v;
  for (size_t i = 0; i < states.size(); ++i) {
    const float x = -1 + 2.0f * float(i % 4) / 4, y = -1 + 2.0f * float(i / 4) / 3;
    add_quad(v, x, y, x + 0.9f, y + 0.9f, 0.1f * float(i % 5), 0, 1, i % 2 == 0);
    add_quad(v, -1, -1, 1, 1, 0.45f);  // overlapping full-screen quad: depth/stencil/blend matter
  }
  fx::Image images[2];
  size_t created[2];
  for (int dynamic = 0; dynamic < 2; ++dynamic) {
    PassHarness h(ctx(), dynamic ? DynamicStateSet::from_features(ctx().features()) : DynamicStateSet::none(), 32);
    auto prog = make_program(ctx(), "PSColor");
    DiagnosticSink sink;
    auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
    ASSERT_TRUE(input);
    std::vector<std::unique_ptr<PassResources>> res;
    for (size_t i = 0; i < states.size(); ++i) {
      res.push_back(std::make_unique<PassResources>(prog->program));
      const float c[4] = {0.1f * float(i % 7), 0.3f, 1.0f - 0.08f * float(i), 0.6f};
      ASSERT_TRUE(res.back()->set_uniform("Color", c, sizeof c, sink));
    }
    VkBuffer vb = h.vertices(v);
    images[dynamic] = h.render(
        [&](VkCommandBuffer cmd, PassRecorder& r) {
          for (size_t i = 0; i < states.size(); ++i)
            draw(cmd, r, {&prog->program, states[i], &*input, res[i].get()}, vb, 12, uint32_t(i * 12));
        },
        {0.2f, 0.2f, 0.2f, 1});
    created[dynamic] = h.pipelines().stats().created;
  }
  ASSERT_FALSE(images[0].empty());
  std::set<std::array<int, 4>> colors;  // the scene is not trivially uniform
  for (uint32_t y = 0; y < images[0].height; ++y)
    for (uint32_t x = 0; x < images[0].width; ++x) colors.insert(pixel(images[0], x, y));
  EXPECT_GE(colors.size(), 6u);
  EXPECT_EQ(images[0].pixels, images[1].pixels) << "dynamic and static paths differ";
  EXPECT_EQ(created[0], states.size());  // static: one pipeline per distinct state
  const DynamicStateSet d = DynamicStateSet::from_features(ctx().features());
  if (d.eds1 && d.color_blend_enable && d.color_blend_equation) EXPECT_EQ(created[1], 1u);
  else EXPECT_LT(created[1], created[0]);
}

TEST_F(PassRecorderTest, RedundantStateIsNotRecordedAgain) {
  for (bool dynamic : {false, true}) {
    PassHarness h(ctx(), dynamic ? DynamicStateSet::from_features(ctx().features()) : DynamicStateSet::none());
    auto prog = make_program(ctx(), "PSColor");
    DiagnosticSink sink;
    auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
    ASSERT_TRUE(input);
    PassResources res(prog->program);
    set_color_for(res);
    std::vector<Vertex> v;
    add_quad(v, -1, -1, 1, 1, 0.5f);
    VkBuffer vb = h.vertices(v);
    PipelineState a, b;
    b.cull_mode = VK_CULL_MODE_BACK_BIT;
    ApplyStats after_first, after_repeat, after_change;
    h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      r.reset_stats();
      draw(cmd, r, {&prog->program, a, &*input, &res}, vb, 6);
      after_first = r.stats();
      draw(cmd, r, {&prog->program, a, &*input, &res}, vb, 6);
      after_repeat = r.stats();
      draw(cmd, r, {&prog->program, b, &*input, &res}, vb, 6);
      after_change = r.stats();
    });
    EXPECT_EQ(after_first.pipeline_binds, 1u);
    EXPECT_EQ(after_repeat.pipeline_binds, after_first.pipeline_binds);
    EXPECT_EQ(after_repeat.dynamic_state_calls, after_first.dynamic_state_calls);
    EXPECT_EQ(after_repeat.descriptor_binds, after_first.descriptor_binds);
    EXPECT_EQ(after_repeat.uniform_uploads, after_first.uniform_uploads);
    if (dynamic) {  // one vkCmdSetCullMode, same pipeline
      EXPECT_EQ(after_change.pipeline_binds, after_first.pipeline_binds);
      EXPECT_EQ(after_change.dynamic_state_calls, after_first.dynamic_state_calls + 1);
    } else {  // another pipeline, no dynamic state
      EXPECT_EQ(after_change.pipeline_binds, after_first.pipeline_binds + 1);
      EXPECT_EQ(after_change.dynamic_state_calls, after_first.dynamic_state_calls);
    }
  }
}

TEST_F(PassRecorderTest, UniformRingUploadsOnlyDirtyBlocks) {
  PassHarness h(ctx(), DynamicStateSet::none());
  auto prog = make_program(ctx(), "PSColor");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  PassResources res(prog->program);
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 1, 1, 0.5f);
  VkBuffer vb = h.vertices(v);
  auto frame = [&](float red) {
    const float c[4] = {red, 0, 0, 1};
    EXPECT_TRUE(res.set_uniform("Color", c, sizeof c, sink));
    uint64_t uploads = 0;
    fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      r.reset_stats();
      draw(cmd, r, {&prog->program, PipelineState{}, &*input, &res}, vb, 6);
      draw(cmd, r, {&prog->program, PipelineState{}, &*input, &res}, vb, 6);
      uploads = r.stats().uniform_uploads;
    });
    EXPECT_NEAR(pixel(img, 2, 2)[0], red * 255, 1);
    return uploads;
  };
  // Two draws per frame: the second reuses the first's upload. Every frame uploads again,
  // changed or not: the previous frame's slice is recycled while this frame may run.
  EXPECT_EQ(frame(1.0f), 1u);  // first use
  EXPECT_EQ(frame(1.0f), 1u);  // same bytes, new frame
  EXPECT_EQ(frame(0.5f), 1u);  // changed
}

// A caller that packs a block itself writes it into the ring in place and passes the
// offsets; the resources' shadow (never set here) is not read.
TEST_F(PassRecorderTest, CallerWrittenUniformsAreBoundByOffset) {
  PassHarness h(ctx(), DynamicStateSet::none());
  auto prog = make_program(ctx(), "PSColor");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  ASSERT_EQ(prog->program.uniform_blocks().size(), 1u);
  const uint32_t size = prog->program.uniform_blocks()[0].size;
  PassResources res(prog->program);
  std::vector<Vertex> v;
  add_quad(v, -1, -1, 1, 1, 0.5f);
  VkBuffer vb = h.vertices(v);
  fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
    const float green[4] = {0, 1, 0, 1};
    std::optional<uint32_t> offset = r.write_uniform(
        size,
        [&](uint8_t* ring) {
          std::memset(ring, 0, size);
          std::memcpy(ring, green, sizeof green);
        },
        sink);
    ASSERT_TRUE(offset) << describe(sink);
    const uint32_t offsets[1] = {*offset};
    PassDesc pass{&prog->program, PipelineState{}, &*input, &res};
    pass.uniform_offsets = offsets;
    draw(cmd, r, pass, vb, 6);
    EXPECT_EQ(r.stats().uniform_uploads, 1u);
    const uint32_t too_many[2] = {*offset, *offset};
    pass.uniform_offsets = too_many;
    DiagnosticSink bad;
    EXPECT_FALSE(r.apply(pass, bad));
    ASSERT_FALSE(bad.diagnostics().empty());
    EXPECT_EQ(bad.diagnostics()[0].id, "vk-uniform-offsets");
  });
  EXPECT_NEAR(pixel(img, 2, 2)[0], 0, 1);
  EXPECT_NEAR(pixel(img, 2, 2)[1], 255, 1);
}

TEST_F(PassRecorderTest, PushDescriptorsRenderLikeDescriptorSets) {
  if (!ctx().features().push_descriptor) GTEST_SKIP() << "no VK_KHR_push_descriptor";
  fx::Image images[2];
  for (int push = 0; push < 2; ++push) {
    PassHarness h(ctx(), DynamicStateSet::from_features(ctx().features()));
    auto prog = make_program(ctx(), "PSTex", push ? DescriptorMode::push : DescriptorMode::sets);
    DiagnosticSink sink;
    auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
    ASSERT_TRUE(input);
    auto table = fx::shading::Table::make(4, 4, 1, 4, fx::shading::TableFormat::unorm8);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 4; ++c) table.store(x, y, 0, c, (x * 4 + y + c) / 20.0);
    auto tex = Texture::from_table(ctx(), table, sink);
    ASSERT_TRUE(tex) << describe(sink);
    SamplerCache samplers(ctx());
    PassResources res(prog->program);
    ASSERT_TRUE(res.bind("Tex", *tex, samplers.get({}, sink), sink));
    std::vector<Vertex> v;
    add_quad(v, -1, -1, 1, 1, 0.5f);
    VkBuffer vb = h.vertices(v);
    images[push] = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      draw(cmd, r, {&prog->program, PipelineState{}, &*input, &res}, vb, 6);
      EXPECT_EQ(push ? r.stats().descriptor_pushes : r.stats().descriptor_binds, 1u);
    });
  }
  EXPECT_EQ(images[0].pixels, images[1].pixels);
}

// Sets kept in a DescriptorArena (as EffectBinding's passes keep them): written once per
// frame in flight, not again while the images stay; a new texture rewrites each frame's set
// when that frame comes round; a texture changed after this frame bound the kept set draws
// through a set of the frame's own, the first draw still sampling the old one; a recorder
// on other frames does not touch the kept sets.
TEST_F(PassRecorderTest, KeptDescriptorSetsAreWrittenOncePerFrameInFlightAndAgainForNewImages) {
  PassHarness h(ctx(), DynamicStateSet::none());
  auto prog = make_program(ctx(), "PSTex");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  auto red = solid_texture(ctx(), 255, 0, sink), green = solid_texture(ctx(), 0, 255, sink);
  ASSERT_TRUE(red && green) << describe(sink);
  SamplerCache samplers(ctx());
  const VkSampler sampler = samplers.get({}, sink);
  DescriptorArena arena(ctx());
  PassResources res(prog->program);
  res.keep_sets_in(arena);
  std::vector<Vertex> left, right;
  add_quad(left, -1, -1, 0, 1, 0.5f);
  add_quad(right, 0, -1, 1, 1, 0.5f);
  VkBuffer left_vb = h.vertices(left), right_vb = h.vertices(right);
  const PassDesc pass{&prog->program, PipelineState{}, &*input, &res};
  // One frame: the left half with `first`, the right half after binding `second`; the
  // descriptor writes it made and the two halves' red and green.
  struct Frame {
    uint64_t writes;
    int left_red, left_green, right_red, right_green;
  };
  auto frame = [&](const Texture& first, const Texture& second) {
    EXPECT_TRUE(res.bind("Tex", first, sampler, sink));
    uint64_t writes = 0;
    fx::Image img = h.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      r.reset_stats();
      draw(cmd, r, pass, left_vb, 6);
      EXPECT_TRUE(res.bind("Tex", second, sampler, sink));
      draw(cmd, r, pass, right_vb, 6);
      writes = r.stats().descriptor_writes;
    });
    return Frame{writes, pixel(img, 1, 4)[0], pixel(img, 1, 4)[1], pixel(img, 6, 4)[0], pixel(img, 6, 4)[1]};
  };
  // Two frames in flight (FrameResourcesDesc's default): each writes its own set once.
  for (int f = 0; f < 4; ++f) {
    const Frame r = frame(*red, *red);
    EXPECT_EQ(r.writes, f < 2 ? 1u : 0u) << "frame " << f;
    EXPECT_EQ(r.left_red, 255);
    EXPECT_EQ(r.right_red, 255);
  }
  // Green from the next frame on: each frame's set is written again when its frame comes.
  for (int f = 0; f < 3; ++f) {
    const Frame g = frame(*green, *green);
    EXPECT_EQ(g.writes, f < 2 ? 1u : 0u) << "frame " << f;
    EXPECT_EQ(g.left_green, 255);
    EXPECT_EQ(g.right_green, 255);
  }
  // Red bound after the kept set drew the left half: the right half takes a new set.
  const Frame mixed = frame(*green, *red);
  EXPECT_EQ(mixed.writes, 1u);
  EXPECT_EQ(mixed.left_green, 255);
  EXPECT_EQ(mixed.left_red, 0);
  EXPECT_EQ(mixed.right_red, 255);
  EXPECT_EQ(mixed.right_green, 0);
  EXPECT_EQ(arena.pool_count(), 1u);
  // A recorder on other FrameResources (another window's frames) takes sets of its own
  // frames each time: the kept sets serve the first one, whose frames may still read them.
  PassHarness other(ctx(), DynamicStateSet::none());
  VkBuffer other_vb = other.vertices(left);
  for (int f = 0; f < 3; ++f) {
    uint64_t writes = 0;
    other.render([&](VkCommandBuffer cmd, PassRecorder& r) {
      r.reset_stats();
      draw(cmd, r, pass, other_vb, 6);
      writes = r.stats().descriptor_writes;
    });
    EXPECT_EQ(writes, 1u) << "other frames " << f;
  }
  EXPECT_EQ(frame(*red, *red).writes, 1u) << "the kept set of this slot held green";
  EXPECT_EQ(frame(*red, *red).writes, 1u);
  EXPECT_EQ(frame(*red, *red).writes, 0u) << "the kept sets again";
  EXPECT_FALSE(sink.has_errors()) << describe(sink);
}

TEST_F(PassRecorderTest, MissingVertexAttributeNamesTheSemantic) {
  auto prog = make_program(ctx(), "PSTex");
  DiagnosticSink sink;
  VertexLayout layout = quad_layout();
  layout.attributes.pop_back();  // no TEXCOORD0
  EXPECT_FALSE(match_vertex_layout(layout, prog->program.vertex_inputs(), sink));
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-vertex-attribute-missing");
  EXPECT_NE(sink.diagnostics()[0].message.find("TEXCOORD"), std::string::npos);
  EXPECT_NE(sink.diagnostics()[0].message.find("POSITION"), std::string::npos);
  EXPECT_EQ(canonical_semantic("texcoord0"), "TEXCOORD");
  EXPECT_EQ(canonical_semantic("TEXCOORD1"), "TEXCOORD1");
  EXPECT_EQ(canonical_semantic("SV_Position"), "POSITION");  // a D3D9-style vertex input
  EXPECT_EQ(canonical_semantic("SV_POSITION1"), "POSITION1");
}

TEST_F(PassRecorderTest, UnboundTextureIsADiagnosticNotADraw) {
  PassHarness h(ctx(), DynamicStateSet::none());
  auto prog = make_program(ctx(), "PSTex");
  DiagnosticSink sink;
  auto input = match_vertex_layout(quad_layout(), prog->program.vertex_inputs(), sink);
  ASSERT_TRUE(input);
  PassResources res(prog->program);
  h.render([&](VkCommandBuffer, PassRecorder& r) {
    EXPECT_FALSE(r.apply({&prog->program, PipelineState{}, &*input, &res}, sink));
  });
  ASSERT_TRUE(sink.has_errors());
  EXPECT_EQ(sink.diagnostics().back().id, "vk-texture-unbound");
}

TEST_F(PassRecorderTest, PipelineCachePersistsAndRejectsForeignFiles) {
  DiagnosticSink sink;
  auto cache = PipelineCache::create(ctx(), sink);
  ASSERT_TRUE(cache);
  const auto dir = std::filesystem::temp_directory_path() / ("fxkit_pc_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / "pipelines.bin";
  ASSERT_TRUE(cache->save_file(path, sink)) << describe(sink);
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  std::vector<uint8_t> data = PipelineCache::load_file(ctx(), path, sink);
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(sink.diagnostics().size(), 0u);
  auto reloaded = PipelineCache::create(ctx(), sink, data);
  EXPECT_TRUE(reloaded) << describe(sink);
  // Another device's file (vendor id changed in the header) starts cold with a note.
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(12);
    const uint32_t vendor = ctx().info().vendor_id ^ 0xFFFFu;
    f.write(reinterpret_cast<const char*>(&vendor), 4);
  }
  EXPECT_TRUE(PipelineCache::load_file(ctx(), path, sink).empty());
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-pipeline-cache-stale");
  EXPECT_TRUE(PipelineCache::load_file(ctx(), dir / "missing.bin", sink).empty());
  EXPECT_EQ(sink.diagnostics().size(), 1u);
  std::filesystem::remove_all(dir);
}

TEST_F(PassRecorderTest, SamplerCacheSharesAndClampsToTheDevice) {
  SamplerCache samplers(ctx());
  DiagnosticSink sink;
  SamplerKey a;
  a.max_anisotropy = 1e6f;
  a.mip_lod_bias = 1e6f;
  VkSampler s1 = samplers.get(a, sink), s2 = samplers.get(a, sink);
  EXPECT_NE(s1, VK_NULL_HANDLE);
  EXPECT_EQ(s1, s2);
  EXPECT_EQ(samplers.size(), 1u);
  const SamplerKey e = samplers.effective(a);
  EXPECT_LE(e.max_anisotropy, std::max(1.0f, ctx().info().limits.maxSamplerAnisotropy));
  if (!ctx().features().sampler_anisotropy) {
    EXPECT_EQ(e.max_anisotropy, 1.0f);
  }
  EXPECT_LE(e.mip_lod_bias, ctx().info().limits.maxSamplerLodBias);
}

TEST_F(PassRecorderTest, TexturesFromTablesCubesAndVolumes) {
  DiagnosticSink sink;
  auto strand = fx::shading::bake("strand", {}, sink, {});
  ASSERT_TRUE(strand) << describe(sink);
  EXPECT_TRUE(Texture::from_table(ctx(), *strand, sink)) << describe(sink);
  auto volume = fx::shading::Table::make(4, 4, 4, 1, fx::shading::TableFormat::float32);
  auto vt = Texture::from_table(ctx(), volume, sink);
  ASSERT_TRUE(vt) << describe(sink);
  EXPECT_EQ(vt->kind(), ImageKind::image3d);
  fx::Image face = fx::Image::blank(4, 4, 3);
  std::array<const fx::Image*, 6> faces;
  faces.fill(&face);
  auto cube = Texture::cube_from_images(ctx(), faces, ColorSpace::srgb, sink);
  ASSERT_TRUE(cube) << describe(sink);
  EXPECT_EQ(cube->kind(), ImageKind::cube);
  Texture borrowed = Texture::wrap(cube->view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, ImageKind::cube);
  EXPECT_FALSE(borrowed.owns_image());
  EXPECT_EQ(borrowed.view(), cube->view());
  fx::Image bad = fx::Image::blank(4, 2, 3);
  faces[2] = &bad;
  EXPECT_FALSE(Texture::cube_from_images(ctx(), faces, ColorSpace::srgb, sink));
  EXPECT_EQ(sink.diagnostics().back().id, "vk-texture-invalid");
}

}  // namespace
}  // namespace fx::vk
