// docs/embedding.md: the device made from the fixture's Vulkan handles as an engine's, an
// effect loaded and set up, and one frame recorded the way the page shows (into an
// Offscreen image standing in for the engine's swapchain image). The frame loop followed
// literally with a glm::mat4's memory draws what set_scene draws with the same transforms.
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "example_fixture.h"
#include "fx/vulkan/buffer.h"
#include "fxkit/fxkit.h"

namespace fx::docs {
namespace {

// A triangle of the page's vertex layout (POSITION, NORMAL; 24-byte stride) in front of
// the camera, and the engine's per-object data.
struct Object {
  float world_view_projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0.5f, 1};
  VkBuffer vertices = VK_NULL_HANDLE;
  void draw(VkCommandBuffer cmd) const {
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
    vkCmdDraw(cmd, 3, 1, 0, 0);
  }
};

TEST_F(ExampleTest, EmbeddingDeviceEffectFrame) {
  std::vector<std::string> logged;
  auto log = [&logged](const std::string& line) { logged.push_back(line); };
  const VkFormat swapchain_format = VK_FORMAT_R8G8B8A8_UNORM;
  const VkInstance instance = ctx().instance();
  const VkPhysicalDevice physical_device = ctx().physical_device();
  const VkDevice vk_device = ctx().device();
  const VkQueue graphics_queue = ctx().queue();
  const uint32_t graphics_family = ctx().queue_family();
  VkPhysicalDeviceVulkan13Features vulkan13{};
  vulkan13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  vulkan13.dynamicRendering = VK_TRUE;
  VkDeviceCreateInfo device_create_info{};
  device_create_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  device_create_info.pNext = &vulkan13;

  fxkit::DeviceOptions options;
  options.target.formats = {.color = {swapchain_format}, .depth = VK_FORMAT_D32_SFLOAT};
  options.target.vertex_layout = {.attributes = {{"POSITION", VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                 {"NORMAL", VK_FORMAT_R32G32B32_SFLOAT, 12}},
                                  .bindings = {{0, 24}}};
  options.target.front_faces = fxkit::Winding::counter_clockwise;  // glTF and OpenGL meshes
  options.target.y_flip = fxkit::YFlip::negative_viewport;         // the engine's viewports
  options.target.default_attribute_binding = 1;  // inputs the layout lacks read (0, 0, 0, 1)
  options.include_dirs = {"effects"};
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::create({instance, physical_device, vk_device, graphics_queue,
                                       graphics_family, &device_create_info}, options, errors);
  if (!device)
    for (const fxkit::Message& m : errors) log(m.rendered);
  ASSERT_TRUE(device) << (logged.empty() ? "" : logged[0]);

  fxkit::Effect effect = device->load("effects/wood.fx");
  if (!effect.ok())
    for (const fxkit::Message& m : effect.messages()) log(m.rendered);  // file:line:col: error: ...
  fxkit::Technique technique = effect.technique("wood");  // or effect.select({.distance = 12.0f})
  const fxkit::Param world_view_projection = effect.param("WORLDVIEWPROJECTION");  // name or semantic
  effect.set(effect.param("LightDirection"), {0.3f, -0.8f, -0.5f});
  ASSERT_TRUE(effect.ok() && technique.valid()) << technique.reason() << (logged.empty() ? "" : logged[0]);
  ASSERT_TRUE(world_view_projection.valid());

  // The engine's side of the frame.
  auto image = fxkit::Offscreen::create(*device, 16, 16, errors);
  ASSERT_TRUE(image);
  fx::DiagnosticSink sink;
  const float triangle[3][6] = {{-1, -1, 0, 0, 0, -1}, {3, -1, 0, 0, 0, -1}, {-1, 3, 0, 0, 0, -1}};
  auto buffer = fx::vk::Buffer::create(ctx(), {sizeof triangle, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                               fx::vk::MemoryUsage::upload, "triangle"}, sink);
  ASSERT_TRUE(buffer && buffer->write(triangle, sizeof triangle));
  const std::vector<Object> objects = {Object{.vertices = buffer->handle()}};
  const VkViewport viewport = image->viewport();
  const VkRect2D scissor = image->scissor();
  auto begin_rendering = [&](VkCommandBuffer cmd) { image->begin(cmd); };
  auto end_rendering = [&](VkCommandBuffer cmd) { image->end(cmd); };
  bool applied = false;

  ASSERT_TRUE(device->submit([&](VkCommandBuffer cmd) {
    for (const fxkit::Reload& r : device->begin_frame()) log(r.str());
    begin_rendering(cmd);  // the engine's vkCmdBeginRendering, attachments as Target::formats
    if (technique.begin(cmd, viewport, scissor)) {
      for (const Object& object : objects) {
        effect.set_matrix(world_view_projection, object.world_view_projection, fxkit::MatrixOrder::row_major);
        for (uint32_t pass = 0; pass < technique.pass_count(); ++pass)
          if (technique.apply(pass)) object.draw(cmd);
      }
    }
    technique.end();
    end_rendering(cmd);
    applied = true;
  }));
  EXPECT_TRUE(applied);
  EXPECT_TRUE(logged.empty()) << logged[0];
  const std::vector<uint8_t> rgba = image->read_rgba8();
  EXPECT_GT(int(rgba[(8 * 16 + 8) * 4]) + rgba[(8 * 16 + 8) * 4 + 1], 0) << "the triangle covers the centre";
  EXPECT_TRUE(effect.stats().passes > 0);
}

// The page's frame loop, word for word, with each object's matrix the memory of a glm::mat4
// (P * V * W of samples/minimal's camera): it draws the image set_scene draws from the same
// transforms, samples/minimal's sphere centred and lit. A wrong MatrixOrder in the page
// draws a transposed matrix: a cropped smear, and no message.
TEST_F(ExampleTest, EmbeddingFrameLoopDrawsWhatSetSceneDraws) {
  std::vector<std::string> logged;
  auto log = [&logged](const std::string& line) { logged.push_back(line); };
  fxkit::DeviceOptions options;
  options.target.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT};
  options.target.vertex_layout = fxkit::Mesh::vertex_layout();
  options.target.front_faces = fxkit::Winding::counter_clockwise;
  options.target.y_flip = fxkit::YFlip::negative_viewport;
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::create(
      {ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(), ctx().queue_family()}, options,
      errors);
  ASSERT_TRUE(device) << (errors.empty() ? "" : errors[0].rendered);
  auto mesh = fxkit::Mesh::create(*device, "sphere", errors);
  auto image = fxkit::Offscreen::create(*device, 64, 64, errors);
  ASSERT_TRUE(mesh && image);
  const fxkit::Scene scene = fxkit::Scene::framing(mesh->radius(), 1.0f);

  struct Object {
    float world_view_projection[16] = {};
    const fxkit::Mesh* mesh = nullptr;
    void draw(VkCommandBuffer cmd) const { mesh->draw(cmd); }
  };
  Object sphere{.mesh = mesh.get()};
  const glm::mat4 wvp = glm::make_mat4(scene.projection) * glm::make_mat4(scene.view) * glm::make_mat4(scene.world);
  std::copy_n(glm::value_ptr(wvp), 16, sphere.world_view_projection);
  const std::vector<Object> objects = {sphere};
  const VkViewport viewport = image->viewport();
  const VkRect2D scissor = image->scissor();
  auto begin_rendering = [&](VkCommandBuffer cmd) { image->begin(cmd); };
  auto end_rendering = [&](VkCommandBuffer cmd) { image->end(cmd); };

  // As the page: the effect's matrices set by the application, each frame, in its loop.
  fxkit::Effect effect = device->load(FXKIT_SOURCE_DIR "/samples/minimal/lit.fx");
  ASSERT_TRUE(effect.ok()) << (effect.messages().empty() ? "" : effect.messages()[0].rendered);
  fxkit::Technique technique = effect.technique("lit");
  const fxkit::Param world_view_projection = effect.param("WORLDVIEWPROJECTION");  // name or semantic
  ASSERT_TRUE(effect.set_matrix(effect.param("WORLD"), scene.world));
  ASSERT_TRUE(device->submit([&](VkCommandBuffer cmd) {
    for (const fxkit::Reload& r : device->begin_frame()) log(r.str());
    begin_rendering(cmd);  // the engine's vkCmdBeginRendering, attachments as Target::formats
    if (technique.begin(cmd, viewport, scissor)) {
      for (const Object& object : objects) {
        effect.set_matrix(world_view_projection, object.world_view_projection, fxkit::MatrixOrder::row_major);
        for (uint32_t pass = 0; pass < technique.pass_count(); ++pass)
          if (technique.apply(pass)) object.draw(cmd);
      }
    }
    technique.end();
    end_rendering(cmd);
  }));
  const std::vector<uint8_t> looped = image->read_rgba8();

  // As samples/minimal: every transform from the scene.
  effect.set_scene(scene);
  ASSERT_TRUE(device->submit([&](VkCommandBuffer cmd) {
    device->begin_frame();
    image->begin(cmd);
    if (technique.begin(cmd, viewport, scissor))
      for (uint32_t pass = 0; pass < technique.pass_count(); ++pass)
        if (technique.apply(pass)) mesh->draw(cmd);
    technique.end();
    image->end(cmd);
  }));
  const std::vector<uint8_t> framed = image->read_rgba8();
  EXPECT_TRUE(logged.empty()) << logged[0];

  const size_t centre = (32 * 64 + 32) * 4;
  EXPECT_GT(framed[centre] + framed[centre + 1] + framed[centre + 2], 3 * 60) << "samples/minimal's sphere is lit";
  ASSERT_EQ(looped.size(), framed.size());
  size_t differing = 0;
  for (size_t i = 0; i < framed.size(); ++i) differing += std::abs(int(looped[i]) - int(framed[i])) > 1 ? 1 : 0;
  EXPECT_EQ(differing, 0u) << "bytes of the page's frame loop differ from set_scene's image (centre "
                           << int(looped[centre]) << " " << int(looped[centre + 1]) << " " << int(looped[centre + 2])
                           << " against " << int(framed[centre]) << " " << int(framed[centre + 1]) << " "
                           << int(framed[centre + 2]) << ")";
}

}  // namespace
}  // namespace fx::docs
