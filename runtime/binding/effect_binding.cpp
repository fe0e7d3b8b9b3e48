// EffectBinding: effect passes -> programs, pipeline states, descriptors and uniforms.
#include "fx/binding/effect_binding.h"

#include "fx/binding/storage_picture.h"

#include "fx/compile/uniform_layout.h"
#include "pass_images.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>

namespace fx::vk {

std::atomic<int64_t> EffectBinding::live_objects_{0};

// A uniform block of a pass, packed by the parameter store (block id `id`) straight into
// the frame's uniform ring: rewritten when a parameter in it changed or the ring slice
// holding its last copy was recycled.
struct BlockSlot {
  uint32_t id = 0;
  BlockHandle handle;  // of `id`, for the per-draw update without an id lookup
  uint32_t size = 0;
  uint64_t frame = UINT64_MAX;  // FrameResources::frame() of the last write (none yet)
};

struct EffectBinding::Pass {
  // What apply() reads, once per object, first.
  std::vector<BlockSlot> blocks;             // in the program's uniform_blocks() order
  std::vector<uint32_t> ring_offsets;        // of each block's last write, parallel to `blocks`
  std::unique_ptr<PassResources> resources;  // of `shader`: released before it (~Pass)
  const PassProgram* program = nullptr;
  ProgramLayout layout;  // the linked layout with same-named blocks told apart
  ShaderProgram shader;
  PipelineState state;
  std::vector<ImageSlot> images;
  std::vector<std::optional<VertexInput>> inputs;  // per vertex layout id
  SourceRange vertex_shader;                       // the state naming the vertex shader (where input errors point)
  // Pipelines per vertex layout id for `pipeline_formats`: pipelines live as long as the
  // binding, so apply() looks the key up once per layout and format change, not per call.
  RenderingFormats pipeline_formats;
  std::vector<VkPipeline> pipelines;
  // A stream-output pass: its buffers, and the vertex layout id (add_vertex_layout) of the
  // vertices they hold, registered at the first draw_stream_output().
  std::optional<StreamCapture> capture;
  uint32_t capture_layout = kNoIndex;
  // A pass that sets a compute shader beside graphics shaders (FX11's Apply binds both; a
  // draw runs the graphics stages, a dispatch the compute shader): its compute half, with
  // the same program layout and a ShaderProgram of the compute stage alone.
  std::unique_ptr<Pass> compute;

  // This pass, or its compute half when it has one: what dispatch() runs (null: neither).
  Pass* dispatched() {
    if (compute) return compute.get();
    return shader.compute_pipeline() ? this : nullptr;
  }

  ~Pass() { resources.reset(); }  // declared first for apply(), it must not outlive the program
};

struct EffectBinding::Technique {
  std::vector<std::unique_ptr<Pass>> passes;
  std::string reason;
};

namespace {

const EffectPass* find_pass(const EffectUnits& units, uint32_t technique, uint32_t pass) {
  for (const EffectPass& p : units.passes())
    if (p.technique_index == technique && p.pass_index == pass) return &p;
  return nullptr;
}

// Block and image names must be unique for PassResources (it finds blocks by name), but an
// HLSL vertex and pixel stage each have a "$Global" block of their own. Later duplicates
// get "@binding" appended.
void make_names_unique(ProgramLayout& layout) {
  std::map<std::string, int> seen;
  for (ProgramBinding& b : layout.bindings)
    if (seen[b.name]++ > 0) b.name.append("@").append(std::to_string(b.binding));
}

// The bindings of `layout` that a stage of `stage_mask` uses: a pass's graphics stages and
// its compute shader each get a descriptor layout of their own resources.
ProgramLayout used_by(const ProgramLayout& layout, uint32_t stage_mask) {
  ProgramLayout out;
  for (const ProgramBinding& b : layout.bindings)
    if (b.stage_mask & stage_mask) out.bindings.push_back(b);
  return out;
}

constexpr uint32_t kComputeStage = 1u << uint32_t(ShaderStage::compute);

// `int StreamOutVertices = N;` on a stream-output pass: the vertices each buffer holds.
uint32_t stream_out_vertices(const PassInfo& pass) {
  for (const Annotation& a : pass.annotations)
    if (a.name == "StreamOutVertices" && a.value.is_numeric() && a.value.number() >= 1)
      return uint32_t(std::min(a.value.number(), double(1u << 24)));
  return StreamCapture::kDefaultVertices;
}

}  // namespace

EffectBinding::EffectBinding(const Context& ctx, ParameterStore& params, EffectTextureCache& textures)
    : params_(&params),
      textures_(&textures),
      samplers_(ctx),
      descriptor_sets_(ctx),
      storage_(ctx),
      fills_(ctx, params) {}

EffectBinding::~EffectBinding() {
  recorder_.reset();    // declared first for apply(), it must not outlive what it references
  techniques_.clear();  // programs before the pipeline cache: nothing else depends on order
  live_objects_ -= counted_objects_;
}

// create()'s steps: each technique's passes made drawable, or the reason the technique
// cannot run.
struct EffectBinding::Builder {
  EffectBinding& b;
  const Context& ctx;
  EffectPrograms& programs;
  ParameterStore& params;
  const EffectBindingDesc& desc;
  DiagnosticSink& sink;
  ImageSources images;
  ImageNotes notes;

