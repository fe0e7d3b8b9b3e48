// fxkit::Effect, Technique and Param: a loaded effect file and what an engine does with it
// per object: choose a technique, set parameters, apply each pass, draw. Every handle
// survives reloads (parameters are translated, the technique is looked up again).
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fx/model/draw_state.h"
#include "fx/model/matrix_order.h"  // fxkit::MatrixOrder
#include "fx/model/param.h"         // fxkit::Param
#include "fx/vulkan/apply_stats.h"
#include "fx/vulkan/pass_apply.h"
#include "fxkit/message.h"
#include "fxkit/script_frame.h"

namespace fxkit {

namespace detail {
struct EffectState;
}

// fxkit::Param (fx/model/param.h): a parameter of an effect (by name or semantic); stays
// valid across reloads. Invalid handles make every set() return false and change nothing.

// What the application asks of an object this frame (docs/selection.md): techniques with
// LOD bands, cost and error annotations are chosen against these.
struct Criteria {
  float distance = 0.f;      // camera distance, world units
  float screen_size = -1.f;  // projected size in pixels; negative: unknown
  float pixels = 0.f;        // covered pixels (turns a per-pixel cost into milliseconds)
  std::string scheme{};      // "" accepts every scheme
  float cost_budget_ms = std::numeric_limits<float>::infinity();
  float max_error = std::numeric_limits<float>::infinity();  // 8-bit levels
  // "" selects for this device. A caps profile (caps_profiles(): "dx6" ... "dx9c",
  // "modern") selects as that generation would, among the techniques this device draws.
  std::string caps{};
};

// The caps profiles Criteria::caps takes, oldest first.
std::vector<std::string> caps_profiles();

// A camera and object transform for the standard semantics (WORLD, VIEW, PROJECTION, their
// products, inverses and transposes, CAMERAPOSITION, TIME, ELAPSEDTIME, VIEWPORTPIXELSIZE).
// Column-major 4x4 (glm's memory order), right-handed, clip-space +Y up, depth 0..1.
struct Scene {
  float world[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float projection[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float eye[3] = {0, 0, 3};
  float time = 0.f;                 // seconds (TIME)
  float elapsed = 1.f / 60.f;       // seconds since the previous frame (ELAPSEDTIME)
  float viewport_size[2] = {0, 0};  // pixels (VIEWPORTPIXELSIZE); 0 leaves it alone
  // A camera looking at a sphere of `radius` around the origin, from the front and a
  // little above, filling about 85% of the shorter side of an image of `aspect`.
  static Scene framing(float radius, float aspect);
};

// An annotation of a parameter (`<float UIMin = 0;>`, `<string UIWidget = "Color";>`), with
// its value as the file wrote it. Names are case-sensitive, as D3DX reads them.
struct Annotation {
  enum class Kind : uint8_t { string, floats, ints, boolean };
  std::string name{};
  Kind kind = Kind::string;
  std::string text{};           // Kind::string
  std::vector<float> values{};  // the numbers (bool: 0 or 1); empty for strings
  // The i-th number, 0 when there is none.
  float number(size_t i = 0) const { return i < values.size() ? values[i] : 0.f; }
};

// What a parameter holds.
// `view`: a D3D11 buffer or storage image (StructuredBuffer, ByteAddressBuffer, RWTexture2D,
// ...) that set_buffer() or set_storage_image() binds.
enum class ParamKind : uint8_t { numeric, structure, string, texture, sampler, other, view };
// The component type of a numeric parameter (half and double read as float).
enum class ScalarKind : uint8_t { boolean, int32, uint32, float32 };

// A parameter's reflection (Effect::params): type, semantic, annotations and default.
struct ParamInfo {
  Param handle{};
  std::string name{};
  std::string semantic{};  // as written; "" when none
  std::string type{};      // HLSL spelling: "float4x4", "float3[4]", "Texture2D", "sampler2D"
  ParamKind kind = ParamKind::other;
  ScalarKind scalar = ScalarKind::float32;  // numeric parameters
  uint32_t rows = 1, columns = 1;           // float4: 1x4; float4x4: 4x4
  uint32_t elements = 0;                    // array elements; 0 when not an array
  uint32_t components = 0;                  // scalars in all (what get()/set() take)
  // Textures: "1D", "2D", "3D", "CUBE" or "" (D3D9's untyped texture), and the file the
  // effect names (ResourceName, Name or File annotation; "" when none).
  std::string texture_shape{};
  std::string resource_name{};
  // The declaration's default: components in D3D order (matrices row by row), or the text
  // of a string. Empty when the declaration has none (the value is then zero).
  std::vector<float> default_value{};
  std::string default_text{};
  bool has_default = false;
  // Whether the application can set it: in a uniform block or a resource binding (not
  // static, not a shader or state object).
  bool settable = false;
  std::vector<Annotation> annotations{};
  // An fx_5_0 interface variable (`iLight g_light;`, an int): the class instance variables it
  // can be bound to, in the order of the ids it holds (Effect::set_class_instance).
  std::vector<std::string> class_instances{};
  // The annotation called `name`, or nullptr.
  const Annotation* annotation(std::string_view name) const;
};

// What Technique::apply recorded for an effect since its last reset_stats() (profiling):
// passes, pipeline binds, vkCmdSet* calls, descriptor binds, pushes and writes, uniform
// uploads. The Vulkan layer's own type (fx/vulkan/apply_stats.h).
using ApplyStats = fx::vk::ApplyStats;

// An output buffer of a stream-output pass (ConstructGSWithSO) and its byte counter, to bind
// elsewhere (a vertex or storage buffer; the counter as an indirect byte count).
struct StreamOutputBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;   // vertex, storage, transform feedback and transfer source usage
  VkBuffer counter = VK_NULL_HANDLE;  // 4 bytes: how many bytes the last capture wrote
  VkDeviceSize size = 0;              // bytes
  uint32_t stride = 0;                // bytes per vertex, as the declaration lays them out
};

// Whether a technique can be drawn on this device, and why not.
struct TechniqueInfo {
  std::string name{};
  uint32_t passes = 0;
  bool drawable = false;
  std::string reason{};  // "" when drawable
  // Why the caps profile the last select() emulated rejects it ("" when it accepts it, or
  // when select() emulated none).
  std::string caps_reason{};
  // The distance band selection tests it against (MinDistance/MaxDistance or LodMin/LodMax),
  // as `fxkit select` prints it: "[-inf, 40)", "[40, inf)"; "" when it has none.
  std::string distance_band{};
  // As the file writes them: selection's (Scheme, MaxError, CostNsPerPixel, ...; see
  // docs/selection.md) and any other.
  std::vector<Annotation> annotations{};
  // An fx_5_0 interface variable (`iLight g_light;`, an int): the class instance variables it
  // can be bound to, in the order of the ids it holds (Effect::set_class_instance).
  std::vector<std::string> class_instances{};
  // The annotation called `name`, or nullptr.
  const Annotation* annotation(std::string_view name) const;
};

// A technique of an effect, by name or by selection. Recorded on the render thread with
// begin(), apply() per pass before each draw, end(): docs/embedding.md, samples/minimal.
class Technique {
 public:
  Technique() = default;
  // Whether it names a technique of the live version that can be drawn.
  bool valid() const;
  std::string name() const;
  uint32_t pass_count() const;
  // Why it cannot be drawn ("" when it can).
  std::string reason() const;

