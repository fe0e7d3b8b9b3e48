// ScriptRunner: a technique's DXSAS Script run into a command buffer, with its render targets.
#include "fx/binding/script_runner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "fx/ascii_case.h"
#include "fx/vulkan/barrier.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {
namespace {

// A D3DFORMAT name of a Format annotation ("A16B16G16R16F", "D3DFMT_A8R8G8B8") as the Vulkan
// format a render target is made in; UNDEFINED for one fxkit does not render into.
VkFormat target_format(std::string name) {
  name = ascii_lower(name);
  if (name.rfind("d3dfmt_", 0) == 0) name = name.substr(7);
  if (name.empty() || name == "a8r8g8b8" || name == "x8r8g8b8" || name == "a8b8g8r8" || name == "x8b8g8r8")
    return VK_FORMAT_R8G8B8A8_UNORM;
  if (name == "a16b16g16r16f") return VK_FORMAT_R16G16B16A16_SFLOAT;
  if (name == "a32b32g32r32f") return VK_FORMAT_R32G32B32A32_SFLOAT;
  if (name == "a16b16g16r16") return VK_FORMAT_R16G16B16A16_UNORM;
  if (name == "g16r16f") return VK_FORMAT_R16G16_SFLOAT;
  if (name == "g32r32f") return VK_FORMAT_R32G32_SFLOAT;
  if (name == "r16f") return VK_FORMAT_R16_SFLOAT;
  if (name == "r32f") return VK_FORMAT_R32_SFLOAT;
  if (name == "a2r10g10b10" || name == "a2b10g10r10") return VK_FORMAT_A2B10G10R10_UNORM_PACK32;
  return VK_FORMAT_UNDEFINED;
}

// The size of a render target parameter: Dimensions (or width / height) in texels, else
// ViewportRatio times the frame, else the frame's size.
VkExtent2D target_size(const Parameter& p, uint32_t frame_width, uint32_t frame_height) {
  auto clamp = [](double v) { return uint32_t(std::clamp(std::ceil(v), 1.0, 8192.0)); };
  if (const Annotation* d = find_annotation(p.annotations, "Dimensions"); d && d->value.components.size() >= 2)
    return {clamp(d->value.number(0)), clamp(d->value.number(1))};
  const Annotation* w = find_annotation(p.annotations, "width");
  const Annotation* h = find_annotation(p.annotations, "height");
  if (w && h && w->value.is_numeric() && h->value.is_numeric())
    return {clamp(w->value.number()), clamp(h->value.number())};
  if (const Annotation* r = find_annotation(p.annotations, "ViewportRatio"); r && r->value.components.size() >= 2)
    return {clamp(r->value.number(0) * frame_width), clamp(r->value.number(1) * frame_height)};
  return {frame_width, frame_height};
}

// The steps after `open` (a loop command) up to its LoopEnd (index of the LoopEnd, or
// steps.size() when the script leaves it open).
size_t loop_end(const std::vector<ScriptStep>& steps, size_t open) {
  int depth = 0;
  for (size_t i = open + 1; i < steps.size(); ++i) {
    const ScriptCommand c = steps[i].command;
    if (c == ScriptCommand::loop_by_count || c == ScriptCommand::loop_by_type) ++depth;
    if (c == ScriptCommand::loop_end && depth-- == 0) return i;
  }
  return steps.size();
}

constexpr uint32_t kMaxLoop = 1024;  // a count read from a parameter: a preview draws no more

// A scalar parameter's value, float or int (0 when it is neither).
float scalar(const ParameterStore& params, Param p) {
  float f = 0;
  if (params.get(p, f)) return f;
  int32_t i = 0;
  return params.get(p, i) ? float(i) : 0.0f;
}

// Orders a rendering on the frame's attachments after the one before it on the same images,
// and what follows the script after its last.
void attachment_barrier(VkCommandBuffer cmd) {
  constexpr VkPipelineStageFlags stages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                          VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                          VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  memory_barrier(cmd, stages, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                 stages,
                 VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                     VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
}

}  // namespace

struct ScriptRunner::State {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  const ScriptFrame* frame = nullptr;
  RenderTarget* current = nullptr;  // null: the frame's attachments
  // RenderColorTarget1..3: drawn into beside `current` (multiple render targets).
  std::array<RenderTarget*, kMaxColorAttachments - 1> more{};
  std::array<float, 4> clear_color{0, 0, 0, 0};
  float clear_depth = 1.0f;
  uint32_t clear_stencil = 0;
  uint32_t pass = kNoIndex;     // the pass whose script runs (its Draw= draws it)
  std::vector<uint32_t> loops;  // the index of each open loop, innermost last
  bool smaller_target_said = false;