  // Null when nothing can be set up (a sampler could not be created).
  std::unique_ptr<Technique> technique(uint32_t t);
  // Null with `reason` set when the technique cannot run, with it empty when nothing can
  // be set up.
  std::unique_ptr<Pass> pass(uint32_t t, uint32_t p, std::string& reason);
  // The pass's pipeline state and ShaderProgram; false with `reason` set when they cannot be made.
  bool program(Pass& pass, const PassInfo& info, std::string& reason);
  // The pass's uniform blocks laid out in the store, each under a block id of its own.
  void uniform_blocks(Pass& pass, const PassInfo& info);
  // The compute half of a pass that also draws: `pass.compute` made from `stage`.
  bool compute_half(Pass& pass, const PassInfo& info, const CompiledShader& stage, std::string& reason);
};

// Whether `holds` holds for some pass of some technique or the compute half of one, tried
// in order up to the first that does.
template <class Techniques, class Predicate>
bool any_pass(Techniques& techniques, Predicate holds) {
  for (auto& tech : techniques)
    for (auto& pass : tech->passes)
      if (holds(*pass) || (pass->compute && holds(*pass->compute))) return true;
  return false;
}

// Visits every pass of every technique and the compute half of one that has it.
template <class Techniques, class Visit>
void for_each_pass(Techniques& techniques, Visit visit) {
  any_pass(techniques, [&](auto& pass) {
    visit(pass);
    return false;
  });
}

namespace {

// Why the pass cannot be drawn as compiled ("" when it can): no units, shaders that did not
// compile, states the pass cannot run with.
std::string pass_blocker(const PassInfo& info, const EffectPass* unit, const PassProgram* program) {
  if (!unit) return "pass '" + info.name + "' has no shader units";
  if (!program->ok())
    return "pass '" + info.name + "': " +
           (program->unsupported.empty() ? std::string("its shaders did not compile") : program->unsupported.front());
  // Fixed-function states are generated stages' input (fx/emulation/fixed_function.h) or,
  // beside shaders, ignored as D3D9 ignores them: only other states stop the pass.
  auto blocking = std::find_if(info.unsupported.begin(), info.unsupported.end(), [](const UnsupportedState& u) {
    return !u.info || u.info->lands != StateLanding::fixed_function;
  });
  if (blocking != info.unsupported.end()) return "pass '" + info.name + "': " + blocking->reason;
  const StageUnit* pixel = unit->find(ShaderStage::fragment);
  const bool generated_pixel = pixel && pixel->kind == StageSourceKind::fixed_function;  // emulates alpha test
  // Emulation needs a discard spliced into the pixel shader's translation unit.
  if (!generated_pixel && info.summary.alpha_test && info.summary.alpha_compare != CompareOp::always)
    return "pass '" + info.name + "': alpha test (AlphaTestEnable) is not emulated yet";
  return {};
}

// The first diagnostic's message, or `fallback` when there is none.
std::string first_message(const DiagnosticSink& sink, const char* fallback) {
  return sink.diagnostics().empty() ? std::string(fallback) : sink.diagnostics().front().message;
}

}  // namespace

std::unique_ptr<EffectBinding> EffectBinding::create(const Context& ctx, const EffectModel& model,
                                                     EffectPrograms& programs, ParameterStore& params,
                                                     EffectTextureCache& textures, FrameResources& frames,
                                                     const EffectBindingDesc& desc, DiagnosticSink& sink) {
  std::unique_ptr<EffectBinding> b(new EffectBinding(ctx, params, textures));
  b->model_ = &model;
  b->storage_extent_ = desc.storage_image_extent;
  b->pipelines_ = PipelineCache::create(ctx, sink);
  if (!b->pipelines_) return nullptr;
  b->frames_ = &frames;
  b->recorder_.emplace(ctx, *b->pipelines_, frames,
                       desc.dynamic.value_or(DynamicStateSet::from_features(ctx.features())));
  Builder build{*b, ctx, programs, params, desc, sink, {model, b->samplers_, textures, desc, b->fills_, programs}, {}};
  for (uint32_t t = 0; t < model.techniques.size(); ++t) {
    std::unique_ptr<Technique> tech = build.technique(t);
    if (!tech) return nullptr;
    b->techniques_.push_back(std::move(tech));
  }
  b->find_written_buffers();
  b->update_object_count();
  return b;
}

std::unique_ptr<EffectBinding::Technique> EffectBinding::Builder::technique(uint32_t t) {
  auto tech = std::make_unique<Technique>();
  for (uint32_t p = 0; p < images.model.techniques[t].passes.size(); ++p) {
    std::unique_ptr<Pass> made = pass(t, p, tech->reason);
    if (!made && tech->reason.empty()) return nullptr;
    if (!made) {
      tech->passes.clear();
      break;
    }
    tech->passes.push_back(std::move(made));
  }
  return tech;
}

std::unique_ptr<EffectBinding::Pass> EffectBinding::Builder::pass(uint32_t t, uint32_t p, std::string& reason) {
  const PassInfo& info = images.model.techniques[t].passes[p];
  const EffectPass* unit = find_pass(programs.units(), t, p);
  const PassProgram* compiled = unit ? &programs.program(*unit) : nullptr;
  reason = pass_blocker(info, unit, compiled);
  if (!reason.empty()) return nullptr;
  auto out = std::make_unique<Pass>();
  out->program = compiled;
  if (const StageUnit* vs = unit->find(ShaderStage::vertex)) out->vertex_shader = vs->range;
  if (!program(*out, info, reason)) return nullptr;
  out->resources = std::make_unique<PassResources>(out->shader);
  out->resources->keep_sets_in(b.descriptor_sets_);
  uniform_blocks(*out, info);
  // Images and samplers: sampler states -> cached samplers, textures resolved (baked,
  // decoded) now, uploaded at the first begin().
  if (!resolve_pass_images(images, info, out->shader, notes, out->images, reason, sink)) return nullptr;
  if (Pass* half = out->compute.get()) {
    half->resources = std::make_unique<PassResources>(half->shader);
    half->resources->keep_sets_in(b.descriptor_sets_);
    uniform_blocks(*half, info);
    if (!resolve_pass_images(images, info, half->shader, notes, half->images, reason, sink)) return nullptr;
  }
  return out;
}

bool EffectBinding::Builder::program(Pass& pass, const PassInfo& info, std::string& reason) {
  DiagnosticSink pass_sink;
  auto state = to_pipeline_state(info.summary, desc.target, ctx.features(), pass_sink);
  if (!state) {
    reason = "pass '" + info.name + "': " + first_message(pass_sink, "state");
    return false;
  }
  if (const auto& so = pass.program->stream_output) {
    if (!so->unsupported.empty()) {
      reason = "pass '" + info.name + "': " + so->unsupported;
      return false;
    }
    if (!ctx.features().transform_feedback) {
      reason = "pass '" + info.name +
               "': stream output (ConstructGSWithSO) needs VK_EXT_transform_feedback with transform feedback "
               "draws, not enabled on " +
               ctx.info().name;
      return false;
    }
    pass.capture = StreamCapture::create(ctx, *so, stream_out_vertices(info), pass_sink);
    if (!pass.capture) {
      reason = "pass '" + info.name + "': " + pass_sink.diagnostics().back().message;
      return false;
    }
    // Captured with nothing rasterized: fxkit's capture rendering has no attachments.
    state->rasterizer_discard = 1;
  }
  pass.layout = pass.program->layout;
  make_names_unique(pass.layout);
  std::vector<const CompiledShader*> stages;
  const CompiledShader* compute = nullptr;
  for (const StageProgram& s : pass.program->stages)
    (s.shader.reflection.stage == ShaderStage::compute ? compute : stages.emplace_back()) = &s.shader;
  if (compute && stages.empty()) stages.push_back(compute);
  else if (compute) {
    if (!compute_half(pass, info, *compute, reason)) return false;
    pass.layout = used_by(pass.layout, ~kComputeStage);
  }
  auto shader = ShaderProgram::create(ctx, stages, pass.layout, desc.descriptors, pass_sink);
  if (!shader) {
    reason = "pass '" + info.name + "': " + first_message(pass_sink, "program");
    return false;
  }
  pass.shader = std::move(*shader);
  // A tessellating pass draws patches of the hull shader's input size.
  const uint32_t points = pass.shader.patch_control_points();
  if (points && desc.patch_control_points && points != desc.patch_control_points) {
    reason = "pass '" + info.name + "': its hull shader takes patches of " + std::to_string(points) +
             " control points; the geometry comes in patches of " + std::to_string(desc.patch_control_points) +
             (desc.patch_control_points == 3 ? " (triangle lists)" : "");
    return false;
  }
  pass.state = with_patches(*state, points);
  return true;
}

bool EffectBinding::Builder::compute_half(Pass& pass, const PassInfo& info, const CompiledShader& stage,
                                          std::string& reason) {
  auto half = std::make_unique<Pass>();
  half->program = pass.program;
  half->layout = used_by(pass.layout, kComputeStage);
  DiagnosticSink made;
  auto shader = ShaderProgram::create(ctx, {&stage}, half->layout, desc.descriptors, made);
  if (!shader) {
    reason = "pass '" + info.name + "', its compute shader: " + first_message(made, "program");
    return false;
  }
  half->shader = std::move(*shader);
  pass.compute = std::move(half);
  return true;
}

void EffectBinding::Builder::uniform_blocks(Pass& pass, const PassInfo& info) {
  const std::vector<UniformBlockLayout> layouts = uniform_layouts(images.model, *pass.program);
  for (const ProgramUniformBlock& block : pass.shader.uniform_blocks()) {
    BlockSlot slot{unique_uniform_block_id(), {}, block.size, 0};
    auto layout = std::find_if(layouts.begin(), layouts.end(),
                               [&](const UniformBlockLayout& l) { return l.binding == block.binding; });
    if (layout != layouts.end()) {
      ParamStatus status = params.bind_layout(slot.id, layout->members, block.size);
      std::string problem = status.message;
      if (problem.empty() && !layout->unplaced.empty()) {
        problem = "no parameter (or a struct without member paths) for: ";
        for (size_t k = 0; k < layout->unplaced.size(); ++k) problem.append(k ? ", " : "").append(layout->unplaced[k]);
      }
      if (!problem.empty())
        sink.warning("vk-uniform-unbound", info.range,
                     "pass '" + info.name + "', block '" + block.name + "': " + problem);
    }
    slot.handle = params.block(slot.id);
    pass.blocks.push_back(slot);
  }
  pass.ring_offsets.resize(pass.blocks.size(), 0);
}

bool EffectBinding::technique_ok(uint32_t t) const {
  return t < techniques_.size() && techniques_[t]->reason.empty() && !techniques_[t]->passes.empty();
}

const std::string& EffectBinding::technique_reason(uint32_t t) const {
  static const std::string no_such = "no such technique", no_passes = "the technique has no passes";
  if (t >= techniques_.size()) return no_such;
  if (techniques_[t]->reason.empty() && techniques_[t]->passes.empty()) return no_passes;
  return techniques_[t]->reason;
}

uint32_t EffectBinding::pass_count(uint32_t t) const {
  return t < techniques_.size() ? uint32_t(techniques_[t]->passes.size()) : 0;
}

uint32_t EffectBinding::first_ok_technique() const {
  for (uint32_t t = 0; t < techniques_.size(); ++t)
    if (technique_ok(t)) return t;
  return kNoIndex;
}

uint32_t EffectBinding::add_vertex_layout(VertexLayout layout) {
  layouts_.push_back(std::move(layout));
  return uint32_t(layouts_.size() - 1);
}

bool EffectBinding::set_texture(std::string_view texture, VkImageView view, VkImageLayout layout, ImageKind kind,
                                DiagnosticSink& sink) {
  uint32_t p = model_->find_parameter(texture);
  if (p == kNoIndex || !model_->texture_of(p)) {
    sink.error("vk-resource-unknown", {}, "the effect has no texture parameter '" + std::string(texture) + "'");
    return false;
  }
  auto it = std::find_if(app_textures_.begin(), app_textures_.end(), [&](const auto& e) { return e.first == p; });
  if (it != app_textures_.end()) it->second = Texture::wrap(view, layout, kind);
  else app_textures_.emplace_back(p, Texture::wrap(view, layout, kind));
  textures_pending_ = true;
  return true;
}

namespace {

// Whether some pass of `techniques` lists a resource named `name` in `(pass.shader.*list)()`
// (with `kind` among them, when given); "vk-resource-unknown" when none does.
template <class Techniques, class List>
bool some_pass_uses(Techniques& techniques, List list, std::string_view name, std::string_view what,
                    DiagnosticSink& sink, std::optional<DescriptorKind> kind = std::nullopt) {
  const bool used = any_pass(techniques, [&](const auto& pass) {
    return std::ranges::any_of((pass.shader.*list)(), [&](const auto& r) {
      if constexpr (requires { r.kind; })
        if (kind && r.kind != *kind) return false;
      return r.name == name;
    });
  });
  if (!used)
    sink.error("vk-resource-unknown", {},
               "no pass of the effect uses a " + std::string(what) + " '" + std::string(name) + "'");
  return used;
}

}  // namespace

bool EffectBinding::set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range,
                               DiagnosticSink& sink) {
  if (!some_pass_uses(techniques_, &ShaderProgram::storage_buffers, name, "storage buffer", sink)) return false;
  storage_.set_buffer(name, buffer, offset, range);
  textures_pending_ = true;
  return true;
}

