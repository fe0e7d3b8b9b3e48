// `fxkit render FILE [--technique NAME|auto] [--mesh sphere|torus|quad|teapot|FILE.obj]
//  [--size WxH] [--param NAME=VALUE]... [--validation] [--ps1x-precision] [--verbose] [--out FILE.png] [--caps X]
//  [--frames N]`:
// renders an effect headlessly (the best Vulkan device, or FXKIT_DEVICE) on a mesh framed
// by the camera, standard semantics filled in, and writes a PNG.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "caps_option.h"
#include "command.h"
#include "fx/binding/effect_preview.h"
#include "fx/binding/effect_scene.h"
#include "fx/binding/preview_defaults.h"
#include "fx/binding/script_runner.h"
#include "fx/compile/effect_file.h"
#include "fx/diagnostic_render.h"
#include "fx/select/technique_validation.h"

namespace fx::tools {
namespace {

struct RenderArgs {
  FrontEndFlags front_end;
  std::string file, technique = "auto", mesh = "sphere", size = "256x256", out = "render.png", caps;
  std::vector<std::string> params;
  bool validation = false, verbose = false, ps1x_precision = false;
  int frames = 1;
};

// "NAME=1,2,3": floats, or ints/bools for integer parameters.
bool set_param(fx::ParameterStore& store, const std::string& assignment, std::string& error) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos) return error = "--param wants NAME=VALUE, got '" + assignment + "'", false;
  const std::string name = assignment.substr(0, eq);
  fxkit::Param p = store.find(name);
  if (!p.valid()) p = store.by_semantic(name);
  const fx::Type* type = store.type(p);
  if (!type) return error = "no parameter '" + name + "'", false;
  std::vector<double> values;
  std::stringstream ss(assignment.substr(eq + 1));
  for (std::string item; std::getline(ss, item, ',');) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str()) return error = "'" + item + "' is not a number", false;
    values.push_back(v);
  }
  fx::ParamStatus status;
  if (type->base == fx::BaseType::float32 || type->base == fx::BaseType::half) {
    std::vector<float> f(values.begin(), values.end());
    status = type->cls == fx::TypeClass::matrix ? store.set_matrix(p, f) : store.set(p, std::span<const float>(f));
  } else {
    std::vector<int32_t> i;
    for (double v : values) i.push_back(int32_t(v));
    status = store.set(p, std::span<const int32_t>(i));
  }
  if (!status) return error = status.message, false;
  return true;
}

