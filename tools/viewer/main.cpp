// fxkit-view FILE.fx: an effect on a mesh in a window, its parameters and techniques as UI,
// reloaded on every save. Built as any application of fxkit is (fxkit::fxkit), plus GLFW
// and Dear ImGui. See tools/viewer/README.md and docs/viewer.md.
#include <GLFW/glfw3.h>
#include <fxkit/fxkit.h>
#include <imgui.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "gpu_timer.h"
#include "imgui_layer.h"
#include "light_control.h"
#include "orbit_camera.h"
#include "param_presets.h"
#include "param_widgets.h"
#include "technique_panel.h"
#include "viewer_options.h"
#include "viewer_script.h"
#include "vulkan_window.h"

namespace {

// What the window shows besides the scene: diagnostics, timings, parameters, techniques.
struct Panels {
  std::vector<fxkit::Message> problems;  // of the failed load or reload on screen
  std::vector<fxkit::ParamInfo> params;  // of the live version
  uint64_t params_serial = ~0ull;
  std::vector<double> pass_ms;
  TechniquePanel techniques;
  LightControl light;
};

void print(const std::vector<fxkit::Message>& messages) {
  for (const fxkit::Message& m : messages) std::fputs(m.rendered.c_str(), stderr);
}

void draw_overlay(const std::vector<fxkit::Message>& problems) {
  if (problems.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(10, ImGui::GetIO().DisplaySize.y - 10), ImGuiCond_Always, ImVec2(0, 1));
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("Errors", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "The last good version is on screen until the next good save:");
  // As `fxkit check` prints them: the source line, the caret, did-you-mean and notes (the
  // default font is monospaced, so the caret lines up).
  for (const fxkit::Message& m : problems)
    ImGui::TextColored(m.severity == fxkit::Severity::error ? ImVec4(1, 0.4f, 0.4f, 1) : ImVec4(1, 0.9f, 0.4f, 1), "%s",
                       m.rendered.c_str());
  ImGui::End();
}

void draw_params(fxkit::Effect& effect, Panels& ui) {
  if (ui.params_serial != effect.serial()) ui.params = effect.params(), ui.params_serial = effect.serial();
  std::map<std::string, std::vector<std::pair<const fxkit::ParamInfo*, ParamWidget>>> by_category;
  for (const fxkit::ParamInfo& p : ui.params) {
    ParamWidget w = widget_for(p);
    if (w.kind != ParamWidget::Kind::hidden) by_category[w.category].push_back({&p, std::move(w)});
  }
  for (auto& [category, widgets] : by_category) {
    if (!category.empty() && !ImGui::CollapsingHeader(category.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
    for (auto& [p, w] : widgets) draw_param(effect, *p, w);
  }
}

// The panel's width at first; it is docked at the left edge, full height, and can be widened.
constexpr float kPanelWidth = 360.f;

// The panel; returns its width. Every text wraps at its edge.
float draw_ui(fxkit::Effect& effect, fxkit::Technique& technique, Panels& ui, const std::string& device_name,
              float camera_distance) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, display.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(kPanelWidth, display.x), display.y),
                                      ImVec2(std::max(kPanelWidth, display.x * 0.5f), display.y));
  ImGui::Begin(effect.path().c_str(), nullptr, ImGuiWindowFlags_NoMove);
  ImGui::PushTextWrapPos(0.f);
  ImGui::Text("%s", device_name.c_str());
  ImGui::Text("frame %.2f ms (%.0f fps)", 1000.0 / std::max(ImGui::GetIO().Framerate, 1e-3f), ImGui::GetIO().Framerate);
  for (size_t p = 0; p < ui.pass_ms.size(); ++p) ImGui::Text("  pass %zu: %.3f ms GPU", p, ui.pass_ms[p]);
  ImGui::Text("technique: %s", technique.valid() ? technique.name().c_str() : "(none can draw)");
  if (ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) ui.light.draw();
  if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) draw_params(effect, ui);
  if (ImGui::CollapsingHeader("Techniques", ImGuiTreeNodeFlags_DefaultOpen))
    ui.techniques.draw(effect, technique, camera_distance);
  // ImGui 1.86's Vulkan backend draws no user textures: the script's targets as text.
  if (technique.has_script() && ImGui::CollapsingHeader("Script render targets", ImGuiTreeNodeFlags_DefaultOpen))
    for (const fxkit::ScriptTarget& t : technique.script_targets())
      ImGui::Text("%s: %ux%u", t.name.c_str(), t.extent.width, t.extent.height);
  ImGui::PopTextWrapPos();
  const float width = ImGui::GetWindowWidth();
  ImGui::End();
  draw_overlay(ui.problems);
  return width;
}

// The part of the window the scene is drawn into: right of the panel when what is left there
// is at least as wide as it is tall (the mesh is then not under the panel), else the whole
// window with the panel over it.
VkRect2D scene_area(VkExtent2D window, float panel_width) {
  const uint32_t panel = uint32_t(std::ceil(panel_width));
  if (panel < window.width && window.width - panel >= window.height)
    return {{int32_t(panel), 0}, {window.width - panel, window.height}};
  return {{0, 0}, window};
}