bool EffectBinding::set_storage_image(std::string_view name, VkImageView view, DiagnosticSink& sink) {
  if (!some_pass_uses(techniques_, &ShaderProgram::images, name, "storage image", sink, DescriptorKind::storage_image))
    return false;
  storage_.set_image(name, view);
  textures_pending_ = true;
  return true;
}

bool EffectBinding::set_texel_buffer(std::string_view name, VkBufferView view, DiagnosticSink& sink) {
  if (!some_pass_uses(techniques_, &ShaderProgram::texel_buffers, name, "texel buffer", sink)) return false;
  storage_.set_texel_view(name, view);
  textures_pending_ = true;
  return true;
}

void EffectBinding::find_written_buffers() {
  for_each_pass(techniques_, [&](const Pass& pass) {
    for (const ProgramStorageBuffer& b : pass.shader.storage_buffers())
      if (b.written) written_.push_back(b.name);
    for (const ProgramTexelBuffer& t : pass.shader.texel_buffers())
      if (t.kind == DescriptorKind::storage_texel_buffer) written_.push_back(t.name);
  });
  std::sort(written_.begin(), written_.end());
  written_.erase(std::unique(written_.begin(), written_.end()), written_.end());
}

bool EffectBinding::written_by_a_pass(std::string_view name) const {
  return std::binary_search(written_.begin(), written_.end(), name, std::less<>());
}

