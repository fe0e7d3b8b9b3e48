// fx::vk::EffectBinding: one effect (model + compiled programs + parameter values) made
// drawable in the application's command buffers. Per pass it holds the ShaderProgram, the
// pipeline state mapped from the pass's states, its descriptors (samplers from the sampler
// states, textures from generators, files or the app's image views) and uniform blocks fed
// from the ParameterStore (only blocks whose parameters changed are re-packed, straight
// into the frame's uniform ring). Usage (create, add_vertex_layout, then per frame
// begin_frame, begin, apply per pass around the app's draw, end): docs/rendering.md.
//
// Threading: create() and warm() may run on any thread (a reload worker) while other
// bindings render; begin/apply/end/set_texture belong to the render thread. Texture
// uploads happen in begin() because they use the context's queue.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/binding/effect_storage.h"
#include "fx/binding/effect_textures.h"
#include "fx/binding/pass_recorder.h"
#include "fx/binding/pass_state_mapping.h"
#include "fx/binding/stream_capture.h"
#include "fx/binding/texture_fills.h"
#include "fx/compile/effect_programs.h"
#include "fx/image.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"
#include "fx/vulkan/sampler_cache.h"

namespace fx::vk {

// How an effect is bound.
struct EffectBindingDesc {
  DescriptorMode descriptors = DescriptorMode::sets;
  // Pipeline path: DynamicStateSet::from_features(ctx.features()) or DynamicStateSet::none().
  std::optional<DynamicStateSet> dynamic;  // unset: from the context's features
  // Control points per patch of the geometry drawn with tessellating passes (hull + domain
  // shaders): a triangle list, as every fxkit mesh is, is a patch list of 3. A technique
  // whose hull shader takes another input patch size (InputPatch<T, N>) cannot run; 0
  // accepts any size (the application draws patches of each pass's hull shader size).
  uint32_t patch_control_points = 3;
  // Render target facts the pass states are mapped for (attachment count, samples, depth
  // bits, winding). See pass_state_mapping.h.
  PassTargetInfo target;
  // Folder that texture ResourceNames are relative to (the effect file's folder).
  std::filesystem::path effect_dir;
  // Folders looked in after effect_dir (the -I folders).
  std::vector<std::filesystem::path> texture_dirs;
  // Size of the stand-in storage images (RWTexture2D) nothing else is bound to: a preview
  // gives its target's.
  VkExtent2D storage_image_extent{256, 256};
};

class EffectBinding {
 public:
  // Builds every pass of every technique whose programs compiled. A technique that cannot
  // run (assembly or fixed-function stages, compile errors, unsupported states, a missing
  // device feature, alpha test) is kept with its reason. Null only when nothing at all could
  // be set up (diagnostics say why). Everything referenced must outlive the binding.
  static std::unique_ptr<EffectBinding> create(const Context& ctx, const EffectModel& model, EffectPrograms& programs,
                                               ParameterStore& params, EffectTextureCache& textures,
                                               FrameResources& frames, const EffectBindingDesc& desc,
                                               DiagnosticSink& sink);
  ~EffectBinding();
  EffectBinding(const EffectBinding&) = delete;
  EffectBinding& operator=(const EffectBinding&) = delete;

  // Techniques, indexed as EffectModel::techniques.
  uint32_t technique_count() const { return uint32_t(techniques_.size()); }
  bool technique_ok(uint32_t technique) const;
  // Why the technique cannot run ("" when it can).
  const std::string& technique_reason(uint32_t technique) const;
  uint32_t pass_count(uint32_t technique) const;
  // The first technique that can run, or kNoIndex.
  uint32_t first_ok_technique() const;

  // Registers a layout of the application's vertex buffers; apply() takes the returned id.
  // Shader inputs are matched to it per pass on first use ("vk-vertex-attribute-missing").
  uint32_t add_vertex_layout(VertexLayout layout);