  // The targets bound beside `current`, in slot order up to the first unbound slot, as
  // Direct3D 9 binds them; one smaller than `current` (Vulkan renders the attachments over
  // one area) is left out with a warning.
  std::vector<RenderTarget*> more_targets(const ScriptStep& step, DiagnosticSink& sink) {
    std::vector<RenderTarget*> out;
    for (RenderTarget* t : more) {
      if (!t || t == current || std::find(out.begin(), out.end(), t) != out.end()) break;
      const VkExtent2D size = area().extent;
      if (t->width() >= size.width && t->height() >= size.height) {
        out.push_back(t);
        continue;
      }
      if (!smaller_target_said)
        sink.warning("vk-script-target", step.range,
                     "a render target bound beside RenderColorTarget0 is smaller than it (" +
                         std::to_string(t->width()) + "x" + std::to_string(t->height()) + " against " +
                         std::to_string(area().extent.width) + "x" + std::to_string(area().extent.height) +
                         "): it is not drawn into");
      smaller_target_said = true;
    }
    return out;
  }

  // What the current target draws into: a render target's whole image, or the frame's area.
  VkRect2D area() const { return current ? current->scissor() : frame->attachments.area; }
  RenderingFormats formats(std::span<RenderTarget* const> more) const {
    const std::vector<const RenderTarget*> more_formats(more.begin(), more.end());
    if (current) return current->formats(more_formats);
    RenderingFormats f = frame->attachments.formats;
    append_color_formats(f, more_formats);
    return f;
  }