bool EffectBinding::bind_textures(DiagnosticSink& sink) {
  // Previews fill the buffers no pass writes with a pattern, so what reads them varies.
  const bool preview = textures_->preview_stand_ins();
  if (any_pass(techniques_, [&](Pass& pass) { return !bind_pass_resources(pass, preview, sink); })) return false;
  textures_pending_ = false;
  return true;
}

bool EffectBinding::bind_pass_resources(Pass& pass, bool preview, DiagnosticSink& sink) {
  pass.resources->rewrite_sets();  // set_texture's view may have another's handle
  for (const ProgramStorageBuffer& b : pass.shader.storage_buffers()) {
    const StandInFill fill{preview && !written_by_a_pass(b.name), b.element};
    std::optional<VkDescriptorBufferInfo> info = storage_.buffer(b.name, sink, fill);
    if (!info || !pass.resources->bind_buffer(b.name, info->buffer, info->offset, info->range, sink)) return false;
  }
  for (const ProgramTexelBuffer& t : pass.shader.texel_buffers()) {
    const uint32_t param = model_->find_parameter(t.name);
    const std::string_view element = param != kNoIndex ? std::string_view(model_->parameters[param].type.element) : "";
    const VkFormat format = t.kind == DescriptorKind::uniform_texel_buffer ? sampled_texel_buffer_format(element)
                                                                           : storage_image_format(element);
    const StandInFill fill{preview && !written_by_a_pass(t.name), storage_format_scalar(format)};
    const VkBufferView view = storage_.texel_view(t.name, format, sink, fill);
    if (!view || !pass.resources->bind_texel_buffer(t.name, view, sink)) return false;
  }
  for (ImageSlot& slot : pass.images) {
    if (slot.kind == DescriptorKind::storage_image) {
      const VkImageView view =
          storage_.image(slot.name, slot.storage_format, slot.storage_shape, storage_extent_, sink);
      const ImageKind kind = slot.storage_shape ? slot.storage_shape->kind : ImageKind::image2d;
      if (!view ||
          !pass.resources->bind(slot.name, Texture::wrap(view, VK_IMAGE_LAYOUT_GENERAL, kind), VK_NULL_HANDLE, sink))
        return false;
      continue;
    }
    if (slot.kind == DescriptorKind::sampler) {
      if (!pass.resources->bind_sampler(slot.name, slot.sampler, sink)) return false;
      continue;
    }
    const Texture* texture = nullptr;
    for (const auto& [param, app] : app_textures_)
      if (param == slot.texture_param) texture = &app;
    if (!texture && slot.fill != kNoIndex) texture = fills_.texture(slot.fill, sink);
    if (!texture) texture = textures_->gpu(*slot.data, sink);
    if (!texture || !pass.resources->bind(slot.name, *texture, slot.sampler, sink)) return false;
  }
  return true;
}