  // Samples the application's image instead of the effect's own texture for the texture
  // parameter `texture` (render thread; takes effect at the next begin()). False and
  // "vk-resource-unknown" when the effect has no such texture parameter.
  bool set_texture(std::string_view texture, VkImageView view, VkImageLayout layout, ImageKind kind,
                   DiagnosticSink& sink);
  // The application's buffer range for the storage buffer `name` (a StructuredBuffer,
  // ByteAddressBuffer, Append/Consume buffer or its "name@count" counter, tbuffer) and its
  // view (VK_IMAGE_LAYOUT_GENERAL) for the storage image `name` (RWTexture*), instead of the
  // zeroed stand-ins (EffectStorage). From the next begin() or dispatch(); false and
  // "vk-resource-unknown" when no pass uses such a resource.
  bool set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range,
                  DiagnosticSink& sink);
  bool set_storage_image(std::string_view name, VkImageView view, DiagnosticSink& sink);
  // The application's buffer view for the texel buffer `name` (Buffer<T>, RWBuffer<T>),
  // instead of a view of a zeroed stand-in in the element's format.
  bool set_texel_buffer(std::string_view name, VkBufferView view, DiagnosticSink& sink);
  // Whether pass `pass` of `technique` runs a compute shader: dispatch() it.
  bool compute_pass(uint32_t technique, uint32_t pass) const;
  // Whether pass `pass` has graphics shaders: apply() draws with it (begin_capture() for a
  // stream-output pass). A pass that sets a compute shader beside them (FX11 binds both at
  // Apply, then the application draws or dispatches) is a compute pass and a draw pass.
  bool draw_pass(uint32_t technique, uint32_t pass) const;
  // The workgroup counts a preview dispatches compute pass `pass` with: the pass's
  // `Dispatch` annotation (`int3 Dispatch = {64, 1, 1};`, missing counts 1), else one thread
  // per pixel of a `width` x `height` target (ceil(width / numthreads.x), ceil(height /
  // numthreads.y), 1).
  std::array<uint32_t, 3> dispatch_groups(uint32_t technique, uint32_t pass, uint32_t width, uint32_t height) const;
  // Records compute pass `pass` of `technique` into `cmd`, outside rendering and outside
  // begin()/end(): uniforms, storage resources, `groups` workgroups, then the barrier that
  // makes its writes visible to every later draw and dispatch (PassRecorder::dispatch).
  bool dispatch(VkCommandBuffer cmd, uint32_t technique, uint32_t pass, const std::array<uint32_t, 3>& groups,
                DiagnosticSink& sink);
  // Records every compute pass of `technique`, in pass order, with dispatch_groups() for a
  // `width` x `height` target: what a preview (fxkit render, the viewer) does before it
  // draws the technique's other passes ("simulate, then draw"). True when it has none.
  bool dispatch_compute_passes(VkCommandBuffer cmd, uint32_t technique, uint32_t width, uint32_t height,
                               DiagnosticSink& sink);
  // Whether every pass of `technique` is a compute pass: it draws nothing.
  bool computes_only(uint32_t technique) const;
  // What a preview of such a technique shows: a picture (fx/binding/storage_picture.h) of
  // the first storage image its compute passes bind, else of the first storage buffer they
  // write, read back from the stand-in once the device has finished the passes. nullopt when
  // they write no stand-in (the application's resources, or nothing at all).
  struct ComputeOutput {
    std::string name;     // the storage image or buffer
    bool buffer = false;  // a buffer's words (else an image's texels)
    fx::Image picture;
  };
  std::optional<ComputeOutput> compute_output(uint32_t technique, DiagnosticSink& sink);
  // The storage buffers, images and texel buffers bound so far, and their stand-ins.
  const EffectStorage& storage() const { return storage_; }