  // Starts recording into `cmd` (the application's command buffer, inside its dynamic
  // rendering with the Target's formats): sets the viewport and scissor and uploads textures
  // not yet on the GPU. After a reload it draws the new version. False: nothing to draw
  // (apply() then returns false too).
  bool begin(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor);
  // Binds pass `pass` (pipeline, dynamic state, descriptors, changed uniform data); the app
  // draws after it returns true. Inline: one call into the library per pass; problems stay
  // in the effect's messages() from end() on.
  bool apply(uint32_t pass) {
    const detail::PassApply* a = pass_apply_;
    return a && a->binding && a->apply(a->binding, pass, a->sink);
  }
  // Ends the recording; the next begin() assumes nothing is bound.
  void end();
  // Whether pass `pass` runs a compute shader (SetComputeShader): dispatch() it.
  bool compute_pass(uint32_t pass) const;
  // Whether pass `pass` has graphics shaders: apply() it (a stream-output pass is captured).
  // A pass that sets a compute shader beside them, as FX11 allows, is both: dispatch() runs
  // its compute shader, apply() its graphics stages.
  bool draw_pass(uint32_t pass) const;
  // Records compute pass `pass` into `cmd` with x * y * z workgroups, outside the
  // application's rendering and outside begin()/end(), followed by the barrier that makes
  // its buffer and image writes visible to every draw and dispatch recorded after it
  // ("simulate, then draw": dispatch the compute passes, then begin() and apply() the
  // others). False, with the reason in messages(), when it is no compute pass.
  bool dispatch(VkCommandBuffer cmd, uint32_t pass, uint32_t x, uint32_t y = 1, uint32_t z = 1);
  // Dispatches every compute pass, in pass order, as fxkit render does before it draws: each
  // with its `Dispatch` pass annotation's workgroup counts (`int3 Dispatch = {64, 1, 1};`),
  // else one thread per pixel of a `width` x `height` target. Outside rendering and
  // begin()/end(); the draw loop then skips the compute passes. True when there are none.
  bool dispatch_compute_passes(VkCommandBuffer cmd, uint32_t width, uint32_t height);