const VertexInput* EffectBinding::vertex_input(Pass& pass, uint32_t layout, DiagnosticSink& sink) {
  if (layout >= layouts_.size()) {
    sink.error("vk-vertex-layout-unknown", {}, "vertex layout id " + std::to_string(layout) + " was not registered");
    return nullptr;
  }
  if (pass.inputs.size() <= layout) pass.inputs.resize(layouts_.size());
  if (!pass.inputs[layout]) {
    // Located at the pass's VertexShader state, so the error reads as a line of the effect.
    DiagnosticSink matched;
    pass.inputs[layout] = match_vertex_layout(layouts_[layout], pass.shader.vertex_inputs(), matched);
    for (const Diagnostic& d : matched.diagnostics())
      sink.report(d.severity, d.id, d.range.begin.valid() ? d.range : pass.vertex_shader, d.message);
  }
  return pass.inputs[layout] ? &*pass.inputs[layout] : nullptr;
}

bool EffectBinding::warm(uint32_t technique, const RenderingFormats& formats, uint32_t vertex_layout,
                         DiagnosticSink& sink) {
  if (!technique_ok(technique)) {
    sink.error("vk-technique-invalid", {}, technique_reason(technique));
    return false;
  }
  bool ok = true;
  for (uint32_t p = 0; p < pass_count(technique); ++p) {
    // Made with its program, captured, or drawing captured vertices (the layout is the capture's).
    const auto& pass = techniques_[technique]->passes[p];
    if (pass->shader.compute_pipeline() || pass->capture || stream_output_source(technique, p) != kNoIndex) continue;
    const VertexInput* input = vertex_input(*pass, vertex_layout, sink);
    ok = input && pipelines_->get(pass->shader, pass->state, *input, formats, recorder_->dynamic(), sink) && ok;
  }
  update_object_count();
  return ok;
}

bool EffectBinding::begin(VkCommandBuffer cmd, uint32_t technique, const RenderingFormats& formats,
                          const VkViewport& viewport, const VkRect2D& scissor, DiagnosticSink& sink) {
  active_ = nullptr;
  if (!technique_ok(technique)) {
    sink.error("vk-technique-invalid", {}, technique_reason(technique));
    return false;
  }
  if (textures_pending_ && !bind_textures(sink)) return false;
  active_ = techniques_[technique].get();
  applied_ = nullptr;
  formats_ = formats;
  recorder_->begin(cmd, formats, viewport, scissor);
  return true;
}

