// fxkit::Offscreen: a RenderTarget of the device Target's first colour format and its depth
// format, read back as RGBA8.
#include "fxkit/offscreen.h"

#include "api_state.h"
#include "fx/vulkan/render_target.h"

namespace fxkit {

struct Offscreen::Impl {
  const fx::vk::Context* ctx = nullptr;
  std::optional<fx::vk::RenderTarget> target;
  YFlip y_flip = YFlip::negative_viewport;
};

Offscreen::Offscreen(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Offscreen::~Offscreen() = default;

std::unique_ptr<Offscreen> Offscreen::create(Device& device, uint32_t width, uint32_t height,
                                             std::vector<Message>& errors) {
  const Target& t = device.target();
  fx::DiagnosticSink sink;
  fx::vk::DepthAttachment depth = fx::vk::DepthAttachment::none;
  if (t.formats.depth == VK_FORMAT_D32_SFLOAT) depth = fx::vk::DepthAttachment::d32;
  else if (t.formats.depth == VK_FORMAT_D24_UNORM_S8_UINT) depth = fx::vk::DepthAttachment::d24s8;
  else if (t.formats.depth != VK_FORMAT_UNDEFINED)
    sink.error("offscreen-format", {}, "Offscreen renders with D32_SFLOAT or D24_UNORM_S8_UINT depth only");
  if (t.formats.color.empty()) sink.error("offscreen-format", {}, "Offscreen needs a colour format in the Target");
  auto impl = std::make_unique<Impl>();
  impl->ctx = &*device.state().ctx;
  impl->y_flip = t.y_flip;
  if (!sink.has_errors())
    impl->target = fx::vk::RenderTarget::create(*impl->ctx,
                                                {width, height, t.formats.color[0], depth, 0, "fxkit offscreen"}, sink);
  if (impl->target && impl->target->formats().depth != t.formats.depth)
    sink.error("offscreen-format", {}, "the device has no D24_UNORM_S8_UINT depth attachment; use D32_SFLOAT");
  if (sink.has_errors()) {
    auto more = detail::to_messages(sink.diagnostics(), nullptr);
    errors.insert(errors.end(), more.begin(), more.end());
    return nullptr;
  }
  return std::unique_ptr<Offscreen>(new Offscreen(std::move(impl)));
}

void Offscreen::begin(VkCommandBuffer cmd, std::array<float, 4> clear) {
  fx::vk::ClearValues values;
  values.color = clear;
  impl_->target->begin(cmd, values);
}

void Offscreen::end(VkCommandBuffer cmd) {
  impl_->target->end(cmd);
  impl_->target->record_readback(cmd);
}

VkViewport Offscreen::viewport() const {
  const float w = float(width()), h = float(height());
  if (impl_->y_flip == YFlip::negative_viewport) return {0.f, h, w, -h, 0.f, 1.f};
  return {0.f, 0.f, w, h, 0.f, 1.f};
}

VkRect2D Offscreen::scissor() const { return impl_->target->scissor(); }
uint32_t Offscreen::width() const { return impl_->target->width(); }
uint32_t Offscreen::height() const { return impl_->target->height(); }

std::vector<uint8_t> Offscreen::read_rgba8() const {
  fx::DiagnosticSink sink;
  std::optional<fx::Image> image = impl_->target->readback_pixels(sink);
  return image ? image->pixels : std::vector<uint8_t>{};
}

bool Offscreen::write_png(const std::string& path, std::vector<Message>& errors) const {
  fx::DiagnosticSink sink;
  std::optional<fx::Image> image = impl_->target->readback_pixels(sink);
  if (image) fx::write_png(path, *image, sink);
  auto more = detail::to_messages(sink.diagnostics(), nullptr);
  errors.insert(errors.end(), more.begin(), more.end());
  return image && !sink.has_errors();
}

}  // namespace fxkit