  // Whether pass `pass` captures its output stream (ConstructGSWithSO): begin_capture() it,
  // not apply(). The device needs VK_EXT_transform_feedback (reason() says so otherwise).
  bool stream_output_pass(uint32_t pass) const;
  // Starts capturing stream-output pass `pass` into its buffers, outside the application's
  // rendering and outside begin()/end() (the capture runs in a rendering of its own, with
  // nothing rasterized). The application then binds and draws its geometry (the Target's
  // vertex layout) into `cmd` and calls end_capture(), which records the barrier after
  // which later draws read what was captured. False, with the reason in messages(), when
  // it is no stream-output pass.
  bool begin_capture(VkCommandBuffer cmd, uint32_t pass);
  void end_capture();
  // Between begin() and end(): applies pass `pass` and draws every vertex stream-output pass
  // `stream_output_pass` captured last, however many that was (Direct3D's DrawAuto).
  bool draw_stream_output(VkCommandBuffer cmd, uint32_t pass, uint32_t stream_output_pass);
  // Output buffer `slot` of stream-output pass `pass` ({} when it has none).
  StreamOutputBuffer stream_output_buffer(uint32_t pass, uint32_t slot = 0) const;

  // Whether the technique has a DXSAS Script annotation (docs/dxsas.md): it draws its own
  // frame with run_script(), not with begin() and apply().
  bool has_script() const;
  // Records the technique's script into `cmd`, outside the application's rendering and
  // outside begin()/end(): its render targets (made by fxkit for each loaded version and
  // frame size), clears, passes, Draw=Geometry (frame.draw_geometry), Draw=Buffer (a quad of
  // fxkit's over frame.area, in the Target's vertex layout and conventions) and
  // ScriptExternal (frame.draw_scene), into `frame`'s images. False, with the reason in
  // messages(), when it has no script or a pass cannot be drawn.
  bool run_script(VkCommandBuffer cmd, const ScriptFrame& frame);
  // The render targets the last run_script() drew with (thumbnails); their views stay valid
  // until the next run_script() after a reload or a frame size change.
  std::vector<ScriptTarget> script_targets() const;

 private:
  friend class Effect;
  std::shared_ptr<detail::EffectState> effect_;
  const detail::PassApply* pass_apply_ = nullptr;  // effect_'s, for the inline apply()
  std::string name_;                               // "" follows selection
  // name_'s technique index and its pass count in the version of serial resolved_serial_
  // (0: none yet), so that begin() and pass_count() compare no names while it stays.
  mutable uint64_t resolved_serial_ = 0;
  mutable uint32_t resolved_ = 0, passes_ = 0;
};

class Effect {
 public:
  Effect() = default;
  // Whether a good version is live (false while a first load has errors).
  bool ok() const;
  const std::string& path() const;
  // Errors and warnings of the last load or reload attempt.
  std::vector<Message> messages() const;
  // Changes on every successful reload.
  uint64_t serial() const;

  // Every technique, drawable or not with the reason.
  std::vector<TechniqueInfo> techniques() const;
  // The technique called `name` (not valid() when there is none; reason() says so).
  Technique technique(std::string_view name) const;
  // The technique selection chooses for `criteria`, re-chosen with them after reloads.
  Technique select(const Criteria& criteria = {}) const;