  // Begins rendering into the current target and `more`, cleared as `clear` says.
  void begin(const ClearValues& clear, std::span<RenderTarget* const> more) {
    if (current) return current->begin(cmd, clear, more);
    const FrameAttachments& frame_images = frame->attachments;
    attachment_barrier(cmd);
    std::array<VkRenderingAttachmentInfo, kMaxColorAttachments> colors{};
    uint32_t count = 0;
    colors[count++] = color_attachment(frame_images.color, frame_images.color_layout, clear);
    for (RenderTarget* t : more)
      if (count < kMaxColorAttachments) {
        t->color().transition(cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
        colors[count++] = color_attachment(t->color().view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, clear);
      }
    auto info = structure<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    info.renderArea = frame_images.area;
    info.layerCount = 1;
    info.colorAttachmentCount = count;
    info.pColorAttachments = colors.data();
    VkRenderingAttachmentInfo depth{};
    if (frame_images.depth) {
      depth = depth_attachment(frame_images.depth, frame_images.depth_layout, clear);
      if (frame_images.formats.depth != VK_FORMAT_UNDEFINED) info.pDepthAttachment = &depth;
      if (frame_images.formats.stencil != VK_FORMAT_UNDEFINED) info.pStencilAttachment = &depth;
    }
    vkCmdBeginRendering(cmd, &info);
  }

  // Ends the rendering begin() started; the script's targets drawn are then sampled by
  // later passes.
  void end(std::span<RenderTarget* const> drawn) {
    vkCmdEndRendering(cmd);
    if (current && current != frame->target) current->color().transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    for (RenderTarget* t : drawn) t->color().transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  }
};

std::unique_ptr<ScriptRunner> ScriptRunner::create(const Context& ctx, const EffectModel& model, EffectBinding& binding,
                                                   ParameterStore& params, uint32_t technique, uint32_t frame_width,
                                                   uint32_t frame_height, DiagnosticSink& sink) {
  if (technique >= model.techniques.size() || !model.techniques[technique].script) {
    sink.error("vk-script-none", {}, "technique " + std::to_string(technique) + " has no DXSAS Script annotation");
    return nullptr;
  }
  std::unique_ptr<ScriptRunner> r(new ScriptRunner(ctx, model, binding, params, technique));
  const TechniqueInfo& t = model.techniques[technique];
  std::vector<const ScriptPlan*> plans = {&*t.script};
  for (const PassInfo& pass : t.passes)
    if (pass.script) plans.push_back(&*pass.script);
  for (const ScriptPlan* plan : plans)
    for (const ScriptStep& step : plan->steps) {
      if (step.command != ScriptCommand::render_color_target || step.parameter == kNoIndex ||
          r->targets_.count(step.parameter))
        continue;
      const Parameter& p = model.parameters[step.parameter];
      const VkExtent2D size = target_size(p, frame_width, frame_height);
      std::string format_name;
      const Annotation* format = find_annotation(p.annotations, "Format");
      if (format && format->value.is_string()) format_name = format->value.text;
      VkFormat vk_format = target_format(format_name);
      if (vk_format == VK_FORMAT_UNDEFINED) {
        sink.warning("vk-script-target", format->range,
                     "render target '" + p.name + "': format '" + format_name +
                         "' is not one fxkit renders into; RGBA8 instead");
        vk_format = VK_FORMAT_R8G8B8A8_UNORM;
      }
      auto target = RenderTarget::create(ctx,
                                         {size.width, size.height, vk_format, DepthAttachment::d24s8,
                                          VK_IMAGE_USAGE_SAMPLED_BIT, "fxkit script target"},
                                         sink);
      if (!target) return nullptr;
      RenderTarget& made = r->targets_.emplace(step.parameter, std::move(*target)).first->second;
      if (!binding.set_texture(p.name, made.color().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               ImageKind::image2d, sink))
        return nullptr;
    }
  return r;
}

ScriptRunner::~ScriptRunner() {
  if (ctx_ && !targets_.empty()) ctx_->wait_idle();
}

std::vector<std::pair<std::string, const RenderTarget*>> ScriptRunner::targets() const {
  std::vector<std::pair<std::string, const RenderTarget*>> out;
  for (const auto& [param, target] : targets_) out.emplace_back(model_->parameters[param].name, &target);
  return out;
}

const RenderTarget* ScriptRunner::target(const std::string& name) const {
  const uint32_t p = model_->find_parameter(name);
  auto it = targets_.find(p);
  return it != targets_.end() ? &it->second : nullptr;
}

bool ScriptRunner::draws_scene() const {
  const TechniqueInfo& t = model_->techniques[technique_];
  auto has = [](const ScriptPlan& plan) {
    return std::any_of(plan.steps.begin(), plan.steps.end(),
                       [](const ScriptStep& s) { return s.command == ScriptCommand::script_external; });
  };
  return has(*t.script) ||
         std::any_of(t.passes.begin(), t.passes.end(), [&](const PassInfo& p) { return p.script && has(*p.script); });
}

bool ScriptRunner::record(VkCommandBuffer cmd, const ScriptFrame& frame, DiagnosticSink& sink) {
  State state;
  state.cmd = cmd;
  state.frame = &frame;
  state.current = frame.target;
  // A target no pass has drawn yet is sampled as transparent black, not undefined memory.
  for (auto& [param, target] : targets_)
    if (target.color().layout() != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) {
      target.begin(cmd, ClearValues{std::array<float, 4>{0, 0, 0, 0}, 1.0f, 0});
      target.end(cmd);
      target.color().transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
  const std::vector<ScriptStep>& steps = model_->techniques[technique_].script->steps;
  const bool ok = run(steps, 0, steps.size(), state, sink);
  if (!frame.target) attachment_barrier(cmd);
  return ok;
}

bool ScriptRunner::run(const std::vector<ScriptStep>& steps, size_t begin, size_t end, State& state,
                       DiagnosticSink& sink) {
  for (size_t i = begin; i < end; ++i) {
    const ScriptStep& step = steps[i];
    const Param param = step.parameter != kNoIndex ? params_->find(model_->parameters[step.parameter].name) : Param{};
    switch (step.command) {
      case ScriptCommand::render_color_target: {
        RenderTarget* target = step.parameter == kNoIndex ? nullptr : &targets_.at(step.parameter);
        if (step.slot == 0) state.current = target ? target : state.frame->target;
        else if (step.slot < kMaxColorAttachments) state.more[step.slot - 1] = target;
        break;
      }
      case ScriptCommand::render_depth_stencil_target: break;  // each colour target has its own depth
      case ScriptCommand::clear_set_color: {
        std::array<float, 4> c{0, 0, 0, 1};
        const Type* type = params_->type(param);
        if (type) params_->get(param, std::span<float>(c.data(), std::min<size_t>(4, type->component_count())));
        state.clear_color = c;
        break;
      }
      case ScriptCommand::clear_set_depth: state.clear_depth = scalar(*params_, param); break;
      case ScriptCommand::clear_set_stencil:
        state.clear_stencil = uint32_t(std::clamp(scalar(*params_, param), 0.0f, 255.0f));
        break;
      case ScriptCommand::clear: {
        ClearValues clear{std::nullopt, std::nullopt, state.clear_stencil};
        if (step.clear == ScriptClear::color) clear.color = state.clear_color;
        else clear.depth = state.clear_depth;  // depth and stencil clear together
        // Direct3D 9 clears every bound render target.
        const std::vector<RenderTarget*> more = state.more_targets(step, sink);
        state.begin(clear, more);
        state.end(more);
        break;
      }
      case ScriptCommand::pass:
        if (!draw_pass(step, state, sink)) return false;
        break;
      case ScriptCommand::draw:
        if (state.pass != kNoIndex && !draw(step, step.draw, state.pass, state, sink)) return false;
        break;
      case ScriptCommand::script_external:
        if (state.frame->draw_scene) {
          state.begin(ClearValues{std::nullopt, std::nullopt, 0}, {});
          state.frame->draw_scene(state.cmd, state.formats({}), state.area());
          state.end({});
        }
        break;
      case ScriptCommand::loop_by_count:
      case ScriptCommand::loop_by_type: {
        const size_t close = loop_end(steps, i);
        uint32_t count = 1;  // LoopByType: the preview has one of each
        if (step.command == ScriptCommand::loop_by_count) {
          count = uint32_t(std::clamp(scalar(*params_, param), 0.0f, float(kMaxLoop)));
        }
        for (uint32_t k = 0; k < count; ++k) {
          state.loops.push_back(k);
          const bool ok = run(steps, i + 1, close, state, sink);
          state.loops.pop_back();
          if (!ok) return false;
        }
        i = close;
        break;
      }
      case ScriptCommand::loop_get_index: {
        const uint32_t index = state.loops.empty() ? 0 : state.loops.back();
        const Type* type = params_->type(param);
        if (type && type->base == BaseType::float32) params_->set(param, float(index));
        else params_->set(param, int32_t(index));
        break;
      }
      case ScriptCommand::loop_end: break;  // reached only past an unbalanced script's end
    }
  }
  return true;
}

bool ScriptRunner::draw_pass(const ScriptStep& step, State& state, DiagnosticSink& sink) {
  const uint32_t outer = state.pass;
  const uint32_t pass = step.pass;
  state.pass = pass;
  const PassInfo& info = model_->techniques[technique_].passes[pass];
  const bool ok = info.script ? run(info.script->steps, 0, info.script->steps.size(), state, sink)
                              : draw(step, ScriptDraw::geometry, pass, state, sink);
  state.pass = outer;
  return ok;
}

bool ScriptRunner::draw(const ScriptStep& step, ScriptDraw what, uint32_t pass, State& state, DiagnosticSink& sink) {
  const VkRect2D area = state.area();
  const float x = float(area.offset.x), y = float(area.offset.y);
  const float w = float(area.extent.width), h = float(area.extent.height);
  const bool flipped = state.frame->viewport.height < 0;
  const VkViewport viewport{x, flipped ? y + h : y, w, flipped ? -h : h, 0.0f, 1.0f};
  const std::vector<RenderTarget*> more = state.more_targets(step, sink);
  state.begin(ClearValues{std::nullopt, std::nullopt, 0}, more);
  bool ok = binding_->begin(state.cmd, technique_, state.formats(more), viewport, area, sink);
  if (ok) {
    ok = binding_->apply(pass, state.frame->vertex_layout, sink);
    const auto& drawing = what == ScriptDraw::buffer ? state.frame->draw_quad : state.frame->draw_geometry;
    if (ok && drawing) drawing(state.cmd);
    binding_->end();
  }
  state.end(more);
  return ok;
}

}  // namespace fx::vk
