// Pictures of what compute passes wrote, for previews of techniques that draw nothing
// (fxkit render, preview-rate): a storage buffer's words or a storage image's texels as an
// RGBA8 image whose constancy says whether the passes wrote anything that varies.
#pragma once
#include <cstdint>
#include <span>

#include "fx/binding/effect_storage.h"
#include "fx/compile/shader_reflection.h"
#include "fx/image.h"

namespace fx::vk {

// A buffer's 32-bit words, `width` a row (the last row padded with the smallest value): each
// a grey level from the smallest value to the largest, read as `element` says (float, int or
// uint; others as uint). Non-finite floats are black. One flat grey when every word is equal.
fx::Image buffer_picture(std::span<const uint32_t> words, ScalarKind element, uint32_t width);

// A storage image's texels: float channels clamped to [0, 1], integer channels scaled from the
// smallest value to the largest of the image; one or two channels show as red (and green);
// the fourth channel is not shown (the picture is opaque).
fx::Image texel_picture(const StorageTexels& texels);

}  // namespace fx::vk
