// fxkit in an application, headless: create, load, select, set parameters, record into the
// application's command buffer, draw, read back, poll for reloads. See docs/embedding.md.
#include <fxkit/fxkit.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : FXKIT_MINIMAL_EFFECT;
  fxkit::HeadlessOptions headless;
  headless.validation = argc > 2 && std::string(argv[2]) == "--validate";
  fxkit::DeviceOptions options;
  options.target.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT};
  options.target.vertex_layout = fxkit::Mesh::vertex_layout();
  options.target.front_faces = fxkit::Winding::counter_clockwise;  // as the built-in meshes
  options.target.y_flip = fxkit::YFlip::negative_viewport;         // as Offscreen::viewport()
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::headless(options, headless, errors);
  auto mesh = device ? fxkit::Mesh::create(*device, "sphere", errors) : nullptr;
  auto image = device ? fxkit::Offscreen::create(*device, 64, 64, errors) : nullptr;
  fxkit::Effect effect = device ? device->load(path) : fxkit::Effect{};
  for (const fxkit::Message& m : effect.messages()) errors.push_back(m);
  if (!effect.ok() || !mesh || !image) {
    for (const fxkit::Message& m : errors) std::fputs(m.rendered.c_str(), stderr);
    return 1;
  }
  fxkit::Technique technique = effect.select();
  effect.set_scene(fxkit::Scene::framing(mesh->radius(), 1.0f));
  effect.set(effect.param("Tint"), {1.0f, 0.5f, 0.2f, 1.0f});
  for (int frame = 0; frame < 3; ++frame) {
    for (const fxkit::Reload& r : device->begin_frame()) std::fputs(r.str().c_str(), stdout);
    device->submit([&](VkCommandBuffer cmd) {
      image->begin(cmd);
      if (technique.begin(cmd, image->viewport(), image->scissor()))
        for (uint32_t pass = 0; pass < technique.pass_count(); ++pass)
          if (technique.apply(pass)) mesh->draw(cmd);
      technique.end();
      image->end(cmd);
    });
  }
  const std::vector<uint8_t> rgba = image->read_rgba8();
  const size_t centre = (32 * 64 + 32) * 4;
  std::printf("%s: technique %s, centre pixel %u %u %u\n", path.c_str(), technique.name().c_str(), rgba[centre],
              rgba[centre + 1], rgba[centre + 2]);
  return fxkit::has_errors(device->take_validation_messages()) ? 1 : 0;
}