int run_render(const RenderArgs& args) {
  fx::FrontEndOptions options;
  std::string error;
  if (!args.front_end.to_options(options, error)) {
    std::fprintf(stderr, "fxkit render: %s\n", error.c_str());
    return kUsageError;
  }
  if (args.ps1x_precision) options.preprocessor.defines.emplace_back(fx::kPs1xPrecisionMacro, "1");
  unsigned width = 0, height = 0;
  if (std::sscanf(args.size.c_str(), "%ux%u", &width, &height) != 2 || !width || !height || width > 8192 ||
      height > 8192) {
    std::fprintf(stderr, "fxkit render: --size wants WxH, got '%s'\n", args.size.c_str());
    return kUsageError;
  }
  if (!std::filesystem::is_regular_file(args.file)) {
    std::fprintf(stderr, "fxkit render: cannot read '%s'\n", args.file.c_str());
    return kUsageError;
  }
  fx::DiagnosticSink diags;
  std::string located;
  auto effect = fx::EffectFile::load(args.file, options, diags, &located);
  if (!effect) {
    std::fputs(located.c_str(), stderr);
    return kInputErrors;
  }
  auto report = [&](const fx::DiagnosticSink& sink) {
    if (!sink.diagnostics().empty()) std::fputs(fx::render_text(sink.diagnostics(), effect->sources).c_str(), stderr);
  };
  std::optional<fx::DeviceCaps> caps;
  if (!args.caps.empty()) {
    caps = load_caps_option(args.caps, diags);
    if (!caps) return report(diags), kUsageError;
  }
  auto mesh = fx::make_mesh(args.mesh, diags);
  if (!mesh) return report(diags), kUsageError;
  for (const std::string& a : args.params)
    if (!set_param(*effect->params, a, error)) {
      std::fprintf(stderr, "fxkit render: %s\n", error.c_str());
      return kUsageError;
    }

  fx::vk::ContextOptions ctx_options;
  ctx_options.validation = args.validation;
  auto ctx = fx::vk::Context::headless(ctx_options, diags);
  if (!ctx) return report(diags), kUsageError;
  int status = kSuccess;
  {
    fx::vk::EffectPreviewDesc preview_desc;
    preview_desc.width = width;
    preview_desc.height = height;
    auto preview = fx::vk::EffectPreview::create(*ctx, *mesh, preview_desc, diags);
    if (!preview) return report(diags), kUsageError;
    preview->textures().set_preview_stand_ins(true);  // textures no file fills show what the shader does
    fx::vk::EffectBindingDesc desc = preview->binding_desc();
    desc.effect_dir = std::filesystem::path(args.file).parent_path();
    desc.texture_dirs.assign(options.preprocessor.include_dirs.begin(), options.preprocessor.include_dirs.end());
    auto binding = fx::vk::EffectBinding::create(*ctx, *effect->model, *effect->programs, *effect->params,
                                                 preview->textures(), preview->frames(), desc, diags);
    if (!binding) return report(diags), kInputErrors;

    uint32_t technique = fx::kNoIndex;
    if (args.technique != "auto") {
      technique = effect->find_technique(args.technique);
      if (technique == fx::kNoIndex) {
        std::fprintf(stderr, "fxkit render: no technique '%s'\n", args.technique.c_str());
        return kUsageError;
      }
    } else if (caps) {
      // D3DX's rule on the given caps, skipping what this device cannot draw either.
      auto validation = fx::validate_techniques(*effect->model, *caps, {.programs = effect->programs.get()});
      for (std::optional<size_t> t = fx::find_next_valid(validation); t; t = fx::find_next_valid(validation, t))
        if (binding->technique_ok(uint32_t(*t))) {
          technique = uint32_t(*t);
          break;
        }
    } else {
      technique = binding->first_ok_technique();
    }
    if (technique == fx::kNoIndex) {
      std::fprintf(stderr, "fxkit render: no technique of '%s' can be drawn here\n", args.file.c_str());
      for (uint32_t t = 0; t < binding->technique_count(); ++t)
        std::fprintf(stderr, "  %s: %s\n", effect->model->techniques[t].name.c_str(),
                     binding->technique_reason(t).c_str());
      return kInputErrors;
    }
    if (!binding->technique_ok(technique)) {
      std::fprintf(stderr, "fxkit render: technique '%s' cannot be drawn: %s\n",
                   effect->model->techniques[technique].name.c_str(), binding->technique_reason(technique).c_str());
      return kInputErrors;
    }
    auto inputs = fx::vk::technique_vertex_inputs(*effect->model, *effect->programs, technique);
    const uint32_t layout = binding->add_vertex_layout(preview->vertex_layout(inputs));
    std::vector<fx::vk::SceneBinding> bound;
    fx::vk::set_standard_semantics(*effect->params, *effect->model, preview->scene(), &bound);
    const auto read = fx::vk::parameters_read(*effect->programs, technique);
    const std::vector<fx::vk::PreviewDefault> stand_ins =
        fx::vk::set_preview_defaults(*effect->params, *effect->model, read);
    for (const std::string& a : args.params) set_param(*effect->params, a, error);  // --param wins
    if (args.verbose) {
      for (const fx::vk::SceneBinding& b : bound)
        std::fprintf(stderr, "fxkit render: %s <- %s (%s)\n", b.parameter.c_str(), b.semantic.c_str(),
                     b.by_name ? "by its name" : "by its semantic");
      for (const fx::vk::PreviewDefault& d : stand_ins)
        std::fprintf(stderr, "fxkit render: %s <- %s (stand-in)\n", d.parameter.c_str(), d.rule.c_str());
    }
    const std::vector<std::string> unbound = fx::vk::zero_transforms(*effect->params, *effect->model, read);
    for (const std::string& name : unbound)
      std::fprintf(stderr,
                   "fxkit render: warning: '%s' is read by the shaders but left zero (no standard semantic, and "
                   "not a name docs/parameters.md lists); set it with --param\n",
                   name.c_str());
    // A technique with a DXSAS Script runs it: its render targets, passes and full-screen quads.
    std::unique_ptr<fx::vk::ScriptRunner> script;
    if (effect->model->techniques[technique].script) {
      script = fx::vk::ScriptRunner::create(*ctx, *effect->model, *binding, *effect->params, technique, width, height,
                                            diags);
      if (!script) return report(diags), kInputErrors;
      if (args.verbose) std::fprintf(stderr, "fxkit render: running the technique's DXSAS Script\n");
      if (args.verbose && script->draws_scene())
        std::fprintf(stderr, "fxkit render: ScriptExternal <- the preview's test scene (stand-in)\n");
    }
    // Textures with neither a file nor a generator, and no script target: the cache binds
    // a stand-in (a missing file has its own warning). A texture shader fills its texture
    // (a fill that fails has its own warning).
    if (args.verbose)
      for (const fx::TextureInfo& t : effect->model->textures) {
        const fx::Parameter& param = effect->model->parameters[t.parameter];
        if (t.shader) {
          std::fprintf(stderr, "fxkit render: %s <- texture shader '%s' (%ux%u%s)\n", param.name.c_str(),
                       t.shader->function.c_str(), t.shader->width, t.shader->height,
                       t.shader->shape == fx::TextureShape::tex3d  ? ("x" + std::to_string(t.shader->depth)).c_str()
                       : t.shader->shape == fx::TextureShape::cube ? " cube"
                                                                   : "");
          continue;
        }
        const fx::ImageDim dim = t.shape == fx::TextureShape::cube    ? fx::ImageDim::cube
                                 : t.shape == fx::TextureShape::tex3d ? fx::ImageDim::dim_3d
                                 : t.shape == fx::TextureShape::tex1d ? fx::ImageDim::dim_1d
                                                                      : fx::ImageDim::dim_2d;
        if (t.generator.empty() && t.resource_name.empty() && !(script && script->target(param.name)))
          std::fprintf(stderr, "fxkit render: %s <- %s (stand-in: no ResourceName)\n", param.name.c_str(),
                       fx::vk::stand_in_name(fx::vk::texture_stand_in(&param, dim, true)));
      }
    auto frame = [&] {
      return script ? preview->render_script(*script, layout, diags)
                    : preview->render(*binding, technique, layout, diags);
    };
    // The first frame pays for the driver's shader compile; later ones are timed (wall
    // clock, submit to readback) and the median is reported.
    auto image = frame();
    std::vector<double> ms;
    for (int f = 1; image && f < args.frames; ++f) {
      auto start = std::chrono::steady_clock::now();
      image = frame();
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    // A technique that draws nothing shows what its compute passes wrote.
    const bool computes_only = binding->computes_only(technique);
    std::optional<fx::vk::EffectBinding::ComputeOutput> computed;
    if (image && computes_only) {
      ctx->wait_idle();
      computed = binding->compute_output(technique, diags);
      if (computed) image = computed->picture;
    }
    if (args.verbose)
      for (const std::string& name : binding->storage().patterned())
        std::fprintf(stderr, "fxkit render: %s <- a pattern (stand-in: a buffer no pass writes)\n", name.c_str());
    report(diags);
    if (!image) return kInputErrors;
    if (computes_only) {
      const std::string shown =
          !computed          ? "the clear colour (its compute passes write no stand-in fxkit can read back)"
          : computed->buffer ? "the words its compute passes wrote to buffer '" + computed->name +
                                   "', 64 a row, grey from the smallest to the largest"
                             : "the texels its compute passes wrote to image '" + computed->name + "'";
      std::fprintf(stderr, "fxkit render: the technique draws nothing: the image is %s\n", shown.c_str());
    }
    if (image->constant()) {
      const uint8_t* p = image->pixels.data();
      std::fprintf(stderr, "fxkit render: warning: the image is constant (every pixel %u,%u,%u,%u)%s\n", p[0], p[1],
                   p[2], p[3], unbound.empty() ? "" : "; see the transforms left zero above");
    } else if (!computes_only) {
      // Pixels within 2 levels of the clear colour are background; the rest is the object.
      std::array<uint8_t, 4> background{};
      for (size_t c = 0; c < 4; ++c) background[c] = uint8_t(std::lround(preview_desc.clear[c] * 255.0f));
      if (auto flat = image->flat_over(background, 2))
        std::fprintf(stderr,
                     "fxkit render: warning: the image is one flat colour over the drawn object (%u,%u,%u,%u)\n",
                     (*flat)[0], (*flat)[1], (*flat)[2], (*flat)[3]);
    }
    if (!fx::write_png(args.out, *image, diags)) return report(diags), kUsageError;
    const fx::TechniqueInfo& t = effect->model->techniques[technique];
    std::printf("%s: technique %s on %s, %ux%u -> %s", args.file.c_str(), t.name.c_str(), args.mesh.c_str(), width,
                height, args.out.c_str());
    if (!ms.empty()) {
      std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
      std::printf(", %.2f ms/frame (median of %zu)", ms[ms.size() / 2], ms.size());
    }
    // The measured error of the technique's approximation (effects/generated/costs.fxh),
    // said as what it is: not this image's error, nor a limit.
    if (const fx::Annotation* e = fx::find_annotation(t.annotations, "MaxError"))
      std::printf(", technique's measured max error %.3g (8-bit levels, its MaxError annotation)", e->value.number());
    std::printf("\n");
  }
  ctx->wait_idle();
  if (args.validation) {
    // Every error and warning fails the run. (A vertex output the pixel shader does not
    // read, which Direct3D allows, is no warning: linking removes it.)
    size_t failing = 0;
    for (const fx::vk::ValidationMessage& m : ctx->validation_messages()) {
      ++failing;
      std::fprintf(stderr, "validation %s: %s: %s\n", fx::to_string(m.severity), m.id_name.c_str(), m.text.c_str());
    }
    if (failing) status = kInputErrors;
  }
  return status;
}

}  // namespace