  // Whether pass `pass` of `technique` captures its output stream (ConstructGSWithSO):
  // begin_capture() it, not apply().
  bool stream_output_pass(uint32_t technique, uint32_t pass) const;
  // Starts capturing stream-output pass `pass` of `technique` into its buffers (created with
  // the binding: `int StreamOutVertices` on the pass, else StreamCapture::kDefaultVertices
  // vertices each), outside the application's rendering and outside begin()/end(): records a
  // barrier after earlier reads of the buffers, a rendering of its own with no attachments,
  // the pass (rasterizer discard: nothing is drawn) for geometry of `vertex_layout`, and
  // begins transform feedback. The application then draws its geometry (the particles of
  // last frame, the seed points) into `cmd` and calls end_capture().
  bool begin_capture(VkCommandBuffer cmd, uint32_t technique, uint32_t pass, uint32_t vertex_layout,
                     DiagnosticSink& sink);
  // Ends the capture: the counters take the bytes captured, and a barrier makes the vertices
  // visible to the draws, shaders and copies recorded after it.
  void end_capture();
  // Between begin() and end(): applies pass `pass` of the begun technique for the vertices
  // stream-output pass `stream_output_pass` captured last, binds them (vertex buffer 0) and
  // draws them all, however many the capture wrote (Direct3D's DrawAuto).
  bool draw_stream_output(VkCommandBuffer cmd, uint32_t pass, uint32_t stream_output_pass, DiagnosticSink& sink);
  // Output buffer `slot` of stream-output pass `pass` and its counter, to bind elsewhere;
  // nullopt when the pass writes no such slot.
  std::optional<StreamOutputBuffer> stream_output_buffer(uint32_t technique, uint32_t pass, uint32_t slot = 0) const;
  // Captures every stream-output pass of `technique`, in pass order, each with `draw`
  // recording the geometry (of `vertex_layout`): what a preview does before it draws. True
  // when there are none.
  bool capture_stream_output_passes(VkCommandBuffer cmd, uint32_t technique, uint32_t vertex_layout,
                                    const std::function<void(VkCommandBuffer)>& draw, DiagnosticSink& sink);
  // The stream-output pass before pass `pass` whose vertices a preview draws with it (the
  // last one before it; the D3D10 particle pattern), or kNoIndex.
  uint32_t stream_output_source(uint32_t technique, uint32_t pass) const;

  // Creates the technique's pipelines for these formats and layout now (instead of at the
  // first apply). False with diagnostics if one cannot be made.
  bool warm(uint32_t technique, const RenderingFormats& formats, uint32_t vertex_layout, DiagnosticSink& sink);

  // Starts applying `technique` into `cmd` (inside the app's dynamic rendering with
  // attachments of `formats`); uploads textures not yet on the GPU. False (nothing is
  // recorded by apply then) when the technique cannot run or an upload failed.
  bool begin(VkCommandBuffer cmd, uint32_t technique, const RenderingFormats& formats, const VkViewport& viewport,
             const VkRect2D& scissor, DiagnosticSink& sink);
  // Binds pass `pass` of the begun technique for geometry of `vertex_layout`; the app draws
  // after it returns true.
  bool apply(uint32_t pass, uint32_t vertex_layout, DiagnosticSink& sink);
  // apply() for vertex layout 0 as a plain function (fxkit::detail::PassApply): `binding` an
  // EffectBinding, `sink` a DiagnosticSink.
  static bool apply_layout0(void* binding, uint32_t pass, void* sink);
  // Ends the technique; the next begin() assumes nothing is bound.
  void end();

  // The pipeline (created if needed) and program that pass `pass` of `technique` binds for
  // these formats and vertex layout: for tools that record the same work by hand (fxkit
  // bench apply). False with diagnostics when the pass cannot be drawn.
  bool pass_objects(uint32_t technique, uint32_t pass, const RenderingFormats& formats, uint32_t vertex_layout,
                    VkPipeline& pipeline, const ShaderProgram*& program, DiagnosticSink& sink);

