// EffectTextureCache: bake/decode once, upload once, stand-ins for missing files.
#include "fx/binding/effect_textures.h"

#include <span>
#include <system_error>
#include <variant>

#include "fx/shading/generator.h"

namespace fx::vk {
namespace {

// Generator parameters in a canonical order (the map is sorted by lower-cased name).
std::string generator_key(const TextureInfo& t) {
  std::string key = "gen:" + t.generator;
  for (const auto& [name, value] : t.generator_params.entries()) {
    key += ';' + name + '=';
    if (const double* d = std::get_if<double>(&value)) key += std::to_string(*d);
    else key += std::get<std::string>(value);
  }
  return key;
}

std::string stand_in_key(StandIn kind, ImageDim dim, bool arrayed) {
  return std::string("stand-in:") + stand_in_name(kind) + ":" + std::to_string(int(dim)) + (arrayed ? ":array" : "");
}

// A neutral stand-in is one texel: a normal map's "straight out of the surface", white for
// colours and masks, a depth of 1.0 for a depth comparison (a shadow map nothing is in front
// of). A preview stand-in is an image (texture_stand_in.h). Made in the shape the shader samples.
EffectTextureData stand_in(StandIn kind, ImageDim dim, bool arrayed) {
  EffectTextureData d;
  d.key = stand_in_key(kind, dim, arrayed);
  d.dim = dim;
  d.arrayed = arrayed;
  d.stand_in = true;
  d.depth = kind == StandIn::depth;
  d.multisampled = kind == StandIn::multisampled;
  if (d.depth) return d;  // uploaded by Texture::solid_depth
  if (fx::DdsTexture texels = stand_in_texels(kind, dim); !texels.data.empty()) {
    d.dds = std::move(texels);
    return d;
  }
  const uint8_t c = kind == StandIn::flat_normal ? 128 : 255;
  fx::Image image = fx::Image::blank(1, 1, 4);
  const uint8_t texel[4] = {c, c, 255, 255};
  std::copy(texel, texel + 4, image.pixels.begin());
  d.image = std::move(image);
  return d;
}

ImageKind image_kind(ImageDim dim) {
  switch (dim) {
    case ImageDim::dim_1d: return ImageKind::image1d;
    case ImageDim::dim_3d: return ImageKind::image3d;
    case ImageDim::cube: return ImageKind::cube;
    default: return ImageKind::image2d;
  }
}

// The first of effect_dir/name, then each of more_dirs/name that is a readable file ("" if
// none); `size` gets its size. An absolute name is taken as it is.
std::filesystem::path find_texture_file(const std::string& name, const std::filesystem::path& effect_dir,
                                        std::span<const std::filesystem::path> more_dirs, std::uintmax_t& size) {
  const std::filesystem::path relative(name);
  std::vector<std::filesystem::path> candidates;
  if (relative.is_absolute()) candidates.push_back(relative);
  else {
    candidates.push_back(effect_dir / relative);
    for (const auto& dir : more_dirs) candidates.push_back(dir / relative);
  }
  for (const auto& candidate : candidates) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(candidate, ec)) continue;
    size = std::filesystem::file_size(candidate, ec);
    if (!ec) return candidate;
  }
  return {};
}

const char* dim_name(ImageDim dim) {
  switch (dim) {
    case ImageDim::dim_1d: return "a 1D";
    case ImageDim::dim_3d: return "a 3D";
    case ImageDim::cube: return "a cube";
    default: return "a 2D";
  }
}

// A texture file as the shader samples it: DDS (any shape, by its header) or what stb reads
// (2D). Nullopt, with `why`, when it cannot be decoded, has another shape than `dim`, or is
// in a format the device can neither sample nor fxkit decode.
std::optional<EffectTextureData> read_texture_file(const Context& ctx, const std::filesystem::path& file, ImageDim dim,
                                                   bool arrayed, DiagnosticSink& sink, std::string& why) {
  auto bytes = fx::read_image_bytes(file, sink);
  if (!bytes) return std::nullopt;
  EffectTextureData data;
  data.dim = dim;
  data.arrayed = arrayed;
  ImageDim shape = ImageDim::dim_2d;
  uint32_t layers = 1;
  if (fx::is_dds(*bytes)) {
    data.dds = fx::decode_dds(*bytes, sink, file.string());
    if (!data.dds) return std::nullopt;
    if (!Texture::can_sample_dds(ctx, *data.dds)) {
      why = "device '" + ctx.info().name + "' cannot sample its DXGI format " + std::to_string(int(data.dds->format)) +
            " and fxkit does not decode it";
      return std::nullopt;
    }
    shape = data.dds->shape == fx::DdsShape::texture1d ? ImageDim::dim_1d
            : data.dds->shape == fx::DdsShape::volume  ? ImageDim::dim_3d
            : data.dds->shape == fx::DdsShape::cube    ? ImageDim::cube
                                                       : ImageDim::dim_2d;
    layers = data.dds->shape == fx::DdsShape::cube ? data.dds->layers / 6 : data.dds->layers;
  } else {
    data.image = fx::decode_image(*bytes, sink);
    if (!data.image) return std::nullopt;
  }
  if (shape != dim) {
    why = std::string("the file holds ") + dim_name(shape) + " texture; the shader samples " + dim_name(dim) + " one";
    return std::nullopt;
  }
  if (layers > 1 && !arrayed) {
    why = "the file holds an array of " + std::to_string(layers) + "; the shader samples one texture";
    return std::nullopt;
  }
  return data;
}

}  // namespace