[[gnu::always_inline]] inline bool EffectBinding::write_blocks(Pass& pass, bool& moved, DiagnosticSink& sink) {
  // Locals: the stores below (the ring, the blocks) may alias members as far as the
  // compiler knows, and this runs once per object.
  ParameterStore& params = *params_;
  PassRecorder& recorder = *recorder_;
  const uint64_t frame = frames_->frame();
  uint32_t* ring_offset = pass.ring_offsets.data();  // parallel to pass.blocks
  for (BlockSlot& block : pass.blocks) {
    bool changed;
    const std::span<const uint8_t> bytes = params.update_block(block.handle, changed);
    // Written in this frame's ring slice already (begin_frame() recycles the slice).
    if (!changed && block.frame == frame) {
      ++ring_offset;
      continue;
    }
    // Captured by value: nothing of this loop has to live in memory across the copy.
    const uint32_t size = block.size;
    std::optional<uint32_t> offset = recorder.write_uniform(
        size,
        [from = bytes.data(), held = bytes.size(), size](uint8_t* ring) {
          // A block bind_layout refused has no bytes: the shader reads zeros.
          if (held == size) [[likely]]
            std::memcpy(ring, from, size);
          else std::memset(ring, 0, size);
        },
        sink);
    if (!offset) [[unlikely]]
      return false;
    *ring_offset++ = *offset;
    block.frame = frame;
    moved = true;
  }
  return true;
}

[[gnu::always_inline]] inline bool EffectBinding::apply_inline(uint32_t pass_index, uint32_t vertex_layout,
                                                               DiagnosticSink& sink) {
  if (!active_ || pass_index >= active_->passes.size()) [[unlikely]]
    return unknown_pass(pass_index, sink);
  Pass& pass = *active_->passes[pass_index];
  bool moved = false;  // a block was written to a new ring offset
  if (!write_blocks(pass, moved, sink)) [[unlikely]]
    return false;
  // The same pass again (the next object of a group): only the uniform offsets can differ.
  // The recorder's last apply() was this pass's (apply_pass sets applied_ only then) and
  // its images are bound only in begin(), which clears applied_: reapply()'s own checks
  // would repeat these.
  if (&pass == applied_ && vertex_layout == applied_layout_ && recorder_->rebind(pass.ring_offsets, moved)) [[likely]]
    return true;
  return apply_pass(pass, vertex_layout, sink);
}

bool EffectBinding::apply(uint32_t pass_index, uint32_t vertex_layout, DiagnosticSink& sink) {
  return apply_inline(pass_index, vertex_layout, sink);
}

bool EffectBinding::apply_layout0(void* binding, uint32_t pass_index, void* sink) {
  return static_cast<EffectBinding*>(binding)->apply_inline(pass_index, 0, *static_cast<DiagnosticSink*>(sink));
}

bool EffectBinding::unknown_pass(uint32_t pass_index, DiagnosticSink& sink) {
  sink.error("vk-pass-unknown", {},
             "apply() of pass " + std::to_string(pass_index) + " outside begin()/end() or past the last pass");
  return false;
}

bool EffectBinding::apply_pass(Pass& pass, uint32_t vertex_layout, DiagnosticSink& sink) {
  applied_ = nullptr;
  if (pass.shader.compute_pipeline()) {
    sink.error("vk-pass-compute", {}, "a compute pass is dispatched (dispatch()), outside begin()/end(), not applied");
    return false;
  }
  if (pass.capture) {
    sink.error("vk-pass-stream-output", {},
               "a stream-output pass is captured (begin_capture()), outside begin()/end(), not applied");
    return false;
  }
  const VertexInput* input = vertex_input(pass, vertex_layout, sink);
  if (!input) return false;
  if (!(pass.pipeline_formats == formats_)) {
    pass.pipeline_formats = formats_;
    std::fill(pass.pipelines.begin(), pass.pipelines.end(), VK_NULL_HANDLE);
  }
  if (pass.pipelines.size() <= vertex_layout) pass.pipelines.resize(layouts_.size(), VK_NULL_HANDLE);
  VkPipeline& pipeline = pass.pipelines[vertex_layout];
  if (!pipeline) {
    pipeline = pipelines_->get(pass.shader, pass.state, *input, formats_, recorder_->dynamic(), sink);
    if (!pipeline) return false;
    update_object_count();
  }
  PassDesc desc{&pass.shader, pass.state, input, pass.resources.get(), pipeline, pass.ring_offsets};
  const size_t pools = descriptor_sets_.pool_count();
  if (!recorder_->apply(desc, sink)) return false;
  if (descriptor_sets_.pool_count() != pools) update_object_count();  // the apply kept its first set
  applied_ = &pass;
  applied_layout_ = vertex_layout;
  return true;
}

