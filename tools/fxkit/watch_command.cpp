// `fxkit watch FILE [-I DIR]... [-D NAME[=VALUE]]... [--json] [--frames N] [--events N]
//  [--timeout S] [--mesh M] [--out FILE.png]`: loads an effect, reloads it whenever it or
// an include is saved, and prints one line per reload event (one JSON object per line with
// --json). With --out (or --mesh) it also renders every frame headlessly through the Vulkan
// effect binding (a technique's DXSAS Script run with its render targets, docs/dxsas.md, and
// the preview's texture stand-ins) and rewrites the PNG after the first frame of each new version.
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "command.h"
#include "compile_workers_option.h"
#include "fx/binding/effect_preview.h"
#include "fx/binding/effect_scene.h"
#include "fx/binding/preview_defaults.h"
#include "fx/binding/script_runner.h"
#include "fx/diagnostic_render.h"
#include "fx/reload/effect_library.h"
#include "fx/reload/reload_transaction.h"
#include "fx/reload/vulkan_reload_backend.h"

namespace fx::tools {
namespace {

struct WatchArgs {
  FrontEndFlags front_end;
  std::string file;
  std::string mesh, out;
  bool json = false;
  int frames = 0;      // stop after this many frames (0: no limit)
  int events = 0;      // stop after this many events (0: no limit)
  double timeout = 0;  // stop after this many seconds (0: no limit)
  int coalesce_ms = 50;
  CompileWorkersFlag workers;
};

nlohmann::json event_json(const fx::ReloadEvent& ev) {
  nlohmann::json diags = ev.sources ? fx::render_json(ev.diagnostics, *ev.sources) : nlohmann::json::array();
  if (!ev.sources)
    for (const fx::Diagnostic& d : ev.diagnostics) diags.push_back({{"id", d.id}, {"message", d.message}});
  return {{"event", fx::to_string(ev.kind)},
          {"file", ev.file},
          {"changed", ev.changed},
          {"recompiled", ev.recompiled},
          {"defaults_changed", ev.defaults_changed},
          {"ms",
           {{"detect", ev.ms.detect},
            {"parse", ev.ms.parse},
            {"compile", ev.ms.compile},
            {"glslang", ev.ms.glslang},
            {"pipeline", ev.ms.pipeline},
            {"first_frame", ev.ms.first_frame},
            {"total", ev.ms.total}}},
          {"technique", ev.technique},
          {"serial", ev.serial},
          {"diagnostics", std::move(diags)}};
}

// "a, b, c".
std::string comma_list(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

void print_event(const fx::ReloadEvent& ev, bool json) {
  if (json) {
    std::printf("%s\n", json_text(event_json(ev), -1).c_str());
  } else {
    std::printf("%s %s (%s): %zu recompiled, %.1f ms (detect %.1f, parse %.1f, compile %.1f, pipeline %.1f)\n",
                fx::to_string(ev.kind), ev.file.c_str(), comma_list(ev.changed).c_str(), ev.recompiled.size(),
                ev.ms.total, ev.ms.detect, ev.ms.parse, ev.ms.compile, ev.ms.pipeline);
    if (!ev.defaults_changed.empty()) std::printf("defaults changed: %s\n", comma_list(ev.defaults_changed).c_str());
    if (!ev.diagnostics.empty() && ev.sources) std::fputs(fx::render_text(ev.diagnostics, *ev.sources).c_str(), stdout);
  }
  std::fflush(stdout);
}

int run_watch(const WatchArgs& args) {
  fx::EffectLibraryOptions options;
  options.include_dirs = args.front_end.include_dirs;
  options.defines = args.front_end.defines;
  auto profile = fx::parse_effect_profile(args.front_end.profile);
  if (args.front_end.profile != "auto" && !profile) {
    std::fprintf(stderr, "fxkit watch: unknown --profile '%s'\n", args.front_end.profile.c_str());
    return kUsageError;
  }
  options.profile = profile.value_or(fx::EffectProfile::automatic);
  options.coalesce = std::chrono::milliseconds(args.coalesce_ms);
  options.compile_workers = args.workers.options(0);
  if (!std::filesystem::is_regular_file(args.file)) {
    std::fprintf(stderr, "fxkit watch: cannot read '%s'\n", args.file.c_str());
    return kUsageError;
  }
  // Rendering: a headless device, the mesh framed by the camera, a binding per version.
  const bool render = !args.mesh.empty() || !args.out.empty();
  std::optional<fx::vk::Context> ctx;
  std::unique_ptr<fx::vk::EffectPreview> preview;
  std::unique_ptr<fx::vk::ReloadBackend> backend;
  if (render) {
    fx::DiagnosticSink sink;
    auto mesh = fx::make_mesh(args.mesh.empty() ? "sphere" : args.mesh, sink);
    if (mesh) ctx = fx::vk::Context::headless({}, sink);
    if (ctx) preview = fx::vk::EffectPreview::create(*ctx, *mesh, {}, sink);
    if (!preview) {
      for (const fx::Diagnostic& d : sink.diagnostics())
        std::fprintf(stderr, "fxkit watch: %s [%s]\n", d.message.c_str(), d.id.c_str());
      return kUsageError;
    }
    preview->textures().set_preview_stand_ins(true);  // as fxkit render: textures no file fills show
    fx::vk::EffectPreview* p = preview.get();
    backend = std::make_unique<fx::vk::ReloadBackend>(
        *ctx, preview->textures(), preview->frames(),
        fx::vk::ReloadBackendDesc{preview->formats(), preview->binding_desc(),
                                  [p](std::span<const fx::InterfaceVariable> in) { return p->vertex_layout(in); }});
    options.backend = backend.get();
  }

  fx::EffectLibrary lib(std::move(options));
  if (!lib.compile_workers_error().empty())
    std::fprintf(stderr, "fxkit watch: warning: compiling in this process: %s [compile-workers-unavailable]\n",
                 lib.compile_workers_error().c_str());
  fx::EffectHandle effect = lib.load(args.file);
  fx::ReloadEvent loaded;  // the initial load, reported like a reload
  loaded.kind = effect.ok() ? fx::ReloadEventKind::reloaded : fx::ReloadEventKind::failed;
  loaded.file = args.file;
  loaded.changed = {args.file};
  loaded.diagnostics = effect.diagnostics();
  loaded.sources = effect.diagnostic_sources();
  loaded.serial = effect.serial();
  print_event(loaded, args.json);
  for (const fx::Diagnostic& d : lib.watcher_diagnostics())
    std::fprintf(stderr, "fxkit watch: %s [%s]\n", d.message.c_str(), d.id.c_str());

  using Clock = std::chrono::steady_clock;
  Clock::time_point start = Clock::now();
  int events = 0;
  uint64_t written_serial = 0;  // the version whose frame is in the PNG
  // The DXSAS Script runner of the version and technique drawn, remade when either changes.
  std::unique_ptr<fx::vk::ScriptRunner> script;
  std::pair<uint64_t, uint32_t> script_for{0, fx::kNoIndex};
  auto render_frame = [&] {
    auto version = effect.version();
    fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
    if (!binding) return;
    uint32_t technique = effect.technique();
    if (!binding->technique_ok(technique)) technique = binding->first_ok_technique();
    fx::vk::set_standard_semantics(*effect.params(), *version->model, preview->scene());
    fx::vk::set_preview_defaults(*effect.params(), *version->model,
                                 fx::vk::parameters_read(*version->programs, technique));
    fx::DiagnosticSink sink;
    const bool scripted = bool(version->model->techniques[technique].script);
    if (scripted && script_for != std::pair{version->serial, technique}) {
      script.reset();
      const glm::vec2 size = preview->scene().viewport_size;
      script = fx::vk::ScriptRunner::create(*ctx, *version->model, *binding, *effect.params(), technique,
                                            uint32_t(size.x), uint32_t(size.y), sink);
      script_for = {version->serial, technique};
    }
    std::optional<fx::Image> image;
    if (!scripted) image = preview->render(*binding, technique, 0, sink);
    else if (script) image = preview->render_script(*script, 0, sink);
    for (const fx::Diagnostic& d : sink.diagnostics())
      std::fprintf(stderr, "fxkit watch: %s [%s]\n", d.message.c_str(), d.id.c_str());
    if (image && !args.out.empty() && written_serial != version->serial) {
      if (fx::write_png(args.out, *image, sink)) written_serial = version->serial;
      else std::fprintf(stderr, "fxkit watch: cannot write '%s'\n", args.out.c_str());
    }
  };
  if (render) effect.select();
  // One loop iteration is one frame: wait (bounded) for a reload, then poll at the boundary.
  for (uint64_t frame = 0; args.frames <= 0 || frame < static_cast<uint64_t>(args.frames); ++frame) {
    if (args.timeout > 0 && std::chrono::duration<double>(Clock::now() - start).count() >= args.timeout) break;
    lib.wait(std::chrono::milliseconds(16));
    for (const fx::ReloadEvent& ev : lib.poll(frame)) {
      print_event(ev, args.json);
      ++events;
    }
    if (render) render_frame();
    if (args.events > 0 && events >= args.events) break;
  }
  lib.release_all();
  return effect.ok() ? kSuccess : kInputErrors;
}

}  // namespace

void register_watch(CLI::App& app, Runner& run) {
  auto args = std::make_shared<WatchArgs>();
  CLI::App* cmd = app.add_subcommand("watch", "Reload an effect whenever it or an include is saved");
  args->front_end.add_to(*cmd);
  cmd->add_flag("--json", args->json, "One JSON object per event per line");
  cmd->add_option("--frames", args->frames, "Stop after N frames (a frame is at most 16 ms here)");
  cmd->add_option("--events", args->events, "Stop after N reload events");
  cmd->add_option("--timeout", args->timeout, "Stop after S seconds");
  cmd->add_option("--coalesce-ms", args->coalesce_ms, "Quiet time before a saved file is reloaded")
      ->capture_default_str();
  cmd->add_option("--mesh", args->mesh, "Mesh to render: sphere, torus, quad, teapot or an .obj (default sphere)");
  cmd->add_option("--out", args->out, "PNG rewritten after the first frame of each new version");
  args->workers.add_to(*cmd);
  cmd->add_option("FILE", args->file, "Effect file")->required();
  cmd->callback([args, &run] { run = [args] { return run_watch(*args); }; });
}

}  // namespace fx::tools