std::shared_ptr<const EffectTextureData> EffectTextureCache::resolve(const EffectModel& model,
                                                                     const TextureInfo& texture,
                                                                     const std::filesystem::path& effect_dir,
                                                                     ImageDim dim, bool arrayed, DiagnosticSink& sink,
                                                                     std::span<const std::filesystem::path> more_dirs) {
  const Parameter* param = texture.parameter < model.parameters.size() ? &model.parameters[texture.parameter] : nullptr;
  const StandIn neutral = texture_stand_in(param, dim, preview_stand_ins_);
  const SourceRange at = texture.resource_range.valid() ? texture.resource_range : param ? param->range : SourceRange{};
  const std::string what =
      "texture file '" + texture.resource_name + "' of '" + (param ? param->name : std::string()) + "'";
  const std::string standing_in = std::string("; a ") + stand_in_name(neutral) + " stands in";
  std::string key;
  std::filesystem::path file;
  if (!texture.generator.empty()) {
    key = generator_key(texture);
  } else if (!texture.resource_name.empty()) {
    std::error_code ec;
    std::uintmax_t size = 0;
    file = find_texture_file(texture.resource_name, effect_dir, more_dirs, size);
    if (!file.empty()) {
      const auto mtime = std::filesystem::last_write_time(file, ec).time_since_epoch().count();
      key = "file:" + file.lexically_normal().string() + ':' + std::to_string(size) + ':' + std::to_string(mtime) +
            ':' + std::to_string(int(dim)) + (arrayed ? ":array" : "");
    } else {
      sink.warning("vk-texture-file-missing", at,
                   what + " cannot be found beside the effect or in the include folders" + standing_in);
      key = stand_in_key(neutral, dim, arrayed);
    }
  } else {
    key = stand_in_key(neutral, dim, arrayed);
  }
  if (auto hit = cached(key)) return hit;
  // Baking can take a while (BRDF factorisation): done outside the lock, so two threads may
  // race to bake the same table; the first to insert wins and both get equal data.
  EffectTextureData data;
  if (key.rfind("stand-in:", 0) == 0) {
    data = stand_in(neutral, dim, arrayed);
  } else if (!texture.generator.empty()) {
    auto table = shading::bake(texture.generator, texture.generator_params, sink, texture.generator_range);
    if (!table) return nullptr;
    data.table = std::move(*table);
  } else {
    DiagnosticSink decode;
    std::string why;
    if (auto file_data = read_texture_file(*ctx_, file, dim, arrayed, decode, why)) {
      data = std::move(*file_data);
    } else {
      for (const Diagnostic& d : decode.diagnostics()) why += (why.empty() ? "" : "; ") + d.message;
      sink.warning("vk-texture-file-missing", at, what + " cannot be used (" + why + ")" + standing_in);
      data = stand_in(neutral, dim, arrayed);
      key = data.key;
    }
  }
  data.key = key;
  return keep(std::move(data));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::depth_stand_in(ImageDim dim, bool arrayed) {
  if (auto hit = cached(stand_in_key(StandIn::depth, dim, arrayed))) return hit;
  return keep(stand_in(StandIn::depth, dim, arrayed));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::multisampled_stand_in(bool arrayed) {
  if (auto hit = cached(stand_in_key(StandIn::multisampled, ImageDim::dim_2d, arrayed))) return hit;
  return keep(stand_in(StandIn::multisampled, ImageDim::dim_2d, arrayed));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::integer_stand_in(ScalarKind sampled, ImageDim dim,
                                                                              bool arrayed) {
  const StandIn kind = sampled == ScalarKind::int32 ? StandIn::signed_zero : StandIn::unsigned_zero;
  if (auto hit = cached(stand_in_key(kind, dim, arrayed))) return hit;
  return keep(stand_in(kind, dim, arrayed));
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::cached(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = cpu_.find(key);
  return it != cpu_.end() ? it->second : nullptr;
}

std::shared_ptr<const EffectTextureData> EffectTextureCache::keep(EffectTextureData data) {
  std::string key = data.key;
  auto shared = std::make_shared<const EffectTextureData>(std::move(data));
  std::lock_guard<std::mutex> lock(mutex_);
  return cpu_.emplace(std::move(key), std::move(shared)).first->second;  // the first to insert wins
}

const Texture* EffectTextureCache::gpu(const EffectTextureData& data, DiagnosticSink& sink) {
  if (auto it = gpu_.find(data.key); it != gpu_.end()) return &it->second;
  std::optional<Texture> texture;
  if (data.depth) {
    texture = Texture::solid_depth(*ctx_, 1.0f, image_kind(data.dim), data.arrayed, sink);
  } else if (data.multisampled) {
    const uint8_t* p = data.image->pixels.data();
    texture = Texture::solid_multisampled(*ctx_, {p[0], p[1], p[2], p[3]}, data.arrayed, sink);
  } else if (data.stand_in && data.image) {
    const uint8_t* p = data.image->pixels.data();
    texture = Texture::solid(*ctx_, {p[0], p[1], p[2], p[3]}, image_kind(data.dim), data.arrayed, sink);
  } else if (data.table) texture = Texture::from_table(*ctx_, *data.table, sink);
  else if (data.dds) texture = Texture::from_dds(*ctx_, *data.dds, data.arrayed, sink);
  else if (data.image) texture = Texture::from_image(*ctx_, *data.image, ColorSpace::linear, sink);
  if (!texture) return nullptr;
  return &gpu_.emplace(data.key, std::move(*texture)).first->second;
}

void EffectTextureCache::clear() {
  gpu_.clear();
  std::lock_guard<std::mutex> lock(mutex_);
  cpu_.clear();
}

}  // namespace fx::vk