bool EffectBinding::pass_objects(uint32_t technique, uint32_t pass_index, const RenderingFormats& formats,
                                 uint32_t vertex_layout, VkPipeline& pipeline, const ShaderProgram*& program,
                                 DiagnosticSink& sink) {
  if (!technique_ok(technique) || pass_index >= techniques_[technique]->passes.size()) {
    sink.error("vk-pass-unknown", {},
               "no drawable pass " + std::to_string(pass_index) + " in technique " + std::to_string(technique));
    return false;
  }
  Pass& pass = *techniques_[technique]->passes[pass_index];
  const VertexInput* input = vertex_input(pass, vertex_layout, sink);
  if (!input) return false;
  pipeline = pipelines_->get(pass.shader, pass.state, *input, formats, recorder_->dynamic(), sink);
  program = &pass.shader;
  update_object_count();
  return pipeline != VK_NULL_HANDLE;
}

bool EffectBinding::no_pass_that_runs(uint32_t technique, uint32_t pass, std::string_view kind,
                                      DiagnosticSink& sink) const {
  sink.error("vk-pass-unknown", {},
             "pass " + std::to_string(pass) + " of technique " + std::to_string(technique) + " is no " +
                 std::string(kind) + " pass that can run" +
                 (technique_ok(technique) ? "" : " (" + technique_reason(technique) + ")"));
  return false;
}

bool EffectBinding::compute_pass(uint32_t technique, uint32_t pass) const {
  return technique_ok(technique) && pass < techniques_[technique]->passes.size() &&
         techniques_[technique]->passes[pass]->dispatched();
}

bool EffectBinding::draw_pass(uint32_t technique, uint32_t pass) const {
  return technique_ok(technique) && pass < techniques_[technique]->passes.size() &&
         !techniques_[technique]->passes[pass]->shader.compute_pipeline();
}

std::array<uint32_t, 3> EffectBinding::dispatch_groups(uint32_t technique, uint32_t pass, uint32_t width,
                                                       uint32_t height) const {
  std::array<uint32_t, 3> groups{1, 1, 1};
  if (!compute_pass(technique, pass)) return groups;
  for (const Annotation& a : model_->techniques[technique].passes[pass].annotations)
    if (a.name == "Dispatch" && a.value.is_numeric()) {
      for (size_t d = 0; d < 3 && d < a.value.components.size(); ++d)
        groups[d] = uint32_t(std::clamp(a.value.components[d], 1.0, 65535.0));
      return groups;
    }
  const uint32_t* local = techniques_[technique]->passes[pass]->dispatched()->shader.local_size();
  groups[0] = (std::max(width, 1u) + local[0] - 1) / local[0];
  groups[1] = (std::max(height, 1u) + local[1] - 1) / local[1];
  return groups;
}

bool EffectBinding::dispatch(VkCommandBuffer cmd, uint32_t technique, uint32_t pass_index,
                             const std::array<uint32_t, 3>& groups, DiagnosticSink& sink) {
  if (active_) {
    sink.error("vk-pass-compute", {}, "dispatch() between begin() and end(): compute runs outside rendering");
    return false;
  }
  if (!compute_pass(technique, pass_index)) return no_pass_that_runs(technique, pass_index, "compute", sink);
  if (textures_pending_ && !bind_textures(sink)) return false;
  Pass& pass = *techniques_[technique]->passes[pass_index]->dispatched();
  bool moved = false;
  if (!write_blocks(pass, moved, sink)) return false;
  PassDesc desc{&pass.shader, pass.state, nullptr, pass.resources.get(), VK_NULL_HANDLE, pass.ring_offsets};
  const size_t pools = descriptor_sets_.pool_count();
  const bool ok = recorder_->dispatch(cmd, desc, groups.data(), sink);
  if (descriptor_sets_.pool_count() != pools) update_object_count();
  return ok;
}

bool EffectBinding::dispatch_compute_passes(VkCommandBuffer cmd, uint32_t technique, uint32_t width, uint32_t height,
                                            DiagnosticSink& sink) {
  for (uint32_t p = 0; p < pass_count(technique); ++p)
    if (compute_pass(technique, p) && !dispatch(cmd, technique, p, dispatch_groups(technique, p, width, height), sink))
      return false;
  return true;
}

bool EffectBinding::computes_only(uint32_t technique) const {
  if (!technique_ok(technique) || pass_count(technique) == 0) return false;
  for (uint32_t p = 0; p < pass_count(technique); ++p)
    if (draw_pass(technique, p)) return false;
  return true;
}

std::optional<EffectBinding::ComputeOutput> EffectBinding::compute_output(uint32_t technique, DiagnosticSink& sink) {
  if (!technique_ok(technique)) return std::nullopt;
  constexpr uint32_t kWordsPerRow = 64;
  for (const auto& drawn : techniques_[technique]->passes) {
    const Pass* pass = drawn->dispatched();
    if (!pass) continue;
    for (const ImageSlot& slot : pass->images)
      if (slot.kind == DescriptorKind::storage_image)
        if (std::optional<StorageTexels> texels = storage_.read_image(slot.name, sink))
          return ComputeOutput{slot.name, false, texel_picture(*texels)};
  }
  for (const auto& drawn : techniques_[technique]->passes) {
    const Pass* pass = drawn->dispatched();
    if (!pass) continue;
    for (const ProgramStorageBuffer& b : pass->shader.storage_buffers())
      if (b.written)
        if (std::optional<std::vector<uint32_t>> words = storage_.read_buffer(b.name))
          return ComputeOutput{b.name, true, buffer_picture(*words, b.element, kWordsPerRow)};
  }
  return std::nullopt;
}