// What a screenshot shows: the pixels that differ from its top-left corner (the clear
// colour), and the first and last column holding one.
struct Drawn {
  size_t pixels = 0;
  uint32_t left = 0, right = 0;
};

Drawn drawn(const std::vector<uint8_t>& rgba, uint32_t width) {
  Drawn d;
  d.left = width;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (std::equal(rgba.begin() + long(i), rgba.begin() + long(i) + 3, rgba.begin())) continue;
    const uint32_t x = uint32_t(i / 4 % width);
    ++d.pixels, d.left = std::min(d.left, x), d.right = std::max(d.right, x);
  }
  if (!d.pixels) d.left = 0;
  return d;
}

// Writes the last capture() as a PNG and says what it shows; false when it cannot.
bool write_screenshot(VulkanWindow& window, const std::string& path, const fxkit::Technique& technique) {
  window.wait_idle();
  uint32_t w = 0, h = 0;
  const std::vector<uint8_t> rgba = window.read_screenshot(w, h);
  if (rgba.empty() || !stbi_write_png(path.c_str(), int(w), int(h), 4, rgba.data(), int(w * 4))) {
    std::fprintf(stderr, "fxkit-view: cannot write %s\n", path.c_str());
    return false;
  }
  const Drawn d = drawn(rgba, w);
  std::printf("fxkit-view: %s: %ux%u, technique %s, %zu pixels drawn in columns %u to %u\n", path.c_str(), w, h,
              technique.name().c_str(), d.pixels, d.left, d.right);
  std::fflush(stdout);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  ViewerOptions opt;
  std::string error;
  if (!parse_viewer_options(argc, argv, opt, error)) {
    if (!error.empty()) std::fprintf(stderr, "fxkit-view: %s\n", error.c_str());
    std::fputs(kViewerUsage, error.empty() ? stdout : stderr);
    return error.empty() ? 0 : 2;
  }
  auto window = VulkanWindow::create(
      {.title = "fxkit-view " + opt.file, .width = opt.width, .height = opt.height, .validation = opt.validate}, error);
  if (!window) return std::fprintf(stderr, "fxkit-view: %s\n", error.c_str()), 2;

  fxkit::DeviceOptions options;
  options.target.formats = {.color = {window->color_format()}, .depth = window->depth_format()};
  options.target.vertex_layout = fxkit::Mesh::vertex_layout();
  options.target.default_attribute_binding = 1;                    // inputs the mesh lacks read (0, 0, 0, 1), as in D3D
  options.target.front_faces = fxkit::Winding::counter_clockwise;  // as the built-in meshes
  options.target.y_flip = fxkit::YFlip::negative_viewport;
  // RWTexture2D stand-ins (one compute thread per pixel) the size of the window as opened.
  options.target.extent = {uint32_t(opt.width), uint32_t(opt.height)};
  std::vector<fxkit::Message> errors;
  auto device = fxkit::Device::create({window->instance(), window->physical_device(), window->device(), window->queue(),
                                       window->queue_family(), window->created_with()},
                                      options, errors);
  auto mesh = device ? fxkit::Mesh::create(*device, opt.mesh, errors) : nullptr;
  if (!mesh) return print(errors), 2;
  print(device->warnings());
  auto ui_layer = ImGuiLayer::create(*window);
  if (!ui_layer) return std::fprintf(stderr, "fxkit-view: ImGui's Vulkan backend could not be set up\n"), 2;

  fxkit::Effect effect = device->load(opt.file);
  Panels ui;
  print(effect.messages());
  if (!effect.ok()) ui.problems = effect.messages();  // comes alive when a save fixes it
  fxkit::Technique technique;
  ui.techniques.pin(effect, technique, opt.technique);
  if (!opt.load_params.empty()) {
    if (!load_params(effect, opt.load_params, error)) return std::fprintf(stderr, "fxkit-view: %s\n", error.c_str()), 2;
    if (!error.empty()) std::fprintf(stderr, "fxkit-view: %s\n", error.c_str());
  }
  std::optional<ViewerScript> script;
  if (!opt.script.empty() && !(script = ViewerScript::load(opt.script, error)))
    return std::fprintf(stderr, "%s\n", error.c_str()), 2;
  OrbitCamera camera(mesh->radius());
  GpuTimer timer(window->device(), options.frames_in_flight, window->timestamp_period_ns());
  bool failed_reload = false, script_failed = false;
  bool script_said = false;  // a DXSAS script's failure printed once, not every frame

  uint64_t stand_ins_serial = 0;  // the version set_preview_defaults last ran on
  for (int frame_no = 0; !glfwWindowShouldClose(window->glfw()) && (opt.frames == 0 || frame_no < opt.frames);) {
    glfwPollEvents();
    WindowFrame frame;
    if (!window->begin_frame(frame)) {
      glfwWaitEventsTimeout(0.1);  // minimised
      continue;
    }
    bool reloaded = false;
    for (const fxkit::Reload& r : device->begin_frame()) {
      std::fputs(r.str().c_str(), stdout);
      std::fflush(stdout);
      failed_reload = r.kind == fxkit::Reload::Kind::failed;
      ui.problems = failed_reload ? r.messages : std::vector<fxkit::Message>{};
      reloaded = true;
    }
    ScriptFrame scripted;
    if (script) scripted = script->before_frame(effect, ui.techniques, technique, reloaded);
    if (!scripted.error.empty()) std::fprintf(stderr, "%s\n", scripted.error.c_str()), script_failed = true;
    ui_layer->new_frame();
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureMouse) {
      if (io.MouseDown[0]) camera.turn(io.MouseDelta.x, io.MouseDelta.y);
      if (io.MouseWheel != 0.f) camera.zoom(io.MouseWheel);
    }
    const float panel_width = draw_ui(effect, technique, ui, device->device_name(), camera.distance());
    const VkRect2D area = scene_area(frame.extent, panel_width);

    const float aspect = float(area.extent.width) / float(area.extent.height);
    fxkit::Scene scene = camera.scene(aspect, float(glfwGetTime()));
    scene.elapsed = 1.f / std::max(ImGui::GetIO().Framerate, 1.f);
    scene.viewport_size[0] = float(area.extent.width), scene.viewport_size[1] = float(area.extent.height);
    effect.set_scene(scene);
    if (effect.serial() != stand_ins_serial) {  // once per loaded version
      stand_ins_serial = effect.serial();
      for (const std::string& name : effect.set_preview_defaults())
        std::printf("stand-in value for %s\n", name.c_str());
    }
    ui.light.apply(effect);
    if (const auto ms = timer.begin(frame.cmd, frame.slot); !ms.empty()) ui.pass_ms = ms;
    // The technique's compute passes first, outside rendering, as fxkit render runs them.
    technique.dispatch_compute_passes(frame.cmd, area.extent.width, area.extent.height);
    // Then its stream-output passes capture the mesh, also outside rendering.
    for (uint32_t pass = 0; pass < technique.pass_count(); ++pass)
      if (technique.stream_output_pass(pass) && technique.begin_capture(frame.cmd, pass)) {
        mesh->draw(frame.cmd);
        technique.end_capture();
      }
    const float clear[4] = {0.18f, 0.2f, 0.24f, 1.f};
    window->begin_scene(frame, clear);
    const VkViewport viewport{
        float(area.offset.x), float(area.extent.height), float(area.extent.width), -float(area.extent.height), 0, 1};
    const bool dxsas = technique.has_script();
    if (dxsas) {
      // A DXSAS Script draws its own frame, outside rendering: its render targets, its passes,
      // the mesh for Draw=Geometry, into the window's images over the scene area.
      window->end_scene(frame);
      fxkit::ScriptFrame script_frame;
      script_frame.color = window->image_view(frame.image);
      script_frame.depth = window->depth_view();
      script_frame.depth_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
      script_frame.area = area;
      script_frame.draw_geometry = [&](VkCommandBuffer cmd) { mesh->draw(cmd); };
      if (!technique.run_script(frame.cmd, script_frame) && !script_said) {
        print(effect.messages());
        script_said = true;
      }
    } else if (technique.begin(frame.cmd, viewport, area)) {
      uint32_t captured = UINT32_MAX;  // the stream-output pass the passes after it draw (DrawAuto)
      for (uint32_t pass = 0; pass < technique.pass_count(); ++pass) {
        timer.mark(frame.cmd);
        if (technique.stream_output_pass(pass)) captured = pass;
        else if (captured != UINT32_MAX) technique.draw_stream_output(frame.cmd, pass, captured);
        else if (technique.draw_pass(pass) && technique.apply(pass)) mesh->draw(frame.cmd);
        timer.mark(frame.cmd);
      }
    }
    if (!dxsas) {
      technique.end();
      window->end_scene(frame);
    }
    ++frame_no;
    if ((!opt.screenshot.empty() && frame_no == opt.frames) || (!scripted.screenshot.empty() && !scripted.with_ui))
      window->capture(frame);
    ui_layer->record(frame);
    if (!scripted.screenshot.empty() && scripted.with_ui) window->capture(frame, true);
    if (!window->end_frame(frame)) break;
    if (!scripted.screenshot.empty() && !write_screenshot(*window, scripted.screenshot, technique))
      script_failed = true;
    if (scripted.quit) break;
  }
  window->wait_idle();

  int status = effect.ok() && !failed_reload && !script_failed ? 0 : 1;
  if (!opt.screenshot.empty() && !write_screenshot(*window, opt.screenshot, technique)) status = 2;
  if (!opt.save_params.empty() && !save_params(effect, opt.save_params, error)) {
    std::fprintf(stderr, "fxkit-view: %s\n", error.c_str());
    status = 2;
  }
  for (const fxkit::Message& m : effect.messages())
    if (m.code == "scene-transform-unbound") std::fputs(m.rendered.c_str(), stderr);
  if (window->validation_messages()) {
    std::fprintf(stderr, "fxkit-view: %u validation messages\n", window->validation_messages());
    status = 1;
  }
  ui_layer.reset();
  effect = {};
  technique = {};
  mesh.reset();
  device.reset();
  return status;
}