  const ApplyStats& stats() const { return recorder_->stats(); }
  void reset_stats() { recorder_->reset_stats(); }
  // Pipelines created and samplers held by this binding.
  size_t pipeline_count() const;
  const DynamicStateSet& dynamic() const { return recorder_->dynamic(); }

  // Vulkan objects (shader modules, layouts, pipelines, samplers, pipeline caches, descriptor
  // pools) that live bindings hold, summed over the process: returns to its baseline when
  // every binding made after it is gone. Updated by create, warm, pass_objects, an apply()
  // that creates a pipeline or a descriptor pool, and destruction.
  static int64_t live_vulkan_objects() { return live_objects_.load(); }

 private:
  struct Pass;
  struct Technique;
  struct Builder;  // create()'s steps
  EffectBinding(const Context& ctx, ParameterStore& params, EffectTextureCache& textures);
  bool bind_textures(DiagnosticSink& sink);
  // bind_textures() for one pass (or compute half); `preview` fills unwritten buffers.
  bool bind_pass_resources(Pass& pass, bool preview, DiagnosticSink& sink);
  // The storage and texel buffers some pass writes (written_), sorted: made once by create().
  void find_written_buffers();
  // Whether some pass writes the storage or texel buffer `name` (a stand-in it only reads
  // may hold a preview pattern).
  bool written_by_a_pass(std::string_view name) const;
  // Writes the pass's changed uniform blocks into the frame's ring (pass.ring_offsets);
  // `moved` is set when one went to a new offset.
  bool write_blocks(Pass& pass, bool& moved, DiagnosticSink& sink);
  // apply()'s out-of-line parts, so the per-object path stays small: the error for a bad
  // pass index, and a pass bound from scratch (pipeline, state, descriptors).
  [[gnu::noinline]] static bool unknown_pass(uint32_t pass_index, DiagnosticSink& sink);
  [[gnu::noinline]] bool apply_pass(Pass& pass, uint32_t vertex_layout, DiagnosticSink& sink);
  // apply()'s body, inline in both apply() and apply_layout0().
  bool apply_inline(uint32_t pass, uint32_t vertex_layout, DiagnosticSink& sink);
  const VertexInput* vertex_input(Pass& pass, uint32_t layout, DiagnosticSink& sink);
  // "vk-pass-unknown" for a dispatch() or begin_capture() of a pass that is no `kind` pass
  // that can run; false.
  bool no_pass_that_runs(uint32_t technique, uint32_t pass, std::string_view kind, DiagnosticSink& sink) const;
  void update_object_count();

  // What apply() reads, once per object, first: with the recorder's own first fields, in
  // as few cache lines as they fit. The recorder is released first (~EffectBinding).
  ParameterStore* params_;
  FrameResources* frames_ = nullptr;
  Technique* active_ = nullptr;
  const Pass* applied_ = nullptr;  // the pass the last apply() recorded, and its vertex layout
  uint32_t applied_layout_ = 0;
  std::optional<PassRecorder> recorder_;
  const EffectModel* model_ = nullptr;
  EffectTextureCache* textures_;
  std::optional<PipelineCache> pipelines_;
  SamplerCache samplers_;
  DescriptorArena descriptor_sets_;  // the passes' sets, kept across frames
  std::vector<std::unique_ptr<Technique>> techniques_;
  std::vector<VertexLayout> layouts_;
  std::vector<std::pair<uint32_t, Texture>> app_textures_;  // texture parameter -> app view
  EffectStorage storage_;
  TextureFills fills_;  // textures the effect's texture shaders fill, at the first bind
  VkExtent2D storage_extent_{};
  std::vector<std::string> written_;  // find_written_buffers()
  bool textures_pending_ = true;
  RenderingFormats formats_;   // of the begun technique
  Pass* capturing_ = nullptr;  // the pass begin_capture() began, until end_capture()
  VkCommandBuffer capture_cmd_ = VK_NULL_HANDLE;
  int64_t counted_objects_ = 0;
  static std::atomic<int64_t> live_objects_;
};

}  // namespace fx::vk