bool EffectBinding::stream_output_pass(uint32_t technique, uint32_t pass) const {
  return technique_ok(technique) && pass < techniques_[technique]->passes.size() &&
         techniques_[technique]->passes[pass]->capture.has_value();
}

bool EffectBinding::begin_capture(VkCommandBuffer cmd, uint32_t technique, uint32_t pass_index, uint32_t vertex_layout,
                                  DiagnosticSink& sink) {
  if (active_ || capturing_) {
    sink.error("vk-pass-stream-output", {},
               "begin_capture() between begin() and end() or during another capture: it runs outside rendering");
    return false;
  }
  if (!stream_output_pass(technique, pass_index))
    return no_pass_that_runs(technique, pass_index, "stream-output", sink);
  if (textures_pending_ && !bind_textures(sink)) return false;
  Pass& pass = *techniques_[technique]->passes[pass_index];
  const VertexInput* input = vertex_input(pass, vertex_layout, sink);
  bool moved = false;
  if (!input || !write_blocks(pass, moved, sink)) return false;
  const RenderingFormats none;  // the capture's rendering has no attachments
  const VkPipeline pipeline = pipelines_->get(pass.shader, pass.state, *input, none, recorder_->dynamic(), sink);
  if (!pipeline) return false;
  update_object_count();
  pass.capture->begin_rendering(cmd);
  recorder_->begin(cmd, none, VkViewport{0, 0, 1, 1, 0, 1}, VkRect2D{{0, 0}, {1, 1}});
  PassDesc desc{&pass.shader, pass.state, input, pass.resources.get(), pipeline, pass.ring_offsets};
  if (!recorder_->apply(desc, sink)) {
    recorder_->end();
    vkCmdEndRendering(cmd);
    return false;
  }
  pass.capture->begin(cmd);
  capturing_ = &pass;
  capture_cmd_ = cmd;
  return true;
}

void EffectBinding::end_capture() {
  if (!capturing_) return;
  capturing_->capture->end(capture_cmd_);
  recorder_->end();
  capturing_ = nullptr;
}

bool EffectBinding::draw_stream_output(VkCommandBuffer cmd, uint32_t pass_index, uint32_t stream_output_pass_index,
                                       DiagnosticSink& sink) {
  if (!active_ || stream_output_pass_index >= active_->passes.size() ||
      !active_->passes[stream_output_pass_index]->capture) {
    sink.error("vk-pass-unknown", {},
               "draw_stream_output() outside begin()/end(), or pass " + std::to_string(stream_output_pass_index) +
                   " of the begun technique is no stream-output pass");
    return false;
  }
  Pass& source = *active_->passes[stream_output_pass_index];
  if (source.capture_layout == kNoIndex) source.capture_layout = add_vertex_layout(source.capture->vertex_layout());
  if (!apply(pass_index, source.capture_layout, sink)) return false;
  source.capture->draw(cmd);
  return true;
}

std::optional<StreamOutputBuffer> EffectBinding::stream_output_buffer(uint32_t technique, uint32_t pass,
                                                                      uint32_t slot) const {
  if (!stream_output_pass(technique, pass)) return std::nullopt;
  StreamOutputBuffer b = techniques_[technique]->passes[pass]->capture->buffer(slot);
  if (!b.buffer) return std::nullopt;
  return b;
}

bool EffectBinding::capture_stream_output_passes(VkCommandBuffer cmd, uint32_t technique, uint32_t vertex_layout,
                                                 const std::function<void(VkCommandBuffer)>& draw,
                                                 DiagnosticSink& sink) {
  for (uint32_t p = 0; p < pass_count(technique); ++p) {
    if (!stream_output_pass(technique, p)) continue;
    if (!begin_capture(cmd, technique, p, vertex_layout, sink)) return false;
    draw(cmd);
    end_capture();
  }
  return true;
}

uint32_t EffectBinding::stream_output_source(uint32_t technique, uint32_t pass) const {
  uint32_t source = kNoIndex;
  for (uint32_t p = 0; p < pass && p < pass_count(technique); ++p)
    if (stream_output_pass(technique, p)) source = p;
  return source;
}

void EffectBinding::end() {
  if (active_) recorder_->end();
  active_ = nullptr;
  applied_ = nullptr;
}

size_t EffectBinding::pipeline_count() const { return pipelines_->size(); }

void EffectBinding::update_object_count() {
  // + the VkPipelineCache and the descriptor pools of the kept sets
  int64_t owned = 1 + int64_t(pipelines_->size()) + int64_t(samplers_.size()) + int64_t(descriptor_sets_.pool_count());
  for_each_pass(techniques_, [&](const Pass& pass) {
    owned += int64_t(pass.shader.stage_infos().size()) + 2;  // modules, set and pipeline layout
  });
  live_objects_ += owned - counted_objects_;
  counted_objects_ = owned;
}

}  // namespace fx::vk