void register_render(CLI::App& app, Runner& run) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render an effect on a mesh headlessly and write a PNG");
  args->front_end.add_to(*cmd);
  cmd->add_option("--technique", args->technique, "Technique name, or auto (the first that can be drawn)")
      ->capture_default_str();
  cmd->add_option("--mesh", args->mesh, "sphere, torus, quad, teapot or an .obj file")->capture_default_str();
  cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
  cmd->add_option("--param", args->params, "NAME=VALUE[,VALUE...] (name or semantic)");
  cmd->add_flag("--verbose", args->verbose, "Print which parameters the scene bound, and how");
  cmd->add_flag("--validation", args->validation, "Enable the validation layers; any message fails the run");
  cmd->add_flag("--ps1x-precision", args->ps1x_precision,
                "Model ps.1.x hardware arithmetic in assembly pixel shaders ([-1,1] or [-8,8], 8-bit fractions)");
  cmd->add_option("--out", args->out, "Output PNG")->capture_default_str();
  cmd->add_option("--caps", args->caps, caps_option_help());
  cmd->add_option("--frames", args->frames, "Frames to render; past the first, the median time is printed")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  cmd->add_option("FILE", args->file, "Effect file")->required();
  cmd->callback([args, &run] { run = [args] { return run_render(*args); }; });
}

}  // namespace fx::tools