  // By exact name, else by semantic (case-insensitive).
  Param param(std::string_view name_or_semantic) const;
  // Every top-level parameter of the live version, in declaration order (empty when none).
  std::vector<ParamInfo> params() const;
  // Setters: the value's shape must match the parameter's type (a float3 takes 3 floats).
  // False, with a message kept for messages(), when it does not.
  bool set(Param p, float value);
  bool set(Param p, int32_t value);
  bool set(Param p, bool value);
  bool set(Param p, std::span<const float> values);
  bool set(Param p, std::initializer_list<float> values) { return set(p, std::span<const float>(values)); }
  // Inline for the per-object call (a matrix the application set before, drawn with the
  // same pass object after object): it writes into the live version's uniform bytes; every
  // other case takes the checked path.
  bool set_matrix(Param p, const float* m16, MatrixOrder order = MatrixOrder::row_major) {
    detail::DrawState* d = draw_ ? *draw_ : nullptr;
    if (d && d->store_hot(p.index, p.generation, m16, order == MatrixOrder::column_major)) [[likely]]
      return true;
    return set_matrix_checked(p, m16, order);
  }
  bool set(Param p, std::span<const int32_t> values);
  // Binds an fx_5_0 interface variable to a class instance variable (`g_sun`, `g_lamps[1]`),
  // as FX11's SetClassInstance: calls through the variable run that instance's class. No
  // recompile; false when `instance` is not one of ParamInfo::class_instances.
  bool set_class_instance(Param interface_variable, std::string_view instance);
  // The current value of ParamInfo::components: floats for float parameters, ints for int,
  // uint and bool ones (false when the kind or the count does not match).
  bool get(Param p, std::span<float> out) const;
  bool get(Param p, std::span<int32_t> out) const;
  // Follows the file's default again (reloads then apply edited defaults to it).
  bool reset(Param p);
  // Every parameter whose semantic is a standard one; returns how many were set.
  uint32_t set_scene(const Scene& scene);
  // For tools that preview effects nobody set up (a viewer): the parameters the shaders read
  // that the file gives no default and are still zero get a stand-in that draws something
  // (identity bone palettes, grey colours, a light direction, one light; docs/parameters.md,
  // "Stand-ins for a preview"). Returns their names. A stand-in counts as a value the
  // application set. An engine sets its own values instead.
  std::vector<std::string> set_preview_defaults();
  // Counters of the live version's recording.
  ApplyStats stats() const;
  void reset_stats();

  // Samples the application's image for texture parameter `name` (from the next begin()).
  // The view stays the application's; it must outlive the frames that use it. Call it again
  // for a view made anew (after a resize), even when its handle equals the old one's.
  bool set_texture(std::string_view name, VkImageView view, VkImageLayout layout,
                   VkImageViewType type = VK_IMAGE_VIEW_TYPE_2D);
  // Reads an image file (PNG, JPEG, TGA, BMP: what stb_image reads) for texture parameter
  // `name`, uploads it as a 2D texture and samples it from the next begin(), as set_texture
  // (also after reloads). Render thread: the upload uses the device's queue. The device
  // keeps the upload until it is destroyed (uploads are shared per file and modification
  // time). False, with the reason in messages(), when `name` is no texture parameter or the
  // file cannot be read.
  bool set_texture_file(std::string_view name, const std::string& file);
  // Binds `range` bytes of the application's `buffer` from `offset` (it needs
  // VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) to the storage buffer `name`: a StructuredBuffer,
  // RWStructuredBuffer, (RW)ByteAddressBuffer, Append/ConsumeStructuredBuffer (its counter is
  // the buffer "name@count") or tbuffer, from the next begin() or dispatch(), also after
  // reloads. Until then a zeroed 64 KiB stand-in serves it. The buffer must outlive the
  // frames that use it. False, with the reason in messages(), when no pass uses `name`.
  bool set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset = 0, VkDeviceSize range = VK_WHOLE_SIZE);
  // The same for the storage image `name` (RWTexture1D/2D/3D and arrays): the application's
  // view, in VK_IMAGE_LAYOUT_GENERAL, of an image with VK_IMAGE_USAGE_STORAGE_BIT. Until then a
  // zeroed stand-in of the texture's shape serves it: the target's width (1D), its size (2D),
  // its size and 4 deep (3D), 4 layers (1D and 2D arrays).
  bool set_storage_image(std::string_view name, VkImageView view);
  // The same for the texel buffer `name` (Buffer<T>, RWBuffer<T>): the application's buffer
  // view (VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT or STORAGE_TEXEL_BUFFER_BIT). Until then a
  // view of a zeroed 64 KiB stand-in in the element's format (float4: R32G32B32A32_SFLOAT).
  bool set_texel_buffer(std::string_view name, VkBufferView view);

 private:
  friend class Device;
  bool set_matrix_checked(Param p, const float* m16, MatrixOrder order);
  std::shared_ptr<detail::EffectState> state_;
  // The live version's per-object state (null when none), which the device refreshes where
  // versions change: points into *state_.
  detail::DrawState* const* draw_ = nullptr;
};

}  // namespace fxkit
